// SPDX-License-Identifier: Apache-2.0
// Labelling: the register FIFO of node pairs to join, up to MaxPush pushes and one pop per clock.
`default_nettype none

// The twin of hls::labelling::EdgeQueue (hls::RegFifo): a pop moves the head, then the pushes
// append in order. A pop and the pushes of one clock leave head + count - pop = the old tail, so
// every write slot follows from the registers alone. The caller never pushes into a full queue
// (a lane takes a pixel only while at most Depth - 4 edges are queued, the border sweep reads a
// row only while its edges fit).
module scw_labelling_edge_queue #(
  parameter int unsigned Depth   = 8,
  parameter int unsigned NodeW   = 6,
  parameter int unsigned MaxPush = 2,
  parameter int unsigned Room    = 0,  // room_o: at most Depth - Room edges queued
  localparam int unsigned PtrW   = $clog2(Depth),
  localparam int unsigned CountW = $clog2(Depth + 1),
  localparam int unsigned PushW  = $clog2(MaxPush + 1)
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  input  logic                     pop_i,
  input  logic [PushW-1:0]         push_n_i,  // pushes k = 0 .. push_n_i - 1, in order
  input  logic [MaxPush*NodeW-1:0] push_a_i,  // push k at [k * NodeW +: NodeW]
  input  logic [MaxPush*NodeW-1:0] push_b_i,
  output logic [CountW-1:0]        count_o,
  output logic                     room_o,    // count_o <= Depth - Room, from a register
  output logic                     nonempty_o,  // count_o != 0, from a register
  output logic [NodeW-1:0]         head_a_o,
  output logic [NodeW-1:0]         head_b_o
);
  if (Depth < 2 || (Depth & (Depth - 1)) != 0) begin : gen_bad_depth
    $error("scw_labelling_edge_queue: Depth must be a power of two >= 2");
  end
  if (MaxPush < 1 || MaxPush > Depth) begin : gen_bad_push
    $error("scw_labelling_edge_queue: 1 .. Depth pushes per clock");
  end

  logic [PtrW-1:0] head_q, head_d, tail0;
  logic [NodeW-1:0] head_a_q, head_b_q, head_a_d, head_b_d;
  logic [CountW-1:0] count_q, count_d;
  logic room_q, room_d, nonempty_q;
  logic [NodeW-1:0] slot_a_q [Depth];
  logic [NodeW-1:0] slot_b_q [Depth];

  assign tail0    = head_q + PtrW'(count_q);
  assign count_o  = count_q;
  assign count_d  = count_q - CountW'(pop_i) + CountW'(push_n_i);
  assign room_o   = room_q;
  assign nonempty_o = nonempty_q;

  // A copy of count_o != 0 without reset (it follows count_d, which reset holds at 0, from the
  // first clock): the union-find's first read address follows from it, and an asynchronous
  // clear-to-output (891 ps in the 7-series cells) would stand in that path's time.
  always_ff @(posedge clk_i) begin
    nonempty_q <= count_d != '0;
  end
  assign head_d   = head_q + PtrW'(pop_i);

  // The head's edge from a register: the slot the head moves to, or the first push when it is
  // written there (into an empty queue, or one whose only edge leaves). The union-find reads
  // its first address from it; the pop, decided late, only selects.
  logic [PtrW-1:0] head1;
  logic into0, into1;
  assign head1 = head_q + 1'b1;
  assign into0 = (count_q == '0) && (push_n_i != '0);
  assign into1 = (count_q == CountW'(1)) && (push_n_i != '0);
  always_comb begin
    if (pop_i) begin
      head_a_d = into1 ? push_a_i[NodeW-1:0] : slot_a_q[head1];
      head_b_d = into1 ? push_b_i[NodeW-1:0] : slot_b_q[head1];
    end else begin
      head_a_d = into0 ? push_a_i[NodeW-1:0] : slot_a_q[head_q];
      head_b_d = into0 ? push_b_i[NodeW-1:0] : slot_b_q[head_q];
    end
  end
  always_ff @(posedge clk_i) begin
    head_a_q <= head_a_d;
    head_b_q <= head_b_d;
  end
  assign head_a_o = head_a_q;
  assign head_b_o = head_b_q;

  // room_d = count_d <= Depth - Room, compared from count_q for every push count and pop, so
  // the pop (the union-find's decision this clock) only selects.
  localparam int Limit = Depth - Room;
  always_comb begin
    room_d = 1'b0;
    for (int p = 0; p <= MaxPush; p++) begin
      if (PushW'(p) == push_n_i) begin
        if (pop_i) room_d = (Limit - p + 1 >= 0) && (32'(count_q) <= 32'(Limit - p + 1));
        else room_d = (Limit - p >= 0) && (32'(count_q) <= 32'(Limit - p));
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      head_q  <= '0;
      count_q <= '0;
      room_q  <= 1'b1;
    end else begin
      head_q  <= head_d;
      count_q <= count_d;
      room_q  <= room_d;
    end
  end

  // One block per slot (Verilator refuses delayed writes to array elements in a for loop): the
  // slot takes push k when it is k past the tail.
  for (genvar i = 0; i < Depth; i++) begin : gen_slot
    always_ff @(posedge clk_i) begin
      for (int k = 0; k < MaxPush; k++) begin
        if (PushW'(k) < push_n_i && tail0 + PtrW'(k) == PtrW'(i)) begin
          slot_a_q[i] <= push_a_i[k*NodeW +: NodeW];
          slot_b_q[i] <= push_b_i[k*NodeW +: NodeW];
        end
      end
    end
  end
endmodule
