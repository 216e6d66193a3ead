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
//   c1  the line buffers' output registers
//   c2  align the right pixels by dmin % Ppc, shift them into the candidate window; read the
//       column sums
//   c3  |L - R| for the new and the leaving row; the column-sum RAM's output register
//   c4  C = C + new - leaving (the first row restarts it; right pixels left of 0 give 0),
//       written back
//   c5  D = C(x) - C(x - N) per lane (0 for x < N)
//   p1 .. pK  prefix sums of D across the beat's lanes, K = log2(Ppc) (a Sklansky tree)
//   s   S(lane i) = S(last lane of the previous beat, 0 at a row's start) + prefix(i) -> out
// Every block-RAM read has its output register and every add its own clock (the sums are
// modulo 2^SadBits, exact because every true window sum fits). The column-sum RAM is read in
// c2 and written in c4 of the same beat, so the next row's read of that column must come at
// least 3 beats later: frames are at least 3 beats wide.
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
  localparam int unsigned LbAW    = $clog2(Slots * Cols),
  localparam int unsigned ColBits = $clog2(Window * 255 + 1),
  localparam int unsigned SadBits = $clog2(Window * Window * 255 + 1)
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  // static configuration (registered by the parent)
  input  logic [WW-1:0]                   cfg_dmin_i,
  input  logic [5:0]                      cfg_cap_i,
  // one beat pair at word col_i of row row_i, kept in line-buffer slot s = row % (N + 1):
  // base_i = s * Cols, old_base_i = ((s + 1) % (N + 1)) * Cols (row y - N), the line buffers'
  // row addresses, formed by the parent where the slot changes (once a row), so that the
  // read address is one add behind a register rather than a slot increment, a multiply by
  // Cols and an add (the stage's worst path at P = 4)
  input  logic                            valid_i,
  input  logic [ColW-1:0]                 col_i,
  input  logic [HW-1:0]                   row_i,
  input  logic [LbAW-1:0]                 base_i,
  input  logic [LbAW-1:0]                 old_base_i,
  input  logic [BeatW-1:0]                left_i,
  input  logic [BeatW-1:0]                right_i,
  input  logic [TagBits-1:0]              tag_i,
  // lane i, candidate d at [(i * NumDisp + d) * SadBits +: SadBits]; texture lane i likewise
  output logic                            valid_o,
  output logic [Ppc*NumDisp*SadBits-1:0]  sad_o,
  output logic [Ppc*SadBits-1:0]          texture_o,
  output logic [TagBits-1:0]              tag_o,
  // the tag one stage before tag_o and the enable that moves it there: a parent forms a
  // register from it that is loaded together with tag_o (decode ahead of the output)
  output logic [TagBits-1:0]              tag_pre_o,
  output logic                            tag_pre_en_o
);
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned PreStages = (Ppc > 1) ? $clog2(Ppc) : 0;
  localparam int unsigned Latency /*verilator public*/ = 7 + PreStages;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned LbDepth = Slots * Cols;
  localparam int unsigned LbSlice = (LbAW >= 15) ? 1 : (32768 >> LbAW);  // bits a slice
  localparam int unsigned PpcLog  = (Ppc > 1) ? $clog2(Ppc) : 1;
  localparam int unsigned HistPx  = NumDisp - 1;     // right pixels kept from earlier beats
  localparam int unsigned WinPx   = NumDisp + Ppc - 1;  // candidate window of a beat
  localparam int unsigned CW      = Ppc * NumDisp * ColBits;  // column sums of one beat
  localparam int unsigned XW      = WW + 2;           // signed column arithmetic

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_disparity_sums: Ppc must be 1, 2 or 4");
  end
  if (Window % 2 != 1 || Window < 3 || Window < Ppc || NumDisp < 2 || MaxWidthPx % Ppc != 0)
  begin : gen_bad
    $error("scw_disparity_sums: need an odd Window >= 3, >= Ppc, NumDisp >= 2, Ppc | MaxWidthPx");
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
  logic [ColW-1:0] col_back;
  logic [LbAW-1:0] wr_addr, old_addr, old_back_addr;
  // Left of column 0 it wraps to some other word: those pixels are masked, whatever they are.
  assign col_back      = col_i - back_words_q;
  assign wr_addr       = base_i + LbAW'(col_i);
  assign old_addr      = old_base_i + LbAW'(col_i);
  assign old_back_addr = old_base_i + LbAW'(col_back);

  logic [BeatW-1:0] lold_rd, rold_rd, rdel_rd;
  // The line buffers are cut into bit slices of LbSlice bits, each as deep as a block RAM of
  // that width (32K x 1, 16K x 2, 8K x 4, ...): every slice is one RAM deep, so no output
  // multiplexer sits between a block RAM's output and its register.
  for (genvar b = 0; b < BeatW; b += LbSlice) begin : gen_lb
    localparam int unsigned SW = (BeatW - b < LbSlice) ? BeatW - b : LbSlice;
    scw_ram_sdp #(.Width(SW), .Depth(LbDepth)) u_left_rows (
      .clk_i, .wr_en_i(valid_i), .wr_addr_i(wr_addr), .wr_data_i(left_i[b +: SW]),
      .rd_en_i(valid_i), .rd_addr_i(old_addr), .rd_data_o(lold_rd[b +: SW])
    );
    scw_ram_sdp #(.Width(SW), .Depth(LbDepth)) u_right_rows (
      .clk_i, .wr_en_i(valid_i), .wr_addr_i(wr_addr), .wr_data_i(right_i[b +: SW]),
      .rd_en_i(valid_i), .rd_addr_i(old_back_addr), .rd_data_o(rold_rd[b +: SW])
    );
  end
  // The new row's right pixels dmin back: written k >= 1 beats ago (k = 0 bypasses it).
  scw_ram_sdp #(.Width(BeatW), .Depth(Cols)) u_right_delay (
    .clk_i, .wr_en_i(valid_i), .wr_addr_i(col_i), .wr_data_i(right_i),
    .rd_en_i(valid_i), .rd_addr_i(col_back), .rd_data_o(rdel_rd)
  );

  // ---- stage pipeline of valid, position and tag ------------------------------------------
  // v_q[k]: a beat in stage k (c1 = 1 .. the output = Latency).
  logic [Latency:1] v_q;
  logic [ColW-1:0] col1_q, col2_q, col3_q, col4_q, col5_q;
  logic [HW-1:0] row1_q, row2_q;
  logic [BeatW-1:0] left1_q, left2_q, left3_q, right1_q, right2_q;
  logic [Latency*TagBits-1:0] tag_q;  // stage k at [(k-1)*TagBits +: TagBits]
  // first_q[k]: the beat in stage k starts its row.
  logic [Latency-1:6] first_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) v_q <= '0;
    else v_q <= {v_q[Latency-1:1], valid_i};
  end

  // Each stage's registers load with that stage's valid: the enables differ from stage to
  // stage, so no run of them becomes a shift register (an SRL's clock-to-out is slow).
  always_ff @(posedge clk_i) begin
    if (valid_i) begin
      col1_q   <= col_i;
      row1_q   <= row_i;
      left1_q  <= left_i;
      right1_q <= right_i;
    end
    if (v_q[1]) begin
      col2_q   <= col1_q;
      row2_q   <= row1_q;
      left2_q  <= left1_q;
      right2_q <= right1_q;
    end
    if (v_q[2]) begin
      col3_q  <= col2_q;
      left3_q <= left2_q;
    end
    if (v_q[3]) col4_q <= col3_q;
    if (v_q[4]) col5_q <= col4_q;
  end
  always_ff @(posedge clk_i) begin
    if (valid_i) tag_q[TagBits-1:0] <= tag_i;
  end
  for (genvar k = 1; k < Latency; k++) begin : gen_tag
    always_ff @(posedge clk_i) begin
      if (v_q[k]) tag_q[k*TagBits +: TagBits] <= tag_q[(k-1)*TagBits +: TagBits];
    end
  end
  always_ff @(posedge clk_i) begin
    if (v_q[5]) first_q[6] <= col5_q == '0;
  end
  for (genvar k = 7; k < Latency; k++) begin : gen_first
    always_ff @(posedge clk_i) begin
      if (v_q[k-1]) first_q[k] <= first_q[k-1];
    end
  end

  // ---- c1: line-buffer output registers ---------------------------------------------------
  // x0 - dmin for c2's masks: candidate d of lane i reads column x0 + i - dmin - d.
  logic [BeatW-1:0] lold_q, rold_q, rdel_q;
  logic signed [XW-1:0] xr2_q;
  always_ff @(posedge clk_i) begin
    xr2_q  <= signed'(XW'(col1_q) * XW'(Ppc)) - dmin_q;
    lold_q <= lold_rd;
    rold_q <= rold_rd;
    rdel_q <= rdel_rd;
  end

  // ---- c2: candidate windows ---------------------------------------------------------------
  logic [BeatW-1:0] rnew_w, rnew_prev_q, rold_prev_q;
  logic [BeatW-1:0] rnew_al, rold_al;  // R(x0 + i - dmin) of the new and the leaving row
  logic [HistPx*PixW-1:0] hnew_q, hold_q;
  logic [WinPx*PixW-1:0] wnew, wold;  // [m]: R(x0 + Ppc - 1 - dmin - m)
  assign rnew_w = (back_words_q == '0) ? right2_q : rdel_q;

  for (genvar i = 0; i < Ppc; i++) begin : gen_align
    logic [2*BeatW-1:0] pair_new, pair_old;  // {this word, previous word}
    assign pair_new = {rnew_w, rnew_prev_q};
    assign pair_old = {rold_q, rold_prev_q};
    assign rnew_al[i*PixW +: PixW] = pair_new[(Ppc + i - 32'(shift_q))*PixW +: PixW];
    assign rold_al[i*PixW +: PixW] = pair_old[(Ppc + i - 32'(shift_q))*PixW +: PixW];
    assign wnew[(Ppc - 1 - i)*PixW +: PixW] = rnew_al[i*PixW +: PixW];
    assign wold[(Ppc - 1 - i)*PixW +: PixW] = rold_al[i*PixW +: PixW];
  end
  assign wnew[WinPx*PixW-1:Ppc*PixW] = hnew_q;
  assign wold[WinPx*PixW-1:Ppc*PixW] = hold_q;

  always_ff @(posedge clk_i) begin
    if (v_q[2]) begin
      rnew_prev_q <= rnew_w;
      rold_prev_q <= rold_q;
      hnew_q      <= wnew[HistPx*PixW-1:0];
      hold_q      <= wold[HistPx*PixW-1:0];
    end
  end

  logic [WinPx*PixW-1:0] wnew_q, wold_q;
  logic [BeatW-1:0] lold3_q;
  logic signed [XW-1:0] xr3_q;
  logic first_row, full, first3_q, full3_q;
  assign first_row = row2_q == '0;
  assign full      = row2_q >= HW'(Window);  // the leaving row y - N exists
  always_ff @(posedge clk_i) begin
    wnew_q   <= wnew;
    wold_q   <= wold;
    lold3_q  <= lold_q;
    xr3_q    <= xr2_q;
    first3_q <= first_row;
    full3_q  <= full;
  end

  // ---- c3: absolute differences ------------------------------------------------------------

  // The differences leave c2 already gated, so that c3 is a plain three-input add: a right
  // pixel left of column 0 gives C = 0 (everything gated), the first row restarts C (no kept
  // sum), the leaving row exists only from row N on. From here to the window sums every
  // candidate's value is a word of its own (an unpacked array, J = i * NumDisp + d), not a
  // field of one wide vector: the same registers, but a simulator then adds words instead of
  // cutting and splicing fields of a 585-bit vector at every clock (that cutting was a third of
  // the thesis P = 4 pipeline's Verilated time).
  logic [PixW-1:0] dnew_q [Ppc*NumDisp];
  logic [PixW-1:0] dold_q [Ppc*NumDisp];
  logic [Ppc*NumDisp-1:0] keep_q;  // add the kept column sum
  logic [PixW-1:0] tnew_q [Ppc];
  logic [PixW-1:0] told_q [Ppc];
  logic keep_t_q;
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_c3
    logic [PixW-1:0] l_new, l_old;
    assign l_new   = left3_q[i*PixW +: PixW];
    assign l_old   = lold3_q[i*PixW +: PixW];
    always_ff @(posedge clk_i) begin
      tnew_q[i] <= (l_new > PixW'(cap_q)) ? l_new - PixW'(cap_q) : PixW'(cap_q) - l_new;
      told_q[i] <= !full3_q ? '0
                 : (l_old > PixW'(cap_q)) ? l_old - PixW'(cap_q) : PixW'(cap_q) - l_old;
    end
    for (genvar d = 0; d < NumDisp; d++) begin : gen_cand
      localparam int unsigned J = i * NumDisp + d;
      logic [PixW-1:0] r_new, r_old;
      assign r_new = wnew_q[(Ppc - 1 - i + d)*PixW +: PixW];
      assign r_old = wold_q[(Ppc - 1 - i + d)*PixW +: PixW];
      logic mask;  // the right pixel is left of column 0
      assign mask = xr3_q < XW'(d - i);  // x0 + i - dmin < d
      always_ff @(posedge clk_i) begin
        dnew_q[J] <= mask ? '0 : (l_new > r_new) ? l_new - r_new : r_new - l_new;
        dold_q[J] <= (mask || !full3_q) ? '0 : (l_old > r_old) ? l_old - r_old : r_old - l_old;
        keep_q[J] <= !mask && !first3_q;
      end
    end
  end

  always_ff @(posedge clk_i) keep_t_q <= !first3_q;

  // ---- column-sum RAMs: read in c2 (output register in c3), written in c4 -----------------
  // A block RAM is at most 72 bits wide, so the words past a power of two take as many block
  // RAMs as that power's half would: at 1,280 columns x 585 bits, 24.5 RAMB36 where 1,024
  // words need 16.5. When the rest is at most a quarter of a block part of 512 words or more
  // (P = 1 and 2 at 1,280 px), it is kept in LUT RAM (scw_ram_sdp's BlockDepth; docs/disparity.md).
  localparam int unsigned ColsPow2  = (Cols > 1) ? (1 << ($clog2(Cols) - 1)) : 1;
  localparam int unsigned ColsBlock = (ColsPow2 >= 512 && Cols - ColsPow2 <= ColsPow2 / 4 &&
                                       Cols > ColsPow2) ? ColsPow2 : Cols;
  logic [CW-1:0] csum_rd, csum_rd_q, csum_d;
  logic [Ppc*ColBits-1:0] tsum_rd, tsum_rd_q, tsum_d;
  scw_ram_sdp #(.Width(CW), .Depth(Cols), .BlockDepth(ColsBlock)) u_col_sums (
    .clk_i, .wr_en_i(v_q[4]), .wr_addr_i(col4_q), .wr_data_i(csum_d),
    .rd_en_i(v_q[2]), .rd_addr_i(col2_q), .rd_data_o(csum_rd)
  );
  scw_ram_sdp #(.Width(Ppc * ColBits), .Depth(Cols), .BlockDepth(ColsBlock)) u_texture_sums (
    .clk_i, .wr_en_i(v_q[4]), .wr_addr_i(col4_q), .wr_data_i(tsum_d),
    .rd_en_i(v_q[2]), .rd_addr_i(col2_q), .rd_data_o(tsum_rd)
  );
  always_ff @(posedge clk_i) begin
    csum_rd_q <= csum_rd;
    tsum_rd_q <= tsum_rd;
  end

  // ---- c4: column sums ---------------------------------------------------------------------
  // Written to the RAM as one word (csum_d), registered one word a candidate (csum_q). The word
  // is packed by a loop: field by field assigns a simulator merges into one concatenation,
  // which Verilator 5.006 builds through a temporary a field longer at each step (quadratic
  // in the word: 180 fields at P = 4).
  logic [ColBits-1:0] csum_c [Ppc*NumDisp];
  logic [ColBits-1:0] csum_q [Ppc*NumDisp];
  logic [ColBits-1:0] tsum_c [Ppc];
  logic [ColBits-1:0] tsum_q [Ppc];
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_c4
    for (genvar d = 0; d < NumDisp; d++) begin : gen_cand
      localparam int unsigned J = i * NumDisp + d;
      assign csum_c[J] = (keep_q[J] ? csum_rd_q[J*ColBits +: ColBits] : '0) +
                         ColBits'(dnew_q[J]) - ColBits'(dold_q[J]);
      always_ff @(posedge clk_i) csum_q[J] <= csum_c[J];
    end
    assign tsum_c[i] = (keep_t_q ? tsum_rd_q[i*ColBits +: ColBits] : '0) +
                       ColBits'(tnew_q[i]) - ColBits'(told_q[i]);
    always_ff @(posedge clk_i) tsum_q[i] <= tsum_c[i];
  end
  always_comb begin
    for (int j = 0; j < Ppc * NumDisp; j++) csum_d[j*ColBits +: ColBits] = csum_c[j];
    for (int i = 0; i < Ppc; i++) tsum_d[i*ColBits +: ColBits] = tsum_c[i];
  end

  // ---- c5: D = C(x) - C(x - N) -------------------------------------------------------------
  // C(x - N) of lane i is lane (i - N) mod Ppc of the beat ceil((N - i) / Ppc) back. Each lane
  // keeps the one lane it needs, column and texture sums, in a delay line of that many beats
  // moved by the c5 valid, ending in a plain register (gone_q: the subtraction starts at a
  // flip-flop). A line of two beats or more is a ring of distributed RAM (scw_delay_ring):
  // 21 beats of 598 bits at the thesis's P = 1, which as a shift register of whole beats made a
  // simulator copy 12,285 bits at every beat and cost a 7-series part 598 SRLs where the ring
  // takes 100 RAM32M. Lanes before column N subtract 0.
  // Lane i, candidate k (k = NumDisp: the texture sum) at index i * K + k from here on.
  localparam int unsigned K  = NumDisp + 1;
  logic [SadBits-1:0] delta_q [Ppc*K];
  logic [WW-1:0] x5;
  assign x5 = WW'(col5_q) * WW'(Ppc);
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_c5
    localparam int unsigned BackBeats = (Window - i + Ppc - 1) / Ppc;
    localparam int unsigned BackLane  = BackBeats * Ppc + i - Window;
    logic leaves;  // x >= N
    assign leaves = (x5 + WW'(i)) >= WW'(Window);
    logic [K*ColBits-1:0] keep;  // lane BackLane of the beat in c5: what lane i will subtract
    for (genvar d = 0; d < NumDisp; d++) begin : gen_keep
      assign keep[d*ColBits +: ColBits] = csum_q[BackLane*NumDisp + d];
    end
    assign keep[NumDisp*ColBits +: ColBits] = tsum_q[BackLane];
    logic [K*ColBits-1:0] gone_q;  // each lane's delay line's output register
    if (BackBeats == 1) begin : gen_reg
      always_ff @(posedge clk_i) begin
        if (v_q[5]) gone_q <= keep;
      end
    end else begin : gen_ring
      scw_delay_ring #(.Width(K * ColBits), .Depth(BackBeats)) u_back (
        .clk_i, .rst_ni, .en_i(v_q[5]), .d_i(keep), .q_o(gone_q)
      );
    end
    for (genvar k = 0; k < K; k++) begin : gen_delta
      logic [ColBits-1:0] c;
      if (k < NumDisp) begin : gen_c
        assign c = csum_q[i*NumDisp + k];
      end else begin : gen_t
        assign c = tsum_q[i];
      end
      always_ff @(posedge clk_i) begin
        delta_q[i*K + k] <= SadBits'(c) - (leaves ? SadBits'(gone_q[k*ColBits +: ColBits]) : '0);
      end
    end
  end

  // ---- p1 .. pK: prefix sums across the lanes ----------------------------------------------
  // Level l: a lane with bit l set adds the last lane of the block of 2^l lanes before it.
  // Level 0 is delta_q, level l + 1 the registered sums of level l (each reads the one below
  // by name, as Yosys 0.23 needs).
  for (genvar l = 0; l <= PreStages; l++) begin : gen_pre
    logic [SadBits-1:0] v [Ppc*K];
    if (l == 0) begin : gen_delta
      for (genvar j = 0; j < Ppc * K; j++) begin : gen_j
        assign v[j] = delta_q[j];
      end
    end else begin : gen_sum
      for (genvar i = 0; i < Ppc; i++) begin : gen_lane
        localparam int unsigned From = ((i >> (l - 1)) << (l - 1)) - 1;
        for (genvar k = 0; k < K; k++) begin : gen_k
          if (((i >> (l - 1)) & 1) != 0) begin : gen_add
            always_ff @(posedge clk_i) begin
              v[i*K + k] <= gen_pre[l-1].v[i*K + k] + gen_pre[l-1].v[From*K + k];
            end
          end else begin : gen_keep
            always_ff @(posedge clk_i) v[i*K + k] <= gen_pre[l-1].v[i*K + k];
          end
        end
      end
    end
  end

  // ---- s: window sums ----------------------------------------------------------------------
  logic [SadBits-1:0] run_q [K];  // S of the previous beat's last lane
  logic [SadBits-1:0] s_q [Ppc*K];
  logic first;
  assign first = first_q[Latency-1];
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_s
    for (genvar k = 0; k < K; k++) begin : gen_k
      logic [SadBits-1:0] s_d;
      assign s_d = (first ? '0 : run_q[k]) + gen_pre[PreStages].v[i*K + k];
      always_ff @(posedge clk_i) s_q[i*K + k] <= s_d;
      if (i == Ppc - 1) begin : gen_run
        always_ff @(posedge clk_i) begin
          if (v_q[Latency-1]) run_q[k] <= s_d;
        end
      end
    end
  end

  always_comb begin  // packed by a loop, as csum_d
    for (int i = 0; i < Ppc; i++) begin
      for (int d = 0; d < NumDisp; d++) sad_o[(i*NumDisp + d)*SadBits +: SadBits] = s_q[i*K + d];
      texture_o[i*SadBits +: SadBits] = s_q[i*K + NumDisp];
    end
  end
  assign valid_o = v_q[Latency];
  assign tag_o   = tag_q[(Latency-1)*TagBits +: TagBits];
  assign tag_pre_o    = tag_q[(Latency-2)*TagBits +: TagBits];
  assign tag_pre_en_o = v_q[Latency-1];
endmodule
