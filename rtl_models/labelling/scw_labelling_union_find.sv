// SPDX-License-Identifier: Apache-2.0
// Labelling: the merge unit, union-find over the parent RAM one queued edge at a time.
`default_nettype none

// The twin of hls::labelling::UnionFind (docs/labelling.md "Merge unit"). A parent word is
// {linked, parent}: linked = 0, n is a root; else parent < n (the model's parent + 1, split so
// that no decrement sits between a read and the next address). Roots link larger under smaller,
// so a component's root is its smallest node. The parent RAM reads through a register: rd_data_i
// is the word at the address read in the previous clock.
//   Idle   pop an edge (a, b), read parent[a]
//   FindA  follow parent[] from a to its root ra; then read parent[b]
//   FindB  follow parent[] from b to rb; when found, write parent[max] = min + 1 if ra != rb
//   PathA  write parent[a] = root + 1 unless a is the root (path compression)
//   PathB  the same for b
// An edge takes depth(a) + depth(b) + 5 clocks. The unit steps only while en_i.
module scw_labelling_union_find #(
  parameter int unsigned Nodes = 64,
  localparam int unsigned NodeW = (Nodes > 1) ? $clog2(Nodes) : 1,
  localparam int unsigned PW    = NodeW + 1  // a parent word {linked, parent}
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             en_i,
  input  logic             q_nonempty_i,
  input  logic [NodeW-1:0] head_a_i,
  input  logic [NodeW-1:0] head_b_i,
  input  logic [PW-1:0]    rd_data_i,
  output logic             pop_o,
  output logic             idle_o,
  output logic             rd_en_o,
  output logic [NodeW-1:0] rd_addr_o,
  output logic             wr_en_o,
  output logic [NodeW-1:0] wr_addr_o,
  output logic [PW-1:0]    wr_data_o
);
  typedef enum logic [2:0] {StIdle, StFindA, StFindB, StPathA, StPathB} state_e;

  state_e state_q, state_d;
  logic [NodeW-1:0] a_q, a_d, b_q, b_d, ra_q, ra_d, root_q, root_d, cur_q, cur_d;
  logic [NodeW-1:0] up, lo, hi;
  logic at_root;

  assign idle_o  = state_q == StIdle;
  assign at_root = !rd_data_i[NodeW];
  assign up      = rd_data_i[NodeW-1:0];  // the parent of the node just read
  // The two roots of FindB's last clock, ordered.
  assign lo      = (ra_q < cur_q) ? ra_q : cur_q;
  assign hi      = (ra_q < cur_q) ? cur_q : ra_q;

  always_comb begin
    state_d   = state_q;
    a_d       = a_q;
    b_d       = b_q;
    ra_d      = ra_q;
    root_d    = root_q;
    cur_d     = cur_q;
    pop_o     = 1'b0;
    rd_en_o   = 1'b0;
    rd_addr_o = cur_q;
    wr_en_o   = 1'b0;
    wr_addr_o = a_q;
    wr_data_o = '0;
    if (en_i) begin
      unique case (state_q)
        StIdle: begin
          if (q_nonempty_i) begin
            pop_o     = 1'b1;
            a_d       = head_a_i;
            b_d       = head_b_i;
            rd_en_o   = 1'b1;
            rd_addr_o = head_a_i;
            cur_d     = head_a_i;
            state_d   = StFindA;
          end
        end
        StFindA: begin
          rd_en_o = 1'b1;
          if (at_root) begin
            ra_d      = cur_q;
            rd_addr_o = b_q;
            cur_d     = b_q;
            state_d   = StFindB;
          end else begin
            rd_addr_o = up;
            cur_d     = up;
          end
        end
        StFindB: begin
          if (at_root) begin
            root_d    = lo;
            wr_en_o   = ra_q != cur_q;
            wr_addr_o = hi;
            wr_data_o = {1'b1, lo};
            state_d   = StPathA;
          end else begin
            rd_en_o   = 1'b1;
            rd_addr_o = up;
            cur_d     = up;
          end
        end
        StPathA: begin
          wr_en_o   = a_q != root_q;
          wr_addr_o = a_q;
          wr_data_o = {1'b1, root_q};
          state_d   = StPathB;
        end
        StPathB: begin
          wr_en_o   = b_q != root_q;
          wr_addr_o = b_q;
          wr_data_o = {1'b1, root_q};
          state_d   = StIdle;
        end
        default: state_d = StIdle;
      endcase
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StIdle;
    end else begin
      state_q <= state_d;
    end
  end

  always_ff @(posedge clk_i) begin
    a_q    <= a_d;
    b_q    <= b_d;
    ra_q   <= ra_d;
    root_q <= root_d;
    cur_q  <= cur_d;
  end
endmodule
