// SPDX-License-Identifier: Apache-2.0
// The whole collision-warning pipeline: two camera branches (frame check, map-grid expander,
// rectifier), disparity, labelling and warning, every link an scw_fifo.
`default_nettype none

//  left raw  -> [camera L] --rect--> scw_disparity -> FIFO -> scw_road -> FIFO -> scw_labelling
//                                                              |line      -> FIFO -> fork
//                                                              +--> FIFO -------------+
//                                                                   (one line a frame) v
//  right raw -> [camera R] --rect-->    fork -> FIFO -> obj (the object table, for the host)
//                  |flag                fork -> FIFO -> scw_warning -> FIFO -> scw_result_merge
//                  |                                                              |
//                  +----------------------------------------------------> FIFO -> out
// The C++ chain sim/pipeline/pipeline_chain.hpp builds the same graph from the stages' models (or their
// Verilated twins) and sim::Fifo, the twin of scw_fifo, so the two agree clock for clock
// (tests/pipeline). Parameters: hls::pipeline::PipelineParams, the one list of built sizes.
// The labelling stage takes Ppc pixels per beat, one lane per pixel (scw_labelling "Lanes").
module scw_pipeline #(
  parameter int unsigned Ppc            /*verilator public*/ = 1,
  parameter int unsigned MaxWidthPx     /*verilator public*/ = 64,
  parameter int unsigned MaxHeight      /*verilator public*/ = 48,
  parameter int unsigned RectRows       /*verilator public*/ = 16,
  parameter int unsigned GridLog2       /*verilator public*/ = 3,
  parameter int unsigned Window         /*verilator public*/ = 5,
  parameter int unsigned NumDisp        /*verilator public*/ = 16,
  parameter int unsigned MaxTilesX      /*verilator public*/ = 2,
  parameter int unsigned MaxTilesY      /*verilator public*/ = 2,
  parameter int unsigned LabelsPerTile  /*verilator public*/ = 64,
  parameter int unsigned MaxObjects     /*verilator public*/ = 32,
  parameter int unsigned MaxDisparityPx /*verilator public*/ = 32,
  parameter int unsigned RawFifoDepth   /*verilator public*/ = 2,
  parameter int unsigned MapFifoDepth   /*verilator public*/ = 4,
  parameter int unsigned RectFifoDepth  /*verilator public*/ = 4,
  parameter int unsigned DispFifoDepth  /*verilator public*/ = 4,
  parameter int unsigned ObjFifoDepth   /*verilator public*/ = 2,
  parameter int unsigned ResFifoDepth   /*verilator public*/ = 2,
  parameter int unsigned FlagFifoDepth  /*verilator public*/ = 4,
  // road lines: frames in flight between the road stage's sof and the warning stage's first word
  parameter int unsigned LineFifoDepth  /*verilator public*/ = 4,
  localparam int unsigned MaxWH    = (MaxWidthPx > MaxHeight) ? MaxWidthPx : MaxHeight,
  localparam int unsigned KBits    = $clog2(MaxWH) + 2 + 7,
  localparam int unsigned KCols    = ((MaxWidthPx - 1) >> GridLog2) + 2,
  localparam int unsigned KRows    = ((MaxHeight - 1) >> GridLog2) + 2,
  localparam int unsigned KAddrW   = $clog2(KRows) + $clog2(KCols),
  localparam int unsigned KnotW    = 2 * KBits,
  localparam int unsigned BeatW    = Ppc * scw_pkg::PixelBits,
  localparam int unsigned DispW    = Ppc * scw_pkg::DispBits,
  localparam int unsigned WW       = $clog2(MaxWidthPx + 1),
  localparam int unsigned HW       = $clog2(MaxHeight + 1),
  localparam int unsigned SlotW    = $clog2(RectRows),
  localparam int unsigned ObjW     = scw_pkg::ObjWordBits,
  localparam int unsigned ResW     = scw_pkg::ResultWordBits,
  localparam int unsigned OutW     = scw_pkg::PipeResultBits
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  // frame and rectification
  input  logic [WW-1:0]      cfg_width_i,
  input  logic [HW-1:0]      cfg_height_i,
  input  logic [SlotW-1:0]   cfg_lead_i,
  // disparity (hls::disparity::DisparityConfig)
  input  logic [scw_pkg::DisparityCfgBits-1:0] cfg_disparity_i,  // scw_pkg::disparity_cfg_t
  // labelling (hls::labelling::LabellingConfig; width and height are the frame's)
  input  logic [scw_pkg::LabellingCfgBits-1:0] cfg_labelling_i,  // scw_pkg::labelling_cfg_t
  // warning (hls::warning::WarningConfig): scw_pkg::warning_cfg_t
  input  logic [scw_pkg::WarningCfgBits-1:0] cfg_warning_i,
  // road (hls::road::RoadConfig): scw_pkg::road_cfg_t
  input  logic [scw_pkg::RoadCfgBits-1:0] cfg_road_i,
  // map knots, written while run_i is low; knot_right_i picks the camera
  input  logic               run_i,
  input  logic               knot_we_i,
  input  logic               knot_right_i,
  input  logic [KAddrW-1:0]  knot_addr_i,
  input  logic [KnotW-1:0]   knot_data_i,
  // raw pixel streams
  input  logic               l_valid_i,
  output logic               l_ready_o,
  input  logic [BeatW-1:0]   l_data_i,
  input  logic               l_sof_i,
  input  logic               l_eol_i,
  input  logic               r_valid_i,
  output logic               r_ready_o,
  input  logic [BeatW-1:0]   r_data_i,
  input  logic               r_sof_i,
  input  logic               r_eol_i,
  // the object table: every object word of a frame (scw_labelling's), the last one marked
  output logic               obj_valid_o,
  input  logic               obj_ready_i,
  output logic [ObjW-1:0]    obj_data_o,
  output logic               obj_last_o,
  // one result word per frame
  output logic               out_valid_o,
  input  logic               out_ready_i,
  output logic [OutW-1:0]    out_data_o,
  output logic               out_last_o,
  // sticky: {labelling, disparity, rectify R [2:0], rectify L [2:0]}
  output logic [7:0]         err_o
);
  // The links' fill levels (scw_fifo count_o) are for debug probes; nothing here reads them.
  /* verilator lint_off PINCONNECTEMPTY */
  logic             cl_valid, cl_ready, cl_sof, cl_eol, cr_valid, cr_ready, cr_sof, cr_eol;
  logic [BeatW-1:0] cl_data, cr_data;
  logic             fl_valid, fl_ready, fl_error, fr_valid, fr_ready, fr_error;
  logic [2:0]       err_l, err_r;
  logic             err_disp, err_lab;

  scw_pipeline_camera #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .RectRows(RectRows),
    .GridLog2(GridLog2), .RawFifoDepth(RawFifoDepth), .MapFifoDepth(MapFifoDepth),
    .RectFifoDepth(RectFifoDepth), .FlagFifoDepth(FlagFifoDepth)
  ) u_cam_l (
    .clk_i, .rst_ni, .cfg_width_i, .cfg_height_i, .cfg_lead_i, .run_i,
    .knot_we_i(knot_we_i && !knot_right_i), .knot_addr_i, .knot_data_i,
    .in_valid_i(l_valid_i), .in_ready_o(l_ready_o), .in_data_i(l_data_i),
    .in_sof_i(l_sof_i), .in_eol_i(l_eol_i),
    .out_valid_o(cl_valid), .out_ready_i(cl_ready), .out_data_o(cl_data),
    .out_sof_o(cl_sof), .out_eol_o(cl_eol),
    .flag_valid_o(fl_valid), .flag_ready_i(fl_ready), .flag_error_o(fl_error),
    .err_o(err_l)
  );

  scw_pipeline_camera #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .RectRows(RectRows),
    .GridLog2(GridLog2), .RawFifoDepth(RawFifoDepth), .MapFifoDepth(MapFifoDepth),
    .RectFifoDepth(RectFifoDepth), .FlagFifoDepth(FlagFifoDepth)
  ) u_cam_r (
    .clk_i, .rst_ni, .cfg_width_i, .cfg_height_i, .cfg_lead_i, .run_i,
    .knot_we_i(knot_we_i && knot_right_i), .knot_addr_i, .knot_data_i,
    .in_valid_i(r_valid_i), .in_ready_o(r_ready_o), .in_data_i(r_data_i),
    .in_sof_i(r_sof_i), .in_eol_i(r_eol_i),
    .out_valid_o(cr_valid), .out_ready_i(cr_ready), .out_data_o(cr_data),
    .out_sof_o(cr_sof), .out_eol_o(cr_eol),
    .flag_valid_o(fr_valid), .flag_ready_i(fr_ready), .flag_error_o(fr_error),
    .err_o(err_r)
  );

  // disparity -> FIFO
  logic             d_valid, d_ready, d_sof, d_eol, dq_valid, dq_ready;
  logic [DispW-1:0] d_data;
  logic [DispW+1:0] dq_word;

  scw_disparity #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .Window(Window),
    .NumDisp(NumDisp)
  ) u_disparity (
    .clk_i, .rst_ni, .cfg_width_i, .cfg_height_i, .cfg_disparity_i,
    .l_valid_i(cl_valid), .l_ready_o(cl_ready), .l_data_i(cl_data), .l_sof_i(cl_sof),
    .l_eol_i(cl_eol),
    .r_valid_i(cr_valid), .r_ready_o(cr_ready), .r_data_i(cr_data), .r_sof_i(cr_sof),
    .r_eol_i(cr_eol),
    .out_valid_o(d_valid), .out_ready_i(d_ready), .out_data_o(d_data), .out_sof_o(d_sof),
    .out_eol_o(d_eol), .err_o(err_disp)
  );

  // Registered output (the same behaviour clock for clock): the labelling stage decodes the
  // head beat's sof and eol into its phase, which from the FIFO's LUT RAM was the top's worst
  // path (3,934 ps at the thesis size).
  scw_fifo #(.Width(DispW + 2), .Depth(DispFifoDepth), .OutReg(1'b1)) u_disp_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(d_valid), .in_ready_o(d_ready), .in_data_i({d_eol, d_sof, d_data}),
    .out_valid_o(dq_valid), .out_ready_i(dq_ready), .out_data_o(dq_word),
    .count_o()
  );

  // road -> FIFO (registered like the disparity FIFO: the labelling stage decodes its head beat)
  logic             r_valid, r_ready, r_sof, r_eol, rq_valid, rq_ready;
  logic             ln_valid, ln_ready, lq_valid, lq_ready;  // the road lines
  logic [17:0]      ln_a;
  logic [31:0]      ln_b;
  logic [49:0]      lq_word;
  logic [DispW-1:0] r_data;
  logic [DispW+1:0] rq_word;

  scw_road #(.Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight)) u_road (
    .clk_i, .rst_ni,
    .cfg_road_i,
    .in_valid_i(dq_valid), .in_ready_o(dq_ready), .in_data_i(dq_word[DispW-1:0]),
    .in_sof_i(dq_word[DispW]), .in_eol_i(dq_word[DispW+1]),
    .out_valid_o(r_valid), .out_ready_i(r_ready), .out_data_o(r_data), .out_sof_o(r_sof),
    .out_eol_o(r_eol),
    .line_valid_o(ln_valid), .line_ready_i(ln_ready), .line_a_o(ln_a), .line_b_o(ln_b)
  );

  // The line each frame was gated with, to the warning stage, which takes one with each frame's
  // first object word and measures heights above it.
  scw_fifo #(.Width(50), .Depth(LineFifoDepth)) u_line_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(ln_valid), .in_ready_o(ln_ready), .in_data_i({ln_b, ln_a}),
    .out_valid_o(lq_valid), .out_ready_i(lq_ready), .out_data_o(lq_word),
    .count_o()
  );

  scw_fifo #(.Width(DispW + 2), .Depth(DispFifoDepth), .OutReg(1'b1)) u_road_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(r_valid), .in_ready_o(r_ready), .in_data_i({r_eol, r_sof, r_data}),
    .out_valid_o(rq_valid), .out_ready_i(rq_ready), .out_data_o(rq_word),
    .count_o()
  );

  // labelling -> FIFO -> warning -> FIFO
  logic            o_valid, o_ready, o_last, oq_valid, oq_ready;
  logic [ObjW-1:0] o_data;
  logic [ObjW:0]   oq_word;
  logic            w_valid, w_ready, w_last, wq_valid, wq_ready;
  logic [ResW-1:0] w_data;
  logic [ResW:0]   wq_word;

  scw_labelling #(
    .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .MaxTilesX(MaxTilesX),
    .MaxTilesY(MaxTilesY), .LabelsPerTile(LabelsPerTile), .MaxObjects(MaxObjects), .Lanes(Ppc)
  ) u_labelling (
    .clk_i, .rst_ni,
    .cfg_width_i(16'(cfg_width_i)), .cfg_height_i(16'(cfg_height_i)),
    .cfg_labelling_i,
    .in_valid_i(rq_valid), .in_ready_o(rq_ready), .in_data_i(rq_word[DispW-1:0]),
    .in_sof_i(rq_word[DispW]), .in_eol_i(rq_word[DispW+1]),
    .out_valid_o(o_valid), .out_ready_i(o_ready), .out_data_o(o_data), .out_last_o(o_last),
    .err_o(err_lab)
  );

  scw_fifo #(.Width(ObjW + 1), .Depth(ObjFifoDepth)) u_obj_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(o_valid), .in_ready_o(o_ready), .in_data_i({o_last, o_data}),
    .out_valid_o(oq_valid), .out_ready_i(oq_ready), .out_data_o(oq_word),
    .count_o()
  );

  // The object words go to the warning stage and out to the host in lockstep: a word leaves
  // the object FIFO when both FIFOs behind it have room. Both readies are FIFO flags (registered),
  // so the fork adds no path through a stage (sim::Fork is its twin).
  logic          ow_valid, ow_ready, ot_valid, ot_ready, wi_valid, wi_ready;
  logic [ObjW:0] wi_word, ot_word;
  assign oq_ready = ow_ready && ot_ready;
  assign ow_valid = oq_valid && ot_ready;
  assign ot_valid = oq_valid && ow_ready;

  scw_fifo #(.Width(ObjW + 1), .Depth(ObjFifoDepth)) u_objw_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(ow_valid), .in_ready_o(ow_ready), .in_data_i(oq_word),
    .out_valid_o(wi_valid), .out_ready_i(wi_ready), .out_data_o(wi_word),
    .count_o()
  );

  scw_fifo #(.Width(ObjW + 1), .Depth(ObjFifoDepth)) u_table_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(ot_valid), .in_ready_o(ot_ready), .in_data_i(oq_word),
    .out_valid_o(obj_valid_o), .out_ready_i(obj_ready_i), .out_data_o(ot_word),
    .count_o()
  );
  assign obj_data_o = ot_word[ObjW-1:0];
  assign obj_last_o = ot_word[ObjW];

  scw_warning #(.MaxDisparityPx(MaxDisparityPx)) u_warning (
    .clk_i, .rst_ni,
    .cfg_warning_i, .cfg_road_height_i(1'b1),
    .in_valid_i(wi_valid), .in_ready_o(wi_ready), .in_data_i(wi_word[ObjW-1:0]),
    .in_last_i(wi_word[ObjW]),
    .road_valid_i(lq_valid), .road_ready_o(lq_ready), .road_a_i(lq_word[17:0]),
    .road_b_i(lq_word[49:18]),
    .out_valid_o(w_valid), .out_ready_i(w_ready), .out_data_o(w_data), .out_last_o(w_last)
  );

  scw_fifo #(.Width(ResW + 1), .Depth(ResFifoDepth)) u_res_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(w_valid), .in_ready_o(w_ready), .in_data_i({w_last, w_data}),
    .out_valid_o(wq_valid), .out_ready_i(wq_ready), .out_data_o(wq_word),
    .count_o()
  );

  // result word: warning result + the input checks' flags -> FIFO -> out
  logic            m_valid, m_ready, m_last;
  logic [OutW-1:0] m_data;
  logic [OutW:0]   out_word;

  scw_result_merge #(.ResW(ResW)) u_merge (
    .clk_i, .rst_ni,
    .res_valid_i(wq_valid), .res_ready_o(wq_ready), .res_data_i(wq_word[ResW-1:0]),
    .res_last_i(wq_word[ResW]),
    .left_valid_i(fl_valid), .left_ready_o(fl_ready), .left_error_i(fl_error),
    .right_valid_i(fr_valid), .right_ready_o(fr_ready), .right_error_i(fr_error),
    .out_valid_o(m_valid), .out_ready_i(m_ready), .out_data_o(m_data), .out_last_o(m_last)
  );

  scw_fifo #(.Width(OutW + 1), .Depth(ResFifoDepth)) u_out_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(m_valid), .in_ready_o(m_ready), .in_data_i({m_last, m_data}),
    .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .out_data_o(out_word),
    .count_o()
  );
  assign out_data_o = out_word[OutW-1:0];
  assign out_last_o = out_word[OutW];

  assign err_o = {err_lab, err_disp, err_r, err_l};
  /* verilator lint_on PINCONNECTEMPTY */
endmodule
