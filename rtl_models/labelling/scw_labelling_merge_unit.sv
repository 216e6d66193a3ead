// SPDX-License-Identifier: Apache-2.0
// Labelling: a merge unit, the queue of edges to join and the union-find that joins them.
`default_nettype none

// The twin of an hls::labelling::EdgeQueue and the UnionFind that pops it (docs/labelling.md
// "Merge unit"). Each lane has one for its strip's edges, the stage one for the strip borders'.
// The parent RAM is the caller's: rd_data_i is the word at the address read in the previous
// clock. The unit steps only while en_i; the caller pushes only while the edges fit.
module scw_labelling_merge_unit #(
  parameter int unsigned Nodes   = 64,
  parameter int unsigned Depth   = 8,
  parameter int unsigned MaxPush = 2,
  parameter int unsigned Room    = 0,  // room_o: at most Depth - Room edges queued
  localparam int unsigned NodeW  = (Nodes > 1) ? $clog2(Nodes) : 1,
  localparam int unsigned PW     = NodeW + 1,  // a parent word {linked, parent}
  localparam int unsigned CountW = $clog2(Depth + 1),
  localparam int unsigned PushW  = $clog2(MaxPush + 1)
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  input  logic                     en_i,
  input  logic [PushW-1:0]         push_n_i,  // edges k = 0 .. push_n_i - 1, in order
  input  logic [MaxPush*NodeW-1:0] push_a_i,  // edge k at [k * NodeW +: NodeW]
  input  logic [MaxPush*NodeW-1:0] push_b_i,
  input  logic [PW-1:0]            rd_data_i,
  output logic [CountW-1:0]        count_o,   // edges queued
  output logic                     room_o,    // count_o <= Depth - Room (registered)
  output logic                     idle_o,    // no edge in the union-find
  output logic                     rd_en_o,
  output logic [NodeW-1:0]         rd_addr_o,
  output logic                     wr_en_o,
  output logic [NodeW-1:0]         wr_addr_o,
  output logic [PW-1:0]            wr_data_o
);
  logic pop, nonempty;
  logic [NodeW-1:0] head_a, head_b;


  scw_labelling_edge_queue #(
    .Depth  (Depth),
    .NodeW  (NodeW),
    .MaxPush(MaxPush),
    .Room   (Room)
  ) u_edge_queue (
    .clk_i,
    .rst_ni,
    .pop_i   (pop),
    .push_n_i,
    .push_a_i,
    .push_b_i,
    .count_o,
    .room_o,
    .nonempty_o(nonempty),
    .head_a_o(head_a),
    .head_b_o(head_b)
  );

  // ---- the union-find ----------------------------------------------------------------------
  // parent[n] = {linked, parent}: linked = 0, n is a root; else parent < n (the model's parent +
  // 1, split so that no decrement sits between a read and the next address). Roots link larger
  // under smaller, so a component's root is its smallest node. rd_data_i is the word at the
  // address read in the previous clock.
  //   Idle   pop an edge (a, b), read parent[a]
  //   FindA  follow parent[] from a to its root ra; then read parent[b]
  //   FindB  follow parent[] from b to rb; when found, write parent[max] = min if ra != rb
  //   PathA  write parent[a] = root unless a is the root (path compression)
  //   PathB  the same for b
  // An edge takes depth(a) + depth(b) + 5 clocks. The unit steps only while en_i.
  typedef enum logic [2:0] {StIdle, StFindA, StFindB, StPathA, StPathB} state_e;

  state_e state_q, state_d;
  // the state's decodes the read port follows, as registers without reset (reset holds state_d at
  // StIdle, so they equal state_q's decode from the first clock; see the edge queue's nonempty)
  logic s_idle_q, s_finda_q, s_findb_q, s_patha_q, s_pathb_q;
  logic [NodeW-1:0] a_q, a_d, b_q, b_d, ra_q, ra_d, root_q, root_d, cur_q, cur_d;
  logic [NodeW-1:0] up, lo, hi;
  logic at_root;

  assign idle_o  = state_q == StIdle;
  assign at_root = !rd_data_i[NodeW];
  assign up      = rd_data_i[NodeW-1:0];  // the parent of the node just read
  // The two roots of FindB's last clock, ordered.
  // ra_q vs cur_q and the edge's ends vs the root, compared as those registers load
  logic lt_q, ne_q, a_ne_q, b_ne_q;
  assign lo      = lt_q ? ra_q : cur_q;
  assign hi      = lt_q ? cur_q : ra_q;

  always_comb begin
    state_d   = state_q;
    a_d       = a_q;
    b_d       = b_q;
    ra_d      = ra_q;
    root_d    = root_q;
    cur_d     = cur_q;
    pop     = 1'b0;
    rd_en_o   = 1'b0;
    rd_addr_o = cur_q;
    wr_en_o   = 1'b0;
    wr_addr_o = a_q;
    wr_data_o = '0;
    if (en_i) begin
      unique case (state_q)
        StIdle: begin
          if (nonempty) begin
            pop     = 1'b1;
            a_d       = head_a;
            b_d       = head_b;
            rd_en_o   = 1'b1;
            rd_addr_o = head_a;
            cur_d     = head_a;
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
    // The read and write ports again, from the registered decodes and compares: the same
    // accesses, shorter paths.
    rd_en_o   = en_i && ((s_idle_q && nonempty) || s_finda_q || (s_findb_q && !at_root));
    rd_addr_o = s_idle_q ? head_a : ((s_finda_q && at_root) ? b_q : up);
    wr_en_o   = en_i && ((s_findb_q && at_root && ne_q) || (s_patha_q && a_ne_q) ||
                         (s_pathb_q && b_ne_q));
    wr_addr_o = s_findb_q ? hi : (s_patha_q ? a_q : b_q);
    wr_data_o = {1'b1, s_findb_q ? lo : root_q};
  end

  always_ff @(posedge clk_i) begin
    s_idle_q  <= state_d == StIdle;
    s_finda_q <= state_d == StFindA;
    s_findb_q <= state_d == StFindB;
    s_patha_q <= state_d == StPathA;
    s_pathb_q <= state_d == StPathB;
    // (ra_d, cur_d when the next state is FindB: cur_q, b_q from FindA; ra_q, up within FindB)
    lt_q      <= s_finda_q ? (cur_q < b_q) : (ra_q < up);
    ne_q      <= s_finda_q ? (cur_q != b_q) : (ra_q != up);
    if (s_findb_q) begin  // the last FindB clock leaves the root's
      a_ne_q <= a_q != lo;
      b_ne_q <= b_q != lo;
    end
  end

  always_ff @(posedge clk_i) begin
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
