// SPDX-License-Identifier: Apache-2.0
// Disparity front: N x N SADs of every candidate and the texture sum, from incremental sums.
`default_nettype none

// The datapath of DisparityCore::step (hls/disparity/disparity.hpp), a free-running pipeline:
// a beat on valid_i at cycle t leaves on valid_o at t + Latency, in order, never stalled (the
// parent only feeds beats it has room for). Per candidate d and column x the column sum
// C_d(x) = sum of |L - R(x - dmin - d)| over the window's rows is kept in a RAM and updated
// with the new row's difference minus the leaving row's; the window sum is the running
// S_d(x) = S_d(x - 1) + C_d(x) - C_d(x - N), with C_d(x - N) from a shift register of column
// sums. So a beat costs 2 P NumDisp absolute differences whatever N is.
//
//   c0  write the row into the left/right line buffers (N + 1 rows) and a one-row right delay;
//       read the leaving row's left word, the right words dmin pixels back
//   c1  align the right pixels by dmin % Ppc, shift them into the candidate window,
//       |L - R| for the new and the leaving row, read the column sums
//   c2  C = C + new - leaving (the first row restarts it; right pixels left of 0 give 0)
//   c3  write C back, window sums along the row -> output registers
// The column-sum RAM is read in c1 and written in c3 of the same beat, so the next row's read
// of that column must come at least 3 beats later: frames are at least 3 beats wide.
module scw_disparity_sums #(
  parameter int unsigned Ppc        /*verilator public*/ = 1,
  parameter int unsigned MaxWidthPx /*verilator public*/ = 32,
  parameter int unsigned MaxHeight  /*verilator public*/ = 16,
  parameter int unsigned Window     /*verilator public*/ = 3,
  parameter int unsigned NumDisp    /*verilator public*/ = 4,
  parameter int unsigned TagBits    = 1,
  localparam int unsigned PixW    = scw_pkg::PixelBits,
  localparam int unsigned BeatW   = Ppc * PixW,
  localparam int unsigned Cols    = MaxWidthPx / Ppc,
  localparam int unsigned ColW    = (Cols > 1) ? $clog2(Cols) : 1,
  localparam int unsigned WW      = $clog2(MaxWidthPx + 1),
  localparam int unsigned HW      = $clog2(MaxHeight + 1),
  localparam int unsigned Slots   = Window + 1,
  localparam int unsigned SlotW   = $clog2(Slots),
  localparam int unsigned ColBits = $clog2(Window * 255 + 1),
  localparam int unsigned SadBits = $clog2(Window * Window * 255 + 1)
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  // static configuration (registered by the parent)
  input  logic [WW-1:0]                   cfg_dmin_i,
  input  logic [5:0]                      cfg_cap_i,
  // one beat pair at word col_i of row row_i, kept in line-buffer slot slot_i = row % (N + 1)
  input  logic                            valid_i,
  input  logic [ColW-1:0]                 col_i,
  input  logic [HW-1:0]                   row_i,
  input  logic [SlotW-1:0]                slot_i,
  input  logic [BeatW-1:0]                left_i,
  input  logic [BeatW-1:0]                right_i,
  input  logic [TagBits-1:0]              tag_i,
  // lane i, candidate d at [(i * NumDisp + d) * SadBits +: SadBits]; texture lane i likewise
  output logic                            valid_o,
  output logic [Ppc*NumDisp*SadBits-1:0]  sad_o,
  output logic [Ppc*SadBits-1:0]          texture_o,
  output logic [TagBits-1:0]              tag_o
);
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency /*verilator public*/ = 4;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned LbDepth = Slots * Cols;
  localparam int unsigned LbAW    = $clog2(LbDepth);
  localparam int unsigned PpcLog  = (Ppc > 1) ? $clog2(Ppc) : 1;
  localparam int unsigned HistPx  = NumDisp - 1;     // right pixels kept from earlier beats
  localparam int unsigned WinPx   = NumDisp + Ppc - 1;  // candidate window of a beat
  localparam int unsigned CW      = Ppc * NumDisp * ColBits;  // column sums of one beat
  localparam int unsigned Back    = (Window + Ppc - 1) / Ppc;  // beats kept for C(x - N)
  localparam int unsigned XW      = WW + 2;           // signed column arithmetic

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_disparity_sums: Ppc must be 1, 2 or 4");
  end
  if (Window % 2 != 1 || Window < 3 || NumDisp < 2 || MaxWidthPx % Ppc != 0) begin : gen_bad
    $error("scw_disparity_sums: need an odd Window >= 3, NumDisp >= 2, MaxWidthPx %% Ppc == 0");
  end

  // ---- configuration ---------------------------------------------------------------------
  // dmin = k Ppc + s: the right words are read k words back and realigned by s lanes.
  logic [ColW-1:0] back_words_q;
  logic [PpcLog-1:0] shift_q;
  logic [5:0] cap_q;
  logic signed [XW-1:0] dmin_q;
  always_ff @(posedge clk_i) begin
    back_words_q <= ColW'(cfg_dmin_i >> $clog2(Ppc));
    shift_q      <= PpcLog'(cfg_dmin_i & WW'(Ppc - 1));
    cap_q        <= cfg_cap_i;
    dmin_q       <= XW'(cfg_dmin_i);
  end

  // ---- c0: line buffers ------------------------------------------------------------------
  logic [SlotW-1:0] old_slot;
  logic [ColW-1:0] col_back;
  logic [LbAW-1:0] wr_addr, old_addr, old_back_addr;
  assign old_slot      = (slot_i == SlotW'(Window)) ? '0 : slot_i + 1'b1;  // row y - N
  assign col_back      = (col_i >= back_words_q) ? col_i - back_words_q : '0;  // masked anyway
  assign wr_addr       = LbAW'(slot_i) * LbAW'(Cols) + LbAW'(col_i);
  assign old_addr      = LbAW'(old_slot) * LbAW'(Cols) + LbAW'(col_i);
  assign old_back_addr = LbAW'(old_slot) * LbAW'(Cols) + LbAW'(col_back);

  logic [BeatW-1:0] lold_rd, rold_rd, rdel_rd;
  scw_ram_sdp #(.Width(BeatW), .Depth(LbDepth)) u_left_rows (
    .clk_i, .wr_en_i(valid_i), .wr_addr_i(wr_addr), .wr_data_i(left_i),
    .rd_en_i(valid_i), .rd_addr_i(old_addr), .rd_data_o(lold_rd)
  );
  scw_ram_sdp #(.Width(BeatW), .Depth(LbDepth)) u_right_rows (
    .clk_i, .wr_en_i(valid_i), .wr_addr_i(wr_addr), .wr_data_i(right_i),
    .rd_en_i(valid_i), .rd_addr_i(old_back_addr), .rd_data_o(rold_rd)
  );
  // The new row's right pixels dmin back: written k >= 1 beats ago (k = 0 bypasses it).
  scw_ram_sdp #(.Width(BeatW), .Depth(Cols)) u_right_delay (
    .clk_i, .wr_en_i(valid_i), .wr_addr_i(col_i), .wr_data_i(right_i),
    .rd_en_i(valid_i), .rd_addr_i(col_back), .rd_data_o(rdel_rd)
  );

  logic v1_q, v2_q, v3_q, v4_q;
  logic [ColW-1:0] col1_q, col2_q, col3_q;
  logic [HW-1:0] row1_q, row2_q;
  logic [BeatW-1:0] left1_q, right1_q;
  logic [TagBits-1:0] tag1_q, tag2_q, tag3_q, tag4_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      v1_q <= 1'b0;
      v2_q <= 1'b0;
      v3_q <= 1'b0;
      v4_q <= 1'b0;
    end else begin
      v1_q <= valid_i;
      v2_q <= v1_q;
      v3_q <= v2_q;
      v4_q <= v3_q;
    end
  end

  always_ff @(posedge clk_i) begin
    col1_q   <= col_i;
    row1_q   <= row_i;
    left1_q  <= left_i;
    right1_q <= right_i;
    tag1_q   <= tag_i;
    col2_q   <= col1_q;
    row2_q   <= row1_q;
    tag2_q   <= tag1_q;
    col3_q   <= col2_q;
    tag3_q   <= tag2_q;
    tag4_q   <= tag3_q;
  end

  // ---- c1: candidate windows and absolute differences -------------------------------------
  logic [BeatW-1:0] rnew_w, rnew_prev_q, rold_prev_q;
  logic [BeatW-1:0] rnew_al, rold_al;  // R(x0 + i - dmin) of the new and the leaving row
  logic [HistPx*PixW-1:0] hnew_q, hold_q;
  logic [WinPx*PixW-1:0] wnew, wold;  // [m]: R(x0 + Ppc - 1 - dmin - m)
  assign rnew_w = (back_words_q == '0) ? right1_q : rdel_rd;

  for (genvar i = 0; i < Ppc; i++) begin : gen_align
    logic [2*BeatW-1:0] pair_new, pair_old;  // {this word, previous word}
    assign pair_new = {rnew_w, rnew_prev_q};
    assign pair_old = {rold_rd, rold_prev_q};
    assign rnew_al[i*PixW +: PixW] = pair_new[(Ppc + i - 32'(shift_q))*PixW +: PixW];
    assign rold_al[i*PixW +: PixW] = pair_old[(Ppc + i - 32'(shift_q))*PixW +: PixW];
    assign wnew[(Ppc - 1 - i)*PixW +: PixW] = rnew_al[i*PixW +: PixW];
    assign wold[(Ppc - 1 - i)*PixW +: PixW] = rold_al[i*PixW +: PixW];
  end
  assign wnew[WinPx*PixW-1:Ppc*PixW] = hnew_q;
  assign wold[WinPx*PixW-1:Ppc*PixW] = hold_q;

  always_ff @(posedge clk_i) begin
    if (v1_q) begin
      rnew_prev_q <= rnew_w;
      rold_prev_q <= rold_rd;
      hnew_q      <= wnew[HistPx*PixW-1:0];
      hold_q      <= wold[HistPx*PixW-1:0];
    end
  end

  logic [Ppc*NumDisp*PixW-1:0] dnew_d, dold_d, dnew_q, dold_q;
  logic [Ppc*NumDisp-1:0] mask_d, mask_q;  // the right pixel is left of column 0
  logic [Ppc*PixW-1:0] tnew_d, told_d, tnew_q, told_q;
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_c1
    logic [PixW-1:0] l_new, l_old;
    logic signed [XW-1:0] first_d;  // x - dmin: candidate d reads column x - dmin - d
    assign l_new   = left1_q[i*PixW +: PixW];
    assign l_old   = lold_rd[i*PixW +: PixW];
    assign first_d = signed'(XW'(col1_q) * XW'(Ppc) + XW'(i)) - dmin_q;
    assign tnew_d[i*PixW +: PixW] = (l_new > PixW'(cap_q)) ? l_new - PixW'(cap_q)
                                                           : PixW'(cap_q) - l_new;
    assign told_d[i*PixW +: PixW] = (l_old > PixW'(cap_q)) ? l_old - PixW'(cap_q)
                                                           : PixW'(cap_q) - l_old;
    for (genvar d = 0; d < NumDisp; d++) begin : gen_cand
      logic [PixW-1:0] r_new, r_old;
      assign r_new = wnew[(Ppc - 1 - i + d)*PixW +: PixW];
      assign r_old = wold[(Ppc - 1 - i + d)*PixW +: PixW];
      assign dnew_d[(i*NumDisp + d)*PixW +: PixW] = (l_new > r_new) ? l_new - r_new
                                                                    : r_new - l_new;
      assign dold_d[(i*NumDisp + d)*PixW +: PixW] = (l_old > r_old) ? l_old - r_old
                                                                    : r_old - l_old;
      assign mask_d[i*NumDisp + d] = first_d < XW'(d);
    end
  end

  always_ff @(posedge clk_i) begin
    dnew_q <= dnew_d;
    dold_q <= dold_d;
    mask_q <= mask_d;
    tnew_q <= tnew_d;
    told_q <= told_d;
  end

  // ---- c1 -> c2: column-sum RAMs (read in c1, written back in c3) ---------------------------
  logic [CW-1:0] csum_rd, csum_d, csum_q;
  logic [Ppc*ColBits-1:0] tsum_rd, tsum_d, tsum_q;
  scw_ram_sdp #(.Width(CW), .Depth(Cols)) u_col_sums (
    .clk_i, .wr_en_i(v3_q), .wr_addr_i(col3_q), .wr_data_i(csum_q),
    .rd_en_i(v1_q), .rd_addr_i(col1_q), .rd_data_o(csum_rd)
  );
  scw_ram_sdp #(.Width(Ppc * ColBits), .Depth(Cols)) u_texture_sums (
    .clk_i, .wr_en_i(v3_q), .wr_addr_i(col3_q), .wr_data_i(tsum_q),
    .rd_en_i(v1_q), .rd_addr_i(col1_q), .rd_data_o(tsum_rd)
  );

  // ---- c2: column sums ---------------------------------------------------------------------
  logic first_row, full;
  assign first_row = row2_q == '0;
  assign full      = row2_q >= HW'(Window);  // the leaving row y - N exists
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_c2
    for (genvar d = 0; d < NumDisp; d++) begin : gen_cand
      localparam int unsigned J = i * NumDisp + d;
      logic [ColBits-1:0] kept;
      assign kept = first_row ? '0 : csum_rd[J*ColBits +: ColBits];
      assign csum_d[J*ColBits +: ColBits] =
          mask_q[J] ? '0
                    : kept + ColBits'(dnew_q[J*PixW +: PixW])
                      - (full ? ColBits'(dold_q[J*PixW +: PixW]) : '0);
    end
    logic [ColBits-1:0] tkept;
    assign tkept = first_row ? '0 : tsum_rd[i*ColBits +: ColBits];
    assign tsum_d[i*ColBits +: ColBits] = tkept + ColBits'(tnew_q[i*PixW +: PixW])
                                          - (full ? ColBits'(told_q[i*PixW +: PixW]) : '0);
  end

  always_ff @(posedge clk_i) begin
    csum_q <= csum_d;
    tsum_q <= tsum_d;
  end

  // ---- c3: window sums along the row -------------------------------------------------------
  // back_q holds the column sums of the last Back beats, newest first: C(x - N) of lane i is
  // lane (i - N) mod Ppc of the beat ceil((N - i) / Ppc) back. Lanes before column N leave 0.
  // Whole beats are shifted (SRL-friendly); only the lanes that leave a window are tapped.
  /* verilator lint_off UNUSEDSIGNAL */
  logic [Back*CW-1:0] back_q;
  logic [Back*Ppc*ColBits-1:0] tback_q;
  /* verilator lint_on UNUSEDSIGNAL */
  if (Back == 1) begin : gen_back1
    always_ff @(posedge clk_i) begin
      if (v3_q) begin
        back_q  <= csum_q;
        tback_q <= tsum_q;
      end
    end
  end else begin : gen_back
    always_ff @(posedge clk_i) begin
      if (v3_q) begin
        back_q  <= {back_q[(Back-1)*CW-1:0], csum_q};
        tback_q <= {tback_q[(Back-1)*Ppc*ColBits-1:0], tsum_q};
      end
    end
  end

  logic [NumDisp*SadBits-1:0] run_q;  // S_d of the last pixel of the previous beat
  logic [SadBits-1:0] trun_q;
  // Lane i continues lane i - 1's sums: split_var keeps Verilator from seeing a loop.
  logic [Ppc*NumDisp*SadBits-1:0] sad_d /*verilator split_var*/;
  logic [Ppc*SadBits-1:0] tex_d /*verilator split_var*/;
  logic [WW-1:0] x3;
  assign x3 = WW'(col3_q) * WW'(Ppc);

  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_c3
    localparam int unsigned BackBeats = (Window - i + Ppc - 1) / Ppc;
    localparam int unsigned BackLane  = BackBeats * Ppc + i - Window;
    logic leaves;  // x >= N
    assign leaves = (x3 + WW'(i)) >= WW'(Window);
    for (genvar d = 0; d < NumDisp; d++) begin : gen_cand
      localparam int unsigned J  = i * NumDisp + d;
      localparam int unsigned JB = (BackBeats - 1) * CW + (BackLane * NumDisp + d) * ColBits;
      logic [SadBits-1:0] prev, gone;
      if (i == 0) begin : gen_first
        assign prev = (col3_q == '0) ? '0 : run_q[d*SadBits +: SadBits];
      end else begin : gen_next
        assign prev = sad_d[((i - 1)*NumDisp + d)*SadBits +: SadBits];
      end
      assign gone = leaves ? SadBits'(back_q[JB +: ColBits]) : '0;
      assign sad_d[J*SadBits +: SadBits] = prev + SadBits'(csum_q[J*ColBits +: ColBits]) - gone;
    end
    localparam int unsigned TB = (BackBeats - 1) * Ppc * ColBits + BackLane * ColBits;
    logic [SadBits-1:0] tprev, tgone;
    if (i == 0) begin : gen_tfirst
      assign tprev = (col3_q == '0) ? '0 : trun_q;
    end else begin : gen_tnext
      assign tprev = tex_d[(i - 1)*SadBits +: SadBits];
    end
    assign tgone = leaves ? SadBits'(tback_q[TB +: ColBits]) : '0;
    assign tex_d[i*SadBits +: SadBits] = tprev + SadBits'(tsum_q[i*ColBits +: ColBits]) - tgone;
  end

  always_ff @(posedge clk_i) begin
    if (v3_q) begin
      run_q  <= sad_d[(Ppc-1)*NumDisp*SadBits +: NumDisp*SadBits];
      trun_q <= tex_d[(Ppc-1)*SadBits +: SadBits];
    end
    sad_o     <= sad_d;
    texture_o <= tex_d;
  end

  assign valid_o = v4_q;
  assign tag_o   = tag4_q;
endmodule
