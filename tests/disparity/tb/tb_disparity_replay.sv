// SPDX-License-Identifier: Apache-2.0
// Self-checking replay of a disparity golden vector set against scw_disparity: left and right
// pixels driven with their own idle cycles, output backpressure, every output beat compared.
`timescale 1ns / 1ps
`default_nettype none

// Run with +vectors=<set folder> +width +height +beats (the manifest's config, and the hex files'
// beats: all three pixel files of a set have frames x W * H / Ppc beats, frames back to back):
// the rest of the stage's configuration is the set's cfg.hex, one word for cfg_disparity_i
// (scw_pkg::disparity_cfg_t; its fields in the manifest's layout).
// Parameters: config.ppc, max_width_px, max_height, window, num_disp (built candidates), CfgW,
// cfg.hex's width, and Cap, the most beats a set may have.
module tb_disparity_replay #(
  parameter int Ppc        = 2,
  parameter int MaxWidthPx = 128,
  parameter int MaxHeight  = 64,
  parameter int Window     = 5,
  parameter int NumDisp    = 16,
  parameter int Cap        = 16384,
  parameter int CfgW       = 109   // scw_pkg::DisparityCfgBits
);
  localparam int BeatW = Ppc * 8;
  localparam int OutW  = Ppc * 16;
  localparam int WW    = $clog2(MaxWidthPx + 1);
  localparam int HW    = $clog2(MaxHeight + 1);

  logic [BeatW+1:0] l_mem   [Cap];  // {eol, sof, px[Ppc-1..0]}
  logic [BeatW+1:0] r_mem   [Cap];
  logic [OutW+1:0]  exp_mem [Cap];
  string dir;
  int width, height, beats;
  logic [CfgW-1:0] cfg_mem [1];
  initial begin
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    beats = tb_replay_count("beats", Cap);
    if (!$value$plusargs("width=%d", width) || !$value$plusargs("height=%d", height))
      $fatal(1, "give the set's config: +width +height");
    if (beats % (width * height / Ppc) != 0)
      $fatal(1, "%0d beats are not whole %0d x %0d frames at %0d px per beat", beats, width,
             height, Ppc);
    $readmemh({dir, "/cfg.hex"}, cfg_mem, 0, 0);
    $readmemh({dir, "/left.hex"}, l_mem, 0, beats - 1);
    $readmemh({dir, "/right.hex"}, r_mem, 0, beats - 1);
    $readmemh({dir, "/expected.hex"}, exp_mem, 0, beats - 1);
  end

  logic clk, rst_n;
  longint cyc;
  tb_replay_clock u_clock (.clk, .rst_n, .cyc);

  // Left source: offers on 3 of 4 cycles; right source on 4 of 5, out of step. A beat is held
  // until taken (the stage takes both sides together).
  int i, j;
  logic l_valid, l_ready, r_valid, r_ready;
  logic [BeatW+1:0] l_beat, r_beat;
  tb_replay_source #(.Period(4), .Idle(3)) u_l (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(1'b1), .ready_i(l_ready), .count_i(beats),
    .valid_o(l_valid), .count_o(i)
  );
  tb_replay_source #(.Period(5), .Idle(2)) u_r (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(1'b1), .ready_i(r_ready), .count_i(beats),
    .valid_o(r_valid), .count_o(j)
  );
  assign l_beat  = l_mem[(i < beats) ? i : 0];
  assign r_beat  = r_mem[(j < beats) ? j : 0];

  // Sink: ready on a co-prime 1,1,0,1,0,0,1 cycle; each output must be the next expected line.
  int o = 0;
  logic out_valid, out_ready, out_sof, out_eol, err;
  logic [OutW-1:0] out_data;
  tb_replay_sink u_sink (.cyc_i(cyc), .gaps_i(1'b1), .ready_o(out_ready));

  scw_disparity #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .Window(Window),
    .NumDisp(NumDisp)
  ) u_dut (
    .clk_i(clk), .rst_ni(rst_n),
    .cfg_width_i(WW'(width)), .cfg_height_i(HW'(height)), .cfg_disparity_i(cfg_mem[0]),
    .l_valid_i(l_valid), .l_ready_o(l_ready), .l_data_i(l_beat[BeatW-1:0]),
    .l_sof_i(l_beat[BeatW]), .l_eol_i(l_beat[BeatW+1]),
    .r_valid_i(r_valid), .r_ready_o(r_ready), .r_data_i(r_beat[BeatW-1:0]),
    .r_sof_i(r_beat[BeatW]), .r_eol_i(r_beat[BeatW+1]),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_data_o(out_data),
    .out_sof_o(out_sof), .out_eol_o(out_eol), .err_o(err)
  );

  tb_replay_hold #(.Bits(OutW + 2)) u_hold (
    .clk, .cyc_i(cyc), .valid_i(out_valid), .ready_i(out_ready),
    .data_i({out_eol, out_sof, out_data}), .index_i(o)
  );

  // A bound in clocks, not a delay: Verilator 5.006 keeps a delay in 32 bits of the time
  // precision (ps), so a thesis-size set's delay wrapped and fired early.
  always @(posedge clk)
    if (cyc > beats * 40 + 12500) $fatal(1, "timeout after %0d of %0d beats (%0d, %0d in)", o, beats, i, j);
  always @(posedge clk) begin
    if (err) $fatal(1, "err_o on a well-formed frame (cycle %0d)", cyc);
    if (out_valid && out_ready) begin
      if ({out_eol, out_sof, out_data} !== exp_mem[o])
        $fatal(1, "beat %0d (frame %0d, row %0d): got %h, expected %h", o,
               o / (width * height / Ppc), o % (width * height / Ppc) / (width / Ppc),
               {out_eol, out_sof, out_data}, exp_mem[o]);
      o <= o + 1;
      if (o + 1 == beats) begin
        if (i != beats || j != beats)
          $fatal(1, "frame out, but only %0d left and %0d right beats taken of %0d", i, j,
                 beats);
        $display("PASS: %0d beats match %s", beats, dir);
        $finish;
      end
    end
  end
endmodule
