// SPDX-License-Identifier: Apache-2.0
// Joins a frame's warning result with its two input-check flags into the pipeline's result word.
`default_nettype none

// The rectifiers repair broken input frames, so the warning stage cannot see them; the frame
// checks at the inputs can. Their per-frame flags wait in FIFOs and meet the frame's result
// here. One output register under one enable; the three inputs are taken together (the C++
// twin is hls::pipeline::ResultMerge).
module scw_result_merge #(
  parameter int unsigned ResW /*verilator public*/ = scw_pkg::ResultWordBits,
  localparam int unsigned OutW = ResW + 2
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  input  logic            res_valid_i,
  output logic            res_ready_o,
  input  logic [ResW-1:0] res_data_i,
  input  logic            res_last_i,
  input  logic            left_valid_i,
  output logic            left_ready_o,
  input  logic            left_error_i,
  input  logic            right_valid_i,
  output logic            right_ready_o,
  input  logic            right_error_i,
  output logic            out_valid_o,
  input  logic            out_ready_i,
  output logic [OutW-1:0] out_data_o,
  output logic            out_last_o
);
  logic valid_q, last_q, adv, take;
  logic [OutW-1:0] data_q;

  assign adv           = !valid_q || out_ready_i;
  assign take          = adv && res_valid_i && left_valid_i && right_valid_i;
  assign res_ready_o   = take;
  assign left_ready_o  = take;
  assign right_ready_o = take;
  assign out_valid_o   = valid_q;
  assign out_data_o    = data_q;
  assign out_last_o    = last_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_q <= 1'b0;
    else if (adv) valid_q <= take;
  end

  always_ff @(posedge clk_i) begin
    if (take) begin
      data_q <= {right_error_i, left_error_i, res_data_i};
      last_q <= res_last_i;
    end
  end
endmodule
