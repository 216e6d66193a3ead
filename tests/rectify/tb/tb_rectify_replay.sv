// SPDX-License-Identifier: Apache-2.0
// Self-checking replay of a rectify golden vector set against scw_rectify: raw pixels and map
// driven with their own idle cycles, output backpressure, every output beat compared.
`timescale 1ns / 1ps
`default_nettype none

// Run: +vectors=<set folder> +width=<W> +height=<H> +lead=<D> +beats=<N>, from the set's
// manifest.json (config.width, config.height, config.lead_rows, and the hex files' beats: all
// three files of a set have frames x W * H / Ppc beats, frames back to back, each with the one
// map). Parameters: config.ppc, max_width_px, max_height, rows, frac_bits, coord_bits, and Cap,
// the most beats a set may have.
module tb_rectify_replay #(
  parameter int Ppc        = 2,
  parameter int MaxWidthPx = 128,
  parameter int MaxHeight  = 96,
  parameter int Rows       = 32,
  parameter int FracBits   = 5,
  parameter int CoordBits  = 14,
  parameter int Cap        = 16384
);
  localparam int MaxWH   = (MaxWidthPx > MaxHeight) ? MaxWidthPx : MaxHeight;
  // What scw_rectify derives from its parameters; the manifest's coord_bits must agree.
  localparam int DutCoordBits = $clog2(MaxWH * (1 << FracBits) + 1) + 1;
  localparam int BeatW = Ppc * 8;
  localparam int MapW  = Ppc * 2 * CoordBits;
  localparam int WW    = $clog2(MaxWidthPx + 1);
  localparam int HW    = $clog2(MaxHeight + 1);
  localparam int SlotW = $clog2(Rows);

  logic [BeatW+1:0] in_mem  [Cap];  // {eol, sof, px[Ppc-1..0]}
  logic [MapW+1:0]  map_mem [Cap];  // {eol, sof, {y, x}[Ppc-1..0]}
  logic [BeatW+1:0] exp_mem [Cap];
  string dir;
  int width, height, lead, beats;
  initial begin
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    beats = tb_replay_count("beats", Cap);
    if (!$value$plusargs("width=%d", width) || !$value$plusargs("height=%d", height) ||
        !$value$plusargs("lead=%d", lead))
      $fatal(1, "give +width= +height= +lead= (config.width, height, lead_rows)");
    if (CoordBits != DutCoordBits)
      $fatal(1, "coord_bits %0d in the manifest, but scw_rectify derives %0d", CoordBits,
             DutCoordBits);
    if (beats % (width * height / Ppc) != 0)
      $fatal(1, "%0d beats are not whole %0d x %0d frames at %0d px per beat", beats, width,
             height, Ppc);
    $readmemh({dir, "/input.hex"}, in_mem, 0, beats - 1);
    $readmemh({dir, "/map.hex"}, map_mem, 0, beats - 1);
    $readmemh({dir, "/expected.hex"}, exp_mem, 0, beats - 1);
  end

  logic clk, rst_n;
  longint cyc;
  tb_replay_clock u_clock (.clk, .rst_n, .cyc);

  // Raw source: offers on 3 of 4 cycles; holds a beat until it is accepted.
  int i;
  logic in_valid, in_ready;
  logic [BeatW+1:0] in_beat;
  tb_replay_source #(.Period(4), .Idle(3)) u_in (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(1'b1), .ready_i(in_ready), .count_i(beats),
    .valid_o(in_valid), .count_o(i)
  );
  assign in_beat  = in_mem[(i < beats) ? i : 0];

  // Map source: offers on 4 of 5 cycles, out of step with the raw source.
  int j;
  logic map_valid, map_ready;
  logic [MapW+1:0] map_beat;
  tb_replay_source #(.Period(5), .Idle(2)) u_map (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(1'b1), .ready_i(map_ready), .count_i(beats),
    .valid_o(map_valid), .count_o(j)
  );
  assign map_beat  = map_mem[(j < beats) ? j : 0];

  // Sink: ready on a co-prime 1,1,0,1,0,0,1 cycle; each output must be the next expected line.
  int o = 0;
  logic out_valid, out_ready, out_sof, out_eol;
  logic [BeatW-1:0] out_data;
  logic [2:0] err;
  tb_replay_sink u_sink (.cyc_i(cyc), .gaps_i(1'b1), .ready_o(out_ready));

  scw_rectify #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .Rows(Rows), .FracBits(FracBits)
  ) u_dut (
    .clk_i(clk), .rst_ni(rst_n),
    .cfg_width_i(WW'(width)), .cfg_height_i(HW'(height)), .cfg_lead_i(SlotW'(lead)),
    .in_valid_i(in_valid), .in_ready_o(in_ready), .in_data_i(in_beat[BeatW-1:0]),
    .in_sof_i(in_beat[BeatW]), .in_eol_i(in_beat[BeatW+1]),
    .map_valid_i(map_valid), .map_ready_o(map_ready), .map_data_i(map_beat[MapW-1:0]),
    .map_sof_i(map_beat[MapW]), .map_eol_i(map_beat[MapW+1]),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_data_o(out_data),
    .out_sof_o(out_sof), .out_eol_o(out_eol), .err_o(err)
  );

  tb_replay_hold #(.Bits(BeatW + 2)) u_hold (
    .clk, .cyc_i(cyc), .valid_i(out_valid), .ready_i(out_ready),
    .data_i({out_eol, out_sof, out_data}), .index_i(o)
  );

  // A bound in clocks, not a delay: Verilator 5.006 keeps a delay in 32 bits of the time
  // precision (ps), so a thesis-size set's delay wrapped and fired early.
  always @(posedge clk)
    if (cyc > beats * 40 + 12500) $fatal(1, "timeout after %0d of %0d beats (raw %0d, map %0d in)", o, beats, i, j);
  always @(posedge clk) begin
    if (err != '0) $fatal(1, "err_o = %b on a well-formed frame (cycle %0d)", err, cyc);
    if (out_valid && out_ready) begin
      if ({out_eol, out_sof, out_data} !== exp_mem[o])
        $fatal(1, "beat %0d (frame %0d, row %0d): got %h, expected %h", o,
               o / (width * height / Ppc), o % (width * height / Ppc) / (width / Ppc),
               {out_eol, out_sof, out_data}, exp_mem[o]);
      o <= o + 1;
      if (o + 1 == beats) begin
        // The last output row needs the last raw row, and every output beat one map beat.
        if (i != beats || j != beats)
          $fatal(1, "frame out, but only %0d raw and %0d map beats taken of %0d", i, j, beats);
        $display("PASS: %0d beats match %s", beats, dir);
        $finish;
      end
    end
  end
endmodule
