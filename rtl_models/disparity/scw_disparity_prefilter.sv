// SPDX-License-Identifier: Apache-2.0
// Disparity prefilter: streaming x-Sobel with cap (cv::StereoBM PREFILTER_XSOBEL), Latency 4.
`default_nettype none

// P(x, v) = clamp(g(x, v-1) + 2 g(x, v) + g(x, v+1), -cap, cap) + cap, g = I(x+1) - I(x-1);
// rows -1 and H read as rows 1 and H-2; columns 0 and W-1, and the last row when H is odd,
// are cap (docs/disparity.md). Cycle-exact twin of scw::hls::disparity::XSobel: a writer and a
// reader share five row slots and a counter avail (rows written minus rows read, across
// frames); wr_allowed_o = avail <= 3, rd_allowed_o = avail >= min(2, H - v), both from
// registers only. out_valid_o/out_data_o follow rd_i by Latency clocks.
//
// Storage: g, not I, is stored (Q9.0 two's complement per pixel), so the reader needs one word
// per row and no neighbour from the next word. One scw_ram_sdp per slot, Cols words of Ppc g
// values: the reader reads the same word of all five slots in one clock, and five RAMs of one
// row each fill a RAMB18 apiece at 1280 pixels (rows of 9-bit g are 2K x 9, 1K x 18, 512 x 36).
// The writer computes g-word k - 1 when raw word k arrives (it keeps the previous raw word and
// the last pixel of the one before). The row's last g-word, whose last pixel is column W - 1
// (cap, so its missing right neighbour does not matter), is written one clock after the row's
// last raw word: that clock's raw word, if any, starts a row and writes no g-word, so one write
// port suffices. The row is counted in avail at its last raw word, as in XSobel; the reader can
// start on it the next clock but reaches its last word a clock later at the earliest, after
// that write (rows of one word are written whole from the input instead).
//
// Reader pipeline (free running; rd_i issues): s0 RAM read of word out_x in all slots, slot
// selects and cap lanes registered -> s1 the RAMs' output registers -> s2 select up/cur/down
// rows, up + down -> s3 + 2 cur, clamp, + cap -> out.
module scw_disparity_prefilter #(
  parameter int unsigned Ppc        /*verilator public*/ = 1,
  parameter int unsigned MaxWidthPx /*verilator public*/ = 64,
  parameter int unsigned MaxHeight  /*verilator public*/ = 32,
  localparam int unsigned PixW  = scw_pkg::PixelBits,
  localparam int unsigned BeatW = Ppc * PixW,
  localparam int unsigned WW    = $clog2(MaxWidthPx + 1),
  localparam int unsigned HW    = $clog2(MaxHeight + 1)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // static configuration: width (pixels, multiple of Ppc), height (rows), cap (1 .. 63)
  input  logic [WW-1:0]    cfg_width_i,
  input  logic [HW-1:0]    cfg_height_i,
  input  logic [5:0]       cfg_cap_i,
  // raw pixels: wr_i only while wr_allowed_o
  output logic             wr_allowed_o,
  input  logic             wr_i,
  input  logic [BeatW-1:0] wr_data_i,
  // prefiltered pixels: rd_i only while rd_allowed_o; the beat follows Latency clocks later
  output logic             rd_allowed_o,
  input  logic             rd_i,
  output logic             out_valid_o,
  output logic [BeatW-1:0] out_data_o
);
  // Cycles from rd_i to out_valid_o; scw::hls::disparity::XSobel::kReadLatency is checked
  // against it at compile time.
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency /*verilator public*/ = 4;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned Slots  = 5;
  localparam int unsigned SlotW  = 3;
  localparam int unsigned GW     = PixW + 1;  // g = I(x+1) - I(x-1), -255 .. 255
  localparam int unsigned WordW  = Ppc * GW;
  localparam int unsigned UdW    = GW + 1;    // g(v-1) + g(v+1)
  localparam int unsigned SumW   = GW + 2;    // + 2 g(v): |s| <= 1020
  localparam int unsigned Cols   = MaxWidthPx / Ppc;
  localparam int unsigned ColW   = $clog2(Cols);
  localparam int unsigned PpcLog = $clog2(Ppc);
  localparam logic [SlotW-1:0] LastSlot = SlotW'(Slots - 1);

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_disparity_prefilter: Ppc must be 1, 2 or 4");
  end
  if (MaxWidthPx % Ppc != 0 || Cols < 2 || MaxHeight < 1) begin : gen_bad_geom
    $error("scw_disparity_prefilter: need MaxWidthPx %% Ppc == 0, MaxWidthPx / Ppc >= 2 and %s",
           "MaxHeight >= 1");
  end

  // ---- configuration ---------------------------------------------------------------------
  // Static: registered without reset (settled while rst_ni is low), with what derives from it.
  logic [ColW-1:0] last_col_q, last_col_m1_q;
  logic [HW-1:0] last_row_q;
  logic one_col_q, odd_q;
  logic [5:0] cap_q;
  logic [6:0] cap2_q;
  logic [WW-1:0] cols_cfg;
  assign cols_cfg = cfg_width_i >> PpcLog;
  always_ff @(posedge clk_i) begin
    last_col_q <= ColW'(cols_cfg - 1'b1);
    last_col_m1_q <= ColW'(cols_cfg - WW'(2));
    one_col_q  <= cols_cfg == WW'(1);
    last_row_q <= cfg_height_i - 1'b1;
    odd_q      <= cfg_height_i[0];
    cap_q      <= cfg_cap_i;
    cap2_q     <= {cfg_cap_i, 1'b0};
  end

  // ---- shared counter ----------------------------------------------------------------------
  logic [2:0] avail_q, avail_inc, avail_dec;  // 0 .. 4
  assign avail_inc = avail_q + 3'd1;
  assign avail_dec = avail_q - 3'd1;
  logic wr_row_done, rd_row_done, last_row;

  assign wr_allowed_o = !avail_q[2];
  assign rd_allowed_o = last_row ? (avail_q != '0) : (avail_q[2] || avail_q[1]);

  // ---- writer ------------------------------------------------------------------------------
  logic [ColW-1:0] in_x_q, g_addr_q, gw_addr;
  logic [SlotW-1:0] in_slot_q, g_slot_q, gw_slot;
  logic pend_q, wr_last, gw_en;
  logic [BeatW-1:0] prev_q, g_src;
  logic [PixW-1:0] left_q;
  logic [WordW-1:0] g_word;

  // wr_last_q: the next raw word ends its row (rows of two words or more; a one-word row
  // always does), a register, so the row count's update is a select behind wr_i.
  logic wr_last_q, in_x0_q;  // and in_x0_q: in_x_q == 0
  assign wr_last     = one_col_q || wr_last_q;
  assign wr_row_done = wr_i && wr_last;
  // g-word k - 1 as raw word k arrives, the held last g-word of a row one clock later, or a
  // one-word row straight from the input.
  assign gw_en   = pend_q || (wr_i && (one_col_q || !in_x0_q));
  assign gw_slot = one_col_q ? in_slot_q : g_slot_q;
  assign gw_addr = one_col_q ? '0 : g_addr_q;
  assign g_src   = one_col_q ? wr_data_i : prev_q;

  // Lane i's neighbours: the word before's last pixel for lane 0, the arriving word's first
  // for lane Ppc-1 (only garbage where it is column 0 or W-1, which are cap).
  for (genvar i = 0; i < Ppc; i++) begin : gen_g
    logic [PixW-1:0] lft, rgt;
    if (i == 0) begin : gen_l0
      assign lft = left_q;
    end else begin : gen_ln
      assign lft = g_src[(i-1)*PixW +: PixW];
    end
    if (i == Ppc - 1) begin : gen_rlast
      assign rgt = wr_data_i[PixW-1:0];
    end else begin : gen_rn
      assign rgt = g_src[(i+1)*PixW +: PixW];
    end
    assign g_word[i*GW +: GW] = {1'b0, rgt} - {1'b0, lft};
  end
  if (Ppc == 1) begin : gen_p1_unused
    logic unused_src;
    assign unused_src = ^g_src;  // one lane: g needs only the pixels either side
  end

  always_ff @(posedge clk_i) begin
    if (wr_i) begin
      prev_q   <= wr_data_i;
      left_q   <= prev_q[BeatW-PixW +: PixW];
      g_addr_q <= in_x_q;
      g_slot_q <= in_slot_q;
    end
  end

  // ---- reader ------------------------------------------------------------------------------
  logic [ColW-1:0] out_x_q;
  logic [HW-1:0] out_y_q;
  logic [SlotW-1:0] out_slot_q, slot_inc, slot_dec, slot_up, slot_dn;
  logic first_row, rd_last;
  logic [Slots-1:0] up_oh, cur_oh, dn_oh;
  logic [Ppc-1:0] cap_lanes;

  assign first_row   = out_y_q == '0;
  assign last_row    = out_y_q == last_row_q;
  assign rd_last     = out_x_q == last_col_q;
  assign rd_row_done = rd_i && rd_last;
  assign slot_inc    = (out_slot_q == LastSlot) ? '0 : out_slot_q + 1'b1;
  assign slot_dec    = (out_slot_q == '0) ? LastSlot : out_slot_q - 1'b1;
  assign slot_up     = first_row ? slot_inc : slot_dec;  // row v - 1, or 1 at v = 0
  assign slot_dn     = last_row ? slot_dec : slot_inc;   // row v + 1, or H - 2 at v = H - 1
  for (genvar s = 0; s < Slots; s++) begin : gen_oh
    assign up_oh[s]  = slot_up == SlotW'(s);
    assign cur_oh[s] = out_slot_q == SlotW'(s);
    assign dn_oh[s]  = slot_dn == SlotW'(s);
  end
  for (genvar i = 0; i < Ppc; i++) begin : gen_cap
    logic edge_col;
    if (Ppc == 1) begin : gen_both
      assign edge_col = out_x_q == '0 || rd_last;
    end else if (i == 0) begin : gen_first
      assign edge_col = out_x_q == '0;
    end else if (i == Ppc - 1) begin : gen_last
      assign edge_col = rd_last;
    end else begin : gen_mid
      assign edge_col = 1'b0;
    end
    assign cap_lanes[i] = edge_col || (odd_q && last_row);
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_x_q     <= '0;
      in_slot_q  <= '0;
      pend_q     <= 1'b0;
      out_x_q    <= '0;
      out_y_q    <= '0;
      out_slot_q <= '0;
      avail_q    <= '0;
      wr_last_q  <= 1'b0;
      in_x0_q    <= 1'b1;
    end else begin
      if (wr_i) begin
        wr_last_q <= !wr_last && in_x_q == last_col_m1_q;
        in_x0_q   <= wr_last;
      end
      if (wr_i) begin
        if (wr_last) begin
          in_x_q    <= '0;
          in_slot_q <= (in_slot_q == LastSlot) ? '0 : in_slot_q + 1'b1;
        end else begin
          in_x_q <= in_x_q + 1'b1;
        end
      end
      pend_q <= wr_row_done && !one_col_q;
      if (rd_i) begin
        if (rd_last) begin
          out_x_q    <= '0;
          out_slot_q <= slot_inc;
          out_y_q    <= last_row ? '0 : out_y_q + 1'b1;
        end else begin
          out_x_q <= out_x_q + 1'b1;
        end
      end
      avail_q <= (wr_row_done == rd_row_done) ? avail_q : wr_row_done ? avail_inc : avail_dec;
    end
  end

  // ---- row storage -------------------------------------------------------------------------
  logic [Slots*WordW-1:0] rd_words;  // slot s in [s*WordW +: WordW]
  for (genvar s = 0; s < Slots; s++) begin : gen_slot
    scw_ram_sdp #(
      .Width(WordW),
      .Depth(Cols)
    ) u_ram (
      .clk_i,
      .wr_en_i  (gw_en && (gw_slot == SlotW'(s))),
      .wr_addr_i(gw_addr),
      .wr_data_i(g_word),
      .rd_en_i  (rd_i),
      .rd_addr_i(out_x_q),
      .rd_data_o(rd_words[s*WordW +: WordW])
    );
  end

  // ---- s1: the RAMs' output registers; s2: pick the rows, up + down -------------------------
  logic s1_valid_q, s15_valid_q, s2_valid_q, out_valid_q;
  logic [Slots*WordW-1:0] rd_words_q;
  logic [Slots-1:0] s1_up_q, s1_cur_q, s1_dn_q, s15_up_q, s15_cur_q, s15_dn_q;
  logic [Ppc-1:0] s1_cap_q, s15_cap_q, s2_cap_q;
  logic [WordW-1:0] g_up, g_cur, g_dn;
  logic [Ppc*UdW-1:0] ud;
  logic [Ppc*UdW-1:0] s2_ud_q;
  logic [WordW-1:0] s2_cur_q;
  logic [BeatW-1:0] out_pix, out_data_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_valid_q  <= 1'b0;
      s15_valid_q <= 1'b0;
      s2_valid_q  <= 1'b0;
      out_valid_q <= 1'b0;
    end else begin
      s1_valid_q  <= rd_i;
      s15_valid_q <= s1_valid_q;
      s2_valid_q  <= s15_valid_q;
      out_valid_q <= s2_valid_q;
    end
  end

  // One-hot AND-OR: the selects come straight from registers.
  always_comb begin
    g_up  = '0;
    g_cur = '0;
    g_dn  = '0;
    for (int s = 0; s < Slots; s++) begin
      g_up  = g_up | (rd_words_q[s*WordW +: WordW] & {WordW{s15_up_q[s]}});
      g_cur = g_cur | (rd_words_q[s*WordW +: WordW] & {WordW{s15_cur_q[s]}});
      g_dn  = g_dn | (rd_words_q[s*WordW +: WordW] & {WordW{s15_dn_q[s]}});
    end
  end

  for (genvar i = 0; i < Ppc; i++) begin : gen_ud
    logic signed [GW-1:0] gu, gd;
    assign gu = $signed(g_up[i*GW +: GW]);
    assign gd = $signed(g_dn[i*GW +: GW]);
    assign ud[i*UdW +: UdW] = UdW'(gu) + UdW'(gd);
  end

  always_ff @(posedge clk_i) begin
    s1_up_q    <= up_oh;
    s1_cur_q   <= cur_oh;
    s1_dn_q    <= dn_oh;
    s1_cap_q   <= cap_lanes;
    rd_words_q <= rd_words;
    s15_up_q   <= s1_up_q;
    s15_cur_q  <= s1_cur_q;
    s15_dn_q   <= s1_dn_q;
    s15_cap_q  <= s1_cap_q;
    s2_ud_q    <= ud;
    s2_cur_q   <= g_cur;
    s2_cap_q   <= s15_cap_q;
    out_data_q <= out_pix;
  end

  // ---- s3: + 2 cur, clamp to [-cap, cap], + cap ------------------------------------------
  for (genvar i = 0; i < Ppc; i++) begin : gen_out
    logic signed [UdW-1:0] a;
    logic signed [GW-1:0] b;
    logic signed [SumW-1:0] s;
    logic signed [SumW:0] sp;  // s + cap: negative exactly when s < -cap
    logic hi;
    logic [6:0] val;
    assign a   = $signed(s2_ud_q[i*UdW +: UdW]);
    assign b   = $signed(s2_cur_q[i*GW +: GW]);
    assign s   = SumW'(a) + (SumW'(b) <<< 1);
    assign sp  = (SumW + 1)'(s) + $signed((SumW + 1)'(cap_q));
    assign hi  = s > $signed(SumW'(cap_q));
    assign val = s2_cap_q[i] ? {1'b0, cap_q} : sp[SumW] ? '0 : hi ? cap2_q : sp[6:0];
    assign out_pix[i*PixW +: PixW] = PixW'(val);

    logic unused_sp;
    assign unused_sp = ^sp[SumW-1:7];
  end

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
endmodule
