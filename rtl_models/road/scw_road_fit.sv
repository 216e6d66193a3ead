// SPDX-License-Identifier: Apache-2.0
// Road stage: the fit between frames, a serial engine computing fit_line() and band() exactly.
`default_nettype none

// The twin of hls::road::fit_line and hls::road::band (hls/road/road_params.hpp), bit for bit on
// every input the ports carry (tests/road/test_road_rtl.cpp drives it alone against them):
//   den = n svv - sv^2, num = n svd - sv sd               (Mul, Sub)
//   keep unless n >= min_count, den > 0, num > 0          (SubFlags, Check)
//   a = floor(num 2^12 / den), keep if num >= den 2^6     (DivA: ovf)
//   keep unless a_min <= a <= a_max                        (DivAFlags, CheckA)
//   c = a sv - sd 2^12, keep if c < 0                      (MulC, SubC, CheckC)
//   nb = floor(c / n) = -b, keep unless a h_min <= nb <= a h_max   (DivB .. CheckB)
//   both bands of the line (kept or new)                  (Band .. BandTol)
// Every product is a shift-add multiplier (one bit a clock) and every quotient a restoring divider
// (one bit in two clocks), so no carry chain is longer than 47 bits, and each check is registered
// before the control acts on it: the whole fit takes Clocks (186) clocks of the 256 the stage
// gives it. The widths follow from the sums' (docs/road.md,
// "Widths"): n svv < 2^63 and n svd < 2^68, so den fits 64 bits signed, num 69; a < 2^18 once
// num < den 2^6; c is in (-2^48, 2^49); -b < 2^28 once the divider's check passes (a h_max <=
// (2^18 - 1) 1023 < 2^28, so a larger -b is implausible anyway).
// start_i: the sums, the configuration and keep_* must hold from then until done_o, which rises
// Clocks clocks after start_i (at most) and holds, with the results, until the next start_i.
module scw_road_fit #(
  parameter int unsigned MaxClocks = 511  // the clocks the caller gives it
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        start_i,
  // the frame's sums (hls::road::FitSums)
  input  logic [21:0] n_i,
  input  logic [30:0] sv_i,
  input  logic [40:0] svv_i,
  input  logic [35:0] sd_i,
  input  logic [45:0] svd_i,
  // configuration (hls::road::RoadConfig)
  input  logic [19:0] min_count_i,
  input  logic [17:0] a_min_i,
  input  logic [17:0] a_max_i,
  input  logic [9:0]  h_min_i,
  input  logic [9:0]  h_max_i,
  input  logic [14:0] tol_i,
  input  logic [7:0]  tol_rel_i,
  input  logic [14:0] gate_i,
  input  logic [7:0]  gate_rel_i,
  // the road so far, kept when the fit is not plausible
  input  logic [17:0] keep_a_i,
  input  logic [31:0] keep_b_i,
  // the next road and its bands (hls::road::Line, Band), code x 2^12, b's two's complement
  output logic        done_o,
  output logic [17:0] line_a_o,
  output logic [31:0] line_b_o,
  output logic [17:0] road_lo_a_o,
  output logic [18:0] road_hi_a_o,
  output logic [31:0] road_lo_b_o,
  output logic [31:0] road_hi_b_o,
  output logic [17:0] gate_lo_a_o,
  output logic [18:0] gate_hi_a_o,
  output logic [31:0] gate_lo_b_o,
  output logic [31:0] gate_hi_b_o
);
  // Clocks from start_i to done_o on the longest path (a plausible fit), from the units' own:
  // each wait ends the clock after its unit's busy falls; a difference takes two more clocks.
  localparam int unsigned MulClocks  = 31;            // sv x sv, sv x sd, a x sv
  localparam int unsigned DivAClocks = 2 * (18 + 1);  // scw_road_div: 2 (QW + 1)
  localparam int unsigned DivBClocks = 2 * (28 + 1);
  localparam int unsigned BandClocks = 10;            // a x rel (BW = 10: it also does a x h)
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Clocks /*verilator public*/ =
      (1 + MulClocks) + 3 + (DivAClocks + 2) + 1 + (MulClocks + 1) + 2 + (DivBClocks + 2) + 1 +
      1 + (BandClocks + 1) + 1 + 1 + 1;
  /* verilator lint_on UNUSEDPARAM */
  if (Clocks > MaxClocks) begin : gen_too_slow
    $error("scw_road_fit: takes more than MaxClocks");
  end

  typedef enum logic [4:0] {
    StIdle, StMul, StSub, StSubFlags, StCheck, StDivA, StDivAFlags, StCheckA, StMulC, StSubC,
    StCheckC, StDivB, StDivBFlags, StCheckB, StBand, StBandMul, StBandAdd, StBandTol
  } state_e;

  state_e      state_d, state_q;
  logic        done_d, done_q;
  logic [17:0] line_a_d, line_a_q;
  logic [31:0] line_b_d, line_b_q;

  // ---- units -----------------------------------------------------------------------------------
  logic        mul_start, mul_c_start, band_start, div_a_start, div_b_start, sel_c, sel_band;
  logic        nsvv_busy, sv_busy, nsvd_busy, svsd_busy, ah0_busy, ah1_busy, b0_busy, b1_busy;
  logic        div_a_busy, div_b_busy, ovf_a, ovf_b;
  logic [62:0] p_nsvv;
  logic [61:0] p_sv;   // sv x sv, then a x sv
  logic [67:0] p_nsvd;
  logic [66:0] p_svsd;
  logic [27:0] p_ah0, p_ah1;  // a x h_min, a x h_max, then a x tol_rel, a x gate_rel
  /* verilator lint_off UNUSEDSIGNAL */
  logic [39:0] p_b0, p_b1;    // b x tol_rel, b x gate_rel (signed); the bands drop bits 7:0
  /* verilator lint_on UNUSEDSIGNAL */
  logic [63:0] diff0;         // den, then c (signed)
  logic [68:0] num;           // signed
  logic [17:0] qa;            // a
  logic [27:0] nb;            // -b

  scw_road_mul #(.AW(41), .BW(22)) u_mul_nsvv (
    .clk_i, .rst_ni, .start_i(mul_start), .a_i(svv_i), .b_i(n_i), .busy_o(nsvv_busy),
    .p_o(p_nsvv)
  );
  // sv x sv for den, then sv x a for c: both have sv as the multiplicand.
  scw_road_mul #(.AW(31), .BW(31)) u_mul_sv (
    .clk_i, .rst_ni, .start_i(mul_start || mul_c_start), .a_i(sv_i),
    .b_i(state_q == StIdle ? sv_i : 31'(qa)), .busy_o(sv_busy), .p_o(p_sv)
  );
  scw_road_mul #(.AW(46), .BW(22)) u_mul_nsvd (
    .clk_i, .rst_ni, .start_i(mul_start), .a_i(svd_i), .b_i(n_i), .busy_o(nsvd_busy),
    .p_o(p_nsvd)
  );
  scw_road_mul #(.AW(36), .BW(31)) u_mul_svsd (
    .clk_i, .rst_ni, .start_i(mul_start), .a_i(sd_i), .b_i(sv_i), .busy_o(svsd_busy),
    .p_o(p_svsd)
  );

  // den = n svv - sv^2 (in (-2^62, 2^63)), then c = a sv - sd 2^12 (in (-2^48, 2^49)).
  scw_road_sub #(.W(64), .LoW(32)) u_sub_den_c (
    .clk_i,
    .a_i(sel_c ? {2'b0, p_sv} : {1'b0, p_nsvv}),
    .b_i(sel_c ? {16'b0, sd_i, 12'b0} : {2'b0, p_sv}),
    .d_o(diff0)
  );
  scw_road_sub #(.W(69), .LoW(35)) u_sub_num (
    .clk_i, .a_i({1'b0, p_nsvd}), .b_i({2'b0, p_svsd}), .d_o(num)
  );

  // a = floor(num 2^12 / den): the dividend's top part num >> 6 against den is the check
  // num >= den 2^6 (a >= 2^18). num > 0 and den > 0 here, so num < 2^68 and den < 2^63.
  scw_road_div #(.DW(63), .QW(18), .LoW(32)) u_div_a (
    .clk_i, .rst_ni, .start_i(div_a_start), .r0_i({1'b0, num[67:6]}), .x_i({num[5:0], 12'b0}),
    .d_i(diff0[62:0]), .busy_o(div_a_busy), .q_o(qa), .ovf_o(ovf_a)
  );
  // -b = floor(c / n), c >= 0 here; ovf_b when it is 2^28 or more.
  scw_road_div #(.DW(22), .QW(28), .LoW(12)) u_div_b (
    .clk_i, .rst_ni, .start_i(div_b_start), .r0_i({1'b0, diff0[48:28]}), .x_i(diff0[27:0]),
    .d_i(n_i), .busy_o(div_b_busy), .q_o(nb), .ovf_o(ovf_b)
  );

  // a x h_min and a x h_max for the horizon check, then a x tol_rel and a x gate_rel for the
  // bands: a is line_a_q, which holds the divider's a from the clock after CheckA on.
  scw_road_mul #(.AW(18), .BW(10)) u_mul_ah0 (
    .clk_i, .rst_ni, .start_i(mul_c_start || band_start), .a_i(line_a_q),
    .b_i(sel_band ? {2'b0, tol_rel_i} : h_min_i), .busy_o(ah0_busy), .p_o(p_ah0)
  );
  scw_road_mul #(.AW(18), .BW(10)) u_mul_ah1 (
    .clk_i, .rst_ni, .start_i(mul_c_start || band_start), .a_i(line_a_q),
    .b_i(sel_band ? {2'b0, gate_rel_i} : h_max_i), .busy_o(ah1_busy), .p_o(p_ah1)
  );
  scw_road_mul #(.AW(32), .BW(8), .ASigned(1'b1)) u_mul_b0 (
    .clk_i, .rst_ni, .start_i(band_start), .a_i(line_b_q), .b_i(tol_rel_i), .busy_o(b0_busy),
    .p_o(p_b0)
  );
  scw_road_mul #(.AW(32), .BW(8), .ASigned(1'b1)) u_mul_b1 (
    .clk_i, .rst_ni, .start_i(band_start), .a_i(line_b_q), .b_i(gate_rel_i), .busy_o(b1_busy),
    .p_o(p_b1)
  );

  assign sel_c    = state_q == StMulC || state_q == StSubC || state_q == StCheckC;
  assign sel_band = state_q == StBand;

  // ---- the plausibility checks -----------------------------------------------------------------
  // Each check is registered (its wait state gives it the clock): a compare, then the control's
  // decisions and the units' start and operand muxes, would make the longest paths (3.7 ns).
  logic keep_check, keep_check_q, keep_a, keep_a_q, keep_b, keep_b_q, refuse;
  assign keep_check = (n_i < 22'(min_count_i)) || diff0[63] || (diff0 == '0) || num[68] ||
                      (num == '0);
  assign keep_a     = ovf_a || (qa < a_min_i) || (qa > a_max_i);
  assign keep_b     = ovf_b || (nb < p_ah0) || (nb > p_ah1);
  always_ff @(posedge clk_i) begin
    keep_check_q <= keep_check;
    keep_a_q     <= keep_a;
    keep_b_q     <= keep_b;
  end

  // ---- control ---------------------------------------------------------------------------------
  always_comb begin
    state_d     = state_q;
    done_d      = done_q;
    line_a_d    = line_a_q;
    line_b_d    = line_b_q;
    mul_start   = 1'b0;
    mul_c_start = 1'b0;
    div_a_start = 1'b0;
    div_b_start = 1'b0;
    band_start  = 1'b0;
    refuse      = 1'b0;
    unique case (state_q)
      StIdle: begin
        if (start_i) begin
          mul_start = 1'b1;
          done_d    = 1'b0;
          state_d   = StMul;
        end
      end
      StMul:    if (!(nsvv_busy || sv_busy || nsvd_busy || svsd_busy)) state_d = StSub;
      StSub:      state_d = StSubFlags;  // u_sub_*: the differences two clocks after the products
      StSubFlags: state_d = StCheck;     // keep_check_q: their checks registered
      StCheck: begin
        refuse = keep_check_q;
        if (!keep_check_q) begin
          div_a_start = 1'b1;
          state_d     = StDivA;
        end
      end
      StDivA:      if (!div_a_busy) state_d = StDivAFlags;
      StDivAFlags: state_d = StCheckA;  // keep_a_q
      StCheckA: begin
        refuse = keep_a_q;
        if (!keep_a_q) begin
          mul_c_start = 1'b1;
          line_a_d    = qa;
          state_d     = StMulC;
        end
      end
      StMulC:   if (!(sv_busy || ah0_busy || ah1_busy)) state_d = StSubC;
      StSubC:   state_d = StCheckC;
      StCheckC: begin
        refuse = diff0[63];  // c < 0: the horizon above row 0
        if (!diff0[63]) begin
          div_b_start = 1'b1;
          state_d     = StDivB;
        end
      end
      StDivB:      if (!div_b_busy) state_d = StDivBFlags;
      StDivBFlags: state_d = StCheckB;  // keep_b_q
      StCheckB: begin
        refuse = keep_b_q;
        if (!keep_b_q) line_b_d = -{4'b0, nb};
        state_d = StBand;
      end
      StBand: begin
        band_start = 1'b1;
        state_d    = StBandMul;
      end
      StBandMul: if (!(ah0_busy || ah1_busy || b0_busy || b1_busy)) state_d = StBandAdd;
      StBandAdd: state_d = StBandTol;
      StBandTol: begin
        done_d  = 1'b1;
        state_d = StIdle;
      end
      default: state_d = StIdle;
    endcase
    // A check that fails keeps the road the stage had, and its bands are formed again.
    if (refuse) begin
      line_a_d = keep_a_i;
      line_b_d = keep_b_i;
      state_d  = StBand;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      done_q  <= 1'b0;
    end else begin
      state_q <= state_d;
      done_q  <= done_d;
    end
  end

  always_ff @(posedge clk_i) begin
    line_a_q <= line_a_d;
    line_b_q <= line_b_d;
  end

  // ---- the bands -------------------------------------------------------------------------------
  // band(): lo = (a - (a r >> 8), b - (b r >> 8) - t 2^12), hi = (a + .., b + .. + t 2^12), the
  // shifts arithmetic, b's sums modulo 2^32 as the C++ casts them. BandAdd forms a -+ ra and
  // b -+ rb, BandTol adds the tolerance to bits 31:12 (its own low 12 bits are 0).
  logic [17:0] ra0, ra1;
  logic [31:0] rb0, rb1;
  assign ra0 = p_ah0[25:8];  // a r < 2^26
  assign ra1 = p_ah1[25:8];
  assign rb0 = p_b0[39:8];
  assign rb1 = p_b1[39:8];

  always_ff @(posedge clk_i) begin
    if (state_q == StBandAdd) begin
      road_lo_a_o <= line_a_q - ra0;
      road_hi_a_o <= 19'(line_a_q) + 19'(ra0);
      road_lo_b_o <= line_b_q - rb0;
      road_hi_b_o <= line_b_q + rb0;
      gate_lo_a_o <= line_a_q - ra1;
      gate_hi_a_o <= 19'(line_a_q) + 19'(ra1);
      gate_lo_b_o <= line_b_q - rb1;
      gate_hi_b_o <= line_b_q + rb1;
    end
    if (state_q == StBandTol) begin
      road_lo_b_o[31:12] <= road_lo_b_o[31:12] - 20'(tol_i);
      road_hi_b_o[31:12] <= road_hi_b_o[31:12] + 20'(tol_i);
      gate_lo_b_o[31:12] <= gate_lo_b_o[31:12] - 20'(gate_i);
      gate_hi_b_o[31:12] <= gate_hi_b_o[31:12] + 20'(gate_i);
    end
  end

  assign done_o   = done_q;
  assign line_a_o = line_a_q;
  assign line_b_o = line_b_q;
endmodule
