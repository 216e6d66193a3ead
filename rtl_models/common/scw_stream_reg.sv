// SPDX-License-Identifier: Apache-2.0
// Stream register: registers valid and data at full throughput; ready passes through.
`default_nettype none

// Cuts the forward (valid/data) path only. in_ready_o depends combinationally on out_ready_i,
// which is allowed (valid never depends on ready); use scw_skid_buf to cut ready as well.
module scw_stream_reg #(
  parameter int unsigned Width /*verilator public*/ = 10
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [Width-1:0] in_data_i,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [Width-1:0] out_data_o
);
  logic valid_q;
  logic [Width-1:0] data_q;

  assign in_ready_o  = !valid_q || out_ready_i;
  assign out_valid_o = valid_q;
  assign out_data_o  = data_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_q <= 1'b0;
    else if (in_ready_o) valid_q <= in_valid_i;
  end

  always_ff @(posedge clk_i) begin
    if (in_valid_i && in_ready_o) data_q <= in_data_i;
  end
endmodule
