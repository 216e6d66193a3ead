// SPDX-License-Identifier: Apache-2.0
// Self-checking replay of a pipeline golden vector set against the scw_pipeline top: the knots
// loaded, raw left and right frames driven with their own idle cycles, both outputs stalled, and
// every stream between the stages checked where it leaves its stage (rectified left and right,
// disparity, what the road stage leaves, the object words) besides the top's two outputs (the
// object table and the frame results). The first difference stops the run naming its stream,
// frame, row and column (tb_pipeline_stream_check.sv). Plain SystemVerilog for Verilator 5.006
// and Icarus 11 (docs/vectors.md, "Replaying a set").
`timescale 1ns / 1ps
`default_nettype none

// Run: +vectors=<set folder> +width +height (the manifest's config) +knots +raw_beats
// +disp_beats +obj_words +results (the beats of knots.hex, left.hex, disparity.hex, objects.hex
// and results.hex) [+stalls=0]. Parameters: the manifest's config.params (the top's, by their
// RTL names), each hex file's width_bits, and Cap, the most lines a file may have.
module tb_pipeline_replay #(
  parameter int Ppc            = 1,
  parameter int MaxWidthPx     = 64,
  parameter int MaxHeight      = 48,
  parameter int RectRows       = 16,
  parameter int GridLog2       = 3,
  parameter int Window         = 5,
  parameter int NumDisp        = 16,
  parameter int MaxTilesX      = 2,
  parameter int MaxTilesY      = 2,
  parameter int LabelsPerTile  = 64,
  parameter int MaxObjects     = 32,
  parameter int MaxDisparityPx = 32,
  parameter int CfgWords       = 3,   // cfg.hex: width, height, lead (32-bit words, port order)
  parameter int LabellingCfgW  = 80,  // cfg_labelling.hex: cfg_labelling_i (scw_pkg::LabellingCfgBits)
  parameter int DisparityCfgW  = 109,  // cfg_disparity.hex: cfg_disparity_i (scw_pkg::DisparityCfgBits)
  parameter int WarningCfgW    = 237,  // cfg_warning.hex: cfg_warning_i (scw_pkg::WarningCfgBits)
  parameter int RoadCfgW       = 173,  // cfg_road.hex: cfg_road_i (scw_pkg::RoadCfgBits)
  parameter int KnotBits       = 29,  // knots.hex: {right, address, knot}
  parameter int ObjBits        = 898, // objects.hex: {last, word}
  parameter int ResBits        = 202, // results.hex: {last, result}
  parameter int Cap            = 16384
);
  localparam int MaxWH  = (MaxWidthPx > MaxHeight) ? MaxWidthPx : MaxHeight;
  localparam int KCols  = ((MaxWidthPx - 1) >> GridLog2) + 2;
  localparam int KRows  = ((MaxHeight - 1) >> GridLog2) + 2;
  localparam int KAddrW = $clog2(KRows) + $clog2(KCols);
  localparam int KnotW  = KnotBits - 1 - KAddrW;
  localparam int BeatW  = Ppc * 8;
  localparam int DispW  = Ppc * 16;
  localparam int WW     = $clog2(MaxWidthPx + 1);
  localparam int HW     = $clog2(MaxHeight + 1);
  localparam int SlotW  = $clog2(RectRows);
  localparam int ObjW   = ObjBits - 1;
  localparam int OutW   = ResBits - 1;
  logic [31:0]         cfg     [CfgWords];
  logic [WarningCfgW-1:0] cfg_warning [1];
  logic [RoadCfgW-1:0] cfg_road [1];
  logic [DisparityCfgW-1:0] cfg_disparity [1];
  logic [LabellingCfgW-1:0] cfg_labelling [1];
  logic [KnotBits-1:0] knot    [Cap];
  logic [BeatW+1:0]    l_mem   [Cap];  // left.hex, right.hex: {eol, sof, px}
  logic [BeatW+1:0]    r_mem   [Cap];
  string dir;
  // disp_beats: rect_*.hex (the same count), disparity.hex, road.hex
  int stalls = 1, knots, raw_beats, disp_beats, obj_words, results, max_cycles;
  initial begin
    if ($value$plusargs("stalls=%d", stalls)) begin end
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    knots = tb_replay_count("knots", Cap);
    raw_beats = tb_replay_count("raw_beats", Cap);
    disp_beats = tb_replay_count("disp_beats", Cap);
    obj_words = tb_replay_count("obj_words", Cap);
    results = tb_replay_count("results", Cap);
    // Generous: a frame takes a few thousand clocks at the small size, a few times more stalled.
    max_cycles = 64 * (raw_beats + obj_words + results) + 8 * knots + 200000;
    $readmemh({dir, "/cfg.hex"}, cfg, 0, CfgWords - 1);
    $readmemh({dir, "/cfg_warning.hex"}, cfg_warning, 0, 0);
    $readmemh({dir, "/cfg_road.hex"}, cfg_road, 0, 0);
    $readmemh({dir, "/cfg_disparity.hex"}, cfg_disparity, 0, 0);
    $readmemh({dir, "/cfg_labelling.hex"}, cfg_labelling, 0, 0);
    $readmemh({dir, "/knots.hex"}, knot, 0, knots - 1);
    $readmemh({dir, "/left.hex"}, l_mem, 0, raw_beats - 1);
    $readmemh({dir, "/right.hex"}, r_mem, 0, raw_beats - 1);
  end

  logic clk, rst_n;
  longint cyc;
  tb_replay_clock u_clock (.clk, .rst_n, .cyc);

  // The knots first, one a clock, run_i low; then run_i high for good.
  int k = 0;
  logic run, knot_we;
  assign knot_we = rst_n && (k < knots);
  assign run     = rst_n && (k >= knots);
  always @(posedge clk) if (knot_we) k <= k + 1;
  logic [KnotBits-1:0] knot_w;
  assign knot_w = knot[(k < knots) ? k : 0];

  // Sources: left offers on 3 of 4 cycles, right on 4 of 5; a beat is held until taken.
  int i, j;
  logic l_valid, l_ready, r_valid, r_ready;
  logic [BeatW+1:0] l_beat, r_beat;
  tb_replay_source #(.Period(4), .Idle(3)) u_l (
    .clk, .run_i(run), .cyc_i(cyc), .gaps_i(stalls != 0), .ready_i(l_ready), .count_i(raw_beats),
    .valid_o(l_valid), .count_o(i)
  );
  tb_replay_source #(.Period(5), .Idle(2)) u_r (
    .clk, .run_i(run), .cyc_i(cyc), .gaps_i(stalls != 0), .ready_i(r_ready), .count_i(raw_beats),
    .valid_o(r_valid), .count_o(j)
  );
  assign l_beat  = l_mem[(i < raw_beats) ? i : 0];
  assign r_beat  = r_mem[(j < raw_beats) ? j : 0];

  logic out_valid, out_ready, out_last, obj_valid, obj_ready, obj_last;
  logic [OutW-1:0] out_data;
  logic [ObjW-1:0] obj_data;
  logic [7:0] err;
  // The object table's sink on another phase of the results' pattern.
  tb_replay_sink u_out_sink (.cyc_i(cyc), .gaps_i(stalls != 0), .ready_o(out_ready));
  tb_replay_sink #(.Phase(3)) u_obj_sink (.cyc_i(cyc), .gaps_i(stalls != 0), .ready_o(obj_ready));

  scw_pipeline #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .RectRows(RectRows),
    .GridLog2(GridLog2), .Window(Window), .NumDisp(NumDisp), .MaxTilesX(MaxTilesX),
    .MaxTilesY(MaxTilesY), .LabelsPerTile(LabelsPerTile), .MaxObjects(MaxObjects),
    .MaxDisparityPx(MaxDisparityPx)
  ) u_dut (
    .clk_i(clk), .rst_ni(rst_n),
    // cfg.hex, in the order of the manifest's cfg.hex layout (the ports' order), and each
    // stage's configuration word
    .cfg_width_i(cfg[0][WW-1:0]), .cfg_height_i(cfg[1][HW-1:0]), .cfg_lead_i(cfg[2][SlotW-1:0]),
    .cfg_disparity_i(cfg_disparity[0]),
    .cfg_labelling_i(cfg_labelling[0]),
    .cfg_warning_i(cfg_warning[0]),
    .cfg_road_i(cfg_road[0]),
    .run_i(run), .knot_we_i(knot_we), .knot_right_i(knot_w[KnotBits-1]),
    .knot_addr_i(knot_w[KnotW +: KAddrW]), .knot_data_i(knot_w[KnotW-1:0]),
    .l_valid_i(l_valid), .l_ready_o(l_ready), .l_data_i(l_beat[BeatW-1:0]),
    .l_sof_i(l_beat[BeatW]), .l_eol_i(l_beat[BeatW+1]),
    .r_valid_i(r_valid), .r_ready_o(r_ready), .r_data_i(r_beat[BeatW-1:0]),
    .r_sof_i(r_beat[BeatW]), .r_eol_i(r_beat[BeatW+1]),
    .obj_valid_o(obj_valid), .obj_ready_i(obj_ready), .obj_data_o(obj_data),
    .obj_last_o(obj_last),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_data_o(out_data),
    .out_last_o(out_last), .err_o(err)
  );

  // Each stream where it leaves its stage: the stage's output ports, by hierarchical name.
  logic [31:0] n_rl, n_rr, n_disp, n_road, n_obj, n_table, n_res;
  tb_pipeline_stream_check #(.Name("rect_left"), .Count("disp_beats"), .Cap(Cap),
    .Bits(BeatW + 2), .Pixel(1), .Ppc(Ppc)) u_rect_left (.clk(clk),
    .take(u_dut.u_cam_l.u_rectify.out_valid_o && u_dut.u_cam_l.u_rectify.out_ready_i),
    .line({u_dut.u_cam_l.u_rectify.out_eol_o, u_dut.u_cam_l.u_rectify.out_sof_o,
           u_dut.u_cam_l.u_rectify.out_data_o}), .seen(n_rl));
  tb_pipeline_stream_check #(.Name("rect_right"), .Count("disp_beats"), .Cap(Cap),
    .Bits(BeatW + 2), .Pixel(1), .Ppc(Ppc)) u_rect_right (.clk(clk),
    .take(u_dut.u_cam_r.u_rectify.out_valid_o && u_dut.u_cam_r.u_rectify.out_ready_i),
    .line({u_dut.u_cam_r.u_rectify.out_eol_o, u_dut.u_cam_r.u_rectify.out_sof_o,
           u_dut.u_cam_r.u_rectify.out_data_o}), .seen(n_rr));
  tb_pipeline_stream_check #(.Name("disparity"), .Count("disp_beats"), .Cap(Cap),
    .Bits(DispW + 2), .Pixel(1), .Ppc(Ppc)) u_disparity (.clk(clk),
    .take(u_dut.u_disparity.out_valid_o && u_dut.u_disparity.out_ready_i),
    .line({u_dut.u_disparity.out_eol_o, u_dut.u_disparity.out_sof_o,
           u_dut.u_disparity.out_data_o}), .seen(n_disp));
  tb_pipeline_stream_check #(.Name("road"), .Count("disp_beats"), .Cap(Cap),
    .Bits(DispW + 2), .Pixel(1), .Ppc(Ppc)) u_road (.clk(clk),
    .take(u_dut.u_road.out_valid_o && u_dut.u_road.out_ready_i),
    .line({u_dut.u_road.out_eol_o, u_dut.u_road.out_sof_o, u_dut.u_road.out_data_o}),
    .seen(n_road));
  // ObjBits and ResBits count the last bit too.
  initial begin
    tb_replay_widths("object", "scw_pipeline", ObjBits - 1, $bits(u_dut.u_labelling.out_data_o));
    tb_replay_widths("result", "scw_pipeline", ResBits - 1, $bits(u_dut.out_data_o));
  end
  tb_pipeline_stream_check #(.Name("objects"), .Count("obj_words"), .Cap(Cap), .Bits(ObjBits),
    .Pixel(0)) u_objects (.clk(clk),
    .take(u_dut.u_labelling.out_valid_o && u_dut.u_labelling.out_ready_i),
    .line({u_dut.u_labelling.out_last_o, u_dut.u_labelling.out_data_o}), .seen(n_obj));
  tb_pipeline_stream_check #(.Name("objects"), .Count("obj_words"), .Cap(Cap), .Bits(ObjBits),
    .Pixel(0)) u_table (.clk(clk), .take(obj_valid && obj_ready), .line({obj_last, obj_data}),
    .seen(n_table));
  tb_pipeline_stream_check #(.Name("results"), .Count("results"), .Cap(Cap), .Bits(ResBits),
    .Pixel(0)) u_results (.clk(clk), .take(out_valid && out_ready), .line({out_last, out_data}),
    .seen(n_res));
  // The top's two outputs hold a stalled word.
  tb_replay_hold #(.Name("result"), .Bits(OutW + 1)) u_out_hold (
    .clk, .cyc_i(cyc), .valid_i(out_valid), .ready_i(out_ready), .data_i({out_last, out_data}),
    .index_i(n_res)
  );
  tb_replay_hold #(.Name("word"), .Bits(ObjW + 1)) u_obj_hold (
    .clk, .cyc_i(cyc), .valid_i(obj_valid), .ready_i(obj_ready), .data_i({obj_last, obj_data}),
    .index_i(n_table)
  );

  always @(posedge clk) begin
    if (cyc > max_cycles)
      $fatal(1, "timeout at cycle %0d: %0d of %0d results, %0d of %0d object words, %0d of %0d disparity beats (%0d, %0d raw beats in)",
             cyc, n_res, results, n_obj, obj_words, n_disp, disp_beats, i, j);
    if (rst_n && err !== 8'd0) $fatal(1, "err_o = %b on well-formed frames (cycle %0d)", err, cyc);
    if (n_res == results && n_table == obj_words) begin
      if (n_rl != disp_beats || n_rr != disp_beats || n_disp != disp_beats || n_road != disp_beats ||
          n_obj != obj_words)
        $fatal(1, "results out, but streams short: rect %0d/%0d, disparity %0d, road %0d of %0d, objects %0d of %0d",
               n_rl, n_rr, n_disp, n_road, disp_beats, n_obj, obj_words);
      $display("PASS: %0d beats match %s (%0d results, %0d object words, %0d disparity beats a stream, %0d cycles)",
               results, dir, results, obj_words, disp_beats, cyc);
      $finish;
    end
  end
endmodule
