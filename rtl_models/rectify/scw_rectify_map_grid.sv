// SPDX-License-Identifier: Apache-2.0
// Grid-compressed map: expands knots every G = 2^GridLog2 pixels into scw_rectify's map stream.
`default_nettype none

// A source: while run_i is high it issues one map beat per clock in raster order (sof on the
// first beat of a frame, eol on the last beat of every row), frame after frame, cfg_width_i x
// cfg_height_i, and stalls under out_ready_i. For output pixel (u, v), i = u >> k, j = v >> k,
// du = u mod G, dv = v mod G and the knots K00 = K(i, j), K10 = K(i+1, j), K01 = K(i, j+1),
// K11 = K(i+1, j+1) (x and y alike, KnotFracBits fractional bits):
//   L = K00 G + (K01 - K00) dv,  R = K10 G + (K11 - K10) dv    (shared by the beat's pixels)
//   c = L G + (R - L) du,  m = (c + 2^(s-1)) >>> s,  s = 2k + KnotFracBits - FracBits
//   x = clamp(m_x, -S, W S),  y = clamp(m_y, -S, H S),  S = 2^FracBits.
// Exact until the one rounding; the C++ twin is scw::hls::rectify::MapGrid
// (hls/rectify/map_grid.hpp) clocked by scw::sim::MapGridModel.
//
// Knots: a write port, loaded once like a register file (with run_i low; a write while
// frames stream takes effect for beats issued after it). knot_addr_i = {row j, column i},
// knot_data_i = {y, x}, two's complement. Four simple dual-port RAMs by (row parity, column
// parity) hold the grid, so the four knots of a pixel are always in four different RAMs and
// are read in one cycle; RAM address {j >> 1, i >> 1}. A beat's P pixels share their knots
// (G >= P). Knot addresses beyond the grid land in RAM words no read addresses.
//
// Pipeline under one enable (adv = !out_valid || out_ready), Latency = 11:
//   issue: RAM addresses from the raster counters (sampled at the issuing edge)
//   s0 knot words (block RAM)  -> s1 knot words in registers (nothing behind a block RAM)
//   -> s2 K00, K10 and the vertical differences K01 - K00, K11 - K10 (DSP A/B registers)
//   -> s3 products, C = K G (DSP M/C) -> s4 L, R (DSP P)
//   -> s5 R - L -> s6 (R - L) du per pixel (DSP M) -> s7 (DSP P), L G + 2^(s-1)
//   -> s8 c + 2^(s-1) -> s9 m = that >>> s and its compares with the bounds
//   -> s10 clamp: the output register.
// The lanes share R - L and L G + 2^(s-1), so these stay in the fabric (a register feeding
// several DSPs cannot be their A or C register) and the sum follows the DSP's P register.
// cfg_* are static: set them before rst_ni rises (registered without reset).
module scw_rectify_map_grid #(
  parameter int unsigned Ppc          /*verilator public*/ = 1,
  parameter int unsigned MaxWidthPx   /*verilator public*/ = 64,
  parameter int unsigned MaxHeight    /*verilator public*/ = 32,
  parameter int unsigned GridLog2     /*verilator public*/ = 3,
  parameter int unsigned FracBits     /*verilator public*/ = 5,
  parameter int unsigned KnotFracBits /*verilator public*/ = 7,
  localparam int unsigned MaxWH       = (MaxWidthPx > MaxHeight) ? MaxWidthPx : MaxHeight,
  localparam int unsigned CoordBits   = $clog2(MaxWH * (1 << FracBits) + 1) + 1,
  localparam int unsigned KBits       = $clog2(MaxWH) + 2 + KnotFracBits,
  localparam int unsigned KCols       = ((MaxWidthPx - 1) >> GridLog2) + 2,
  localparam int unsigned KRows       = ((MaxHeight - 1) >> GridLog2) + 2,
  localparam int unsigned KColW       = $clog2(KCols),
  localparam int unsigned KRowW       = $clog2(KRows),
  localparam int unsigned KAddrW      = KRowW + KColW,
  localparam int unsigned KnotW       = 2 * KBits,
  localparam int unsigned MapW        = Ppc * 2 * CoordBits,
  localparam int unsigned WW          = $clog2(MaxWidthPx + 1),
  localparam int unsigned HW          = $clog2(MaxHeight + 1)
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  // static configuration: frame width (pixels, a multiple of Ppc), height (rows)
  input  logic [WW-1:0]     cfg_width_i,
  input  logic [HW-1:0]     cfg_height_i,
  // issue beats while high (an idle cycle on the stream when low)
  input  logic              run_i,
  // knot write port
  input  logic              knot_we_i,
  input  logic [KAddrW-1:0] knot_addr_i,
  input  logic [KnotW-1:0]  knot_data_i,
  // map: per pixel {y, x}, signed fixed point with FracBits fractional bits
  output logic              out_valid_o,
  input  logic              out_ready_i,
  output logic [MapW-1:0]   out_data_o,
  output logic              out_sof_o,
  output logic              out_eol_o
);
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency      /*verilator public*/ = 11;
  localparam int unsigned MapCoordBits /*verilator public*/ = CoordBits;
  localparam int unsigned KnotBits     /*verilator public*/ = KBits;
  localparam int unsigned KnotColBits  /*verilator public*/ = KColW;
  localparam int unsigned KnotRowBits  /*verilator public*/ = KRowW;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned Cols   = MaxWidthPx / Ppc;
  localparam int unsigned ColW   = $clog2(Cols);
  localparam int unsigned PpcLog = $clog2(Ppc);
  localparam int unsigned UW     = ColW + PpcLog;
  localparam int unsigned BColW  = KColW - 1;
  localparam int unsigned BRowW  = KRowW - 1;
  localparam int unsigned BAddrW = BRowW + BColW;
  localparam int unsigned BDepth = 1 << BAddrW;
  localparam int unsigned Shift  = 2 * GridLog2 + KnotFracBits - FracBits;
  // A knot word's bits beyond a multiple of 36 (the RAMB36's 1K x 36 shape) would fill a whole
  // RAMB18 for a few bits when the grid RAMs are more than 512 deep (40 bits at 1280 x 480: 36
  // in block RAM, 4 in LUT RAM, 1.5 -> 1 BRAM36 a RAM, 6 -> 4 a camera). Wider remainders stay.
  localparam int unsigned KnotLutBits = (BDepth > 512 && KnotW % 36 <= 8) ? KnotW % 36 : 0;
  // Signed widths (LW, CW below). L, R are knots times G in convex combination, c knots times
  // G^2: the final values fit exactly (intermediate wrap-around cancels in two's complement),
  // and the multiplier operands are the differences, KBits + 1 and LW + 1 bits (25 x 5 at
  // 1280 x 480, G = 16: one DSP48E1 each).

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_rectify_map_grid: Ppc must be 1, 2 or 4");
  end
  if (GridLog2 < 1 || GridLog2 > 6 || (1 << GridLog2) < Ppc) begin : gen_bad_grid
    $error("scw_rectify_map_grid: need 2 <= G = 2^GridLog2 <= 64 and G >= Ppc");
  end
  if (MaxWidthPx % Ppc != 0 || MaxWidthPx <= (1 << GridLog2) || MaxHeight <= (1 << GridLog2))
  begin : gen_bad_geom
    $error("scw_rectify_map_grid: need MaxWidthPx %% Ppc == 0 and MaxWidthPx, MaxHeight > G");
  end
  if (KnotFracBits < FracBits) begin : gen_bad_frac
    $error("scw_rectify_map_grid: need KnotFracBits >= FracBits");
  end

  // ---- configuration ---------------------------------------------------------------------
  localparam int unsigned LW     = KBits + GridLog2;      // vertical blend L, R
  localparam int unsigned CW     = LW + GridLog2;         // horizontal blend c
  localparam logic signed [CW-1:0] Half = CW'(1) <<< (Shift - 1);
  localparam logic signed [CW-1:0] Lo   = -(CW'(1) <<< FracBits);
  localparam int unsigned Latency1 = Latency - 1;

  logic [ColW-1:0] last_col_cfg;
  logic [HW-1:0] last_row_cfg;
  logic signed [CW-1:0] hi_x, hi_y;
  always_ff @(posedge clk_i) begin
    last_col_cfg <= ColW'((cfg_width_i >> PpcLog) - 1'b1);
    last_row_cfg <= cfg_height_i - 1'b1;
    hi_x         <= $signed(CW'(cfg_width_i) << FracBits);
    hi_y         <= $signed(CW'(cfg_height_i) << FracBits);
  end

  // ---- issue: raster counters, knot RAM addresses ----------------------------------------
  logic adv, issue, last_col, last_row;
  logic [ColW-1:0] col_q;
  logic [HW-1:0] row_q;
  logic [UW-1:0] u;
  logic [KColW-1:0] ki;
  logic [KRowW-1:0] kj;
  logic [GridLog2-1:0] du0, dv;
  logic [Latency-1:0] vld_q, sof_q, eol_q;  // bit k: stage k

  assign adv      = !vld_q[Latency1] || out_ready_i;
  assign issue    = adv && run_i;
  assign last_col = col_q == last_col_cfg;
  assign last_row = row_q == last_row_cfg;
  assign u        = UW'(col_q) << PpcLog;
  assign ki       = KColW'(u >> GridLog2);
  assign kj       = KRowW'(row_q >> GridLog2);
  assign du0      = u[GridLog2-1:0];
  assign dv       = row_q[GridLog2-1:0];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      col_q <= '0;
      row_q <= '0;
    end else if (issue) begin
      if (last_col) begin
        col_q <= '0;
        row_q <= last_row ? '0 : row_q + 1'b1;
      end else begin
        col_q <= col_q + 1'b1;
      end
    end
  end

  // Column c of a pixel's knots is i if i has parity c, else i + 1; likewise rows. The RAM
  // of column parity 0 therefore reads word (i >> 1) + i[0], that of parity 1 word i >> 1.
  logic [BColW-1:0] ca0, ca1;
  logic [BRowW-1:0] ra0, ra1;
  assign ca0 = ki[KColW-1:1] + BColW'(ki[0]);
  assign ca1 = ki[KColW-1:1];
  assign ra0 = kj[KRowW-1:1] + BRowW'(kj[0]);
  assign ra1 = kj[KRowW-1:1];

  // ---- knot RAMs: (row parity r, column parity c) at index r*2 + c -------------------------
  // s0 is the RAMs' own read register; s1 copies it into the fabric, so that block RAM
  // clock-to-out (most of a clock) has nothing behind it.
  logic [KColW-1:0] wcol;
  logic [KRowW-1:0] wrow;
  logic [4*KnotW-1:0] s1_word_q;
  assign wcol = knot_addr_i[KColW-1:0];
  assign wrow = knot_addr_i[KAddrW-1:KColW];

  for (genvar r = 0; r < 2; r++) begin : gen_r
    for (genvar c = 0; c < 2; c++) begin : gen_c
      logic [KnotW-1:0] word, word_q;
      scw_ram_sdp #(
        .Width  (KnotW),
        .Depth  (BDepth),
        .LutBits(KnotLutBits)
      ) u_ram (
        .clk_i,
        .wr_en_i  (knot_we_i && (wrow[0] == 1'(r)) && (wcol[0] == 1'(c))),
        .wr_addr_i({wrow[KRowW-1:1], wcol[KColW-1:1]}),
        .wr_data_i(knot_data_i),
        .rd_en_i  (adv),
        .rd_addr_i({(r == 0) ? ra0 : ra1, (c == 0) ? ca0 : ca1}),
        .rd_data_o(word)
      );
      always_ff @(posedge clk_i) begin
        if (adv) word_q <= word;
      end
      assign s1_word_q[(r*2 + c)*KnotW +: KnotW] = word_q;
    end
  end

  // ---- pipeline control --------------------------------------------------------------------
  logic s0_ip_q, s0_jp_q, s1_ip_q, s1_jp_q;
  logic [GridLog2-1:0] s0_du_q, s1_du_q, s2_du_q, s3_du_q, s4_du_q, s0_dv_q, s1_dv_q;
  logic [MapW-1:0] out_data_q, out_c;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      vld_q <= '0;
    end else if (adv) begin
      vld_q <= {vld_q[Latency-2:0], issue};
    end
  end

  always_ff @(posedge clk_i) begin
    if (adv) begin
      sof_q      <= {sof_q[Latency-2:0], (col_q == '0) && (row_q == '0)};
      eol_q      <= {eol_q[Latency-2:0], last_col};
      s0_ip_q    <= ki[0];
      s0_jp_q    <= kj[0];
      s0_du_q    <= du0;
      s0_dv_q    <= dv;
      s1_ip_q    <= s0_ip_q;
      s1_jp_q    <= s0_jp_q;
      s1_du_q    <= s0_du_q;
      s1_dv_q    <= s0_dv_q;
      s2_du_q    <= s1_du_q;
      s3_du_q    <= s2_du_q;
      s4_du_q    <= s3_du_q;
      out_data_q <= out_c;
    end
  end

  assign out_valid_o = vld_q[Latency1];
  assign out_data_o  = out_data_q;
  assign out_sof_o   = sof_q[Latency1];
  assign out_eol_o   = eol_q[Latency1];

  // ---- s1 -> s2: pick the four knots by parity ----------------------------------------------
  // K00 is in RAM (j[0], i[0]), K10 in (j[0], !i[0]), K01 in (!j[0], i[0]), K11 in the fourth.
  logic [KnotW-1:0] b00, b01, b10, b11, top0, top1, bot0, bot1, k00w, k10w, k01w, k11w;
  assign b00  = s1_word_q[0*KnotW +: KnotW];  // even row, even column
  assign b01  = s1_word_q[1*KnotW +: KnotW];  // even row, odd column
  assign b10  = s1_word_q[2*KnotW +: KnotW];  // odd row, even column
  assign b11  = s1_word_q[3*KnotW +: KnotW];  // odd row, odd column
  assign top0 = s1_jp_q ? b10 : b00;          // knot row j, even column
  assign top1 = s1_jp_q ? b11 : b01;          // knot row j, odd column
  assign bot0 = s1_jp_q ? b00 : b10;          // knot row j + 1
  assign bot1 = s1_jp_q ? b01 : b11;
  assign k00w = s1_ip_q ? top1 : top0;
  assign k10w = s1_ip_q ? top0 : top1;
  assign k01w = s1_ip_q ? bot1 : bot0;
  assign k11w = s1_ip_q ? bot0 : bot1;

  logic signed [GridLog2:0] s2_dv_q;
  always_ff @(posedge clk_i) begin
    if (adv) s2_dv_q <= $signed({1'b0, s1_dv_q});
  end

  // ---- per coordinate (a = 0: x, a = 1: y) ---------------------------------------------------
  for (genvar a = 0; a < 2; a++) begin : gen_coord
    // -- s2..s4: vertical blends L = K00 G + (K01 - K00) dv, R likewise (one DSP each) ---------
    logic signed [KBits-1:0] k00, k10, k01, k11, s2_k00_q, s2_k10_q;
    logic signed [KBits:0] s2_dl_q, s2_dr_q;
    logic signed [LW-1:0] s3_ml_q, s3_mr_q, s3_cl_q, s3_cr_q, s4_l_q, s4_r_q;
    assign k00 = $signed(k00w[a*KBits +: KBits]);
    assign k10 = $signed(k10w[a*KBits +: KBits]);
    assign k01 = $signed(k01w[a*KBits +: KBits]);
    assign k11 = $signed(k11w[a*KBits +: KBits]);
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s2_dl_q  <= (KBits + 1)'(k01) - (KBits + 1)'(k00);
        s2_dr_q  <= (KBits + 1)'(k11) - (KBits + 1)'(k10);
        s2_k00_q <= k00;
        s2_k10_q <= k10;
        s3_ml_q  <= LW'(s2_dl_q * s2_dv_q);
        s3_mr_q  <= LW'(s2_dr_q * s2_dv_q);
        s3_cl_q  <= LW'(s2_k00_q) <<< GridLog2;
        s3_cr_q  <= LW'(s2_k10_q) <<< GridLog2;
        s4_l_q   <= s3_ml_q + s3_cl_q;
        s4_r_q   <= s3_mr_q + s3_cr_q;
      end
    end

    // -- s5..s7: horizontal blend per pixel, c + 2^(s-1) = L G + 2^(s-1) + (R - L) du ---------
    logic signed [LW:0] s5_dlr_q;
    logic signed [LW-1:0] s5_l_q, s6_l_q;
    logic signed [CW-1:0] s7_lh_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s5_dlr_q <= (LW + 1)'(s4_r_q) - (LW + 1)'(s4_l_q);
        s5_l_q   <= s4_l_q;
        s6_l_q   <= s5_l_q;
        s7_lh_q  <= (CW'(s6_l_q) <<< GridLog2) + Half;
      end
    end
    for (genvar l = 0; l < Ppc; l++) begin : gen_lane
      logic signed [GridLog2:0] s5_du_q;
      logic signed [CW-1:0] s6_m_q, s7_p_q, s8_c_q, m, q;
      always_ff @(posedge clk_i) begin
        if (adv) begin
          // du < G: a beat never crosses a knot column
          s5_du_q <= $signed({1'b0, s4_du_q + GridLog2'(l)});
          s6_m_q  <= CW'(s5_dlr_q * s5_du_q);
          s7_p_q  <= s6_m_q;
          s8_c_q  <= s7_p_q + s7_lh_q;
        end
      end
      // -- s9: round (the shift), compare with the bounds; s10: clamp into the output register
      logic s9_lo_q, s9_hi_q;
      logic signed [CW-1:0] s9_m_q, hi;
      assign hi = (a == 0) ? hi_x : hi_y;
      assign m  = s8_c_q >>> Shift;
      always_ff @(posedge clk_i) begin
        if (adv) begin
          s9_m_q  <= m;
          s9_lo_q <= m < Lo;
          s9_hi_q <= m > hi;
        end
      end
      assign q = s9_lo_q ? Lo : (s9_hi_q ? hi : s9_m_q);
      assign out_c[(l*2 + a)*CoordBits +: CoordBits] = q[CoordBits-1:0];

      logic unused_lane;
      assign unused_lane = ^{q[CW-1:CoordBits], s9_m_q[CW-1:CoordBits]};
    end
  end

endmodule
