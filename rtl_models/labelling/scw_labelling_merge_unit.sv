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

  assign nonempty = count_o != '0;

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
    .head_a_o(head_a),
    .head_b_o(head_b)
  );

  scw_labelling_union_find #(.Nodes(Nodes)) u_union_find (
    .clk_i,
    .rst_ni,
    .en_i,
    .q_nonempty_i(nonempty),
    .head_a_i    (head_a),
    .head_b_i    (head_b),
    .rd_data_i,
    .pop_o       (pop),
    .idle_o,
    .rd_en_o,
    .rd_addr_o,
    .wr_en_o,
    .wr_addr_o,
    .wr_data_o
  );
endmodule
