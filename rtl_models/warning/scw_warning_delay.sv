// SPDX-License-Identifier: Apache-2.0
// Warning stage: a value held back a fixed number of pipeline enables (a shift register).
`default_nettype none

// No reset and one enable for the whole chain, so Yosys maps the first Depth - 1 steps to SRL
// shift registers instead of flip-flops; whatever it holds after reset is masked by the stage's
// valid pipeline. The last step is a flip-flop kept out of the SRL: an SRL's clock-to-output
// (about 1.5 ns) would otherwise start the path through whatever logic reads q_o.
module scw_warning_delay #(
  parameter int unsigned Width = 1,
  parameter int unsigned Depth = 4  // >= 1
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [Width-1:0] d_i,
  output logic [Width-1:0] q_o
);
  if (Width < 1 || Depth < 1) begin : gen_bad
    $error("scw_warning_delay: Width and Depth are at least 1");
  end

  logic [Width-1:0] last;
  if (Depth > 1) begin : gen_chain
    logic [(Depth-1)*Width-1:0] q;
    always_ff @(posedge clk_i) begin
      if (en_i) q <= ((Depth - 1) * Width)'({q, d_i});
    end
    assign last = q[(Depth-1)*Width-1 -: Width];
  end else begin : gen_no_chain
    assign last = d_i;
  end

  (* keep *) always_ff @(posedge clk_i) begin
    if (en_i) q_o <= last;
  end
endmodule
