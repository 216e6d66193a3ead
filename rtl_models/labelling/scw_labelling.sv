// SPDX-License-Identifier: Apache-2.0
// Labelling: one-pass tiled connected-component labelling of a disparity stream into objects.
`default_nettype none

// The C++ twin is scw::hls::labelling::Labelling (hls/labelling/labelling.hpp) clocked by
// scw::sim::LabellingModel, clock for clock: same in_ready, out_valid and out data every cycle.
// The rules, the join and the descriptor are in docs/labelling.md. A beat carries Lanes pixels;
// lane i (scw_labelling_lane) labels the i-th of Lanes vertical strips of whole tile columns,
// one pixel per clock. Phases:
//   Init     after reset: clear the parent RAM (a bank per lane side by side), with lanes also
//            the strip-border RAMs, and measure the strips (tile_w x tile columns / Lanes)
//   Frame    one lane: S0 takes the pixel, S1 decides its node (a new one from the lane's pool
//            of LaneNodes: lane i's are i * LaneStride on) and queues edges, P4 .. P6 add it to
//            its node's descriptor, the merge unit (union-find) runs alongside. Lanes: a beat goes whole into
//            the FIFO of the lane whose strip it is in; every lane does the same on its strip
//   Drain    after the frame's last beat or a sof in mid-frame: wait for the lanes
//   Border   (lanes only) every row: the two pixels either side of each strip border that join
//            queue an edge for a merge unit over the whole node space (B0 .. B4)
//   Resolve  every used node in ascending order (R0 .. R3): its root (parents point to smaller
//            nodes, so the parent's root is already known) and its descriptor into the root's;
//            the sweep copies each lane's label count for Emit. Then the next frame may start
// Emit runs alongside the next frame (it reads only the root and sum RAMs, which the next
// frame's Resolve waits for): every used node again (E0, E1); roots of at least min_area
// pixels leave as objects, up to MaxObjects; then the status word with out_last_o.
// Every RAM is a scw_ram_sdp with a registered read (read-first: a read in the clock of a write
// to the same address returns the old word); where the model's next stage needs that word it
// forwards the previous clock's write, as the model does.
// A sof in mid-frame closes the frame early (it is taken afterwards); a beat before any sof is
// dropped and flags the frame it precedes; a misplaced eol flags its frame. err_o is sticky.
// cfg_* are static: set them before rst_ni rises.
module scw_labelling #(
  parameter int unsigned MaxWidthPx    /*verilator public*/ = 32,
  parameter int unsigned MaxHeight     /*verilator public*/ = 24,
  parameter int unsigned MaxTilesX     /*verilator public*/ = 2,
  parameter int unsigned MaxTilesY     /*verilator public*/ = 2,
  parameter int unsigned LabelsPerTile /*verilator public*/ = 16,
  parameter int unsigned MaxObjects    /*verilator public*/ = 16,
  parameter int unsigned Lanes         /*verilator public*/ = 1,
  localparam int unsigned OutW = scw_pkg::ObjWordBits
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  // static configuration (hls::labelling::LabellingConfig)
  input  logic [15:0]     cfg_width_i,
  input  logic [15:0]     cfg_height_i,
  input  logic [scw_pkg::LabellingCfgBits-1:0] cfg_labelling_i,  // scw_pkg::labelling_cfg_t
  // disparities, Q11.4
  input  logic            in_valid_i,
  output logic            in_ready_o,
  input  logic [16*Lanes-1:0] in_data_i,  // pixel k at [16 k +: 16]
  input  logic            in_sof_i,
  input  logic            in_eol_i,
  // objects, then the frame's status word with last
  output logic            out_valid_o,
  input  logic            out_ready_i,
  output logic [OutW-1:0] out_data_o,
  output logic            out_last_o,
  output logic            err_o
);
  // The frame's labels: MaxTilesX x MaxTilesY x LabelsPerTile, each lane drawing on its share.
  localparam int unsigned Nodes /*verilator public*/ = MaxTilesX * MaxTilesY * LabelsPerTile;
  // hls::labelling::kEdgeQueue, kTakeRoom: a lane takes a pixel while at most EdgeQueue -
  // TakeRoom edges are queued (two each from the pixel being taken and the five in P1 .. P5).
  localparam int unsigned EdgeQueue /*verilator public*/ = 16;
  localparam int unsigned TakeRoom /*verilator public*/ = 12;
  // LabellingParams::kLaneFifo: beats each lane's FIFO holds (lanes only).
  localparam int unsigned LaneWidthPx = MaxWidthPx / Lanes;
  localparam int unsigned LaneFifo /*verilator public*/ =
      (LaneWidthPx / Lanes > 2) ? LaneWidthPx / Lanes : 2;
  localparam int unsigned LaneNodes = Nodes / Lanes;
  // LabellingParams::kLaneStride, kNodeSpace: with lanes a lane's nodes start at a power of two,
  // so that its number and a node's address in its banks are bit fields of the node.
  localparam int unsigned LaneStride = (Lanes == 1) ? LaneNodes : (1 << $clog2(LaneNodes));
  localparam int unsigned NodeSpace = Lanes * LaneStride;
  // Labelling::kInitClocks: the parent banks side by side; with lanes also the border RAMs (a row
  // per clock), the strip measure (a tile column per clock) and the lanes' first columns'
  // powers (scw_labelling_lane, 8 clocks after the measure).
  localparam int unsigned InitMax = (LaneStride > MaxHeight) ? LaneStride : MaxHeight;
  localparam int unsigned InitClocks /*verilator public*/ =
      (Lanes == 1) ? Nodes : (InitMax > MaxTilesX + 8 ? InitMax : MaxTilesX + 8);
  // Labelling::kBorderQueue: the border sweep reads a row while five rows' edges fit (the row
  // read and the four in B1 .. B4).
  localparam int unsigned BorderQueue = 16;
  localparam int unsigned BorderRows = 5;
  // Descriptor field widths (hls::labelling::desc_widths, checked equal by
  // sim::labelling_params_match): an object is a set of the frame's pixels and every term is
  // non-negative, so a field is at most its value for the whole W x H frame: area <= W H, a
  // column <= W - 1, a row <= H - 1, a disparity <= 0x7fff, m_pq <= S_p(W) S_q(H) with
  // S_k(n) = sum_{i < n} i^k, sum_d <= W H 0x7fff and sum_dd <= W H 0x7fff^2 (1280 x 480: 20,
  // 11, 9, 15, m10 .. m03 29 28 39 37 36 49 47 45 44, sum_d 35 and sum_dd 50 bits, 569 in all).
  // The bits of 0 .. b (1 for b = 0), at most 64: the width of a field whose largest value is b.
  function automatic int unsigned bits_upto(input logic [127:0] b);
    // assigned to its name: Yosys 0.23 does not parse a return statement
    bits_upto = (b == 0) ? 1 : ($clog2(b + 1) > 64 ? 64 : $clog2(b + 1));
  endfunction
  localparam logic [127:0] Wd = 128'(MaxWidthPx);
  localparam logic [127:0] Hd = 128'(MaxHeight);
  localparam logic [127:0] Sx1 = Wd * (Wd - 1) / 2;
  localparam logic [127:0] Sx2 = (Wd - 1) * Wd * (2 * Wd - 1) / 6;
  localparam logic [127:0] Sx3 = Sx1 * Sx1;
  localparam logic [127:0] Sy1 = Hd * (Hd - 1) / 2;
  localparam logic [127:0] Sy2 = (Hd - 1) * Hd * (2 * Hd - 1) / 6;
  localparam logic [127:0] Sy3 = Sy1 * Sy1;
  localparam int unsigned AreaW /*verilator public*/ = $clog2(Wd * Hd + 1);
  localparam int unsigned PosXW /*verilator public*/ = (MaxWidthPx > 1) ? $clog2(Wd) : 1;
  localparam int unsigned PosYW /*verilator public*/ = (MaxHeight > 1) ? $clog2(Hd) : 1;
  localparam int unsigned DispW /*verilator public*/ = 15;
  localparam int unsigned M10W /*verilator public*/ = bits_upto(Sx1 * Hd);
  localparam int unsigned M01W /*verilator public*/ = bits_upto(Wd * Sy1);
  localparam int unsigned M20W /*verilator public*/ = bits_upto(Sx2 * Hd);
  localparam int unsigned M11W /*verilator public*/ = bits_upto(Sx1 * Sy1);
  localparam int unsigned M02W /*verilator public*/ = bits_upto(Wd * Sy2);
  localparam int unsigned M30W /*verilator public*/ = bits_upto(Sx3 * Hd);
  localparam int unsigned M21W /*verilator public*/ = bits_upto(Sx2 * Sy1);
  localparam int unsigned M12W /*verilator public*/ = bits_upto(Sx1 * Sy2);
  localparam int unsigned M03W /*verilator public*/ = bits_upto(Wd * Sy3);
  // sum_d <= W H 0x7fff, sum_dd <= W H 0x7fff^2 (1280 x 480: 35 and 50 bits)
  localparam logic [127:0] DMax = 128'h7fff;
  localparam int unsigned SumDW /*verilator public*/ = $clog2(Wd * Hd * DMax + 1);
  localparam int unsigned SumDDW /*verilator public*/ = bits_upto(Wd * Hd * DMax * DMax);
  localparam int unsigned DescW /*verilator public*/ =
      AreaW + 4 * PosXW + 4 * PosYW + 2 * DispW + M10W + M01W + M20W + M11W + M02W + M30W +
      M21W + M12W + M03W + SumDW + SumDDW;
  localparam int unsigned XW     = $clog2(MaxWidthPx);       // 0 .. MaxWidthPx - 1
  localparam int unsigned YW     = $clog2(MaxHeight + 1);    // 0 .. MaxHeight
  localparam int unsigned HW     = (MaxHeight > 1) ? $clog2(MaxHeight) : 1;  // a border row
  localparam int unsigned LabW   = (LaneStride > 1) ? $clog2(LaneStride) : 1;  // a lane's node
  localparam int unsigned CntW   = $clog2(LaneNodes + 1);
  localparam int unsigned NodeW  = (NodeSpace > 1) ? $clog2(NodeSpace) : 1;
  localparam int unsigned N1W    = $clog2(NodeSpace + 1);     // node + 1, 0 = none
  localparam int unsigned PW     = NodeW + 1;                 // parent word {linked, parent}
  localparam int unsigned LNodeW = (LaneStride > 1) ? $clog2(LaneStride) : 1;
  localparam int unsigned ObjW   = $clog2(MaxObjects + 1);
  localparam int unsigned InitW  = (InitClocks > 1) ? $clog2(InitClocks) : 1;
  localparam int unsigned LaneSW = (Lanes > 1) ? $clog2(Lanes) : 1;  // a lane number
  localparam int unsigned BordW  = N1W + 16;                 // border word {node + 1, d}
  localparam logic [N1W-1:0] LaneStrideN1 = N1W'(LaneStride);
  localparam logic [16:0] Ppb = 17'(Lanes);                   // pixels per beat

  if (MaxWidthPx < 2 || MaxHeight < 1 || MaxWidthPx > 65535 || MaxHeight > 65535)
  begin : gen_bad_size
    $error("scw_labelling: an image of 2 x 1 .. 65535 x 65535");
  end
  if (MaxTilesX < 1 || MaxTilesY < 1 || LabelsPerTile < 1 || MaxObjects < 1) begin : gen_bad_cap
    $error("scw_labelling: capacities are at least 1");
  end
  if (!(Lanes == 1 || Lanes == 2 || Lanes == 4) || MaxTilesX % Lanes != 0 ||
      MaxWidthPx % Lanes != 0) begin : gen_bad_lanes
    $error("scw_labelling: 1, 2 or 4 lanes, over which the tile columns and width split evenly");
  end

  scw_pkg::labelling_cfg_t cfg;
  assign cfg = cfg_labelling_i;
  if ($bits(cfg) != scw_pkg::LabellingCfgBits) begin : gen_bad_cfg
    $error("scw_labelling: scw_pkg::LabellingCfgBits is not labelling_cfg_t's width");
  end

  // Descriptors (hls::labelling::Object) are scw_pkg::label_desc_t.
  typedef enum logic [2:0] {PhInit, PhFrame, PhDrain, PhBorder, PhResolve} phase_e;

  // ---- registers ---------------------------------------------------------------------------
  phase_e phase_q, phase_d;
  logic [InitW-1:0] init_q;
  // frame position (of the next beat) and flags
  logic in_frame_q, in_frame_d, in_frame;  // in_frame: in_frame_q's twin, beside the phase flags
  logic [XW-1:0] x_q, x_d, lane_col_q, lane_col_d;
  logic [YW-1:0] y_q, y_d;
  logic [LaneSW-1:0] lane_q, lane_d;
  logic err_pending_q, err_pending_d, err_frame_q, err_frame_d, err_sticky_q, err_sticky_d;
  logic tile_ovf_q, tile_ovf_d;
  // Emit: its frame's flags and label counts, objects sent
  logic emit_q, emit_d, emit_tile_ovf_q, emit_err_q, obj_ovf_q, obj_ovf_d;
  logic [ObjW-1:0] emitted_q, emitted_d;
  logic [CntW-1:0] emit_cnt_q [Lanes];
  // the strips, measured in Init: every lane's but the last is strip_q pixels wide; lane i's
  // starts at column i x strip_q (x0_q, lane i at [16 i +: 16]), the last is last_w_q wide
  logic [15:0] strip_q, last_w_q;
  logic [Lanes*16-1:0] x0_q;
  // R2's root written last clock
  logic rfwd_valid_q, rfwd_valid_d;
  logic [NodeW-1:0] rfwd_node_q, rfwd_root_q;
  // the node sweep of Resolve and Emit
  logic sweep_active_q, sweep_active_d;
  logic [LaneSW-1:0] sweep_lane_q, sweep_lane_d;
  logic [LabW-1:0] sweep_label_q, sweep_label_d;
  logic [CntW:0] sweep_next_q, sweep_next_d;  // sweep_label_q + 1, kept beside it
  // Resolve and Emit pipelines
  logic r1_valid_q, r1_valid_d, r2_valid_q, r2_valid_d, r2_self_q, r2_self_d;
  logic r3_valid_q, r4_valid_q, r5_valid_q, r6_valid_q;
  logic e1_valid_q, e1_valid_d, e2_valid_q, e2_valid_d, e2_obj_q, e2_obj_d;
  logic [NodeW-1:0] r1_node_q, r1_node_d, r2_node_q, r2_node_d, r2_parent_q, r2_parent_d;
  logic [NodeW-1:0] r3_root_q, r4_root_q, r5_root_q, r6_root_q, e1_node_q, e1_node_d;
  logic r3_self_q;
  // output register
  logic out_valid_q, out_valid_d, out_load, out_last_q, out_last_d;
  logic [OutW-1:0] out_data_q, out_data_d;

  // ---- phases ------------------------------------------------------------------------------
  // One flag a phase, decoded from phase_d into registers: they steer the RAM ports and the
  // lanes, and an asynchronous clear-to-output (891 ps) would stand in those paths' time. Their
  // reset is synchronous, to PhInit's decode: phase_d is the next phase of the state the reset
  // cuts, so a decode of it on a single reset edge left the old phase's flags for one clock
  // after (a reset held one clock lost a clock of Init and could run a clock of the cut phase:
  // docs/soak.md, "Reset").
  logic ph_init, ph_frame, ph_pixels, ph_border, ph_resolve;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_frame   <= 1'b0;
      ph_init    <= 1'b1;
      ph_frame   <= 1'b0;
      ph_pixels  <= 1'b0;
      ph_border  <= 1'b0;
      ph_resolve <= 1'b0;
    end else begin
      in_frame   <= in_frame_d;
      ph_init    <= phase_d == PhInit;
      ph_frame   <= phase_d == PhFrame;
      ph_pixels  <= (phase_d == PhFrame) || (phase_d == PhDrain);
      ph_border  <= phase_d == PhBorder;
      ph_resolve <= phase_d == PhResolve;
    end
  end
  logic drained;

  // ---- the stage's ports into the lanes' banks (Init, Border, Resolve) ---------------------
  logic par_re, par_we;
  logic [NodeW-1:0] par_raddr, par_waddr;
  logic [PW-1:0] par_wdata, par_rd;
  logic desc_re;
  logic [DescW-1:0] desc_rd;
  logic [CntW-1:0] sw_count;
  logic frame_end;
  // per lane, flattened: lane i at [i * W +: W]
  logic [Lanes-1:0] lane_take, lane_can_take, lane_idle, lane_ovf, lane_left_we, lane_right_we;
  logic [Lanes*16-1:0] lane_px;
  logic [Lanes*YW-1:0] lane_brow;
  logic [Lanes*BordW-1:0] lane_bword;
  logic [Lanes*PW-1:0] lane_par_rd, lane_bpar_rd;
  logic [LNodeW-1:0] bpar_raddr;  // the border merge unit's read port (its node's low bits)
  logic [Lanes*DescW-1:0] lane_desc_rd;
  logic [Lanes*CntW-1:0] lane_count;
  logic [Lanes*16-1:0] lane_x0, lane_width;

  // ---- S0 of the stage: frame the beat, pass it to its lane --------------------------------
  logic room, take, sof_mid, frame_start, beat_drop, beat_in, eol_err, frame_last;
  logic [XW-1:0] xe, lane_cole;
  logic [YW-1:0] ye;
  logic [LaneSW-1:0] lanee;
  logic [XW-1:0] xn, lane_coln;
  logic [YW-1:0] y1;
  logic x_wrap;
  logic [Lanes-1:0] fifo_room_d, fifo_valid;
  logic room_q;

  // With lanes, the room of the next beat's lane FIFO is a register (the FIFO's in_ready, formed
  // a clock early from each FIFO's count, push and pop and picked by the next clock's lane): no
  // count compare or choice by lane stands between the registers and the lane FIFO's push.
  assign room        = (Lanes == 1) ? lane_can_take[0] : room_q;
  assign in_ready_o  = ph_frame && room && !(in_frame && in_sof_i);
  assign take        = in_valid_i && in_ready_o;
  assign sof_mid     = ph_frame && in_frame && in_valid_i && in_sof_i;
  assign frame_start = take && !in_frame && in_sof_i;
  assign beat_drop   = take && !in_frame && !in_sof_i;  // outside any frame
  assign beat_in     = take && (in_frame || in_sof_i);  // a beat of the frame

  // The beat's position: a sof restarts the counters. Whether the beat ends its row, the frame or
  // its lane's strip is compared from the registers for both cases, so that the choice by
  // frame_start (which follows in_ready) comes last.
  logic x_wrap_cont, x_wrap_start, y_last_cont, y_last_start, strip_end_cont, strip_end_start;
  assign xe        = frame_start ? '0 : x_q;
  assign ye        = frame_start ? '0 : y_q;
  assign lanee     = frame_start ? '0 : lane_q;
  assign lane_cole = frame_start ? '0 : lane_col_q;
  assign xn        = xe + XW'(Lanes);  // (only taken when the row goes on: no wrap)
  assign lane_coln = lane_cole + XW'(Lanes);
  assign y1        = ye + 1'b1;
  // The last positions (and the last but one, and whether they fit the counters) of the
  // configuration and of the strips, as registers: static while frames stream (the strips are
  // measured in PhInit, at least 8 clocks before the first beat), so every compare below is of
  // two registers. (Subtracts from strip_q in front of the compares measured 3,747 ps at P = 4.)
  // x + P against the last position is x against the last but one: a compare with no adder;
  // last < 2^XW is a range of the width against constants.
  localparam logic [16:0] FitsEnd = Ppb + (17'd1 << XW);
  logic [16:0] w_last_q, h_last_q, s_last_q;
  logic [XW-1:0] w_prev_q, s_prev_q;
  logic [YW-1:0] h_prev_q;
  logic w_fits_q, s_fits_q, h_fits_q;
  always_ff @(posedge clk_i) begin
    w_last_q <= {1'b0, cfg_width_i} - Ppb;
    s_last_q <= {1'b0, strip_q} - Ppb;
    h_last_q <= {1'b0, cfg_height_i} - 17'd1;
    w_prev_q <= XW'({1'b0, cfg_width_i} - {Ppb[15:0], 1'b0});
    s_prev_q <= XW'({1'b0, strip_q} - {Ppb[15:0], 1'b0});
    h_prev_q <= YW'({1'b0, cfg_height_i} - 17'd2);
    w_fits_q <= ({1'b0, cfg_width_i} >= Ppb) && ({1'b0, cfg_width_i} < FitsEnd);
    s_fits_q <= ({1'b0, strip_q} >= Ppb) && ({1'b0, strip_q} < FitsEnd);
    // y + 1 against the last row as y against the height minus 2, for heights 2 .. 2^YW (a
    // height of 1 wraps y + 1 to 0: only an all-ones y matches, below)
    h_fits_q <= ({1'b0, cfg_height_i} >= 17'd2) && ({1'b0, cfg_height_i} < 17'd1 + (17'd1 << YW));
  end
  assign x_wrap_start    = w_last_q == '0;
  assign y_last_start    = h_last_q == '0;
  assign strip_end_start = s_last_q == '0;
  // x_q == w_last_q, lane_col_q == s_last_q and y_q == h_last_q as registers: each compared a
  // clock early for every value its counter may take next (see x_d, lane_col_d, y_d), picked as
  // the counter is (the compares had stood before the next beat's lane and the pick of its FIFO's
  // room; y's, through frame_last and in_frame_d, measured 3,569 ps in the P = 4 top)
  logic x_wrap_next, strip_end_next, y_last_next, y_wrap_last;
  assign y_wrap_last = h_fits_q ? (y_q == h_prev_q) : ((h_last_q == '0) && (&y_q));
  always_comb begin
    x_wrap_next    = 17'(x_q) == w_last_q;
    strip_end_next = 17'(lane_col_q) == s_last_q;
    y_last_next    = 17'(y_q) == h_last_q;
    if (beat_in && x_wrap) y_last_next = frame_start ? (h_last_q == 17'd1) : y_wrap_last;
    else if (beat_in && frame_start) y_last_next = h_last_q == '0;
    if (beat_in) begin
      if (x_wrap) begin
        x_wrap_next = w_last_q == '0;
      end else if (frame_start) begin
        x_wrap_next = 17'(XW'(Lanes)) == w_last_q;
      end else begin
        x_wrap_next = w_fits_q && (x_q == w_prev_q);
      end
      if (x_wrap || (frame_start ? strip_end_start : strip_end_cont)) begin
        strip_end_next = s_last_q == '0;
      end else if (frame_start) begin
        strip_end_next = 17'(XW'(Lanes)) == s_last_q;
      end else begin
        strip_end_next = s_fits_q && (lane_col_q == s_prev_q);
      end
    end
  end
  always_ff @(posedge clk_i) begin
    x_wrap_cont    <= x_wrap_next;
    strip_end_cont <= strip_end_next;
    y_last_cont    <= y_last_next;
  end
  assign x_wrap     = frame_start ? x_wrap_start : x_wrap_cont;
  assign frame_last = beat_in && x_wrap && (frame_start ? y_last_start : y_last_cont);
  assign eol_err    = beat_in && (in_eol_i != x_wrap);

  always_comb begin
    x_d        = x_q;
    y_d        = y_q;
    lane_d     = lane_q;
    lane_col_d = lane_col_q;
    if (beat_in) begin
      if (x_wrap) begin
        x_d        = '0;
        y_d        = y1;
        lane_d     = '0;
        lane_col_d = '0;
      end else begin
        x_d = xn;
        y_d = ye;
        if (frame_start ? strip_end_start : strip_end_cont) begin
          lane_d     = lanee + 1'b1;
          lane_col_d = '0;
        end else begin
          lane_d     = lanee;
          lane_col_d = lane_coln;
        end
      end
    end
  end

  // ---- the lanes, and with lanes their FIFOs -------------------------------------------------
  if (Lanes == 1) begin : gen_one_lane
    assign lane_take     = beat_in;
    assign lane_px       = in_data_i;
    assign fifo_room_d   = 1'b0;
    assign room_q        = 1'b0;
    assign fifo_valid    = 1'b0;
    assign strip_q       = cfg_width_i;
    assign x0_q          = '0;
    assign last_w_q      = cfg_width_i;
    assign lane_x0       = x0_q;
    assign lane_width    = last_w_q;
    logic unused_border;  // one strip: no borders
    assign unused_border = ^{lane_left_we, lane_right_we, lane_brow, lane_bword, fifo_room_d, room_q};
  end else begin : gen_fifos
    for (genvar i = 0; i < Lanes; i++) begin : gen_fifo
      logic f_valid, f_pop, a_valid_q, a_pop, h_valid_q, h_pop;
      logic [16*Lanes-1:0] f_data, a_data_q, h_data_q;
      logic [LaneSW-1:0] sub_q;
      logic f_push, f_full_next;
      logic [$clog2(LaneFifo + 1)-1:0] f_count;

      // The lane takes its pixels from a head register that the FIFO fills through one more
      // (A, then H): the FIFO's memory is a block RAM, and synthesis makes A its read register
      // (2.5 ns clock to output), too slow to pick a pixel from and test it in the lane's P0 in
      // the same clock; H is the RAM's output register.
      assign fifo_valid[i] = f_valid || a_valid_q || h_valid_q;
      assign f_push       = beat_in && (lanee == LaneSW'(i));
      assign lane_take[i] = ph_pixels && h_valid_q && lane_can_take[i];
      assign h_pop        = lane_take[i] && (sub_q == LaneSW'(Lanes - 1));
      assign a_pop        = a_valid_q && (!h_valid_q || h_pop);
      assign f_pop        = f_valid && (!a_valid_q || a_pop);
      assign lane_px[i*16 +: 16] = h_data_q[sub_q*16 +: 16];
      assign lane_x0[i*16 +: 16]    = (i == 0) ? 16'd0 : x0_q[i*16 +: 16];
      assign lane_width[i*16 +: 16] = (i + 1 < Lanes) ? strip_q : last_w_q;

      /* verilator lint_off PINCONNECTEMPTY */
      scw_fifo #(.Width(16 * Lanes), .Depth(LaneFifo)) u_fifo (
        .clk_i,
        .rst_ni,
        .in_valid_i (f_push),
        .in_ready_o (),
        .in_data_i  (in_data_i),
        .out_valid_o(f_valid),
        .out_ready_i(f_pop),
        .out_data_o (f_data),
        .count_o    (f_count)
      );
      /* verilator lint_on PINCONNECTEMPTY */

      // The FIFO is full next clock when it is full now and nothing leaves, or one short and a
      // beat enters while nothing leaves (a beat enters only with room): fifo_room_d[i] is the
      // FIFO's in_ready next clock.
      assign f_full_next = !f_pop && ((32'(f_count) == LaneFifo) ||
                                      ((32'(f_count) == LaneFifo - 1) && f_push));
      assign fifo_room_d[i] = !f_full_next;

      // The head register, and the pixel of it the lane takes next.
      always_ff @(posedge clk_i) begin
        if (!rst_ni) begin
          sub_q     <= '0;
          a_valid_q <= 1'b0;
          h_valid_q <= 1'b0;
        end else begin
          if (lane_take[i]) sub_q <= sub_q + 1'b1;
          if (f_pop) a_valid_q <= 1'b1;
          else if (a_pop) a_valid_q <= 1'b0;
          if (a_pop) h_valid_q <= 1'b1;
          else if (h_pop) h_valid_q <= 1'b0;
        end
      end
      always_ff @(posedge clk_i) begin
        if (f_pop) a_data_q <= f_data;
        if (a_pop) h_data_q <= a_data_q;
      end
    end
  end

  if (Lanes > 1) begin : gen_room
    // The lane of the next beat: lane_d, or lane 0 outside a frame (as room reads lane_q then).
    // After reset every FIFO is empty.
    always_ff @(posedge clk_i) begin
      if (!rst_ni) room_q <= 1'b1;
      else room_q <= fifo_room_d[in_frame_d ? lane_d : '0];
    end
  end

  for (genvar i = 0; i < Lanes; i++) begin : gen_lane
    scw_labelling_lane #(
      .MaxWidthPx   (MaxWidthPx),
      .MaxHeight    (MaxHeight),
      .MaxTilesX    (MaxTilesX),
      .MaxTilesY    (MaxTilesY),
      .LabelsPerTile(LabelsPerTile),
      .Lanes        (Lanes),
      .Lane         (i),
      .EdgeQueue    (EdgeQueue),
      .TakeRoom     (TakeRoom),
      .AreaW        (AreaW),
      .PosXW        (PosXW),
      .PosYW        (PosYW),
      .DispW        (DispW),
      .M10W         (M10W),
      .M01W         (M01W),
      .M20W         (M20W),
      .M11W         (M11W),
      .M02W         (M02W),
      .M30W         (M30W),
      .M21W         (M21W),
      .M12W         (M12W),
      .M03W         (M03W),
      .SumDW        (SumDW),
      .SumDDW       (SumDDW)
    ) u_lane (
      .clk_i,
      .rst_ni,
      .cfg_tile_w_i (cfg.tile_w),
      .cfg_tile_h_i (cfg.tile_h),
      .cfg_floor_i  (cfg.floor),
      .x0_i         (lane_x0[i*16 +: 16]),
      .width_i      (lane_width[i*16 +: 16]),
      .en_i         (ph_pixels),
      .frame_end_i  (frame_end),
      .take_i       (lane_take[i]),
      .d_i          (lane_px[i*16 +: 16]),
      .can_take_o   (lane_can_take[i]),
      .idle_o       (lane_idle[i]),
      .ovf_o        (lane_ovf[i]),
      .left_we_o    (lane_left_we[i]),
      .right_we_o   (lane_right_we[i]),
      .border_row_o (lane_brow[i*YW +: YW]),
      .border_word_o(lane_bword[i*BordW +: BordW]),
      .init_i       (ph_init && (32'(init_q) < 32'(LaneStride))),
      .init_addr_i  (LNodeW'(init_q)),
      .par_re_i     (par_re),
      .par_raddr_i  (par_raddr),
      .par_we_i     (par_we),
      .par_waddr_i  (par_waddr),
      .par_wdata_i  (par_wdata),
      .par_rd_o     (lane_par_rd[i*PW +: PW]),
      .bpar_raddr_i (bpar_raddr),
      .bpar_rd_o    (lane_bpar_rd[i*PW +: PW]),
      .desc_re_i    (desc_re),
      .desc_raddr_i (r2_node_q),
      .desc_rd_o    (lane_desc_rd[i*DescW +: DescW]),
      .count_o      (lane_count[i*CntW +: CntW])
    );
  end

  // Only the lane whose node it is answers; the others give 0.
  always_comb begin
    par_rd   = '0;
    desc_rd  = '0;
    for (int i = 0; i < Lanes; i++) begin
      par_rd   = par_rd | lane_par_rd[i*PW +: PW];
      desc_rd  = desc_rd | lane_desc_rd[i*DescW +: DescW];
    end
  end
  assign sw_count = lane_count[32'(sweep_lane_q)*CntW +: CntW];

  logic lanes_idle;
  assign lanes_idle = &lane_idle;

  // ---- Border (lanes only): join the strips row by row -------------------------------------
  logic border_done;
  logic tuf_wr_en;
  logic [NodeW-1:0] tuf_wr_addr;
  logic [PW-1:0] tuf_wr_data;

  if (Lanes == 1) begin : gen_no_border
    assign border_done = 1'b1;
    assign tuf_wr_en   = 1'b0;
    assign tuf_wr_addr = '0;
    assign tuf_wr_data = '0;
    assign bpar_raddr  = '0;
    logic unused_bpar;
    assign unused_bpar = ^lane_bpar_rd;
  end else begin : gen_border
    localparam int unsigned Borders = Lanes - 1;
    localparam int unsigned QCntW = $clog2(BorderQueue + 1);
    localparam int unsigned PushW = $clog2(Borders + 1);
    // B0 reads row_q at both sides of every border (and clears it for the next frame); B1 has
    // the words in the RAMs' read registers and passes them through a second register (the
    // block RAM's output register: its clock-to-output without it, about 2.5 ns, left no time
    // for the join); B2 forms the join's multiples and the edge; B3 compares and drops a repeat
    // of the border's last edge; B4 packs the pushes into the queue.
    logic active_q, b1_valid_q, b2_valid_q, b3_valid_q, b4_valid_q, b_read;
    logic [YW-1:0] row_q;
    logic [Borders-1:0] last_has_q;
    logic [Borders*NodeW-1:0] last_a_q, last_b_q;
    logic [Borders-1:0] b4_push_q;  // B4: border b's edge, if any
    logic [Borders*NodeW-1:0] b4_a_q, b4_b_q;
    logic [QCntW-1:0] q_count;
    logic q_room;
    logic [PushW-1:0] push_n;
    logic [Borders*NodeW-1:0] push_a, push_b;
    logic uf_idle;
    logic [16:0] measure_q;
    logic [LaneSW-1:0] measure_k_q;
    logic tuf_rd_en;      // (the lanes' bpar ports read every clock)
    logic [NodeW-1:0] tuf_rd_addr;
    logic unused_border;  // the first strip has no left border, the last no right
    // (and lane 0 starts at column 0: its x0_q stays 0, a constant for synthesis)
    assign unused_border = lane_left_we[0] ^ lane_right_we[Lanes-1] ^ (|x0_q[15:0]) ^ tuf_rd_en;

    assign b_read      = ph_border && active_q && q_room;
    assign border_done = !active_q && !b1_valid_q && !b2_valid_q && !b3_valid_q && !b4_valid_q &&
                         (q_count == '0) && uf_idle;

    for (genvar b = 0; b < Borders; b++) begin : gen_ram
      logic [BordW-1:0] lp, rp;
      logic r_we, l_we;
      logic [HW-1:0] r_waddr, l_waddr;
      logic [BordW-1:0] r_wdata, l_wdata;

      // Write ports: cleared in Init and as the sweep reads; the lanes' edge columns in a frame.
      always_comb begin
        r_we    = 1'b0;
        r_waddr = HW'(row_q);
        r_wdata = '0;
        l_we    = 1'b0;
        l_waddr = HW'(row_q);
        l_wdata = '0;
        if (ph_init) begin
          r_we    = 32'(init_q) < 32'(MaxHeight);
          r_waddr = HW'(init_q);
          l_we    = r_we;
          l_waddr = r_waddr;
        end else if (ph_pixels) begin
          r_we    = lane_right_we[b];
          r_waddr = HW'(lane_brow[b*YW +: YW]);
          r_wdata = lane_bword[b*BordW +: BordW];
          l_we    = lane_left_we[b+1];
          l_waddr = HW'(lane_brow[(b+1)*YW +: YW]);
          l_wdata = lane_bword[(b+1)*BordW +: BordW];
        end else begin
          r_we = b_read;
          l_we = b_read;
        end
      end

      scw_ram_sdp #(.Width(BordW), .Depth(MaxHeight)) u_right_ram (
        .clk_i,
        .wr_en_i  (r_we),
        .wr_addr_i(r_waddr),
        .wr_data_i(r_wdata),
        .rd_en_i  (b_read),
        .rd_addr_i(HW'(row_q)),
        .rd_data_o(lp)
      );

      scw_ram_sdp #(.Width(BordW), .Depth(MaxHeight)) u_left_ram (
        .clk_i,
        .wr_en_i  (l_we),
        .wr_addr_i(l_waddr),
        .wr_data_i(l_wdata),
        .rd_en_i  (b_read),
        .rd_addr_i(HW'(row_q)),
        .rd_data_o(rp)
      );

      // B1: the left strip's last pixel (lp, the neighbour) and the right strip's first (rp,
      // the later pixel), through the output register.
      logic [BordW-1:0] lp_q, rp_q;
      always_ff @(posedge clk_i) begin
        lp_q <= lp;
        rp_q <= rp;
      end

      // B2: 10 |d - d_nb| < d (hls::labelling::joins) is 9 d < 10 d_nb < 11 d in integers
      // (10 (d - d_nb) < d and -d < 10 (d - d_nb)), as the lanes test it: the multiples here,
      // the compares in B3. The edge (lp's node, rp's node) when both are object pixels.
      logic [19:0] d9_q, d11_q, nb10_q;
      logic both_q;
      logic [NodeW-1:0] ea_q, eb_q;
      always_ff @(posedge clk_i) begin
        d9_q   <= {1'b0, rp_q[15:0], 3'b000} + {4'b0000, rp_q[15:0]};
        d11_q  <= {1'b0, rp_q[15:0], 3'b000} + {3'b000, rp_q[15:0], 1'b0} +
                  {4'b0000, rp_q[15:0]};
        nb10_q <= {1'b0, lp_q[15:0], 3'b000} + {3'b000, lp_q[15:0], 1'b0};
        both_q <= (lp_q[BordW-1:16] != '0) && (rp_q[BordW-1:16] != '0);
        ea_q   <= NodeW'(lp_q[BordW-1:16] - 1'b1);
        eb_q   <= NodeW'(rp_q[BordW-1:16] - 1'b1);
      end

      // B3: they join; an edge equal to this border's last is dropped.
      logic joined, push;
      assign joined = b3_valid_q && both_q && (nb10_q > d9_q) && (nb10_q < d11_q);
      assign push   = joined && !(last_has_q[b] && last_a_q[b*NodeW +: NodeW] == ea_q &&
                                  last_b_q[b*NodeW +: NodeW] == eb_q);

      always_ff @(posedge clk_i) begin
        if (!rst_ni) begin
          last_has_q[b] <= 1'b0;
          b4_push_q[b]  <= 1'b0;
        end else begin
          b4_push_q[b] <= push;
          if (frame_end) begin
            last_has_q[b] <= 1'b0;
          end else if (push) begin
            last_has_q[b] <= 1'b1;
          end
        end
      end
      always_ff @(posedge clk_i) begin
        if (push) begin
          last_a_q[b*NodeW +: NodeW] <= ea_q;
          last_b_q[b*NodeW +: NodeW] <= eb_q;
        end
        b4_a_q[b*NodeW +: NodeW] <= ea_q;
        b4_b_q[b*NodeW +: NodeW] <= eb_q;
      end
    end

    // B4: the pushes in border order, packed from push 0: border b's edge goes to push k when k
    // borders before it push (constant part-selects, so each push is a small OR of selects).
    always_comb begin
      logic [PushW-1:0] ahead;
      push_a = '0;
      push_b = '0;
      ahead = '0;
      for (int b = 0; b < Borders; b++) begin
        for (int k = 0; k <= b; k++) begin
          if (b4_push_q[b] && ahead == PushW'(k)) begin
            push_a[k*NodeW +: NodeW] = push_a[k*NodeW +: NodeW] | b4_a_q[b*NodeW +: NodeW];
            push_b[k*NodeW +: NodeW] = push_b[k*NodeW +: NodeW] | b4_b_q[b*NodeW +: NodeW];
          end
        end
        ahead = ahead + PushW'(b4_push_q[b]);
      end
      push_n = ahead;
    end

    // The unit reads through each lane's own port for it, every clock (it uses the word only
    // after a read): its next address goes to the banks without a multiplexer, and the lane it
    // read picks the word, by a register.
    logic [LaneSW-1:0] b_lane_q;
    logic [PW-1:0] b_rd;
    assign bpar_raddr = LNodeW'(tuf_rd_addr);
    always_ff @(posedge clk_i) b_lane_q <= LaneSW'(32'(tuf_rd_addr) >> LNodeW);
    always_comb begin
      b_rd = '0;
      for (int i = 0; i < Lanes; i++) begin
        if (b_lane_q == LaneSW'(i)) b_rd = lane_bpar_rd[i*PW +: PW];
      end
    end

    scw_labelling_merge_unit #(
      .Nodes  (NodeSpace),
      .Depth  (BorderQueue),
      .MaxPush(Borders),
      .Room   (BorderRows * Borders)
    ) u_merge_unit (
      .clk_i,
      .rst_ni,
      .en_i     (ph_border),
      .push_n_i (push_n),
      .push_a_i (push_a),
      .push_b_i (push_b),
      .rd_data_i(b_rd),
      .count_o  (q_count),
      .room_o   (q_room),
      .idle_o   (uf_idle),
      .rd_en_o  (tuf_rd_en),
      .rd_addr_o(tuf_rd_addr),
      .wr_en_o  (tuf_wr_en),
      .wr_addr_o(tuf_wr_addr),
      .wr_data_o(tuf_wr_data)
    );

    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        active_q   <= 1'b0;
        b1_valid_q <= 1'b0;
        b2_valid_q <= 1'b0;
        b3_valid_q <= 1'b0;
        b4_valid_q <= 1'b0;
        row_q      <= '0;
      end else begin
        b1_valid_q <= b_read;
        b2_valid_q <= b1_valid_q;
        b3_valid_q <= b2_valid_q;
        b4_valid_q <= b3_valid_q;
        if (drained) begin
          active_q <= 1'b1;
          row_q    <= '0;
        end else if (b_read) begin
          row_q <= row_q + 1'b1;
          if (17'(row_q) + 17'd1 == {1'b0, cfg_height_i}) active_q <= 1'b0;
        end
      end
    end

    // Init: the strips. A tile column a clock while they do not cover the width; every Lanes-th
    // adds a tile to the strip, so strip_q = tile_w x floor(tile columns / Lanes), and i tiles
    // to lane i's first column (a product of strip_q, through a DSP without registers, took
    // 4 ns). Both are final in the same clock; the lanes take x0 into their first-column powers
    // from there. The last strip's width follows a clock later: the lanes use it from the first
    // frame on, and Init lasts at least MaxTilesX + 8 clocks.
    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        measure_q   <= '0;
        measure_k_q <= '0;
        strip_q     <= '0;
        x0_q        <= '0;
      end else if (ph_init && measure_q < {1'b0, cfg_width_i}) begin
        measure_q   <= measure_q + {1'b0, cfg.tile_w};
        measure_k_q <= measure_k_q + 1'b1;
        if (measure_k_q == LaneSW'(Lanes - 1)) begin
          strip_q <= strip_q + cfg.tile_w;
          for (int i = 1; i < Lanes; i++) begin  // i x tile_w as shifts (i < 4)
            x0_q[i*16 +: 16] <= x0_q[i*16 +: 16] + ((i % 2 == 1) ? cfg.tile_w : 16'd0) +
                                ((i / 2 % 2 == 1) ? {cfg.tile_w[14:0], 1'b0} : 16'd0);
          end
        end
      end
    end
    always_ff @(posedge clk_i) begin
      last_w_q <= cfg_width_i - x0_q[(Lanes-1)*16 +: 16];
    end
  end

  // ---- R3 .. R5 (Resolve): acc[root] = desc[node] (the root itself) or acc[root] + desc[node]
  // R2 reads both; R3 passes them through the RAMs' output registers and chooses R4's
  // forwarding (the sum R4 computes now, or one of the two before, which R2's read missed);
  // R4 adds; R5 writes. A root starts from the empty descriptor, merge()'s identity.
  logic [DescW-1:0] acc_rd, desc_q, r4_a, res_q, res2_q, old_q, old_d, empty;
  logic m1_q, m1_d, old_hit_q, old_hit_d, r5_match, r6_match;

  // empty: no pixel (area and sums 0, minima at their largest, maxima 0, the first pixel last)
  // The ones are sized replications: Yosys 0.23 writes '1 into a part-select at a variable
  // offset as 1'b1 (only the field's lowest bit set).
  always_comb begin
    int unsigned at;
    empty = '0;
    at = AreaW;
    empty[at +: PosXW] = {PosXW{1'b1}};  at = at + 2 * PosXW;  // x_min
    empty[at +: PosYW] = {PosYW{1'b1}};  at = at + 2 * PosYW;  // y_min
    empty[at +: DispW] = {DispW{1'b1}};  at = at + 2 * DispW;  // d_min
    at = at + PosXW + PosYW;                                    // closest
    empty[at +: PosXW + PosYW] = {(PosXW + PosYW){1'b1}};      // first
  end

  assign r5_match  = r5_valid_q && (r5_root_q == r3_root_q);
  assign r6_match  = r6_valid_q && (r6_root_q == r3_root_q);
  assign m1_d      = r4_valid_q && (r4_root_q == r3_root_q) && !r3_self_q;
  assign old_hit_d = r3_self_q || r5_match || r6_match;
  assign old_d     = r3_self_q ? empty : (r5_match ? res_q : res2_q);
  assign r4_a      = m1_q ? res_q : (old_hit_q ? old_q : acc_rd);

  scw_labelling_merge #(
    .AreaW(AreaW),
    .PosXW(PosXW),
    .PosYW(PosYW),
    .DispW(DispW),
    .M10W (M10W),
    .M01W (M01W),
    .M20W (M20W),
    .M11W (M11W),
    .M02W (M02W),
    .M30W (M30W),
    .M21W (M21W),
    .M12W (M12W),
    .M03W (M03W),
    .SumDW (SumDW),
    .SumDDW(SumDDW)
  ) u_merge (
    .clk_i,
    .en_i(r4_valid_q),  // R5's sum
    .a_i (r4_a),
    .b_i (desc_q),
    .o_o (res_q)
  );

  // ---- the node sweep (Resolve and Emit): used nodes ascending, an empty lane costs a clock -
  // Resolve reads the lanes' label counts and copies them for Emit, whose frame they then leave.
  logic sw_yields, sw_step, sw_start;
  logic [NodeW-1:0] sw_node;

  // Each lane's count is tested on its own (not empty; more labels after this one) and the
  // sweep's lane picks the answers: the 4:1 pick of a count no longer stands before the compare.
  logic [Lanes-1:0] cnt_nonzero, cnt_more;
  for (genvar t = 0; t < Lanes; t++) begin : gen_sweep_cnt
    logic [CntW-1:0] cnt_t;
    assign cnt_t = ph_resolve ? lane_count[t*CntW +: CntW] : emit_cnt_q[t];
    assign cnt_nonzero[t] = cnt_t != '0;
    assign cnt_more[t] = sweep_next_q < (CntW + 1)'(cnt_t);
  end
  assign sw_yields = sweep_active_q && cnt_nonzero[sweep_lane_q];
  assign sw_node   = NodeW'(N1W'(sweep_lane_q) * LaneStrideN1 + N1W'(sweep_label_q));

  always_comb begin
    sweep_active_d = sweep_active_q;
    sweep_lane_d   = sweep_lane_q;
    sweep_label_d  = sweep_label_q;
    sweep_next_d   = sweep_next_q;
    if (sw_start) begin
      sweep_active_d = 1'b1;
      sweep_lane_d   = '0;
      sweep_label_d  = '0;
      sweep_next_d   = (CntW + 1)'(1);
    end else if (sw_step && sweep_active_q) begin
      if (sw_yields && cnt_more[sweep_lane_q]) begin
        sweep_label_d = sweep_label_q + 1'b1;
        sweep_next_d  = sweep_next_q + 1'b1;
      end else begin
        sweep_label_d = '0;
        sweep_next_d  = (CntW + 1)'(1);
        sweep_lane_d  = sweep_lane_q + 1'b1;
        if (sweep_lane_q == LaneSW'(Lanes - 1)) sweep_active_d = 1'b0;
      end
    end
  end

  // ---- Resolve: R0 reads parent[], R1 reads the parent's root, R2 the root and descriptors --
  logic res_done, r1_root;
  logic [NodeW-1:0] r2_root;
  logic root_re, root_we, acc_re, acc_we;
  logic [NodeW-1:0] root_raddr, root_rd, acc_raddr;

  assign res_done    = !sweep_active_q && !r1_valid_q && !r2_valid_q && !r3_valid_q &&
                       !r4_valid_q && !r5_valid_q;
  assign r1_valid_d  = ph_resolve && sw_yields;
  assign r1_node_d   = sw_node;
  assign r1_root     = !par_rd[NodeW];
  assign r2_valid_d  = ph_resolve && r1_valid_q;
  assign r2_node_d   = r1_node_q;
  assign r2_self_d   = r1_root;
  assign r2_parent_d = par_rd[NodeW-1:0];
  // The parent's root: read last clock, or written by R2 last clock (the one write that read
  // could not see).
  assign r2_root     = r2_self_q ? r2_node_q
                     : (rfwd_valid_q && rfwd_node_q == r2_parent_q) ? rfwd_root_q : root_rd;
  assign rfwd_valid_d = ph_resolve && r2_valid_q;

  // ---- Emit: E0 reads a node's root, its big flag and sum, E1 decides whether it is an object,
  // E2 sends it. A node waiting for the output register holds E1, E2 and the reads.
  logic swept, objects_full, adv, emit_read, emit_status, emit_object, out_en, big_rd;

  assign out_en       = !out_valid_q || out_ready_i;
  assign swept        = !sweep_active_q && !e1_valid_q && !e2_valid_q;
  assign objects_full = emitted_q >= ObjW'(MaxObjects);
  assign emit_object  = emit_q && e2_valid_q && e2_obj_q && !objects_full && out_en;
  assign adv          = !e2_valid_q || !e2_obj_q || objects_full || out_en;
  assign emit_read    = emit_q && adv && sw_yields;
  assign emit_status  = emit_q && swept && out_en;
  assign e1_valid_d   = emit_q && adv ? sw_yields : e1_valid_q;
  assign e1_node_d    = emit_q && adv ? sw_node : e1_node_q;
  assign e2_valid_d   = emit_q && adv ? e1_valid_q : e2_valid_q;
  assign e2_obj_d     = emit_q && adv ? (root_rd == e1_node_q) && big_rd : e2_obj_q;

  // ---- control -----------------------------------------------------------------------------
  // With lanes, "every lane and FIFO is empty" is an AND over all of them (each lane's pipeline
  // valids, edge queue and merge unit): it is registered, and Border starts a clock after the
  // last lane went idle. Nothing enters a lane in PhDrain, so what was idle a clock ago still is.
  // One lane keeps the direct test: its AND is short, and Resolve follows it.
  logic drain_idle, drain_idle_q;
  assign drain_idle = (phase_q == PhDrain) && lanes_idle && (fifo_valid == '0);
  always_ff @(posedge clk_i) begin
    if (!rst_ni) drain_idle_q <= 1'b0;
    else drain_idle_q <= drain_idle;
  end
  assign drained   = Lanes == 1 ? drain_idle : (phase_q == PhDrain) && drain_idle_q;
  assign frame_end = ph_resolve && res_done;
  // Resolve waits for the last frame's Emit, which still reads the sums.
  assign sw_start  = ((Lanes == 1 ? drained : ph_border && border_done) && !emit_q) ||
                     frame_end;
  assign sw_step   = ph_resolve || (emit_q && adv);

  always_comb begin
    phase_d       = phase_q;
    in_frame_d    = in_frame_q;
    err_pending_d = err_pending_q;
    err_frame_d   = err_frame_q;
    err_sticky_d  = err_sticky_q;
    tile_ovf_d    = tile_ovf_q || (|lane_ovf);
    emit_d        = emit_q && !emit_status;
    obj_ovf_d     = obj_ovf_q || (emit_q && e2_valid_q && e2_obj_q && objects_full);
    emitted_d     = emitted_q + ObjW'(emit_object);
    if (emit_status) begin
      emitted_d = '0;
      obj_ovf_d = 1'b0;
    end
    unique case (phase_q)
      PhInit: begin
        if (init_q == InitW'(InitClocks - 1)) phase_d = PhFrame;
      end
      PhFrame, PhDrain: begin
        if (beat_drop) begin
          err_pending_d = 1'b1;
          err_sticky_d  = 1'b1;
        end
        if (frame_start) begin
          in_frame_d    = 1'b1;
          err_frame_d   = err_pending_q;
          err_pending_d = 1'b0;
        end
        if (eol_err) begin
          err_frame_d  = 1'b1;
          err_sticky_d = 1'b1;
        end
        if (frame_last) in_frame_d = 1'b0;
        if (sof_mid) begin  // close the frame early, take the sof afterwards
          err_frame_d  = 1'b1;
          err_sticky_d = 1'b1;
          in_frame_d   = 1'b0;
        end
        if (drained) begin
          if (Lanes > 1) phase_d = PhBorder;
          else if (!emit_q) phase_d = PhResolve;
        end
      end
      PhBorder: begin
        if (border_done && !emit_q) phase_d = PhResolve;
      end
      PhResolve: begin
        if (res_done) begin  // Emit takes the frame's flags, the stage the next frame
          phase_d     = PhFrame;
          emit_d      = 1'b1;
          tile_ovf_d  = 1'b0;
          err_frame_d = 1'b0;
        end
      end
      default: phase_d = PhInit;
    endcase
    // The frame's last beat or a sof in mid-frame (both only in PhFrame), decided last: they
    // follow in_ready, the longest of the inputs.
    if (frame_last || sof_mid) phase_d = PhDrain;
  end

  // The output word carries every field at the package's widths (scw_pkg::label_desc_t, or
  // scw_pkg::label_status_t in the status word): the sums are widened (or cut) to them.
  localparam int unsigned AreaOutW  = scw_pkg::AreaBits;
  localparam int unsigned CoordOutW = scw_pkg::CoordBits;
  localparam int unsigned SumOutW   = scw_pkg::SumBits;
  scw_pkg::label_status_t out_status;
  always_comb begin
    out_status                 = '0;
    out_status.objects         = AreaOutW'(emitted_q);
    out_status.tile_overflow   = emit_tile_ovf_q;
    out_status.object_overflow = obj_ovf_q;
    out_status.stream_error    = emit_err_q;
  end
  scw_pkg::label_desc_t out_desc;
  if ($bits(out_desc) + 1 != OutW) begin : gen_bad_word
    $error("scw_labelling: scw_pkg::ObjWordBits is not label_desc_t's width plus is_status");
  end
  always_comb begin
    int unsigned at;
    out_desc = '0;
    at = 0;
    out_desc.area      = AreaOutW'(acc_rd[at +: AreaW]);  at = at + AreaW;
    out_desc.x_min     = CoordOutW'(acc_rd[at +: PosXW]);  at = at + PosXW;
    out_desc.x_max     = CoordOutW'(acc_rd[at +: PosXW]);  at = at + PosXW;
    out_desc.y_min     = CoordOutW'(acc_rd[at +: PosYW]);  at = at + PosYW;
    out_desc.y_max     = CoordOutW'(acc_rd[at +: PosYW]);  at = at + PosYW;
    out_desc.d_min     = CoordOutW'(acc_rd[at +: DispW]);  at = at + DispW;
    out_desc.d_max     = CoordOutW'(acc_rd[at +: DispW]);  at = at + DispW;
    out_desc.closest_x = CoordOutW'(acc_rd[at +: PosXW]);  at = at + PosXW;
    out_desc.closest_y = CoordOutW'(acc_rd[at +: PosYW]);  at = at + PosYW;
    out_desc.first_x   = CoordOutW'(acc_rd[at +: PosXW]);  at = at + PosXW;
    out_desc.first_y   = CoordOutW'(acc_rd[at +: PosYW]);  at = at + PosYW;
    out_desc.m10       = SumOutW'(acc_rd[at +: M10W]);   at = at + M10W;
    out_desc.m01       = SumOutW'(acc_rd[at +: M01W]);   at = at + M01W;
    out_desc.m20       = SumOutW'(acc_rd[at +: M20W]);   at = at + M20W;
    out_desc.m11       = SumOutW'(acc_rd[at +: M11W]);   at = at + M11W;
    out_desc.m02       = SumOutW'(acc_rd[at +: M02W]);   at = at + M02W;
    out_desc.m30       = SumOutW'(acc_rd[at +: M30W]);   at = at + M30W;
    out_desc.m21       = SumOutW'(acc_rd[at +: M21W]);   at = at + M21W;
    out_desc.m12       = SumOutW'(acc_rd[at +: M12W]);   at = at + M12W;
    out_desc.m03       = SumOutW'(acc_rd[at +: M03W]);   at = at + M03W;
    out_desc.sum_d     = SumOutW'(acc_rd[at +: SumDW]);  at = at + SumDW;
    out_desc.sum_dd    = SumOutW'(acc_rd[at +: SumDDW]);
  end

  // The output register: an object's sum, or the status word (sim/words/labelling_pack.hpp).
  always_comb begin
    out_valid_d = out_valid_q && !out_ready_i;
    out_load    = emit_object || emit_status;
    out_last_d  = emit_status;
    out_data_d  = {out_desc, 1'b0};
    if (emit_status) begin
      out_data_d = '0;
      out_data_d[0] = 1'b1;
      out_data_d[$bits(out_status):1] = out_status;
    end
    if (out_load) out_valid_d = 1'b1;
  end

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
  assign out_last_o  = out_last_q;
  assign err_o       = err_sticky_q;

  // ---- RAM port multiplexers ---------------------------------------------------------------
  always_comb begin
    par_re    = 1'b0;
    par_raddr = sw_node;
    par_we    = 1'b0;
    par_waddr = r1_node_q;
    par_wdata = '0;
    if (ph_border) begin  // (the border merge unit reads through the lanes' bpar port)
      par_we    = tuf_wr_en;
      par_waddr = tuf_wr_addr;
      par_wdata = tuf_wr_data;
    end else if (ph_resolve) begin
      par_re = sw_yields;     // R0
      par_we = r1_valid_q;    // R1 clears parent[] for the next frame
    end
  end

  assign desc_re    = ph_resolve && r2_valid_q;
  assign root_re    = (ph_resolve && r1_valid_q && !r1_root) || emit_read;
  assign root_raddr = ph_resolve ? r2_parent_d : sw_node;
  assign root_we    = ph_resolve && r2_valid_q;
  assign acc_re     = (ph_resolve && r2_valid_q) || emit_read;
  assign acc_raddr  = ph_resolve ? r2_root : sw_node;
  assign acc_we     = ph_resolve && r5_valid_q;

  // Roots and big flags (the root's area reached cfg.min_area, written with each sum, so the
  // last write, the root's whole area, decides) in distributed RAM: Resolve's next read address
  // and Emit's decision follow from their words a clock after the read.
  (* ram_style = "distributed" *) logic [NodeW-1:0] root_mem_q [NodeSpace];
  (* ram_style = "distributed" *) logic big_mem_q [NodeSpace];
  always_ff @(posedge clk_i) begin
    if (root_we) root_mem_q[r2_node_q] <= r2_root;
    if (acc_we) big_mem_q[r5_root_q] <= 32'(res_q[AreaW-1:0]) >= cfg.min_area;
  end
  always_ff @(posedge clk_i) begin
    if (root_re) root_rd <= root_mem_q[root_raddr];
    if (emit_read) big_rd <= big_mem_q[sw_node];
  end

  scw_labelling_desc_ram #(.DescW(DescW), .Depth(NodeSpace), .OutReg(1'b1)) u_acc_ram (
    .clk_i,
    .wr_en_i  (acc_we),
    .wr_addr_i(r5_root_q),
    .wr_data_i(res_q),
    .rd_en_i  (acc_re),
    .rd_addr_i(acc_raddr),
    .rd_next_i(!emit_q || adv),
    .rd_data_o(acc_rd)
  );

  // ---- registers ---------------------------------------------------------------------------
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      phase_q        <= PhInit;
      init_q         <= '0;
      in_frame_q     <= 1'b0;
      err_pending_q  <= 1'b0;
      err_frame_q    <= 1'b0;
      err_sticky_q   <= 1'b0;
      tile_ovf_q     <= 1'b0;
      emit_q         <= 1'b0;
      obj_ovf_q      <= 1'b0;
      emitted_q      <= '0;
      rfwd_valid_q   <= 1'b0;
      sweep_active_q <= 1'b0;
      r1_valid_q     <= 1'b0;
      r2_valid_q     <= 1'b0;
      r3_valid_q     <= 1'b0;
      r4_valid_q     <= 1'b0;
      r5_valid_q     <= 1'b0;
      r6_valid_q     <= 1'b0;
      e1_valid_q     <= 1'b0;
      e2_valid_q     <= 1'b0;
      out_valid_q    <= 1'b0;
    end else begin
      phase_q        <= phase_d;
      if (ph_init) init_q <= init_q + 1'b1;
      in_frame_q     <= in_frame_d;
      err_pending_q  <= err_pending_d;
      err_frame_q    <= err_frame_d;
      err_sticky_q   <= err_sticky_d;
      tile_ovf_q     <= tile_ovf_d;
      emit_q         <= emit_d;
      obj_ovf_q      <= obj_ovf_d;
      emitted_q      <= emitted_d;
      rfwd_valid_q   <= rfwd_valid_d;
      sweep_active_q <= sweep_active_d;
      r1_valid_q     <= r1_valid_d;
      r2_valid_q     <= r2_valid_d;
      r3_valid_q     <= ph_resolve && r2_valid_q;
      r4_valid_q     <= r3_valid_q;
      r5_valid_q     <= r4_valid_q;
      r6_valid_q     <= r5_valid_q;
      e1_valid_q     <= e1_valid_d;
      e2_valid_q     <= e2_valid_d;
      out_valid_q    <= out_valid_d;
    end
  end

  // Emit's label counts, copied as Resolve's sweep passes each lane.
  for (genvar t = 0; t < Lanes; t++) begin : gen_emit_cnt
    always_ff @(posedge clk_i) begin
      if (ph_resolve && sweep_active_q && sweep_lane_q == LaneSW'(t)) emit_cnt_q[t] <= sw_count;
    end
  end

  // Datapath registers: meaningful only under their valid bits.
  always_ff @(posedge clk_i) begin
    x_q           <= x_d;
    y_q           <= y_d;
    lane_q        <= lane_d;
    lane_col_q    <= lane_col_d;
    rfwd_node_q   <= r2_node_q;
    rfwd_root_q   <= r2_root;
    sweep_lane_q  <= sweep_lane_d;
    sweep_label_q <= sweep_label_d;
    sweep_next_q  <= sweep_next_d;
    r1_node_q     <= r1_node_d;
    r2_node_q     <= r2_node_d;
    r2_self_q     <= r2_self_d;
    r2_parent_q   <= r2_parent_d;
    // R3 .. R6 (the valid bits above): each stage loads under the one before's, so no chain of
    // shift registers forms
    if (r2_valid_q) begin
      r3_root_q <= r2_root;
      r3_self_q <= r2_self_q;
    end
    if (r3_valid_q) begin
      r4_root_q <= r3_root_q;
      desc_q    <= desc_rd;
      m1_q      <= m1_d;
      old_hit_q <= old_hit_d;
      old_q     <= old_d;
    end
    if (r4_valid_q) begin
      r5_root_q <= r4_root_q;
    end
    if (r5_valid_q) begin
      r6_root_q <= r5_root_q;
      res2_q    <= res_q;
    end
    e1_node_q     <= e1_node_d;
    e2_obj_q      <= e2_obj_d;
    if (frame_end) begin
      emit_tile_ovf_q <= tile_ovf_q;
      emit_err_q      <= err_frame_q;
    end
    if (out_load) begin
      out_data_q <= out_data_d;
      out_last_q <= out_last_d;
    end
  end
endmodule
