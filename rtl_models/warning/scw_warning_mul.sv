// SPDX-License-Identifier: Apache-2.0
// Warning stage: a signed by unsigned product rounded to 2^-Shift, in four pipeline stages.
`default_nettype none

// p = (a * b + 2^(Shift-1)) >>> Shift, rshift_round(a * b, Shift) of hls/warning, exact for
// every input. b is cut at bit Split so each partial product fits one DSP48E1 (25 x 18
// signed): a * b = lo + hi * 2^Split with lo = a * b[Split-1:0], hi = a * b[BW-1:Split], and
// since hi * 2^Split is a multiple of 2^Split,
//   p = (((lo + 2^(Shift-1)) >>> Split) + hi) >>> (Shift - Split)     (Split <= Shift)
// which keeps each carry chain to one partial product's width:
//   1  lo, hi            (DSP, multiplier register M)
//   2  lo, hi            (DSP, output register P)
//   3  t = (lo + 2^(Shift-1)) >>> Split
//   4  p = (t + hi) >>> (Shift - Split)
// Without the M register the path from the operands' flip-flops through the multiplier into P
// is about 3 ns of logic; with it, 1.7 ns. Without P, a DSP's clock-to-output is 1.7 ns before
// the carry chain starts. (The rounding constant is not left to the DSP's post-adder: whether
// Yosys packs it depends on the operands' known bits.)
// OutW must hold the result (the caller knows its range); wider bits are dropped.
module scw_warning_mul #(
  parameter int unsigned AW    = 21,  // a, signed: up to 25 for one DSP per partial product
  parameter int unsigned BW    = 32,  // b, unsigned
  parameter int unsigned Split = 17,  // b's low part: up to 17 bits for one DSP
  parameter int unsigned Shift = 24,
  parameter int unsigned OutW  = 29
) (
  input  logic                   clk_i,
  input  logic                   en_i,
  input  logic signed [AW-1:0]   a_i,
  input  logic        [BW-1:0]   b_i,
  output logic signed [OutW-1:0] p_o  // four enabled clocks later
);
  localparam int unsigned HiW  = BW - Split;
  localparam int unsigned LoPW = AW + Split + 1;  // a * b_lo, signed
  localparam int unsigned HiPW = AW + HiW + 1;    // a * b_hi, signed
  localparam int unsigned RndW = LoPW + 1;        // lo + 2^(Shift-1) without overflow
  localparam int unsigned TW   = RndW - Split;
  localparam int unsigned SumW = ((TW > HiPW) ? TW : HiPW) + 1;
  localparam logic [RndW-1:0] Half = RndW'(64'd1 << (Shift - 1));

  if (Split < 1 || Split >= BW || Split > Shift || Shift < 1 || Shift > 62) begin : gen_bad
    $error("scw_warning_mul: need 1 <= Split < BW, Split <= Shift <= 62");
  end

  // Operands sign-extended to the product width: both tools then see an exact signed product,
  // and Yosys narrows it back to one DSP48E1.
  logic signed [LoPW-1:0] a_lo, b_lo;
  logic signed [HiPW-1:0] a_hi, b_hi;
  assign a_lo = {{(LoPW - AW){a_i[AW-1]}}, a_i};
  assign b_lo = {{(LoPW - Split){1'b0}}, b_i[Split-1:0]};
  assign a_hi = {{(HiPW - AW){a_i[AW-1]}}, a_i};
  assign b_hi = {{(HiPW - HiW){1'b0}}, b_i[BW-1:Split]};

  logic signed [LoPW-1:0] lo_m, lo_q;
  logic signed [HiPW-1:0] hi_m, hi_q, hi2_q;
  logic signed [TW-1:0]   t_q;
  logic signed [RndW-1:0] rnd;
  logic signed [SumW-1:0] sum;

  assign rnd = {lo_q[LoPW-1], lo_q} + Half;
  assign sum = {{(SumW - TW){t_q[TW-1]}}, t_q} + {{(SumW - HiPW){hi2_q[HiPW-1]}}, hi2_q};

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      lo_m  <= a_lo * b_lo;
      hi_m  <= a_hi * b_hi;
      lo_q  <= lo_m;
      hi_q  <= hi_m;
      t_q   <= TW'(rnd >>> Split);
      hi2_q <= hi_q;
      p_o   <= OutW'(sum >>> (Shift - Split));
    end
  end
endmodule
