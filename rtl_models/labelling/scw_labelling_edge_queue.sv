// SPDX-License-Identifier: Apache-2.0
// Labelling: the register FIFO of node pairs to join, two pushes and one pop per clock.
`default_nettype none

// The twin of hls::labelling::EdgeQueue: a pop moves the head, then the pushes append in order.
// A pop and the pushes of one clock leave head + count - pop = the old tail, so both write
// slots follow from the registers alone. The caller never pushes into a full queue (the stage
// takes a pixel only while at most Depth - 4 edges are queued).
module scw_labelling_edge_queue #(
  parameter int unsigned Depth = 8,
  parameter int unsigned NodeW = 6,
  localparam int unsigned PtrW   = $clog2(Depth),
  localparam int unsigned CountW = $clog2(Depth + 1)
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              pop_i,
  input  logic [1:0]        push_n_i,   // 0, 1 or 2: push0 first, then push1
  input  logic [NodeW-1:0]  push0_a_i,
  input  logic [NodeW-1:0]  push0_b_i,
  input  logic [NodeW-1:0]  push1_a_i,
  input  logic [NodeW-1:0]  push1_b_i,
  output logic [CountW-1:0] count_o,
  output logic [NodeW-1:0]  head_a_o,
  output logic [NodeW-1:0]  head_b_o
);
  if (Depth < 2 || (Depth & (Depth - 1)) != 0) begin : gen_bad_depth
    $error("scw_labelling_edge_queue: Depth must be a power of two >= 2");
  end

  logic [PtrW-1:0] head_q, tail0, tail1;
  logic [CountW-1:0] count_q;
  logic [NodeW-1:0] slot_a_q [Depth];
  logic [NodeW-1:0] slot_b_q [Depth];

  assign tail0    = head_q + PtrW'(count_q);
  assign tail1    = tail0 + 1'b1;
  assign count_o  = count_q;
  assign head_a_o = slot_a_q[head_q];
  assign head_b_o = slot_b_q[head_q];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      head_q  <= '0;
      count_q <= '0;
    end else begin
      if (pop_i) head_q <= head_q + 1'b1;
      count_q <= count_q - CountW'(pop_i) + CountW'(push_n_i);
    end
  end

  // One block per slot (Verilator refuses delayed writes to array elements in a for loop).
  for (genvar i = 0; i < Depth; i++) begin : gen_slot
    always_ff @(posedge clk_i) begin
      if (push_n_i != 2'd0 && tail0 == PtrW'(i)) begin
        slot_a_q[i] <= push0_a_i;
        slot_b_q[i] <= push0_b_i;
      end else if (push_n_i == 2'd2 && tail1 == PtrW'(i)) begin
        slot_a_q[i] <= push1_a_i;
        slot_b_q[i] <= push1_b_i;
      end
    end
  end
endmodule
