// SPDX-License-Identifier: Apache-2.0
// Warning stage: a value held back a fixed number of pipeline enables (a shift register).
`default_nettype none

// No reset and one enable for the whole chain, so Yosys maps it to SRL shift registers instead
// of Depth * Width flip-flops; whatever it holds after reset is masked by the stage's valid
// pipeline.
module scw_warning_delay #(
  parameter int unsigned Width = 1,
  parameter int unsigned Depth = 1  // >= 1
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [Width-1:0] d_i,
  output logic [Width-1:0] q_o
);
  if (Width < 1 || Depth < 1) begin : gen_bad
    $error("scw_warning_delay: Width and Depth are at least 1");
  end

  logic [Depth*Width-1:0] q;
  always_ff @(posedge clk_i) begin
    if (en_i) q <= (Depth * Width)'({q, d_i});
  end
  assign q_o = q[Depth*Width-1 -: Width];
endmodule
