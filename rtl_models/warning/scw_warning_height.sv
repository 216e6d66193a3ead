// SPDX-License-Identifier: Apache-2.0
// Warning stage: whether an object's top lies at least min_height above the road where it
// stands (hls::warning::road_height), nine enabled clocks after its inputs.
`default_nettype none

// The comparison of hls/warning/warning_params.hpp's road_height(), exactly, with no division:
//   D = dq 2^13 - 2 b - a (2 y_min - 1)            (code x 2^13, |D| < 2^36)
//   obstacle <=> baseline_q8 D >= 32 min_height a dq
// Each product is cut so every partial product fits one DSP48E1 (25 x 18 signed), with its M
// and P registers, and no carry chain spans more than one sum of two partial products:
//   1     a, b, dq, 2 y_min - 1
//   2, 3  t = a (2 y_min - 1), m = min_height a           (DSP, M then P)
//   4     D = dq 2^13 - 2 b - t
//   5, 6  baseline x D in three parts of D (17, 17 and 4 bits), m x dq in two parts of m
//   7     the parts summed pairwise
//   8     L = baseline D, R = 32 m dq
//   9     L >= R
// The registers that feed a multiplier are kept out of SRL shift registers ((* keep *), as
// scw_warning_delay's last step): an SRL's clock-to-output would start the path into the DSP.
// cfg_* are static (registered by the caller).
module scw_warning_height (
  input  logic        clk_i,
  input  logic        en_i,
  input  logic [19:0] baseline_i,    // cfg baseline_q8, registered
  input  logic [15:0] min_height_i,  // cfg min_height_mm, registered
  // stage 0
  input  logic [17:0] road_a_i,      // the frame's road line: slope, code x 2^12 a row
  input  logic [31:0] road_b_i,      //   intercept, signed
  input  logic [15:0] dq_i,          // the rule's disparity, Q11.4
  input  logic [15:0] y_min_i,       // the box's top row
  // stage 9
  output logic        above_o        // the top is at least min_height above the road
);
  localparam int unsigned DW = 38;   // D, signed
  localparam int unsigned LW = 60;   // baseline x D, signed

  logic        [17:0] a1;
  logic signed [31:0] b1;
  logic        [15:0] dq1;
  logic signed [17:0] ym1;  // 2 y_min - 1: -1 .. 131069
  (* keep *) always_ff @(posedge clk_i) begin
    if (en_i) begin
      a1  <= road_a_i;
      b1  <= road_b_i;
      dq1 <= dq_i;
      ym1 <= $signed({1'b0, y_min_i, 1'b0}) - 18'sd1;
    end
  end

  logic signed [36:0] t2, t3;
  logic        [33:0] m2, m3;
  logic signed [31:0] b2, b3;
  logic        [15:0] dq2, dq3;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      t2  <= $signed({1'b0, a1}) * ym1;
      m2  <= min_height_i * a1;
      b2  <= b1;
      dq2 <= dq1;
      t3  <= t2;
      m3  <= m2;
      b3  <= b2;
      dq3 <= dq2;
    end
  end

  logic signed [DW-1:0] d4;
  logic        [33:0]   m4;
  logic        [15:0]   dq4;
  (* keep *) always_ff @(posedge clk_i) begin
    if (en_i) begin
      d4  <= $signed({{(DW - 29){1'b0}}, dq3, 13'b0}) - $signed({{(DW - 33){b3[31]}}, b3, 1'b0}) -
             $signed({{(DW - 37){t3[36]}}, t3});
      m4  <= m3;
      dq4 <= dq3;
    end
  end

  // D = dl + dm 2^17 + dh 2^34 (dh signed), m = ml + mh 2^17.
  logic        [16:0] dl, dm, ml, mh;
  logic signed [3:0]  dh;
  assign dl = d4[16:0];
  assign dm = d4[33:17];
  assign dh = d4[37:34];
  assign ml = m4[16:0];
  assign mh = m4[33:17];

  logic        [36:0] pl5, pm5, pl6, pm6;
  logic signed [24:0] ph5, ph6;
  logic        [32:0] rl5, rh5, rl6, rh6;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      pl5 <= baseline_i * dl;
      pm5 <= baseline_i * dm;
      ph5 <= $signed({1'b0, baseline_i}) * dh;
      rl5 <= ml * dq4;
      rh5 <= mh * dq4;
      pl6 <= pl5;
      pm6 <= pm5;
      ph6 <= ph5;
      rl6 <= rl5;
      rh6 <= rh5;
    end
  end

  logic signed [LW-1:0] l7, lh7, l8, r8;
  logic        [50:0]   r7;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      l7  <= $signed({{(LW - 54){1'b0}}, pm6, 17'b0}) + $signed({{(LW - 37){1'b0}}, pl6});
      lh7 <= $signed({{(LW - 59){ph6[24]}}, ph6, 34'b0});
      r7  <= {1'b0, rh6, 17'b0} + {18'b0, rl6};
      l8  <= l7 + lh7;
      r8  <= $signed({{(LW - 56){1'b0}}, r7, 5'b0});
      above_o <= l8 >= r8;
    end
  end
endmodule
