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
// {column word, row slot / 2}: Rows is a power of two and nothing is wasted. Each RAM is
// built from banks of one RAMB18 (2048 x 9, 1024 x 18 or 512 x 36) by address, every bank's
// output goes straight into a register (block RAM clock-to-out is most of a clock) and the
// bank is chosen a clock later: no read mux sits behind a block RAM.
//
// Pipeline under one enable (adv = !out_valid || out_ready), Latency = 10:
//   s0 RAM addresses (two short adds from the map beat), taps' raw coordinates
//   s1 RAM read; compares of the taps against image and row window
//   s2 bank registers; the bank one-hot, zero for a tap that does not count; window error
//   s3 bank picked, pixel of the word picked, gated: one pixel per RAM
//   s4 taps by parity, d10 = f10 - f00, d11 = f11 - f01           (DSP A/B registers)
//   s5 products d fx, C = f S + S/2                                (DSP M/C registers)
//   s6 a' = f00 S + d10 fx + S/2, b' likewise                      (DSP P register)
//   s7 b' - a'                                                     (DSP A/B registers)
//   s8 product (b' - a') fy, C = a' S                              (DSP M/C registers)
//   s9 v = a S + (b - a) fy + S^2/2, output = v >> 2F              (DSP P register)
// S/2 rides in a' and b' for free (the low F bits of f S are zero) and cancels in b' - a', so
// a' S carries the S^2/2 of the one rounding: the arithmetic is the C++ model's exactly.
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
  // Words per RAM bank, a power of two; 0: one RAMB18 (the only reason to set it is a test
  // that runs the bank registers and the bank pick at a small size).
  parameter int unsigned BankWords  = 0,
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
  localparam int unsigned Latency     /*verilator public*/ = 10;
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
  // One bank = one RAMB18 at this word width (2048 x 9, 1024 x 18, 512 x 36).
  localparam int unsigned B18     = (BankWords != 0) ? BankWords :
                                    (WordW <= 9) ? 2048 : (WordW <= 18) ? 1024 : 512;
  localparam int unsigned BankD   = (Depth < B18) ? Depth : B18;
  localparam int unsigned BankAW  = $clog2(BankD);
  localparam int unsigned Banks   = (Depth + BankD - 1) / BankD;
  localparam int unsigned BankW   = (AddrW > BankAW) ? AddrW - BankAW : 1;

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_rectify: Ppc must be 1, 2 or 4");
  end
  if (MaxWidthPx % (4 * Ppc) != 0 || Rows < 4 || (Rows & (Rows - 1)) != 0) begin : gen_bad_geom
    $error("scw_rectify: need MaxWidthPx %% (4 Ppc) == 0 and Rows a power of two >= 4");
  end
  if ((BankWords & (BankWords - 1)) != 0) begin : gen_bad_bank
    $error("scw_rectify: BankWords must be 0 or a power of two");
  end

  // ---- configuration ---------------------------------------------------------------------
  // cfg_* are static: registered here (no reset, so they settle while rst_ni is low) together
  // with the values derived from them, which keeps them off every timing path.
  logic [HW-1:0] last_row1_q;    // H - 2
  logic [ColW-1:0] last_col1_q;  // the last beat of a row minus one
  logic one_col_q, one_row_q;    // rows of one beat, frames of one row
  logic [8*(AvW+2)-1:0] dlim_q;  // D + 3 - j at [j*(AvW+2) +: AvW+2], signed
  always_ff @(posedge clk_i) begin
    last_row1_q <= cfg_height_i - HW'(2);
    one_row_q   <= cfg_height_i == HW'(1);
    last_col1_q <= ColW'((cfg_width_i >> PpcLog) - WW'(2));
    one_col_q   <= (cfg_width_i >> PpcLog) == WW'(1);
    for (int j = 0; j < 8; j++) begin
      dlim_q[j*(AvW+2) +: AvW+2] <= (AvW + 2)'(cfg_lead_i) + (AvW + 2)'(3) - (AvW + 2)'(j);
    end
  end

  // ---- shared ----------------------------------------------------------------------------
  // The two sides' conditions are kept as registered flags, each next value a select between
  // compares of registers, so the handshake sees flags, not compares:
  //   wr_ok_q = avail + pending <= D + 1                   (the writer may go on)
  //   allowed = avail >= min(D, H - v) = ge_d_q || nz_q     (the reader may go on)
  // with ge_d_q = avail >= D and nz_q = fdiff != 0, fdiff = frames the writer finished minus
  // frames the reader finished: avail >= H - v says exactly that the writer has finished the
  // reader's frame. The counters take each event a clock late (inc_q, dec_q, up_q, dn_q), so
  // no adder follows the handshake; the flags add the event still in flight.
  logic adv, pending, pend_next, inc, dec, fe, wfe;
  logic out_valid_q;
  logic s0_valid_q, s0_eol_q;
  logic inc_q, dec_q, up_q, dn_q;
  logic [AvW-1:0] avail_q;  // avail = avail_q + inc_q - dec_q
  logic [AvW-1:0] fdiff_q;  // fdiff = fdiff_q + up_q - dn_q, <= D + 1 (one-row frames)
  logic wr_ok_q, ge_d_q, nz_q;
  // The compares of avail_q and fdiff_q are made a clock ahead, from the values before and the
  // events in flight, so a flag's next value is two selects from registers (le_q and fz_q
  // are reset to the compares of the counters' reset values).
  logic [7:0] le_w;         // le_w[j] = avail_q <= D + 3 - j
  logic [5:0] le_q;         // le_q[i] = avail_q <= D + 2 - i
  logic [3:0] le_a;         // le_q[a + j], a = 1 + inc_q - dec_q
  logic [4:0] eq_w;         // eq_w[m] = fdiff_q == m - 1
  logic [1:0] nb, nc;       // inc - dec + pend_next (0..2), 1 + inc - dec (0..2)
  logic [2:0] fz_q;         // fdiff_q == 0, 1, 2
  logic nz_p, nz_0, nz_m;   // fdiff' != 0 if this clock's up - dn is +1, 0, -1
  logic [2:0] err_q;

  assign adv       = !out_valid_q || out_ready_i;
  assign pending   = s0_valid_q && s0_eol_q;
  assign pend_next = dec || (!adv && pending);
  assign err_o     = err_q;

  for (genvar j = 0; j < 8; j++) begin : gen_le
    assign le_w[j] = $signed({2'b00, avail_q}) <= $signed(dlim_q[j*(AvW+2) +: AvW+2]);
  end
  for (genvar m = 0; m < 5; m++) begin : gen_eq
    assign eq_w[m] = fdiff_q == AvW'(m - 1);
  end
  // In reset they take the compares of the counters' reset values (avail 0: D + 2 - i >= 0,
  // the sign of dlim; fdiff 0), so a reset of a single clock leaves no stale compare behind.
  logic [5:0] le_rst;
  for (genvar i = 0; i < 6; i++) begin : gen_le_rst
    assign le_rst[i] = !dlim_q[(i+1)*(AvW+2) + AvW+1];
  end
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      le_q <= le_rst;
      fz_q <= 3'b001;
    end else begin
      // avail_q' = avail_q + a - 1: avail_q' <= D + 2 - i is le_w[i + a]
      le_q <= (inc_q == dec_q) ? le_w[6:1] : (inc_q ? le_w[7:2] : le_w[5:0]);
      // fdiff_q' = fdiff_q + g - 1, g = 1 + up_q - dn_q: fdiff_q' == k is eq_w[k + 2 - g]
      fz_q <= (up_q == dn_q) ? eq_w[3:1] : (up_q ? eq_w[2:0] : eq_w[4:2]);
    end
  end
  assign le_a = (inc_q == dec_q) ? le_q[4:1] : (inc_q ? le_q[5:2] : le_q[3:0]);
  assign nb   = dec ? {1'b0, inc} : {inc && pend_next, inc != pend_next};
  assign nc   = (inc == dec) ? 2'd1 : (inc ? 2'd2 : 2'd0);
  // fdiff' = fdiff_q + (up_q - dn_q) + (up - dn), and fdiff_q >= 0
  assign nz_p = !(dn_q && !up_q) || !fz_q[0];
  assign nz_0 = (up_q && !dn_q) || ((up_q == dn_q) ? !fz_q[0] : !fz_q[1]);
  assign nz_m = (up_q == dn_q) ? !fz_q[1] : (up_q ? !fz_q[0] : !fz_q[2]);

  // inc: a raw row finished (written or skipped), wfe: the raw frame's last; dec: an output
  // row's last beat taken, fe: the output frame's last row.
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      inc_q   <= 1'b0;
      dec_q   <= 1'b0;
      up_q    <= 1'b0;
      dn_q    <= 1'b0;
      avail_q <= '0;
      fdiff_q <= '0;
      wr_ok_q <= 1'b1;
      ge_d_q  <= 1'b0;
      nz_q    <= 1'b0;
    end else begin
      inc_q   <= inc;
      dec_q   <= dec;
      up_q    <= inc && wfe;
      dn_q    <= dec && fe;
      avail_q <= avail_q + AvW'(inc_q) - AvW'(dec_q);
      fdiff_q <= fdiff_q + AvW'(up_q) - AvW'(dn_q);
      // avail_q + (a - 1) + nb <= D + 1, i.e. le[a + nb]
      wr_ok_q <= le_a[nb];
      // avail_q + (a - 1) + (nc - 1) >= D, i.e. !le_q[a + nc + 1]
      ge_d_q  <= !le_a[nc + 2'd1];
      if ((inc && wfe) == (dec && fe)) nz_q <= nz_0;
      else if (inc && wfe) nz_q <= nz_p;
      else nz_q <= nz_m;
    end
  end

  // ---- writer ----------------------------------------------------------------------------
  logic [ColW-1:0] in_col_q;
  logic [HW-1:0] in_row_q;
  logic [SlotW-1:0] in_slot_q;
  logic skip_q, rheld_q, rheld_eol_q, in_last_q, in_fs_q, in_rlast_q;
  logic [BeatW-1:0] rheld_q_data;
  logic raw_fs, raw_take, wr_do, wr_eol, wr_last, row_done, skip_set, rheld_set, rheld_clr;
  logic err_raw;
  logic [BeatW-1:0] wr_data;

  // in_last_q: in_col is the row's last beat (beside one-beat rows); in_fs_q: a frame starts.
  assign raw_fs     = in_fs_q;
  assign in_ready_o = !skip_q && !rheld_q && wr_ok_q;
  assign raw_take   = in_valid_i && in_ready_o;
  assign wr_last    = in_last_q || one_col_q;
  assign inc        = row_done;
  assign wfe        = in_rlast_q || one_row_q;

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
    end else if (skip_q && wr_ok_q) begin
      row_done = 1'b1;
    end else if (rheld_q && wr_ok_q) begin
      wr_do     = 1'b1;
      wr_data   = rheld_q_data;
      wr_eol    = rheld_eol_q;
      rheld_clr = 1'b1;
    end
    if (wr_do && (wr_eol != wr_last)) err_raw = 1'b1;
    if (wr_do && wr_last) row_done = 1'b1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_col_q  <= '0;
      in_row_q  <= '0;
      in_slot_q <= '0;
      in_last_q <= 1'b0;
      in_fs_q   <= 1'b1;
      in_rlast_q <= 1'b0;
      skip_q    <= 1'b0;
      rheld_q   <= 1'b0;
    end else begin
      if (row_done) begin
        in_col_q  <= '0;
        in_last_q <= 1'b0;
        in_fs_q   <= wfe;
        in_slot_q <= in_slot_q + 1'b1;
        if (wfe) begin
          in_row_q   <= '0;
          in_rlast_q <= 1'b0;
          skip_q     <= 1'b0;
        end else begin
          in_row_q   <= in_row_q + 1'b1;
          in_rlast_q <= in_row_q == last_row1_q;
        end
      end else if (wr_do) begin
        in_col_q  <= in_col_q + 1'b1;
        in_last_q <= in_col_q == last_col1_q;
        in_fs_q   <= 1'b0;
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

  // A row slot is blank when its row was skipped by a cut frame (the rest of a row cut short
  // included), and after reset; a row written to its end clears it. Both at row_done, when the
  // row becomes the reader's: the reader's taps in a blank slot read 0, whatever the RAM holds
  // (after reset: its power-up contents). The event lands a clock late, like avail's (inc_q),
  // and blank_now already holds it, so the reader sees it as early as the model's reader does
  // and the handshake's logic does not fan out to the Rows bits.
  logic [Rows-1:0] blank_q, blank_now;
  logic ev_q, ev_blank_q;
  logic [SlotW-1:0] ev_slot_q;
  // The event's slot one-hot, a shift of a constant: an indexed write here is a 32-bit offset to
  // Yosys 0.23 (1.8 ns more), and a compare per slot is Rows statements a clock to Verilator.
  logic [Rows-1:0] ev_hot;
  assign ev_hot    = ev_q ? Rows'(1) << ev_slot_q : '0;
  assign blank_now = (blank_q & ~ev_hot) | (ev_hot & {Rows{ev_blank_q}});
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      blank_q <= '1;
      ev_q    <= 1'b0;
    end else begin
      blank_q <= blank_now;
      ev_q    <= row_done;
    end
  end
  always_ff @(posedge clk_i) begin
    ev_blank_q <= !wr_do;
    ev_slot_q  <= in_slot_q;
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

  // Writes land a clock late, from registers: the handshake (avail_q, in_valid_i) stays off
  // the RAMs' write enables. That is safe: a row counts as written (avail_q) at the edge its
  // last beat is taken, the write lands at the next edge, and a reader's first RAM read of
  // the row is an edge later still (accept, then read).
  logic [BankAW-1:0] wr_addr_q;  // within the bank
  logic [2*WordW-1:0] wr_word_q;
  logic [4*Banks-1:0] wr_en_q;  // RAM (r, c), bank b at (r*2 + c)*Banks + b
  logic [BankW-1:0] wr_bank;
  if (Banks > 1) begin : gen_wr_bank
    assign wr_bank = wr_addr[AddrW-1:BankAW];
  end else begin : gen_wr_bank1
    assign wr_bank = '0;
  end
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_en_q <= '0;
    end else begin
      for (int r = 0; r < 2; r++) begin
        for (int c = 0; c < 2; c++) begin
          for (int b = 0; b < Banks; b++) begin
            wr_en_q[(r*2 + c)*Banks + b] <= wr_do && (in_slot_q[0] == 1'(r)) && wr_col_en[c] &&
                                            (wr_bank == BankW'(b));
          end
        end
      end
    end
  end
  always_ff @(posedge clk_i) begin
    wr_addr_q <= wr_addr[BankAW-1:0];
    wr_word_q <= wr_word;
  end

  // ---- reader ----------------------------------------------------------------------------
  logic [ColW-1:0] out_col_q;
  logic [HW-1:0] out_row_q;
  logic [SlotW-1:0] out_slot_q;
  // The slot of the frame's row 0 (out_slot - out_row mod Rows) and that plus one: a tap's
  // slot is then one short add from its raw row y0, with no subtract of the output row.
  logic [SlotW-1:0] sbase_q, sbase1_q;
  logic fill_q, mheld_q, mheld_eol_q;
  logic [MapW-1:0] mheld_data_q;
  logic allowed, out_fs, out_last, map_take, go, emit, zero, mheld_set, mheld_clr;
  logic fill_set, err_map, md_eol;
  logic out_last_q, out_fs_q, out_rlast_q;  // out_rlast_q: v = H - 1 (beside H = 1)
  logic [MapW-1:0] md;

  assign allowed     = ge_d_q || nz_q;
  assign out_fs      = out_fs_q;
  assign out_last    = out_last_q || one_col_q;
  assign dec         = emit && out_last;
  assign fe          = out_rlast_q || one_row_q;
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

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      out_col_q  <= '0;
      out_row_q  <= '0;
      out_slot_q <= '0;
      out_last_q <= 1'b0;
      out_fs_q   <= 1'b1;
      out_rlast_q <= 1'b0;
      fill_q     <= 1'b0;
      mheld_q    <= 1'b0;
      err_q      <= '0;
      sbase_q    <= '0;
      sbase1_q   <= SlotW'(1);
    end else begin
      if (emit) begin
        if (out_last) begin
          out_col_q  <= '0;
          out_last_q <= 1'b0;
          out_fs_q   <= fe;
          out_slot_q <= out_slot_q + 1'b1;
          if (fe) begin
            out_row_q   <= '0;
            out_rlast_q <= 1'b0;
            fill_q      <= 1'b0;
            sbase_q     <= out_slot_q + SlotW'(1);
            sbase1_q    <= out_slot_q + SlotW'(2);
          end else begin
            out_row_q   <= out_row_q + 1'b1;
            out_rlast_q <= out_row_q == last_row1_q;
          end
        end else begin
          out_col_q  <= out_col_q + 1'b1;
          out_last_q <= out_col_q == last_col1_q;
          out_fs_q   <= 1'b0;
        end
      end
      if (fill_set) fill_q <= 1'b1;
      if (mheld_set) mheld_q <= 1'b1;
      else if (mheld_clr) mheld_q <= 1'b0;
      // The window check is flagged from stage 2, three cycles after its beat was taken.
      err_q <= err_q | {win_err, err_map, err_raw};
    end
  end

  always_ff @(posedge clk_i) begin
    if (mheld_set) begin
      mheld_data_q <= map_data_i;
      mheld_eol_q  <= map_eol_i;
    end
  end

  // ---- pipeline control ------------------------------------------------------------------
  // Bit k of each vector is stage k of the beat stream; stage Latency - 1 is the output.
  logic [Latency-1:0] vld_q, sof_q, eol_q;
  logic [Ppc-1:0] lane_winerr;  // per lane (stage 2), ORed into err_q
  logic s0_zero_q, s1_zero_q, win_err;
  logic [BeatW-1:0] out_pix;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      vld_q <= '0;
    end else if (adv) begin
      vld_q <= {vld_q[Latency-2:0], emit};
    end
  end

  always_ff @(posedge clk_i) begin
    if (adv) begin
      sof_q     <= {sof_q[Latency-2:0], out_fs};
      eol_q     <= {eol_q[Latency-2:0], out_last};
      s0_zero_q <= zero;
      s1_zero_q <= s0_zero_q;
    end
  end

  assign s0_valid_q  = vld_q[0];
  assign s0_eol_q    = eol_q[0];
  assign out_valid_q = vld_q[Latency-1];
  assign win_err     = vld_q[2] && (|lane_winerr);
  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_pix;
  assign out_sof_o   = sof_q[Latency-1];
  assign out_eol_o   = eol_q[Latency-1];

  // ---- lanes -----------------------------------------------------------------------------
  localparam int unsigned AW = PixW + FracBits + 2;  // signed horizontal blend, Q(8+F).0
  localparam int unsigned VW = AW + FracBits + 2;    // signed vertical blend before the shift
  localparam int unsigned XW = 1 + QW + CwW;         // the column bits the addresses use

  // Image and window bounds, all on the tap's raw row y0: row y0 is in the window when
  // v + lo <= y0 <= v + hi, row y0 + 1 when v + lo1 <= y0 <= v + hi1 (v the output row), so a
  // lane compares registered coordinates against registered bounds and subtracts nothing.
  logic signed [DW-1:0] width_s, width1_s, height_s, height1_s, lo_s, hi_s, lo1_s, hi1_s, row_s;
  logic signed [DW-1:0] s0_lo_q, s0_hi_q, s0_lo1_q, s0_hi1_q;
  always_ff @(posedge clk_i) begin
    width_s   <= $signed(DW'(cfg_width_i));
    width1_s  <= $signed(DW'(cfg_width_i)) - $signed(DW'(1));
    height_s  <= $signed(DW'(cfg_height_i));
    height1_s <= $signed(DW'(cfg_height_i)) - $signed(DW'(1));
    lo_s      <= $signed(DW'(cfg_lead_i)) - $signed(DW'(Rows)) + $signed(DW'(2));
    hi_s      <= $signed(DW'(cfg_lead_i)) - $signed(DW'(1));
    lo1_s     <= $signed(DW'(cfg_lead_i)) - $signed(DW'(Rows)) + $signed(DW'(1));
    hi1_s     <= $signed(DW'(cfg_lead_i)) - $signed(DW'(2));
  end
  assign row_s = $signed(DW'(out_row_q));
  always_ff @(posedge clk_i) begin
    if (adv) begin
      s0_lo_q  <= row_s + lo_s;
      s0_hi_q  <= row_s + hi_s;
      s0_lo1_q <= row_s + lo1_s;
      s0_hi1_q <= row_s + hi1_s;
    end
  end

  for (genvar l = 0; l < Ppc; l++) begin : gen_lane
    // -- s0: RAM addresses -----------------------------------------------------------------
    // Column parity c reads word (x0 + 1 - c) >> (1 + QW): the tap of that parity is x0 or
    // x0 + 1, whichever has parity c. Row parity r reads slot (slot0 + 1 - r) >> 1 likewise.
    // Taps outside the image or the window read some word and are zeroed at s3.
    logic signed [IntW-1:0] x0i, y0i;
    logic [FracBits-1:0] fx, fy;
    logic [XW-1:0] xp1;
    logic [SlotW-1:0] slot0, slot0p1;
    assign x0i     = $signed(md[l*2*CoordBits + FracBits +: IntW]);
    assign y0i     = $signed(md[l*2*CoordBits + CoordBits + FracBits +: IntW]);
    assign fx      = md[l*2*CoordBits +: FracBits];
    assign fy      = md[l*2*CoordBits + CoordBits +: FracBits];
    assign xp1     = XW'(x0i) + XW'(1);
    assign slot0   = sbase_q + SlotW'(y0i);
    assign slot0p1 = sbase1_q + SlotW'(y0i);

    logic signed [DW-1:0] s0_x0_q, s0_y0_q;
    logic [FracBits-1:0] s0_fx_q, s0_fy_q;
    logic s0_p_q, s0_q_q;
    // The blank bits as the reader finds them now, and the two slots: picked at s1, so the
    // slot's add and the Rows-to-1 select are not one path.
    logic [Rows-1:0] s0_blank_q;
    logic [SlotW-1:0] s0_slot0_q, s0_slot1_q;
    logic [1:0] s0_sub_q;  // which pixel of its word column parity c's tap is (Q > 1)
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s0_blank_q <= blank_now;
        s0_slot0_q <= slot0;
        s0_slot1_q <= slot0p1;
        s0_x0_q  <= DW'(x0i);
        s0_y0_q  <= DW'(y0i);
        s0_fx_q  <= fx;
        s0_fy_q  <= fy;
        s0_p_q   <= slot0[0];
        s0_q_q   <= x0i[0];
        s0_sub_q <= {x0i[1], xp1[1]};
      end
    end

    // -- s1: RAM read; taps against image and window ------------------------------------------
    logic s1_col0_q, s1_col1_q, s1_in0_q, s1_in1_q, s1_win0_q, s1_win1_q, s1_p_q, s1_q_q;
    logic s1_blank0_q, s1_blank1_q;
    logic [FracBits-1:0] s1_fx_q, s1_fy_q;
    logic [1:0] s1_sub_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s1_col0_q <= (s0_x0_q >= 0) && (s0_x0_q < width_s);
        s1_col1_q <= (s0_fx_q != '0) && (s0_x0_q >= -1) && (s0_x0_q < width1_s);
        s1_in0_q  <= (s0_y0_q >= 0) && (s0_y0_q < height_s);
        s1_in1_q  <= (s0_fy_q != '0) && (s0_y0_q >= -1) && (s0_y0_q < height1_s);
        s1_win0_q <= (s0_y0_q >= s0_lo_q) && (s0_y0_q <= s0_hi_q);
        s1_win1_q <= (s0_y0_q >= s0_lo1_q) && (s0_y0_q <= s0_hi1_q);
        s1_p_q    <= s0_p_q;
        s1_q_q    <= s0_q_q;
        s1_blank0_q <= s0_blank_q[s0_slot0_q];
        s1_blank1_q <= s0_blank_q[s0_slot1_q];
        s1_fx_q   <= s0_fx_q;
        s1_fy_q   <= s0_fy_q;
        s1_sub_q  <= s0_sub_q;
      end
    end

    // -- s2: bank registers; which taps contribute ------------------------------------------
    // A row is needed when it holds a contributing tap (map_taps.hpp); a needed row outside
    // the window reads 0 and flags err_o[2]. Tap (row offset o, column offset k) sits in RAM
    // (p ^ o, q ^ k), so the enables are permuted to RAM order here.
    logic any_col, row0, row1, use0, use1, live0, live1;
    logic [3:0] u;  // tap enables, index o * 2 + k
    logic s2_p_q, s2_q_q;
    logic [FracBits-1:0] s2_fx_q, s2_fy_q;
    logic [1:0] s2_sub_q;
    assign any_col = s1_col0_q || s1_col1_q;
    assign row0    = any_col && s1_in0_q;
    assign row1    = any_col && s1_in1_q;
    assign use0    = row0 && s1_win0_q && !s1_zero_q;
    assign use1    = row1 && s1_win1_q && !s1_zero_q;
    assign live0   = use0 && !s1_blank0_q;  // a blank slot's taps read 0 (blank_q)
    assign live1   = use1 && !s1_blank1_q;
    assign u       = {live1 && s1_col1_q, live1 && s1_col0_q, live0 && s1_col1_q,
                      live0 && s1_col0_q};
    logic s2_winerr_q;
    assign lane_winerr[l] = s2_winerr_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s2_winerr_q <= !s1_zero_q && ((row0 && !s1_win0_q) || (row1 && !s1_win1_q));
        s2_p_q   <= s1_p_q;
        s2_q_q   <= s1_q_q;
        s2_fx_q  <= s1_fx_q;
        s2_fy_q  <= s1_fy_q;
        s2_sub_q <= s1_sub_q;
      end
    end

    // -- RAMs (r, c) at index r * 2 + c; s3: bank and pixel picked, gated ------------------------
    // The bank is kept one-hot from s2 on, and all-zero when the RAM's tap does not contribute,
    // so the pick is an AND-OR of registers and the gating comes free.
    logic [4*PixW-1:0] s3_px;  // s3 registers, one per RAM
    for (genvar r = 0; r < 2; r++) begin : gen_r
      for (genvar c = 0; c < 2; c++) begin : gen_c
        logic [AddrW-1:0] addr_q;
        logic [BankW-1:0] bank1_q;
        logic [Banks-1:0] bank2_q;  // one-hot, zero for a tap that does not contribute
        logic [Banks*WordW-1:0] bword_q;  // s2: every bank's word
        logic [WordW-1:0] picked;
        logic en;
        assign en = u[{1'(r) ^ s1_p_q, 1'(c) ^ s1_q_q}];
        always_ff @(posedge clk_i) begin
          if (adv) begin
            addr_q <= {(c == 0) ? xp1[1+QW +: CwW] : x0i[1+QW +: CwW],
                       (r == 0) ? slot0p1[SlotW-1:1] : slot0[SlotW-1:1]};
          end
        end
        if (Banks > 1) begin : gen_bank_sel
          always_ff @(posedge clk_i) begin
            if (adv) bank1_q <= addr_q[AddrW-1:BankAW];
          end
        end else begin : gen_bank_one
          assign bank1_q = '0;
        end
        always_ff @(posedge clk_i) begin
          if (adv) begin
            // A shift of a constant, not a compare per bank: one statement to Verilator.
            bank2_q <= en ? Banks'(1) << bank1_q : '0;
          end
        end
        for (genvar b = 0; b < Banks; b++) begin : gen_bank
          localparam int unsigned BD  = (Depth - b * BankD < BankD) ? Depth - b * BankD : BankD;
          localparam int unsigned BAW = (BD > 1) ? $clog2(BD) : 1;
          logic [WordW-1:0] word;
          scw_ram_sdp #(
            .Width(WordW),
            .Depth(BD)
          ) u_ram (
            .clk_i,
            .wr_en_i  (wr_en_q[(r*2 + c)*Banks + b]),
            .wr_addr_i(wr_addr_q[BAW-1:0]),
            .wr_data_i(wr_word_q[c*WordW +: WordW]),
            .rd_en_i  (adv),
            .rd_addr_i(addr_q[BAW-1:0]),
            .rd_data_o(word)
          );
          always_ff @(posedge clk_i) begin
            if (adv) bword_q[b*WordW +: WordW] <= word;
          end
        end
        always_comb begin
          picked = '0;
          for (int b = 0; b < Banks; b++) begin
            picked = picked | (bword_q[b*WordW +: WordW] & {WordW{bank2_q[b]}});
          end
        end
        logic [PixW-1:0] pix, px_q;
        if (Q > 1) begin : gen_sub
          assign pix = picked[s2_sub_q[c]*PixW +: PixW];
        end else begin : gen_one
          assign pix = picked;
        end
        always_ff @(posedge clk_i) begin
          if (adv) px_q <= pix;
        end
        assign s3_px[(r*2 + c)*PixW +: PixW] = px_q;
        logic unused_ram;
        assign unused_ram = ^{addr_q, picked, bank1_q};
      end
    end

    logic s3_p_q, s3_q_q;
    logic [FracBits-1:0] s3_fx_q, s3_fy_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s3_p_q  <= s2_p_q;
        s3_q_q  <= s2_q_q;
        s3_fx_q <= s2_fx_q;
        s3_fy_q <= s2_fy_q;
      end
    end

    // -- s4: taps by parity, horizontal differences ------------------------------------------
    logic [PixW-1:0] f00, f10, f01, f11, s4_f00_q, s4_f01_q;
    logic signed [PixW:0] s4_d10_q, s4_d11_q;
    logic signed [FracBits:0] s4_fx_q;
    logic [FracBits-1:0] s4_fy_q;
    assign f00 = s3_px[{s3_p_q, s3_q_q}*PixW +: PixW];
    assign f10 = s3_px[{s3_p_q, !s3_q_q}*PixW +: PixW];
    assign f01 = s3_px[{!s3_p_q, s3_q_q}*PixW +: PixW];
    assign f11 = s3_px[{!s3_p_q, !s3_q_q}*PixW +: PixW];
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s4_d10_q <= $signed({1'b0, f10}) - $signed({1'b0, f00});
        s4_d11_q <= $signed({1'b0, f11}) - $signed({1'b0, f01});
        s4_f00_q <= f00;
        s4_f01_q <= f01;
        s4_fx_q  <= $signed({1'b0, s3_fx_q});
        s4_fy_q  <= s3_fy_q;
      end
    end

    // -- s5, s6: horizontal blends a' = f00 S + d10 fx + S/2, b' likewise (one DSP each) --------
    logic signed [AW-1:0] s5_ma_q, s5_mb_q, s5_ca_q, s5_cb_q, s6_a_q, s6_b_q;
    logic [FracBits-1:0] s5_fy_q, s6_fy_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s5_ma_q <= AW'(s4_d10_q * s4_fx_q);
        s5_mb_q <= AW'(s4_d11_q * s4_fx_q);
        s5_ca_q <= $signed(AW'({s4_f00_q, 1'b1, {(FracBits - 1){1'b0}}}));
        s5_cb_q <= $signed(AW'({s4_f01_q, 1'b1, {(FracBits - 1){1'b0}}}));
        s5_fy_q <= s4_fy_q;
        s6_a_q  <= s5_ma_q + s5_ca_q;
        s6_b_q  <= s5_mb_q + s5_cb_q;
        s6_fy_q <= s5_fy_q;
      end
    end

    // -- s7..s9: vertical blend v = a' S + (b' - a') fy (one DSP); the output is v >> 2F -------
    logic signed [AW:0] s7_d_q;
    logic signed [AW-1:0] s7_a_q;
    logic signed [FracBits:0] s7_fy_q;
    logic signed [VW-1:0] s8_m_q, s8_c_q, s9_v_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        s7_d_q  <= (AW + 1)'(s6_b_q) - (AW + 1)'(s6_a_q);
        s7_a_q  <= s6_a_q;
        s7_fy_q <= $signed({1'b0, s6_fy_q});
        s8_m_q  <= VW'(s7_d_q * s7_fy_q);
        s8_c_q  <= VW'(s7_a_q) <<< FracBits;
        s9_v_q  <= s8_m_q + s8_c_q;
      end
    end
    assign out_pix[l*PixW +: PixW] = s9_v_q[2*FracBits +: PixW];

    logic unused_lane;
    assign unused_lane = ^{s9_v_q[VW-1:2*FracBits+PixW], s9_v_q[2*FracBits-1:0], x0i[IntW-1:XW],
                           xp1[0], slot0p1[0], s2_sub_q};
  end

endmodule
