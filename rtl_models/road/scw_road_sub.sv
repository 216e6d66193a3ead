// SPDX-License-Identifier: Apache-2.0
// Road stage: a wide subtraction a - b (mod 2^W) split over two clocks, low half first.
`default_nettype none

// The fit engine's differences of products are up to 69 bits: one carry chain that long does not
// close at the stage's clock (docs/timing.md), two chains of half of it do. Free-running: d_o is
// a - b two clocks after a_i and b_i settle (the engine's operands are product registers that hold
// once their multiplier has finished, and it waits those two clocks).
module scw_road_sub #(
  parameter int unsigned W   = 64,
  parameter int unsigned LoW = 32
) (
  input  logic         clk_i,
  input  logic [W-1:0] a_i,
  input  logic [W-1:0] b_i,
  output logic [W-1:0] d_o
);
  if (LoW < 1 || LoW >= W) begin : gen_bad_params
    $error("scw_road_sub: need 1 <= LoW < W");
  end

  logic [LoW:0]   lo;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [W-LoW:0] hi;  // bit 0 only carries the borrow in: one chain, not a - b - borrow's two
  /* verilator lint_on UNUSEDSIGNAL */
  logic [LoW-1:0] lo_q;
  logic           borrow_q;

  assign lo = {1'b0, a_i[LoW-1:0]} - {1'b0, b_i[LoW-1:0]};
  assign hi = {a_i[W-1:LoW], 1'b0} - {b_i[W-1:LoW], borrow_q};

  always_ff @(posedge clk_i) begin
    lo_q     <= lo[LoW-1:0];
    borrow_q <= lo[LoW];
    d_o      <= {hi[W-LoW:1], lo_q};
  end
endmodule
