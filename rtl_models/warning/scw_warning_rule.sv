// SPDX-License-Identifier: Apache-2.0
// Warning stage: the distance rule, the disparity code that places an object.
`default_nettype none

// Bit for bit hls::warning::rule_disparity(), Latency enabled clocks after the inputs. With
// area A, S1 = sum d and S2 = sum d^2 cut to their low 20, 35 and 50 bits (kRuleAreaBits,
// kRuleSumBits, kRuleSquareBits) and k = cfg_spread_i (Q4.4):
//   V = max(0, A S2 - S1^2)                         (< 2^70)
//   R = isqrt_round(V)                               (scw_warning_sqrt, 35 root bits; <= 2^35)
//   q = floor((16 S1 + k R + 8 A) / (16 A))          (65535 when >= 2^16, A = 0 included)
//   dq = rule ? min(d_max, q) : d_max
// Stages (the register at the end of each):
//   1        the operands
//   2, 3     the partial products of A S2 and S1^2 (DSP48E1 multiplier and output registers M
//            and P; see scw_warning_mul); 2: T = 16 S1 + 8 A
//   4 .. 7   A S2 and S1^2 from their partial products, their difference in two halves (the
//            borrow registered between), V
//   8 .. 43  R (scw_warning_sqrt, one root bit per clock, then the rounding)
//   44, 45   k R (two DSPs, M and P)
//   46, 47   num = T + k R in two halves (the carry registered between); den = 16 A
//   48 .. 63 the 16 quotient bits, one restoring step per clock
//   64       dq
// A S2 = P0 + P1 2^17 + P2 2^34 with P_j = A * S2[17j +: 17] (20 x 17 bits, one DSP each).
// S1 = H 2^17 + L (H 18 bits, L 17): S1^2 = L^2 + H L 2^18 + H^2 2^34, and since H is one bit
// too wide for both ports, H^2 = H H[16:0] + H[17] H 2^17 (three DSPs and a mux).
// The divider: num >= den 2^16 (A = 0 included) is detected beside the first step, which then
// saturates the quotient at 65535. Otherwise num < den 2^16, so before the step of quotient
// bit i the remainder is below den 2^(i+1) < 2^(i+25): each step compares 25 bits of it with
// den (a 26-bit carry chain) and keeps i + 24 bits. No carry chain is longer than 40 bits
// (T; the square root's last step has 38).
// cfg_* are static: registered here without reset.
module scw_warning_rule #(
  // The caller's pipeline depth for this block: checked here, so the caller cannot misalign.
  parameter int unsigned Latency /*verilator public*/ = 64,
  // hls::warning::kRuleAreaBits, kRuleSumBits, kRuleSquareBits, kRuleRootBits
  localparam int unsigned AreaW   /*verilator public*/ = 20,
  localparam int unsigned SumW    /*verilator public*/ = 35,
  localparam int unsigned SquareW /*verilator public*/ = 50,
  localparam int unsigned RootW   /*verilator public*/ = 35
) (
  input  logic                 clk_i,
  input  logic                 en_i,
  input  logic                 cfg_rule_i,    // hls::warning::DistanceRule: 0 closest, 1 spread
  input  logic [7:0]           cfg_spread_i,  // k, Q4.4
  input  logic [AreaW-1:0]     area_i,
  input  logic [SumW-1:0]      sum_d_i,
  input  logic [SquareW-1:0]   sum_dd_i,
  input  logic [15:0]          d_max_i,
  output logic [15:0]          dq_o           // Latency enabled clocks later
);
  localparam int unsigned VW      = 2 * RootW;       // V, A S2, S1^2
  localparam int unsigned HalfW   = VW / 2;          // the difference's halves
  localparam int unsigned SqrtLat = RootW + 1;
  localparam int unsigned TW      = SumW + 5;        // T = 16 S1 + 8 A < 2^40
  localparam int unsigned NumW    = 44;              // num < 2^39 + 255 * 2^35 + 2^23 < 2^44
  localparam int unsigned DenW    = AreaW + 4;
  localparam int unsigned QW      = 16;
  localparam int unsigned RootStage = 7 + SqrtLat;   // R's register
  localparam int unsigned NumStage  = RootStage + 4;
  localparam int unsigned Stages    = NumStage + QW + 1;

  if (Latency != Stages) begin : gen_bad_latency
    $error("scw_warning_rule: Latency is 64");
  end
  if (SumW != AreaW + 15 || SquareW != AreaW + 30 || RootW != SumW || VW != 70 ||
      NumW != DenW + 20) begin : gen_bad_widths
    $error("scw_warning_rule: the widths are those of hls::warning (20, 35, 50, 35)");
  end

  // ---- configuration ------------------------------------------------------------------------
  logic rule_q;
  logic [7:0] spread_q;
  always_ff @(posedge clk_i) begin
    rule_q   <= cfg_rule_i;
    spread_q <= cfg_spread_i;
  end

  // ---- 1: operands --------------------------------------------------------------------------
  logic [AreaW-1:0] a1;
  logic [SumW-1:0] s1_1;
  logic [SquareW-1:0] s2_1;
  logic [15:0] dmax1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      a1    <= area_i;
      s1_1  <= sum_d_i;
      s2_1  <= sum_dd_i;
      dmax1 <= d_max_i;
    end
  end

  // ---- 2, 3: partial products (M, P) --------------------------------------------------------
  logic [16:0] lo1, hp1;   // L and H[16:0]
  logic [17:0] h1;         // H
  assign lo1 = s1_1[16:0];
  assign h1  = s1_1[34:17];
  assign hp1 = h1[16:0];

  logic [36:0] p0_m, p1_m, p0_p, p1_p;  // A S2[16:0], A S2[33:17]
  logic [35:0] p2_m, p2_p;              // A S2[49:34]
  logic [33:0] q0_m, q0_p;              // L^2
  logic [34:0] q1_m, q2_m, q1_p, q2_p;  // H L, H H[16:0]
  logic [17:0] q3_m, q3_p;              // H[17] ? H : 0
  logic [TW-4:0] t8_2;                   // T / 8 = 2 S1 + A
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      p0_m <= 37'(a1) * 37'(s2_1[16:0]);
      p1_m <= 37'(a1) * 37'(s2_1[33:17]);
      p2_m <= 36'(a1) * 36'(s2_1[49:34]);
      q0_m <= 34'(lo1) * 34'(lo1);
      q1_m <= 35'(h1) * 35'(lo1);
      q2_m <= 35'(h1) * 35'(hp1);
      q3_m <= h1[17] ? h1 : '0;
      t8_2 <= {1'b0, s1_1, 1'b0} + (TW - 3)'(a1);
      p0_p <= p0_m;
      p1_p <= p1_m;
      p2_p <= p2_m;
      q0_p <= q0_m;
      q1_p <= q1_m;
      q2_p <= q2_m;
      q3_p <= q3_m;
    end
  end

  // ---- 4 .. 7: V ----------------------------------------------------------------------------
  // 4: X = P0 + P1 2^17 = A S2[33:0] (< 2^54), Y = L^2 + H L 2^18 (< 2^54), W = H^2 (< 2^36)
  // 5: A S2 = X + P2 2^34, S1^2 = Y + W 2^34
  logic [53:0] x4, y4;
  logic [35:0] w4, p2_4;
  logic [VW-1:0] as5, ss5;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      x4   <= {37'(p0_p[36:17]) + p1_p, p0_p[16:0]};
      y4   <= {36'(q0_p[33:18]) + 36'(q1_p), q0_p[17:0]};
      w4   <= {19'(q2_p[34:17]) + 19'(q3_p), q2_p[16:0]};
      p2_4 <= p2_p;
      as5  <= {36'(x4[53:34]) + p2_4, x4[33:0]};
      ss5  <= {36'(y4[53:34]) + w4, y4[33:0]};
    end
  end

  // 6: the low half of A S2 - S1^2 and its borrow; 7: the high half, V = max(0, difference).
  // The high half subtracts the borrow in the same carry chain: {a, 0} - {b, borrow} halved.
  logic [HalfW:0] lo_diff;
  logic [HalfW-1:0] d_lo6, as_hi6, ss_hi6;
  logic borrow6;
  assign lo_diff = {1'b0, as5[HalfW-1:0]} - {1'b0, ss5[HalfW-1:0]};
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      d_lo6   <= lo_diff[HalfW-1:0];
      borrow6 <= lo_diff[HalfW];
      as_hi6  <= as5[VW-1:HalfW];
      ss_hi6  <= ss5[VW-1:HalfW];
    end
  end

  logic [HalfW+1:0] hi_diff;  // 2 (as_hi - ss_hi - borrow), signed
  logic [VW-1:0] v7;
  assign hi_diff = {1'b0, as_hi6, 1'b0} - {1'b0, ss_hi6, borrow6};
  always_ff @(posedge clk_i) begin
    if (en_i) v7 <= hi_diff[HalfW+1] ? '0 : {hi_diff[HalfW:1], d_lo6};
  end

  // ---- 8 .. 43: R ---------------------------------------------------------------------------
  logic [RootW:0] root43;
  scw_warning_sqrt #(.InW(VW), .RootW(RootW), .Latency(SqrtLat)) u_sqrt (
    .clk_i, .en_i, .n_i(v7), .root_o(root43)
  );

  // ---- 44 .. 47: num ------------------------------------------------------------------------
  // T's low 3 bits are zero, so T / 8 is what waits. Delayed, the zeros cost nothing in the
  // netlist (Yosys removes them), but its opt_dff found them constant one stage per pass: 43
  // passes, a third of the stage's synthesis time.
  logic [TW-1:0] t45;
  logic [TW-4:0] t8_45;
  scw_warning_delay #(.Width(TW - 3), .Depth(RootStage)) u_t_delay (
    .clk_i, .en_i, .d_i(t8_2), .q_o(t8_45)
  );
  assign t45 = {t8_45, 3'b000};

  // k R = KR0 + KR1 2^24: R[23:0] k (24 x 8 bits) and R[35:24] k (12 x 8), one DSP each
  logic [31:0] kr0_m, kr0_p;
  logic [19:0] kr1_m, kr1_p;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      kr0_m <= 32'(root43[23:0]) * 32'(spread_q);
      kr1_m <= 20'(root43[35:24]) * 20'(spread_q);
      kr0_p <= kr0_m;
      kr1_p <= kr1_m;
    end
  end

  // 46: the low 24 bits of T + k R with their carry, and k R's upper part (k R < 2^43);
  // 47: num's upper 20 bits, the carry in the same chain ({a, 1} + {b, c} halved).
  logic [24:0] u46;
  logic [19:0] kh46;
  logic [15:0] th46;
  logic [20:0] num_hi;
  logic [NumW-1:0] num47;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      u46   <= {1'b0, t45[23:0]} + {1'b0, kr0_p[23:0]};
      kh46  <= 20'(kr0_p[31:24]) + kr1_p;
      th46  <= t45[TW-1:24];
      num47 <= {num_hi[20:1], u46[23:0]};
    end
  end
  assign num_hi = {4'b0, th46, 1'b1} + {kh46, u46[24]};

  logic [AreaW-1:0] a47;
  scw_warning_delay #(.Width(AreaW), .Depth(NumStage - 1)) u_a_delay (
    .clk_i, .en_i, .d_i(a1), .q_o(a47)
  );

  // ---- 48 .. 63: the quotient ---------------------------------------------------------------
  // The remainder's low bits wait for their turn in SRLs; the 25 bits a step compares and den
  // come from flip-flops kept out of them (an SRL's clock-to-output, about 1.5 ns, would start
  // the carry chain), and so do the last step's quotient and saturation bits.
  for (genvar k = 0; k < QW; k++) begin : gen_div
    localparam int unsigned B = QW - 1 - k;  // the quotient bit this step decides
    logic [B+24:0] rem_in;                    // before the step: below den 2^(B+1)
    logic [DenW-1:0] den_in;
    logic [DenW+1:0] diff;
    logic ge, sat_c, sat_s;
    logic [k:0] q_c, q_s;

    if (k == 0) begin : gen_first
      assign rem_in = num47[B+24:0];
      assign den_in = {a47, 4'b0};
      // num >= den 2^16 (always when den = 0): the quotient saturates
      assign sat_c  = num47[NumW-1:QW] >= {{(NumW - QW - DenW){1'b0}}, den_in};
      assign q_c    = ge;
    end else begin : gen_next
      if (B + 1 > 1) begin : gen_with_low
        assign rem_in = {gen_div[k-1].gen_rem.rem_s, gen_div[k-1].gen_rem.gen_low.low_s};
      end else begin : gen_no_low
        assign rem_in = gen_div[k-1].gen_rem.rem_s;
      end
      assign den_in = gen_div[k-1].gen_rem.den_s;
      assign sat_c  = gen_div[k-1].sat_s;
      assign q_c    = {gen_div[k-1].q_s, ge};
    end
    assign diff = {1'b0, rem_in[B+24:B]} - {2'b0, den_in};
    assign ge   = !diff[DenW+1];

    if (k == QW - 1) begin : gen_out_reg
      (* keep *) always_ff @(posedge clk_i) begin
        if (en_i) begin
          sat_s <= sat_c;
          q_s   <= q_c;
        end
      end
    end else begin : gen_q_reg
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          sat_s <= sat_c;
          q_s   <= q_c;
        end
      end
    end

    // What is left is below den < 2^24 (diff[24] is 0 whenever it is kept): rem_s holds bits
    // B+23 .. B-1 of it, low_s the bits below.
    if (B > 0) begin : gen_rem
      logic [24:0] rem_s;
      logic [DenW-1:0] den_s;
      logic [B+23:0] rem_c;
      assign rem_c = ge ? {diff[DenW-1:0], rem_in[B-1:0]} : rem_in[B+23:0];
      (* keep *) always_ff @(posedge clk_i) begin
        if (en_i) begin
          rem_s <= rem_c[B+23:B-1];
          den_s <= den_in;
        end
      end
      if (B > 1) begin : gen_low
        logic [B-2:0] low_s;
        always_ff @(posedge clk_i) begin
          if (en_i) low_s <= rem_c[B-2:0];
        end
      end
      logic unused_step;
      assign unused_step = diff[DenW];
    end else begin : gen_no_rem
      logic unused_step;
      assign unused_step = ^{diff[DenW:0], rem_in[24]};
    end
  end

  // ---- 64: dq -------------------------------------------------------------------------------
  logic [15:0] dmax63, q63;
  logic sat63;
  scw_warning_delay #(.Width(16), .Depth(Stages - 2)) u_dmax_delay (
    .clk_i, .en_i, .d_i(dmax1), .q_o(dmax63)
  );
  assign q63   = gen_div[QW-1].q_s;
  assign sat63 = gen_div[QW-1].sat_s;
  always_ff @(posedge clk_i) begin
    if (en_i) dq_o <= (rule_q && !sat63 && q63 < dmax63) ? q63 : dmax63;
  end

  logic unused_rule;
  assign unused_rule = num_hi[0];
endmodule
