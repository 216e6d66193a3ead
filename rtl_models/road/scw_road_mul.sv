// SPDX-License-Identifier: Apache-2.0
// Road stage: a serial shift-add multiplier, one multiplier bit (one AW + 1 bit add) a clock.
`default_nettype none

// p = a * b exactly, BW clocks after start_i (busy_o high meanwhile); a is signed when ASigned,
// b is unsigned. The classic product register {hi, lo}: lo starts as b, and each clock adds a to
// hi when lo's bit 0 is set, then shifts {hi, lo} right by one. The adder is AW + 1 bits wide
// however wide the product (a 46 x 22 bit product is 68 bits, too long a carry chain for one
// clock). For a signed a the partial product stays within a's range, so hi keeps AW bits and the
// shift is arithmetic.
// a_i is read from the clock after start_i until busy_o falls and must hold meanwhile (the fit
// engine's operands are registers that do); p_o holds from then until the next start_i.
module scw_road_mul #(
  parameter int unsigned AW      = 32,
  parameter int unsigned BW      = 8,
  parameter bit          ASigned = 1'b0,
  localparam int unsigned CntW   = $clog2(BW + 1)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             start_i,
  input  logic [AW-1:0]    a_i,
  input  logic [BW-1:0]    b_i,
  output logic             busy_o,
  output logic [AW+BW-1:0] p_o
);
  if (AW < 2 || BW < 2) begin : gen_bad_params
    $error("scw_road_mul: need AW >= 2 and BW >= 2");
  end

  logic [CntW-1:0] cnt_d, cnt_q;
  logic [AW-1:0]   hi_d, hi_q;
  logic [BW-1:0]   lo_d, lo_q;
  logic [AW:0]     sum;

  assign sum = {ASigned && hi_q[AW-1], hi_q} + (lo_q[0] ? {ASigned && a_i[AW-1], a_i} : '0);

  always_comb begin
    cnt_d = cnt_q;
    hi_d  = hi_q;
    lo_d  = lo_q;
    if (start_i) begin
      cnt_d = CntW'(BW);
      hi_d  = '0;
      lo_d  = b_i;
    end else if (cnt_q != '0) begin
      cnt_d = cnt_q - 1'b1;
      hi_d  = sum[AW:1];
      lo_d  = {sum[0], lo_q[BW-1:1]};
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) cnt_q <= '0;
    else         cnt_q <= cnt_d;
  end

  always_ff @(posedge clk_i) begin
    hi_q <= hi_d;
    lo_q <= lo_d;
  end

  assign busy_o = cnt_q != '0;
  assign p_o    = {hi_q, lo_q};
endmodule
