// SPDX-License-Identifier: Apache-2.0
// Disparity: SAD block matching of a rectified stereo pair, one beat pair per clock.
`default_nettype none

// The C++ twin is scw::hls::disparity::Disparity clocked by scw::sim::DisparityModel; the
// arithmetic and the rules are in docs/disparity.md.
//
// Control runs at the issue point, data in free-running pipelines behind it:
//   writer   takes one left and one right beat together (only when both are valid), checks
//            sof/eol against the configured geometry, and issues the pair to the core, or, in
//            opencv mode, writes both into the x-Sobel prefilters, whose reader issues instead.
//   credits  a beat is issued only when the result queue has room for P more results counting
//            those still in the pipeline, so the pipeline never stalls and never overflows.
//   core     scw_disparity_sums (window sums) -> one scw_disparity_decide per lane -> queue.
//            A beat issued at cycle t has its results readable at t + ResultLatency.
//   reader   emits the output frame in raster order behind an output register: results where
//            the core computes them (rows R .. H - R - 1, columns < W - R), the invalid code
//            elsewhere without waiting, so a frame's last rows leave while the next comes in.
// A sof in mid-frame is held while the rest of the interrupted frame is issued as zero pixels;
// a beat that should start a frame but has no sof is dropped; both set err_o (sticky).
// cfg_* are static: set them before rst_ni rises (registered without reset).
module scw_disparity #(
  parameter int unsigned Ppc        /*verilator public*/ = 1,
  parameter int unsigned MaxWidthPx /*verilator public*/ = 32,
  parameter int unsigned MaxHeight  /*verilator public*/ = 16,
  parameter int unsigned Window     /*verilator public*/ = 3,
  parameter int unsigned NumDisp    /*verilator public*/ = 4,
  localparam int unsigned PixW     = scw_pkg::PixelBits,
  localparam int unsigned BeatW    = Ppc * PixW,
  localparam int unsigned OutW     = Ppc * scw_pkg::DispBits,
  localparam int unsigned WW       = $clog2(MaxWidthPx + 1),
  localparam int unsigned HW       = $clog2(MaxHeight + 1),
  localparam int unsigned NumW     = $clog2(NumDisp + 1)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // static configuration (hls::disparity::DisparityConfig)
  input  logic [WW-1:0]    cfg_width_i,
  input  logic [HW-1:0]    cfg_height_i,
  // the rest: scw_pkg::disparity_cfg_t (num_disp, edge_candidates: 0 or >= NumDisp, n = all)
  input  logic [scw_pkg::DisparityCfgBits-1:0] cfg_disparity_i,
  // left and right rectified pixels
  input  logic             l_valid_i,
  output logic             l_ready_o,
  input  logic [BeatW-1:0] l_data_i,
  input  logic             l_sof_i,
  input  logic             l_eol_i,
  input  logic             r_valid_i,
  output logic             r_ready_o,
  input  logic [BeatW-1:0] r_data_i,
  input  logic             r_sof_i,
  input  logic             r_eol_i,
  // disparities, Q11.4 in 16 bits per lane
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [OutW-1:0]  out_data_o,
  output logic             out_sof_o,
  output logic             out_eol_o,
  output logic             err_o
);
  localparam int unsigned R         = Window / 2;
  localparam int unsigned Cols      = MaxWidthPx / Ppc;
  localparam int unsigned ColW      = (Cols > 1) ? $clog2(Cols) : 1;
  localparam int unsigned SlotW     = $clog2(Window + 1);
  localparam int unsigned LbAW      = $clog2((Window + 1) * Cols);  // line-buffer address
  localparam int unsigned SadBits   = $clog2(Window * Window * 255 + 1);
  // Latencies, each the twin of a C++ constant (checked by the RTL test at compile time):
  // XSobel::kReadLatency, front_latency(Ppc), decide_latency(NumDisp) (a register after every
  // comparator level of its tree).
  localparam int unsigned PfLatency    = 4;
  localparam int unsigned SumsLatency  = 7 + ((Ppc > 1) ? $clog2(Ppc) : 0);
  localparam int unsigned TreeStages   = $clog2(NumDisp);
  localparam int unsigned DecLatency   = TreeStages + 6;
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned ResultLatency /*verilator public*/ =
      PfLatency + SumsLatency + DecLatency + 1;
  localparam int unsigned QueueWords /*verilator public*/ = 1 << $clog2(ResultLatency + 2);
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned Queue     = Ppc * QueueWords;  // results
  localparam int unsigned QW        = $clog2(Queue);
  localparam int unsigned QCW       = QW + 1;            // 0 .. Queue
  localparam int unsigned QAW       = (QueueWords > 1) ? $clog2(QueueWords) : 1;
  localparam int unsigned LaneW     = (Ppc > 1) ? $clog2(Ppc) : 1;
  localparam int unsigned LnW       = $clog2(Ppc + 1);   // 0 .. Ppc
  localparam int unsigned XW        = WW + NumW + 2;

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_disparity: Ppc must be 1, 2 or 4");
  end

  // ---- configuration ---------------------------------------------------------------------
  logic [ColW-1:0] last_col_q, last_col_m1_q;
  logic [HW-1:0] last_row_q, height_q;
  logic [WW-1:0] dmin_q, width_q;
  logic [NumW-1:0] num_q, edge_q;
  logic [XW-1:0] first_valid_q;  // dmin + e - 1 + R: the first column with a decision
  logic [XW-1:0] edge_base_q;    // 2R + dmin - 1: input column x has x - it candidates inside
  logic [XW-1:0] fvr_q;          // first_valid + R: the first input column with a decision
  logic [XW-1:0] hrm_q;          // H - R - 1
  // Per lane i, what a word column must be for lane i to hold a decision (region) or a
  // computed output (right edge), one less, as the next word's tests are made on this one:
  // col + 1 >= ceil((fvr - i) / P) and col + 1 < ceil((W - R - i) / P).
  // ocm in ColW + 1 bits: at most Cols - 1, or all ones when oc is 0 (never below any column)
  localparam int unsigned OcW = ColW + 1;
  logic [Ppc*XW-1:0] rcm_q;
  logic [Ppc*OcW-1:0] ocm_q;
  logic [Ppc-1:0] rz_q, oz_q;  // the same tests for word column 0
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_cfg
    logic [XW-1:0] rc, oc;
    assign rc = (fvr_q + XW'(Ppc - 1 - i)) >> $clog2(Ppc);
    assign oc = (XW'(width_q) - XW'(R) + XW'(Ppc - 1 - i)) >> $clog2(Ppc);
    always_ff @(posedge clk_i) begin
      rcm_q[i*XW +: XW] <= rc - 1'b1;
      ocm_q[i*OcW +: OcW] <= OcW'(oc - 1'b1);
      rz_q[i]           <= rc == '0;
      oz_q[i]           <= oc != '0;
    end
  end
  scw_pkg::disparity_cfg_t cfg;
  assign cfg = cfg_disparity_i;
  if ($bits(cfg) != scw_pkg::DisparityCfgBits) begin : gen_bad_cfg
    $error("scw_disparity: scw_pkg::DisparityCfgBits is not disparity_cfg_t's width");
  end
  if (WW > scw_pkg::DispDminBits || NumW > scw_pkg::DispNumBits) begin : gen_bad_cfg_widths
    $error("scw_disparity: MaxWidthPx or NumDisp beyond disparity_cfg_t's dmin or num_disp");
  end
  // The build's dmin: a frame's dmin is below its width (DisparityConfig's check).
  /* verilator lint_off UNUSEDSIGNAL */
  logic [scw_pkg::DispDminBits-1:0] dmin_cfg;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [WW-1:0] dmin_w;
  assign dmin_cfg = cfg.dmin;
  assign dmin_w   = dmin_cfg[WW-1:0];
  logic [15:0] invalid_q;
  logic prefilter_q;
  always_ff @(posedge clk_i) begin
    width_q       <= cfg_width_i;
    height_q      <= cfg_height_i;
    last_col_q    <= ColW'((cfg_width_i >> $clog2(Ppc)) - 1'b1);
    last_col_m1_q <= ColW'((cfg_width_i >> $clog2(Ppc)) - WW'(2));
    last_row_q    <= cfg_height_i - 1'b1;
    dmin_q        <= dmin_w;
    num_q         <= (cfg.num_disp == '0 || cfg.num_disp >= scw_pkg::DispNumBits'(NumDisp))
                         ? NumW'(NumDisp) : NumW'(cfg.num_disp);
    // edge_min<NumDisp>(cfg): the fewest candidates a column is decided among.
    edge_q        <= (cfg.edge_candidates == '0 ||
                      cfg.edge_candidates >= scw_pkg::DispNumBits'(num_q))
                         ? num_q : NumW'(cfg.edge_candidates);
    first_valid_q <= XW'(dmin_w) + XW'(edge_q) - 1'b1 + XW'(R);
    edge_base_q   <= XW'(dmin_w) + XW'(2 * R) - 1'b1;
    fvr_q         <= first_valid_q + XW'(R);
    hrm_q         <= XW'(cfg_height_i) - XW'(R + 1);
    invalid_q     <= cfg.opencv_invalid ? {12'(dmin_w) - 12'd1, 4'd0} : '0;
    prefilter_q   <= cfg.prefilter;
  end

  // ---- credits ---------------------------------------------------------------------------
  // core_room_q is the room for the next beat, registered from the count's next value, so the
  // writer's ready and everything behind it start at a register. The count's four possible
  // next values (issue or not, read or not) and their room tests are formed from registers
  // only (n_emit_q, n_out_q); issue and read just pick one.
  logic [QCW-1:0] count_q, ready_q;  // results issued and not read; of those, readable
  logic core_room, core_room_q;
  assign core_room = core_room_q;

  // ---- writer ----------------------------------------------------------------------------
  logic [ColW-1:0] in_col_q;
  logic [HW-1:0] in_row_q;
  logic skip_q, held_q, in_first_q;
  logic [BeatW-1:0] held_l_q, held_r_q;
  logic pf_wr_allowed, pf_rd_allowed, input_room, take, frame_start, have;
  logic held_set, held_clr, err_in;
  logic [BeatW-1:0] have_l, have_r;

  assign input_room  = prefilter_q ? pf_wr_allowed : core_room;
  assign l_ready_o   = !skip_q && !held_q && l_valid_i && r_valid_i && input_room;
  assign r_ready_o   = l_ready_o;
  assign take        = l_ready_o;
  assign frame_start = in_first_q;  // (in_col_q, in_row_q) == (0, 0), a register

  // The pair written, whatever decides whether it is: a taken pair clears neither skip nor
  // held, so the data needs no part of the handshake (only the write enable does).
  assign have_l = skip_q ? '0 : held_q ? held_l_q : l_data_i;
  assign have_r = skip_q ? '0 : held_q ? held_r_q : r_data_i;

  always_comb begin
    have     = 1'b0;
    held_set = 1'b0;
    held_clr = 1'b0;
    err_in   = 1'b0;
    if (take) begin
      if (l_sof_i != r_sof_i || l_eol_i != r_eol_i) err_in = 1'b1;
      if (l_sof_i && !frame_start) begin
        err_in   = 1'b1;
        held_set = 1'b1;
      end else if (!l_sof_i && frame_start) begin
        err_in = 1'b1;  // dropped: a frame starts with sof
      end else begin
        if (l_eol_i != (in_col_q == last_col_q)) err_in = 1'b1;
        have = 1'b1;
      end
    end else if (skip_q && input_room) begin
      have = 1'b1;  // the rest of an interrupted frame, as zeros
    end else if (held_q && input_room) begin
      have     = 1'b1;
      held_clr = 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_col_q <= '0;
      in_row_q <= '0;
      skip_q   <= 1'b0;
      held_q   <= 1'b0;
      in_first_q <= 1'b1;
    end else begin
      if (have) begin
        in_first_q <= (in_col_q == last_col_q) && (in_row_q == last_row_q);
        if (in_col_q != last_col_q) begin
          in_col_q <= in_col_q + 1'b1;
        end else begin
          in_col_q <= '0;
          if (in_row_q == last_row_q) begin
            in_row_q <= '0;
            skip_q   <= 1'b0;
          end else begin
            in_row_q <= in_row_q + 1'b1;
          end
        end
      end
      if (held_set) begin
        held_q <= 1'b1;
        skip_q <= 1'b1;
      end else if (held_clr) begin
        held_q <= 1'b0;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (held_set) begin
      held_l_q <= l_data_i;
      held_r_q <= r_data_i;
    end
  end

  // ---- prefilters (opencv mode) ----------------------------------------------------------
  logic pf_rd, pf_wr, pf_l_wr_allowed, pf_r_wr_allowed, pf_l_rd_allowed, pf_r_rd_allowed;
  // The issue delay line below carries the same valid for both modes.
  /* verilator lint_off UNUSEDSIGNAL */
  logic pf_l_valid, pf_r_valid;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [BeatW-1:0] pf_l_data, pf_r_data;
  // Both prefilters see the same writes and reads, so they agree; both are asked anyway.
  assign pf_wr_allowed = pf_l_wr_allowed && pf_r_wr_allowed;
  assign pf_rd_allowed = pf_l_rd_allowed && pf_r_rd_allowed;
  assign pf_wr         = prefilter_q && have;
  assign pf_rd         = prefilter_q && pf_rd_allowed && core_room;

  scw_disparity_prefilter #(.Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight)) u_pf_l (
    .clk_i, .rst_ni, .cfg_width_i(width_q), .cfg_height_i(height_q),
    .cfg_cap_i(cfg.prefilter_cap),
    .wr_allowed_o(pf_l_wr_allowed), .wr_i(pf_wr), .wr_data_i(have_l),
    .rd_allowed_o(pf_l_rd_allowed), .rd_i(pf_rd),
    .out_valid_o(pf_l_valid), .out_data_o(pf_l_data)
  );
  scw_disparity_prefilter #(.Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight)) u_pf_r (
    .clk_i, .rst_ni, .cfg_width_i(width_q), .cfg_height_i(height_q),
    .cfg_cap_i(cfg.prefilter_cap),
    .wr_allowed_o(pf_r_wr_allowed), .wr_i(pf_wr), .wr_data_i(have_r),
    .rd_allowed_o(pf_r_rd_allowed), .rd_i(pf_rd),
    .out_valid_o(pf_r_valid), .out_data_o(pf_r_data)
  );

  // ---- issue -----------------------------------------------------------------------------
  // One beat pair enters the core per issue; its position, slot and result lanes are decided
  // here and travel with it.
  logic issue;
  logic [ColW-1:0] core_col_q;
  logic [HW-1:0] core_row_q;
  logic [SlotW-1:0] core_slot_q;
  // The slot's and the leaving row's slot's line-buffer row addresses (slot * Cols), for the
  // sums: from the slot, a register, into the delay line's first register.
  logic [LbAW-1:0] core_base, core_old_base;
  assign core_base     = LbAW'(core_slot_q) * LbAW'(Cols);
  assign core_old_base = (core_slot_q == SlotW'(Window)) ? '0
                                                         : core_base + LbAW'(Cols);
  logic [1:0] frames_ahead_q;  // frames the core has started and the reader has not
  // emit_q, region_q, n_emit_q describe the word at (core_col_q, core_row_q) and are formed
  // for the next word when one is issued, from registers: output pixel (x - R, y - R) exists
  // when x >= R and y >= 2R; it holds a decision when x >= fvr.
  logic [Ppc-1:0] emit, region, emit_q, region_q, emit_nx, region_nx;
  logic [LnW-1:0] n_emit_q, n_emit_nx;
  logic emit_row_q, emit_row_nx, core_last_col, core_last_row;
  logic core_fs, read_fs;
  assign issue   = prefilter_q ? pf_rd : have;
  assign core_fs = (core_col_q == '0) && (core_row_q == '0);
  assign emit    = emit_q;
  assign region  = region_q;
  assign core_last_col = core_col_q == last_col_q;
  assign core_last_row = core_row_q == last_row_q;
  assign emit_row_nx   = !core_last_col ? emit_row_q
                       : !core_last_row && (core_row_q >= HW'(2 * R - 1));

  always_comb begin
    n_emit_nx = '0;
    for (int i = 0; i < Ppc; i++) begin
      // word column c + 1 >= ceil((R - i) / P), or column 0 when the row ends
      emit_nx[i]   = emit_row_nx &&
                     (core_last_col ? ((R + Ppc - 1 - i) / Ppc == 0)
                                    : (XW'(core_col_q) + 1'b1 >= XW'((R + Ppc - 1 - i) / Ppc)));
      region_nx[i] = core_last_col ? rz_q[i]
                                   : $signed(XW'(core_col_q)) >= $signed(rcm_q[i*XW +: XW]);
    end
    // The emitted lanes are a suffix, so their count is Ppc minus the lowest lane set (a
    // priority select, not an adder chain).
    for (int i = Ppc - 1; i >= 0; i--) begin
      if (emit_nx[i]) n_emit_nx = LnW'(Ppc - i);
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      emit_q     <= '0;  // row 0 has no output
      region_q   <= '0;  // not read where nothing is emitted
      n_emit_q   <= '0;
      emit_row_q <= 1'b0;
    end else if (issue) begin
      emit_q     <= emit_nx;
      region_q   <= region_nx;
      n_emit_q   <= n_emit_nx;
      emit_row_q <= emit_row_nx;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      core_col_q     <= '0;
      core_row_q     <= '0;
      core_slot_q    <= '0;
      frames_ahead_q <= '0;
    end else begin
      if (issue) begin
        if (core_col_q != last_col_q) begin
          core_col_q <= core_col_q + 1'b1;
        end else begin
          core_col_q  <= '0;
          core_slot_q <= (core_slot_q == SlotW'(Window)) ? '0 : core_slot_q + 1'b1;
          core_row_q  <= (core_row_q == last_row_q) ? '0 : core_row_q + 1'b1;
        end
      end
      frames_ahead_q <= frames_ahead_q + 2'(issue && core_fs) - 2'(read_fs);
    end
  end

  // The left edge (hls::disparity::edge_limit): lane i of the word at core_col_q is input
  // column x = c P + i, whose output column's window fits the right image for
  // k = x - edge_base candidates. k steps by P a word from i - edge_base at a row's start, an
  // add behind a register; its clamp to 0 .. NumDisp enters the issue delay line with the word.
  logic [Ppc*NumW-1:0] limit;
  for (genvar i = 0; i < Ppc; i++) begin : gen_k
    logic signed [XW:0] k0, k_q;
    assign k0 = $signed((XW + 1)'(i)) - $signed({1'b0, edge_base_q});
    always_ff @(posedge clk_i) begin
      if (!rst_ni) k_q <= k0;  // column 0 comes first
      else if (issue) k_q <= core_last_col ? k0 : k_q + $signed((XW + 1)'(Ppc));
    end
    assign limit[i*NumW +: NumW] = k_q < 0 ? '0
                                 : k_q > $signed((XW + 1)'(NumDisp)) ? NumW'(NumDisp)
                                                                     : NumW'(k_q);
  end

  // The core sees a beat PfLatency cycles after its issue: the prefilter's read, or as long a
  // delay of the raw pair, so both modes share one latency.
  localparam int unsigned InfoW = Ppc * NumW + 2 * Ppc + 2 * LbAW + HW + ColW;
  logic [PfLatency-1:0] dly_valid_q;
  logic [PfLatency*InfoW-1:0] dly_info_q;
  logic [PfLatency*2*BeatW-1:0] dly_raw_q;
  if (PfLatency == 1) begin : gen_dly1
    always_ff @(posedge clk_i) begin
      if (!rst_ni) dly_valid_q <= '0;
      else dly_valid_q <= issue;
    end
    always_ff @(posedge clk_i) begin
      dly_info_q <= {limit, emit, region, core_base, core_old_base, core_row_q, core_col_q};
      dly_raw_q  <= {have_r, have_l};
    end
  end else begin : gen_dly
    always_ff @(posedge clk_i) begin
      if (!rst_ni) dly_valid_q <= '0;
      else dly_valid_q <= {dly_valid_q[PfLatency-2:0], issue};
    end
    // Each stage loads with its own valid: different enables keep the delay out of SRLs,
    // whose slow clock-to-out would start the sums' address arithmetic.
    always_ff @(posedge clk_i) begin
      if (issue) begin
        dly_info_q[InfoW-1:0]   <= {limit, emit, region, core_base, core_old_base, core_row_q,
                                    core_col_q};
        dly_raw_q[2*BeatW-1:0]  <= {have_r, have_l};
      end
    end
    for (genvar k = 1; k < PfLatency; k++) begin : gen_stage
      always_ff @(posedge clk_i) begin
        if (dly_valid_q[k-1]) begin
          dly_info_q[k*InfoW +: InfoW]     <= dly_info_q[(k-1)*InfoW +: InfoW];
          dly_raw_q[k*2*BeatW +: 2*BeatW]  <= dly_raw_q[(k-1)*2*BeatW +: 2*BeatW];
        end
      end
    end
  end

  logic c_valid;
  logic [Ppc-1:0] c_emit, c_region;
  logic [Ppc*NumW-1:0] c_limit;
  logic [LbAW-1:0] c_base, c_old_base;
  logic [HW-1:0] c_row;
  logic [ColW-1:0] c_col;
  logic [BeatW-1:0] c_left, c_right, raw_l, raw_r;
  assign c_valid = dly_valid_q[PfLatency-1];
  assign {c_limit, c_emit, c_region, c_base, c_old_base, c_row, c_col} =
      dly_info_q[(PfLatency-1)*InfoW +: InfoW];
  assign {raw_r, raw_l} = dly_raw_q[(PfLatency-1)*2*BeatW +: 2*BeatW];
  assign c_left  = prefilter_q ? pf_l_data : raw_l;
  assign c_right = prefilter_q ? pf_r_data : raw_r;

  // ---- core ------------------------------------------------------------------------------
  logic s_valid;
  logic [Ppc*NumDisp*SadBits-1:0] s_sad;
  logic [Ppc*SadBits-1:0] s_tex;
  // The left edge's candidate counts ride the sums' tag; a clock before the SADs leave, they
  // are decoded into each lane's band mask, so the decision's leaves see a register.
  localparam int unsigned TagW = Ppc * (2 + NumW);
  logic [Ppc*NumW-1:0] s_limit, pre_limit;
  logic [TagW-1:0] s_tag;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [TagW-1:0] pre_tag;  // only its limits are read
  /* verilator lint_on UNUSEDSIGNAL */
  logic pre_en;
  scw_disparity_sums #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .Window(Window),
    .NumDisp(NumDisp), .TagBits(TagW)
  ) u_sums (
    .clk_i, .rst_ni, .cfg_dmin_i(dmin_q), .cfg_cap_i(cfg.prefilter_cap),
    .valid_i(c_valid), .col_i(c_col), .row_i(c_row), .base_i(c_base),
    .old_base_i(c_old_base),
    .left_i(c_left), .right_i(c_right), .tag_i({c_limit, c_emit, c_region}),
    .valid_o(s_valid), .sad_o(s_sad), .texture_o(s_tex), .tag_o(s_tag),
    .tag_pre_o(pre_tag), .tag_pre_en_o(pre_en)
  );
  assign s_limit   = s_tag[TagW-1 -: Ppc*NumW];
  assign pre_limit = pre_tag[TagW-1 -: Ppc*NumW];
  logic [Ppc*NumDisp-1:0] band_q;
  always_ff @(posedge clk_i) begin
    if (pre_en) begin
      for (int i = 0; i < Ppc; i++) begin
        for (int d = 0; d < NumDisp; d++) begin
          band_q[i*NumDisp + d] <= NumW'(d) < pre_limit[i*NumW +: NumW];
        end
      end
    end
  end

  logic [Ppc-1:0] d_valid;
  logic [OutW-1:0] d_disp;
  for (genvar i = 0; i < Ppc; i++) begin : gen_decide
    // A lane without an output pixel is not decided at all: its valid never reaches the queue.
    scw_disparity_decide #(.NumDisp(NumDisp), .SadBits(SadBits), .DminBits(WW)) u_decide (
      .clk_i, .rst_ni,
      .cfg_num_i(num_q), .cfg_dmin_i(dmin_q), .cfg_sad_limit_i(cfg.sad_limit),
      .cfg_texture_i(cfg.texture_threshold), .cfg_uniqueness_i(cfg.uniqueness_ratio),
      .cfg_subpixel_i(cfg.subpixel), .cfg_invalid_i(invalid_q),
      .valid_i(s_valid && s_tag[Ppc + i]), .region_i(s_tag[i]),
      .sad_i(s_sad[i*NumDisp*SadBits +: NumDisp*SadBits]),
      .band_i(band_q[i*NumDisp +: NumDisp]), .limit_i(s_limit[i*NumW +: NumW]),
      .texture_i(s_tex[i*SadBits +: SadBits]),
      .valid_o(d_valid[i]), .disp_o(d_disp[i*16 +: 16])
    );
  end

  // ---- result queue: Ppc banks of QueueWords, result k in bank k % Ppc ------------------
  // Results of a beat are a suffix of its lanes and an output beat takes a prefix of its
  // lanes, so both sides move consecutive positions: a rotation by the position's lane.
  logic [QW-1:0] head_q, tail_q;
  logic [LnW-1:0] n_in;
  logic [LaneW-1:0] rank [Ppc];
  always_comb begin
    n_in = '0;
    for (int i = 0; i < Ppc; i++) begin
      rank[i] = LaneW'(n_in);
      n_in    = n_in + LnW'(d_valid[i]);
    end
  end

  logic [15:0] bank_rd [Ppc];
  logic [15:0] lane_rd [Ppc];  // the result at head + i
  for (genvar b = 0; b < Ppc; b++) begin : gen_bank
    logic [15:0] mem_q [QueueWords];
    logic we;
    logic [QAW-1:0] waddr, raddr;
    logic [15:0] wdata;
    logic [QW-1:0] rpos;
    always_comb begin
      we    = 1'b0;
      waddr = '0;
      wdata = '0;
      for (int i = 0; i < Ppc; i++) begin
        if (d_valid[i] && (LaneW'(tail_q + QW'(rank[i])) == LaneW'(b) || Ppc == 1)) begin
          we    = 1'b1;
          waddr = QAW'((tail_q + QW'(rank[i])) >> $clog2(Ppc));
          wdata = d_disp[i*16 +: 16];
        end
      end
    end
    always_ff @(posedge clk_i) begin
      if (we) mem_q[waddr] <= wdata;
    end
    // The bank's next position at or after head: head + ((b - head) mod Ppc).
    if (Ppc == 1) begin : gen_rpos1
      assign rpos = head_q;
    end else begin : gen_rpos
      assign rpos = head_q + QW'(LaneW'(LaneW'(b) - LaneW'(head_q)));
    end
    assign raddr      = QAW'(rpos >> $clog2(Ppc));
    assign bank_rd[b] = mem_q[raddr];
  end
  for (genvar i = 0; i < Ppc; i++) begin : gen_lane_rd
    if (Ppc == 1) begin : gen_one
      assign lane_rd[i] = bank_rd[0];
    end else begin : gen_rot
      assign lane_rd[i] = bank_rd[LaneW'(head_q + QW'(i))];
    end
  end

  // ---- reader ----------------------------------------------------------------------------
  logic [ColW-1:0] out_col_q;
  logic [HW-1:0] out_row_q;
  logic out_valid_q, out_sof_q, out_eol_q, adv, started, allowed, read;
  logic [OutW-1:0] out_data_q, rd_beat;
  // n_out_q, lanes_q (its lanes, a prefix), row_comp_q and out_first_q describe the word at
  // (out_col_q, out_row_q) and are formed for the next word on a read, from registers: rows
  // R .. H - R - 1 and columns below W - R are computed.
  logic [Ppc-1:0] lanes_q, lanes_nx;
  logic [LnW-1:0] n_out_q, n_out_nx;
  logic row_comp_q, row_comp_nx, out_first_q, out_last_col, out_last_row;
  // out_last_col_q: out_col_q == last_col_q, kept beside the column on a read (rows are at
  // least 3 words wide, see the sums, so column 0 is never the last). row_after_q: whether
  // the row after out_row_q is computed, a function of out_row_q alone, registered every clock;
  // it is read only at a row's last word, at least 2 clocks after the row changed, so it is
  // never stale. The next word's lanes then start at registers rather than behind the row and
  // column compares.
  logic out_last_col_q, row_after_q;
  assign out_last_col = out_last_col_q;
  assign out_last_row = out_row_q == last_row_q;
  /* verilator lint_off UNSIGNED */
  always_ff @(posedge clk_i) begin
    row_after_q <= !out_last_row && (out_row_q >= HW'(R - 1)) && (XW'(out_row_q) < hrm_q);
  end
  /* verilator lint_on UNSIGNED */
  assign row_comp_nx = out_last_col ? row_after_q : row_comp_q;
  // The lanes are a prefix, so their count is the highest lane set plus one (a priority
  // select, not an adder chain).
  always_comb begin
    n_out_nx = '0;
    for (int i = 0; i < Ppc; i++) begin
      lanes_nx[i] = row_comp_nx && (out_last_col ? oz_q[i]
                                                 : {1'b0, out_col_q} < ocm_q[i*OcW +: OcW]);
      if (lanes_nx[i]) n_out_nx = LnW'(i + 1);
    end
  end
  assign read_fs = read && out_first_q;
  assign started = !(out_first_q && (frames_ahead_q == '0));
  assign allowed = started && (ready_q >= QCW'(n_out_q));
  assign adv     = !out_valid_q || out_ready_i;
  assign read    = adv && allowed;

  always_comb begin
    for (int i = 0; i < Ppc; i++) begin
      rd_beat[i*16 +: 16] = invalid_q;
      if (lanes_q[i]) rd_beat[i*16 +: 16] = lane_rd[i];
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      out_col_q   <= '0;
      out_row_q   <= '0;
      out_first_q <= 1'b1;
      out_last_col_q <= 1'b0;
      row_comp_q  <= 1'b0;
      lanes_q     <= '0;
      n_out_q     <= '0;
      out_valid_q <= 1'b0;
      head_q      <= '0;
      tail_q      <= '0;
      count_q     <= '0;
      core_room_q <= 1'b1;
      ready_q     <= '0;
      err_o       <= 1'b0;
    end else begin
      if (adv) out_valid_q <= read;
      if (read) begin
        head_q      <= head_q + QW'(n_out_q);
        out_first_q <= out_last_col && out_last_row;
        row_comp_q  <= row_comp_nx;
        lanes_q     <= lanes_nx;
        n_out_q     <= n_out_nx;
        out_last_col_q <= !out_last_col && (out_col_q == last_col_m1_q);
        if (!out_last_col) begin
          out_col_q <= out_col_q + 1'b1;
        end else begin
          out_col_q <= '0;
          out_row_q <= out_last_row ? '0 : out_row_q + 1'b1;
        end
      end
      tail_q      <= tail_q + QW'(n_in);
      count_q     <= cnt_nx[{issue, read}];
      core_room_q <= room_nx[{issue, read}];
      ready_q     <= read ? ready_rd : ready_nrd;
      if (err_in) err_o <= 1'b1;
    end
  end

  // [{issue, read}]: the count's next value and whether it leaves room for Ppc more results,
  // count + e - o <= Queue - Ppc, that is le[Ppc + o - e] with le[k] = count <= Queue - 2 Ppc + k:
  // compares against constants, picked by the small e and o. The pick is an AND-OR with a
  // one-hot index: each index bit is a function of the two small registered counts alone (one
  // LUT), where an adder and a 2 Ppc + 1-way select by its sum were the stage's worst path.
  logic [QCW-1:0] cnt_nx [4];
  logic [3:0] room_nx;
  logic [2*Ppc:0] le;
  logic [QCW-1:0] ready_rd, ready_nrd;
  for (genvar k = 0; k <= 2 * Ppc; k++) begin : gen_le
    assign le[k] = count_q <= QCW'(Queue - 2 * Ppc + k);
  end
  for (genvar c = 0; c < 4; c++) begin : gen_cnt
    localparam bit Iss = c[1];
    localparam bit Rd  = c[0];
    // pick[k]: Ppc + o - e == k, as equalities of the counts with constants (no adder).
    logic [2*Ppc:0] pick;
    always_comb begin
      pick = '0;
      for (int e = 0; e <= (Iss ? Ppc : 0); e++) begin
        for (int o = 0; o <= (Rd ? Ppc : 0); o++) begin
          if ((!Iss || n_emit_q == LnW'(e)) && (!Rd || n_out_q == LnW'(o)))
            pick[Ppc + o - e] = 1'b1;
        end
      end
    end
    assign cnt_nx[c]  = count_q + (Iss ? QCW'(n_emit_q) : '0) - (Rd ? QCW'(n_out_q) : '0);
    assign room_nx[c] = |(pick & le);
  end
  assign ready_nrd = ready_q + QCW'(n_in);
  assign ready_rd  = ready_q + QCW'(n_in) - QCW'(n_out_q);

  always_ff @(posedge clk_i) begin
    if (read) begin
      out_data_q <= rd_beat;
      out_sof_q  <= out_first_q;
      out_eol_q  <= out_last_col;
    end
  end

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
  assign out_sof_o   = out_sof_q;
  assign out_eol_o   = out_eol_q;
endmodule
