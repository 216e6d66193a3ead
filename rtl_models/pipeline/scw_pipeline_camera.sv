// SPDX-License-Identifier: Apache-2.0
// One camera's branch of the pipeline: input FIFO, frame check, map-grid expander, rectifier.
`default_nettype none

// raw in -> FIFO -> scw_frame_check -> FIFO -> scw_rectify -> FIFO -> out
//                        |  flag -> FIFO -> flag out          ^ map: scw_rectify_map_grid -> FIFO
// Every link is an scw_fifo, as in the C++ chain (sim/pipeline/pipeline_chain.hpp), so the two count the
// same cycles. The knot RAM is written through knot_* while run_i is low.
module scw_pipeline_camera #(
  parameter int unsigned Ppc            = 1,
  parameter int unsigned MaxWidthPx     = 64,
  parameter int unsigned MaxHeight      = 48,
  parameter int unsigned RectRows       = 16,
  parameter int unsigned GridLog2       = 3,
  parameter int unsigned RawFifoDepth   = 2,
  parameter int unsigned MapFifoDepth   = 4,
  parameter int unsigned RectFifoDepth  = 4,
  parameter int unsigned FlagFifoDepth  = 4,
  localparam int unsigned FracBits      = 5,
  localparam int unsigned KnotFracBits  = 7,
  localparam int unsigned MaxWH         = (MaxWidthPx > MaxHeight) ? MaxWidthPx : MaxHeight,
  localparam int unsigned CoordBits     = $clog2(MaxWH * (1 << FracBits) + 1) + 1,
  localparam int unsigned KBits         = $clog2(MaxWH) + 2 + KnotFracBits,
  localparam int unsigned KCols         = ((MaxWidthPx - 1) >> GridLog2) + 2,
  localparam int unsigned KRows         = ((MaxHeight - 1) >> GridLog2) + 2,
  localparam int unsigned KAddrW        = $clog2(KRows) + $clog2(KCols),
  localparam int unsigned KnotW         = 2 * KBits,
  localparam int unsigned BeatW         = Ppc * scw_pkg::PixelBits,
  localparam int unsigned MapW          = Ppc * 2 * CoordBits,
  localparam int unsigned WW            = $clog2(MaxWidthPx + 1),
  localparam int unsigned HW            = $clog2(MaxHeight + 1),
  localparam int unsigned SlotW         = $clog2(RectRows)
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic [WW-1:0]     cfg_width_i,
  input  logic [HW-1:0]     cfg_height_i,
  input  logic [SlotW-1:0]  cfg_lead_i,
  input  logic              run_i,
  input  logic              knot_we_i,
  input  logic [KAddrW-1:0] knot_addr_i,
  input  logic [KnotW-1:0]  knot_data_i,
  input  logic              in_valid_i,
  output logic              in_ready_o,
  input  logic [BeatW-1:0]  in_data_i,
  input  logic              in_sof_i,
  input  logic              in_eol_i,
  output logic              out_valid_o,
  input  logic              out_ready_i,
  output logic [BeatW-1:0]  out_data_o,
  output logic              out_sof_o,
  output logic              out_eol_o,
  output logic              flag_valid_o,
  input  logic              flag_ready_i,
  output logic              flag_error_o,
  output logic [2:0]        err_o
);
  // The links' fill levels (scw_fifo count_o) are for debug probes; nothing here reads them.
  /* verilator lint_off PINCONNECTEMPTY */
  // Links carry {eol, sof, data}.
  logic             raw_valid, raw_ready, chk_in_valid, chk_in_ready, chk_valid, chk_ready;
  logic [BeatW+1:0] raw_word, chk_in_word, chk_word, rect_in_word;
  logic             fl_valid, fl_ready, fl_error;
  logic             map_in_valid, map_in_ready, map_valid, map_ready;
  logic [MapW-1:0]  map_in_data;
  logic             map_in_sof, map_in_eol;
  logic [MapW+1:0]  map_word;
  logic             rect_valid, rect_ready;
  logic [BeatW-1:0] rect_data, chk_data;
  logic             rect_sof, rect_eol, chk_sof, chk_eol;
  logic [BeatW+1:0] out_word;

  scw_fifo #(.Width(BeatW + 2), .Depth(RawFifoDepth)) u_raw_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(in_valid_i), .in_ready_o(in_ready_o), .in_data_i({in_eol_i, in_sof_i, in_data_i}),
    .out_valid_o(raw_valid), .out_ready_i(raw_ready), .out_data_o(raw_word),
    .count_o()
  );

  scw_frame_check #(.Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight)) u_check (
    .clk_i, .rst_ni,
    .cfg_width_i, .cfg_height_i,
    .in_valid_i(raw_valid), .in_ready_o(raw_ready), .in_data_i(raw_word[BeatW-1:0]),
    .in_sof_i(raw_word[BeatW]), .in_eol_i(raw_word[BeatW+1]),
    .out_valid_o(chk_in_valid), .out_ready_i(chk_in_ready), .out_data_o(chk_data),
    .out_sof_o(chk_sof), .out_eol_o(chk_eol),
    .flag_valid_o(fl_valid), .flag_ready_i(fl_ready), .flag_error_o(fl_error)
  );
  assign chk_in_word = {chk_eol, chk_sof, chk_data};

  scw_fifo #(.Width(BeatW + 2), .Depth(RawFifoDepth)) u_chk_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(chk_in_valid), .in_ready_o(chk_in_ready), .in_data_i(chk_in_word),
    .out_valid_o(chk_valid), .out_ready_i(chk_ready), .out_data_o(chk_word),
    .count_o()
  );

  scw_fifo #(.Width(1), .Depth(FlagFifoDepth)) u_flag_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(fl_valid), .in_ready_o(fl_ready), .in_data_i(fl_error),
    .out_valid_o(flag_valid_o), .out_ready_i(flag_ready_i), .out_data_o(flag_error_o),
    .count_o()
  );

  scw_rectify_map_grid #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .GridLog2(GridLog2),
    .FracBits(FracBits), .KnotFracBits(KnotFracBits)
  ) u_map_grid (
    .clk_i, .rst_ni,
    .cfg_width_i, .cfg_height_i,
    .run_i, .knot_we_i, .knot_addr_i, .knot_data_i,
    .out_valid_o(map_in_valid), .out_ready_i(map_in_ready), .out_data_o(map_in_data),
    .out_sof_o(map_in_sof), .out_eol_o(map_in_eol)
  );

  scw_fifo #(.Width(MapW + 2), .Depth(MapFifoDepth)) u_map_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(map_in_valid), .in_ready_o(map_in_ready),
    .in_data_i({map_in_eol, map_in_sof, map_in_data}),
    .out_valid_o(map_valid), .out_ready_i(map_ready), .out_data_o(map_word),
    .count_o()
  );

  assign rect_in_word = chk_word;
  scw_rectify #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .Rows(RectRows),
    .FracBits(FracBits)
  ) u_rectify (
    .clk_i, .rst_ni,
    .cfg_width_i, .cfg_height_i, .cfg_lead_i,
    .in_valid_i(chk_valid), .in_ready_o(chk_ready), .in_data_i(rect_in_word[BeatW-1:0]),
    .in_sof_i(rect_in_word[BeatW]), .in_eol_i(rect_in_word[BeatW+1]),
    .map_valid_i(map_valid), .map_ready_o(map_ready), .map_data_i(map_word[MapW-1:0]),
    .map_sof_i(map_word[MapW]), .map_eol_i(map_word[MapW+1]),
    .out_valid_o(rect_valid), .out_ready_i(rect_ready), .out_data_o(rect_data),
    .out_sof_o(rect_sof), .out_eol_o(rect_eol),
    .err_o
  );

  // Registered output (the same behaviour clock for clock): the disparity stage's prefilter
  // writes I(x+1) - I(x-1) of this word into its row RAM, which from the FIFO's LUT RAM was the
  // top's worst path at the thesis size (3,587 ps).
  scw_fifo #(.Width(BeatW + 2), .Depth(RectFifoDepth), .OutReg(1'b1)) u_rect_fifo (
    .clk_i, .rst_ni,
    .in_valid_i(rect_valid), .in_ready_o(rect_ready), .in_data_i({rect_eol, rect_sof, rect_data}),
    .out_valid_o(out_valid_o), .out_ready_i(out_ready_i), .out_data_o(out_word),
    .count_o()
  );
  assign out_data_o = out_word[BeatW-1:0];
  assign out_sof_o  = out_word[BeatW];
  assign out_eol_o  = out_word[BeatW+1];
  /* verilator lint_on PINCONNECTEMPTY */
endmodule
