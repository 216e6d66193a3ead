// SPDX-License-Identifier: Apache-2.0
// Rectify: streaming bilinear remap of a raw pixel stream through a window of Rows raw rows.
`default_nettype none

// Two sides share a circular buffer of Rows raw rows and one counter, avail = raw rows written
// minus output rows finished (counted across frames). The writer takes raw beats while
// avail + pending <= D + 1 (pending: the last beat of an output row is in stage 0 and has not
// read the RAM yet); the reader takes one map beat per output beat while
// avail >= min(D, H - v). In steady state both move one beat per clock, D rows apart, and a
// frame's last rows are read while the next frame's first rows are written.
//
// Storage: per output lane, four simple dual-port RAMs by (row parity, column parity), so the
// four bilinear taps always read four different RAMs; each word holds Q = max(1, Ppc/2)
// pixels of one parity, so a beat writes one word per column parity. The address is
// {column word, row slot / 2}: Rows is a power of two and nothing is wasted.
//
// Pipeline under one enable (adv = !out_valid || out_ready), Latency = 4:
//   s0 decode taps, window check, RAM addresses -> s1 RAM words -> s2 horizontal blends
//   a = f00 S + (f10 - f00) fx, b likewise -> out  (a S + (b - a) fy + S^2/2) >> 2F.
// cfg_* are static: set them before rst_ni rises (they are registered without reset, and the
// first clock after reset already uses them). Geometry comes from cfg_*; sof/eol are checked,
// never trusted. A sof in mid-frame is held:
// the writer marks the rest of its frame written (no data), the reader emits zeros for the
// rest of its frame, and both start the next frame with the held beat. A beat that should
// start a frame but has no sof is dropped. err_o (sticky): [0] raw stream geometry,
// [1] map stream geometry, [2] a map tap outside the row window (it reads 0).
// The C++ twin is scw::hls::rectify::Rectify clocked by scw::sim::RectifyModel.
module scw_rectify #(
  parameter int unsigned Ppc        /*verilator public*/ = 1,
  parameter int unsigned MaxWidthPx /*verilator public*/ = 64,
  parameter int unsigned MaxHeight  /*verilator public*/ = 32,
  parameter int unsigned Rows       /*verilator public*/ = 16,
  parameter int unsigned FracBits   /*verilator public*/ = 5,
  localparam int unsigned MaxWH     = (MaxWidthPx > MaxHeight) ? MaxWidthPx : MaxHeight,
  localparam int unsigned CoordBits = $clog2(MaxWH * (1 << FracBits) + 1) + 1,
  localparam int unsigned PixW      = scw_pkg::PixelBits,
  localparam int unsigned BeatW     = Ppc * PixW,
  localparam int unsigned MapW      = Ppc * 2 * CoordBits,
  localparam int unsigned WW        = $clog2(MaxWidthPx + 1),
  localparam int unsigned HW        = $clog2(MaxHeight + 1),
  localparam int unsigned SlotW     = $clog2(Rows)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // static configuration: frame width (pixels), height (rows), lead D (rows)
  input  logic [WW-1:0]    cfg_width_i,
  input  logic [HW-1:0]    cfg_height_i,
  input  logic [SlotW-1:0] cfg_lead_i,
  // raw pixels
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [BeatW-1:0] in_data_i,
  input  logic             in_sof_i,
  input  logic             in_eol_i,
  // map: per pixel {y, x}, signed fixed point with FracBits fractional bits
  input  logic             map_valid_i,
  output logic             map_ready_o,
  input  logic [MapW-1:0]  map_data_i,
  input  logic             map_sof_i,
  input  logic             map_eol_i,
  // rectified pixels
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [BeatW-1:0] out_data_o,
  output logic             out_sof_o,
  output logic             out_eol_o,
  output logic [2:0]       err_o
);
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency     /*verilator public*/ = 4;
  localparam int unsigned MapCoordBits /*verilator public*/ = CoordBits;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned Cols    = MaxWidthPx / Ppc;
  localparam int unsigned ColW    = $clog2(Cols);
  localparam int unsigned PpcLog  = $clog2(Ppc);
  localparam int unsigned AvW     = SlotW + 2;
  localparam int unsigned Q       = (Ppc > 1) ? Ppc / 2 : 1;
  localparam int unsigned QW      = $clog2(Q);
  localparam int unsigned Words   = MaxWidthPx / (2 * Q);
  localparam int unsigned CwW     = $clog2(Words);
  localparam int unsigned RiW     = SlotW - 1;
  localparam int unsigned AddrW   = CwW + RiW;
  localparam int unsigned Depth   = Words * (Rows / 2);
  localparam int unsigned WordW   = Q * PixW;
  localparam int unsigned IntW    = CoordBits - FracBits;
  localparam int unsigned DW      = ((IntW > SlotW + 1) ? IntW : SlotW + 1) + 2;
  localparam int unsigned CmpW    = ((HW > AvW) ? HW : AvW) + 1;

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_rectify: Ppc must be 1, 2 or 4");
  end
  if (MaxWidthPx % (4 * Ppc) != 0 || Rows < 4 || (Rows & (Rows - 1)) != 0) begin : gen_bad_geom
    $error("scw_rectify: need MaxWidthPx %% (4 Ppc) == 0 and Rows a power of two >= 4");
  end

  // ---- configuration ---------------------------------------------------------------------
  // cfg_* are static: registered here (no reset, so they settle while rst_ni is low) together
  // with the values derived from them, which keeps them off every timing path.
  logic [WW-1:0] width_q;
  logic [HW-1:0] height_q, last_row_q;
  logic [SlotW-1:0] lead_q;
  logic [SlotW+2:0] wr_limit_q;
  logic [CmpW-1:0] need_first;  // min(D, H): the first row of a frame
  always_ff @(posedge clk_i) begin
    width_q    <= cfg_width_i;
    height_q   <= cfg_height_i;
    lead_q     <= cfg_lead_i;
    last_row_q <= cfg_height_i - 1'b1;
    wr_limit_q <= (SlotW + 3)'(cfg_lead_i) + 1'b1;
    need_first <= (CmpW'(cfg_lead_i) < CmpW'(cfg_height_i)) ? CmpW'(cfg_lead_i)
                                                            : CmpW'(cfg_height_i);
  end

  // ---- shared ----------------------------------------------------------------------------
  logic adv, pending;
  logic out_valid_q;
  logic s0_valid_q, s0_eol_q;
  logic [AvW-1:0] avail_q;
  logic [2:0] err_q;
  logic [ColW-1:0] last_col;
  logic [WW-1:0] cols_cfg;

  assign adv      = !out_valid_q || out_ready_i;
  assign pending  = s0_valid_q && s0_eol_q;
  assign cols_cfg = width_q >> PpcLog;
  assign last_col = ColW'(cols_cfg - 1'b1);
  assign err_o    = err_q;

  // ---- writer ----------------------------------------------------------------------------
  logic [ColW-1:0] in_col_q;
  logic [HW-1:0] in_row_q;
  logic [SlotW-1:0] in_slot_q;
  logic skip_q, rheld_q, rheld_eol_q;
  logic [BeatW-1:0] rheld_q_data;
  logic wr_ok, raw_fs, raw_take, wr_do, wr_eol, wr_last, row_done, skip_set, rheld_set, rheld_clr;
  logic err_raw;
  logic [BeatW-1:0] wr_data;

  // avail + pending <= D + 1, as two compares against registers and a select (no adder).
  assign wr_ok      = pending ? ((AvW + 1)'(avail_q) <= (AvW + 1)'(lead_q))
                              : ((AvW + 1)'(avail_q) <= wr_limit_q);
  assign raw_fs     = (in_row_q == '0) && (in_col_q == '0);
  assign in_ready_o = !skip_q && !rheld_q && wr_ok;
  assign raw_take   = in_valid_i && in_ready_o;
  assign wr_last    = in_col_q == last_col;

  always_comb begin
    wr_do     = 1'b0;
    wr_data   = in_data_i;
    wr_eol    = in_eol_i;
    skip_set  = 1'b0;
    rheld_set = 1'b0;
    rheld_clr = 1'b0;
    err_raw   = 1'b0;
    row_done  = 1'b0;
    if (raw_take) begin
      if (in_sof_i && !raw_fs) begin
        err_raw   = 1'b1;
        rheld_set = 1'b1;
        skip_set  = 1'b1;
      end else if (!in_sof_i && raw_fs) begin
        err_raw = 1'b1;
      end else begin
        wr_do = 1'b1;
      end
    end else if (skip_q && wr_ok) begin
      row_done = 1'b1;
    end else if (rheld_q && wr_ok) begin
      wr_do     = 1'b1;
      wr_data   = rheld_q_data;
      wr_eol    = rheld_eol_q;
      rheld_clr = 1'b1;
    end
    if (wr_do && (wr_eol != wr_last)) err_raw = 1'b1;
    if (wr_do && wr_last) row_done = 1'b1;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      in_col_q  <= '0;
      in_row_q  <= '0;
      in_slot_q <= '0;
      skip_q    <= 1'b0;
      rheld_q   <= 1'b0;
    end else begin
      if (row_done) begin
        in_col_q  <= '0;
        in_slot_q <= in_slot_q + 1'b1;
        if (in_row_q == last_row_q) begin
          in_row_q <= '0;
          skip_q   <= 1'b0;
        end else begin
          in_row_q <= in_row_q + 1'b1;
        end
      end else if (wr_do) begin
        in_col_q <= in_col_q + 1'b1;
      end
      if (skip_set) skip_q <= 1'b1;
      if (rheld_set) rheld_q <= 1'b1;
      else if (rheld_clr) rheld_q <= 1'b0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (rheld_set) begin
      rheld_q_data <= in_data_i;
      rheld_eol_q  <= in_eol_i;
    end
  end

  // What a write puts in each column-parity RAM: the pixels of that parity, and its address.
  logic [2*WordW-1:0] wr_word;  // column parity c in [c*WordW +: WordW]
  logic [1:0] wr_col_en;
  logic [AddrW-1:0] wr_addr;
  if (Ppc == 1) begin : gen_wr_p1
    assign wr_word   = {wr_data, wr_data};
    assign wr_col_en  = in_col_q[0] ? 2'b10 : 2'b01;
    assign wr_addr    = {in_col_q[ColW-1:1], in_slot_q[SlotW-1:1]};
  end else begin : gen_wr_pn
    for (genvar c = 0; c < 2; c++) begin : gen_par
      for (genvar k = 0; k < Q; k++) begin : gen_px
        assign wr_word[c*WordW + k*PixW +: PixW] = wr_data[(2*k + c)*PixW +: PixW];
      end
    end
    assign wr_col_en = 2'b11;
    assign wr_addr   = {in_col_q, in_slot_q[SlotW-1:1]};
  end

  // ---- reader ----------------------------------------------------------------------------
  logic [ColW-1:0] out_col_q;
  logic [HW-1:0] out_row_q;
  logic [SlotW-1:0] out_slot_q;
  logic fill_q, mheld_q, mheld_eol_q;
  logic [MapW-1:0] mheld_data_q;
  logic allowed, out_fs, out_last, map_take, go, emit, zero, mheld_set, mheld_clr;
  logic fill_set, err_map, md_eol;
  logic [HW-1:0] rows_left, left_q, left_next;
  logic [CmpW-1:0] need, need_q, need_next;
  logic [MapW-1:0] md;
  logic [Ppc-1:0] lane_winerr;

  // need = min(D, H - v), kept in registers so the handshake does not wait for a subtract
  // and a compare: left_q counts the rows left in the frame (0 = a frame starts, H rows), and
  // need_q is computed for the next row while the current one streams.
  assign rows_left   = (left_q == '0) ? height_q : left_q;
  assign left_next   = rows_left - 1'b1;
  assign need_next   = (CmpW'(lead_q) < CmpW'(left_next)) ? CmpW'(lead_q)
                                                               : CmpW'(left_next);
  assign need        = (left_q == '0) ? need_first : need_q;
  assign allowed     = CmpW'(avail_q) >= need;
  assign out_fs      = (out_row_q == '0) && (out_col_q == '0);
  assign out_last    = out_col_q == last_col;
  assign map_ready_o = adv && allowed && !fill_q && !mheld_q;
  assign map_take    = map_valid_i && map_ready_o;
  assign go          = adv && allowed;
  // A held beat is the only map beat in use while mheld_q is set (fill beats ignore the map),
  // so the lanes decode straight from registers, off the handshake path.
  assign md          = mheld_q ? mheld_data_q : map_data_i;
  assign md_eol      = mheld_q ? mheld_eol_q : map_eol_i;

  always_comb begin
    emit      = 1'b0;
    zero      = 1'b0;
    mheld_set = 1'b0;
    mheld_clr = 1'b0;
    fill_set  = 1'b0;
    err_map   = 1'b0;
    if (go) begin
      if (fill_q) begin
        emit = 1'b1;
        zero = 1'b1;
      end else if (mheld_q) begin
        emit      = 1'b1;
        mheld_clr = 1'b1;
      end else if (map_take) begin
        if (map_sof_i && !out_fs) begin
          err_map   = 1'b1;
          mheld_set = 1'b1;
          fill_set  = 1'b1;
        end else if (!map_sof_i && out_fs) begin
          err_map = 1'b1;
        end else begin
          emit = 1'b1;
        end
      end
    end
    if (emit && !zero && (md_eol != out_last)) err_map = 1'b1;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_col_q  <= '0;
      out_row_q  <= '0;
      out_slot_q <= '0;
      left_q     <= '0;
      need_q     <= '0;
      fill_q     <= 1'b0;
      mheld_q    <= 1'b0;
      avail_q    <= '0;
      err_q      <= '0;
    end else begin
      if (emit) begin
        if (out_last) begin
          out_col_q  <= '0;
          out_slot_q <= out_slot_q + 1'b1;
          left_q     <= left_next;
          need_q     <= need_next;
          if (out_row_q == last_row_q) begin
            out_row_q <= '0;
            fill_q    <= 1'b0;
          end else begin
            out_row_q <= out_row_q + 1'b1;
          end
        end else begin
          out_col_q <= out_col_q + 1'b1;
        end
      end
      if (fill_set) fill_q <= 1'b1;
      if (mheld_set) mheld_q <= 1'b1;
      else if (mheld_clr) mheld_q <= 1'b0;
      avail_q <= avail_q + AvW'(row_done) - AvW'(emit && out_last);
      // The window check is flagged from stage 0, a cycle after its beat was taken.
      err_q <= err_q | {s0_valid_q && (|s0_winerr_q), err_map, err_raw};
    end
  end

  always_ff @(posedge clk_i) begin
    if (mheld_set) begin
      mheld_data_q <= map_data_i;
      mheld_eol_q  <= map_eol_i;
    end
  end

  // ---- pipeline control ------------------------------------------------------------------
  logic [Ppc-1:0] s0_winerr_q;  // per lane, ORed a stage later
  logic s0_sof_q, s0_zero_q, s1_valid_q, s1_sof_q, s1_eol_q;
  logic s2_valid_q, s2_sof_q, s2_eol_q, out_sof_q, out_eol_q;
  logic [BeatW-1:0] out_pix, out_data_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      s0_valid_q  <= 1'b0;
      s1_valid_q  <= 1'b0;
      s2_valid_q  <= 1'b0;
      out_valid_q <= 1'b0;
    end else if (adv) begin
      s0_valid_q  <= emit;
      s1_valid_q  <= s0_valid_q;
      s2_valid_q  <= s1_valid_q;
      out_valid_q <= s2_valid_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (adv) begin
      s0_sof_q   <= out_fs;
      s0_eol_q   <= out_last;
      s0_zero_q  <= zero;
      s0_winerr_q <= (emit && !zero) ? lane_winerr : '0;
      s1_sof_q   <= s0_sof_q;
      s1_eol_q   <= s0_eol_q;
      s2_sof_q   <= s1_sof_q;
      s2_eol_q   <= s1_eol_q;
      out_sof_q  <= s2_sof_q;
      out_eol_q  <= s2_eol_q;
      out_data_q <= out_pix;
    end
  end

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
  assign out_sof_o   = out_sof_q;
  assign out_eol_o   = out_eol_q;

  // ---- lanes -----------------------------------------------------------------------------
  localparam int unsigned AW = PixW + FracBits + 2;  // signed horizontal blend, Q(8+F).0
  localparam int unsigned VW = AW + FracBits + 2;    // signed vertical blend before the shift
  localparam logic signed [VW-1:0] Half = VW'(1) <<< (2 * FracBits - 1);

  // Window bounds for row y0 (lo_s .. hi_s) and for row y0 + 1 expressed on dy = y0 - v
  // (lo1_s .. hi1_s), so the lanes compare dy without a second adder in the path.
  logic signed [DW-1:0] width_s, height_s, lo_s, hi_s, lo1_s, hi1_s, row_s;
  always_ff @(posedge clk_i) begin
    width_s  <= $signed(DW'(cfg_width_i));
    height_s <= $signed(DW'(cfg_height_i));
    lo_s     <= $signed(DW'(cfg_lead_i)) - $signed(DW'(Rows)) + $signed(DW'(2));
    hi_s     <= $signed(DW'(cfg_lead_i)) - $signed(DW'(1));
    lo1_s    <= $signed(DW'(cfg_lead_i)) - $signed(DW'(Rows)) + $signed(DW'(1));
    hi1_s    <= $signed(DW'(cfg_lead_i)) - $signed(DW'(2));
  end
  assign row_s    = $signed(DW'(out_row_q));

  for (genvar l = 0; l < Ppc; l++) begin : gen_lane
    // -- s0: decode ------------------------------------------------------------------------
    logic signed [IntW-1:0] x0i, y0i;
    logic signed [DW-1:0] x0, x1, y0, y1, dy;
    logic [FracBits-1:0] fx, fy;
    logic col0, col1, any_col, row0, row1, use0, use1, p, q;
    logic [SlotW-1:0] slot0, slot1;
    logic [CwW-1:0] w0, w1;

    assign x0i = $signed(md[l*2*CoordBits + FracBits +: IntW]);
    assign y0i = $signed(md[l*2*CoordBits + CoordBits + FracBits +: IntW]);
    assign fx  = md[l*2*CoordBits +: FracBits];
    assign fy  = md[l*2*CoordBits + CoordBits +: FracBits];
    assign x0  = DW'(x0i);
    assign y0  = DW'(y0i);
    assign x1  = x0 + $signed(DW'(1));
    assign y1  = y0 + $signed(DW'(1));
    assign dy  = y0 - row_s;

    assign col0    = (x0 >= 0) && (x0 < width_s);
    assign col1    = (fx != '0) && (x1 >= 0) && (x1 < width_s);
    assign any_col = col0 || col1;
    assign row0    = any_col && (y0 >= 0) && (y0 < height_s);
    assign row1    = any_col && (fy != '0) && (y1 >= 0) && (y1 < height_s);
    assign use0    = row0 && (dy >= lo_s) && (dy <= hi_s);
    assign use1    = row1 && (dy >= lo1_s) && (dy <= hi1_s);
    assign lane_winerr[l] = (row0 && !use0) || (row1 && !use1);

    assign slot0 = out_slot_q + dy[SlotW-1:0];
    assign slot1 = slot0 + 1'b1;
    assign p     = slot0[0];
    assign q     = x0[0];
    assign w0    = col0 ? x0[1 + QW +: CwW] : '0;
    assign w1    = col1 ? x1[1 + QW +: CwW] : '0;

    // RAM (r, c) holds raw rows of slot parity r and columns of parity c; index r * 2 + c.
    logic [4*WordW-1:0] rd_word;
    logic s0_u00_q, s0_u10_q, s0_u01_q, s0_u11_q, s0_p_q, s0_q_q;
    logic [FracBits-1:0] s0_fx_q, s0_fy_q;
    for (genvar r = 0; r < 2; r++) begin : gen_r
      for (genvar c = 0; c < 2; c++) begin : gen_c
        logic [AddrW-1:0] addr_q;
        logic [WordW-1:0] word;
        always_ff @(posedge clk_i) begin
          if (adv) addr_q <= {(q == 1'(c)) ? w0 : w1, (p == 1'(r)) ? slot0[SlotW-1:1] : slot1[SlotW-1:1]};
        end
        scw_ram_sdp #(
          .Width(WordW),
          .Depth(Depth)
        ) u_ram (
          .clk_i,
          .wr_en_i  (wr_do && (in_slot_q[0] == 1'(r)) && wr_col_en[c]),
          .wr_addr_i(wr_addr),
          .wr_data_i(wr_word[c*WordW +: WordW]),
          .rd_en_i  (adv),
          .rd_addr_i(addr_q),
          .rd_data_o(word)
        );
        assign rd_word[(r*2 + c)*WordW +: WordW] = word;
      end
    end

    // Which pixel of a column-parity word a tap takes (words hold Q pixels).
    logic [1:0] s0_sub_q, s1_sub_q;
    if (Q > 1) begin : gen_sub
      logic [1:0] sub;
      assign sub[0] = (q == 1'b0) ? x0[1] : x1[1];
      assign sub[1] = (q == 1'b1) ? x0[1] : x1[1];
      always_ff @(posedge clk_i) begin
        if (adv) s0_sub_q <= sub;
      end
    end else begin : gen_no_sub
      assign s0_sub_q = '0;
    end

    always_ff @(posedge clk_i) begin
      if (adv) begin
        s0_u00_q <= use0 && col0;
        s0_u10_q <= use0 && col1;
        s0_u01_q <= use1 && col0;
        s0_u11_q <= use1 && col1;
        s0_p_q   <= p;
        s0_q_q   <= q;
        s0_fx_q  <= fx;
        s0_fy_q  <= fy;
      end
    end

    // -- s1: RAM words in; pick the taps; horizontal blends -----------------------------------
    logic s1_u00_q, s1_u10_q, s1_u01_q, s1_u11_q, s1_p_q, s1_q_q;
    logic [FracBits-1:0] s1_fx_q, s1_fy_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s1_u00_q <= s0_u00_q && !s0_zero_q;
        s1_u10_q <= s0_u10_q && !s0_zero_q;
        s1_u01_q <= s0_u01_q && !s0_zero_q;
        s1_u11_q <= s0_u11_q && !s0_zero_q;
        s1_p_q   <= s0_p_q;
        s1_q_q   <= s0_q_q;
        s1_fx_q  <= s0_fx_q;
        s1_fy_q  <= s0_fy_q;
        s1_sub_q <= s0_sub_q;
      end
    end

    logic [PixW-1:0] f00, f10, f01, f11;
    logic [4*PixW-1:0] tap_px;  // the addressed pixel of RAM (r, c) at [(r*2 + c)*PixW]
    for (genvar r = 0; r < 2; r++) begin : gen_tr
      for (genvar c = 0; c < 2; c++) begin : gen_tc
        if (Q > 1) begin : gen_q
          assign tap_px[(r*2 + c)*PixW +: PixW] =
              rd_word[(r*2 + c)*WordW + s1_sub_q[c]*PixW +: PixW];
        end else begin : gen_1
          assign tap_px[(r*2 + c)*PixW +: PixW] = rd_word[(r*2 + c)*WordW +: WordW];
        end
      end
    end
    assign f00 = s1_u00_q ? tap_px[{s1_p_q, s1_q_q}*PixW +: PixW] : '0;
    assign f10 = s1_u10_q ? tap_px[{s1_p_q, !s1_q_q}*PixW +: PixW] : '0;
    assign f01 = s1_u01_q ? tap_px[{!s1_p_q, s1_q_q}*PixW +: PixW] : '0;
    assign f11 = s1_u11_q ? tap_px[{!s1_p_q, !s1_q_q}*PixW +: PixW] : '0;

    logic signed [AW-1:0] a_c, b_c, s2_a_q, s2_b_q;
    logic signed [PixW+1:0] d10, d11;
    logic signed [FracBits:0] fx_s;
    logic [FracBits-1:0] s2_fy_q;
    assign fx_s = $signed({1'b0, s1_fx_q});
    assign d10  = $signed({2'b00, f10}) - $signed({2'b00, f00});
    assign d11  = $signed({2'b00, f11}) - $signed({2'b00, f01});
    assign a_c  = $signed({{(AW - PixW - FracBits){1'b0}}, f00, {FracBits{1'b0}}}) + d10 * fx_s;
    assign b_c  = $signed({{(AW - PixW - FracBits){1'b0}}, f01, {FracBits{1'b0}}}) + d11 * fx_s;

    always_ff @(posedge clk_i) begin
      if (adv) begin
        s2_a_q  <= a_c;
        s2_b_q  <= b_c;
        s2_fy_q <= s1_fy_q;
      end
    end

    // -- s2: vertical blend, one rounding ------------------------------------------------------
    logic signed [VW-1:0] v_c;
    logic signed [FracBits:0] fy_s;
    assign fy_s = $signed({1'b0, s2_fy_q});
    assign v_c  = (VW'(s2_a_q) <<< FracBits) + (VW'(s2_b_q) - VW'(s2_a_q)) * fy_s + Half;
    assign out_pix[l*PixW +: PixW] = v_c[2*FracBits +: PixW];

    logic unused_lane;
    assign unused_lane = ^{x0[DW-1:1+QW+CwW], x0[QW:0], x1[DW-1:1+QW+CwW], x1[QW:0],
                           v_c[VW-1:2*FracBits+PixW], v_c[2*FracBits-1:0], dy[DW-1:SlotW],
                           slot1[0], s1_sub_q};
  end

endmodule
