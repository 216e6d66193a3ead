// SPDX-License-Identifier: Apache-2.0
// Self-checking replay of a labelling golden vector set against scw_labelling: disparities
// driven with idle cycles, output backpressure, every output word compared.
`timescale 1ns / 1ps
`default_nettype none

// Run with +vectors=<set folder> +width +height +beats_in +words_out +frames (the manifest's
// config): the rest of the stage's configuration is the set's cfg.hex, one word for
// cfg_labelling_i (scw_pkg::labelling_cfg_t; its fields in the manifest's layout). Parameters:
// config.max_width_px, max_height, max_tiles_x, max_tiles_y, labels_per_tile, max_objects (the
// build), the words' widths, and Cap, the most beats or words a set may have.
// +stalls=0 turns the idle input cycles and the backpressure off (to tell a stall bug from
// another).
module tb_labelling_replay #(
  parameter int MaxWidthPx    = 64,
  parameter int MaxHeight     = 48,
  parameter int MaxTilesX     = 4,
  parameter int MaxTilesY     = 4,
  parameter int LabelsPerTile = 64,
  parameter int MaxObjects    = 64,
  parameter int Cap           = 16384,
  // The object word's width: the manifest's expected.hex width_bits less the last bit (897 at
  // scw_pkg's widths).
  parameter int OutW          = 897,
  parameter int CfgW          = 80   // cfg.hex's width_bits: scw_pkg::LabellingCfgBits
);
  localparam int Nodes = MaxTilesX * MaxTilesY * LabelsPerTile;
  logic [17:0]   in_mem  [Cap];  // {eol, sof, d[15:0]}
  logic [OutW:0] exp_mem [Cap];  // {last, data[OutW-1:0]}
  string dir;
  int width, height, stalls = 1, beats_in, words_out, frames;
  longint max_cycles;
  logic [CfgW-1:0] cfg_mem [1];
  initial begin
    if ($value$plusargs("stalls=%d", stalls)) begin end
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    beats_in = tb_replay_count("beats_in", Cap);
    words_out = tb_replay_count("words_out", Cap);
    frames = tb_replay_count("frames", Cap);
    // Generous: the stage takes about one beat a clock, then sweeps its used nodes twice a
    // frame; the source idles 1 clock in 4 and the sink 3 in 7.
    max_cycles = 8 * (beats_in + words_out) + 16 * Nodes * (frames + 1) + 10000;
    if (!$value$plusargs("width=%d", width) || !$value$plusargs("height=%d", height))
      $fatal(1, "give the set's config: +width +height");
    $readmemh({dir, "/cfg.hex"}, cfg_mem, 0, 0);
    if (width * height * frames != beats_in)
      $fatal(1, "%0d frames of %0d x %0d are not %0d beats", frames, width, height, beats_in);
    $readmemh({dir, "/in.hex"}, in_mem, 0, beats_in - 1);
    $readmemh({dir, "/expected.hex"}, exp_mem, 0, words_out - 1);
  end

  logic clk, rst_n;
  longint cyc;
  tb_replay_clock u_clock (.clk, .rst_n, .cyc);

  // Source: offers on 3 of 4 cycles; a beat once offered is held until taken.
  int i;
  logic in_valid, in_ready;
  logic [17:0] in_beat;
  tb_replay_source #(.Period(4), .Idle(3)) u_in (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(stalls != 0), .ready_i(in_ready), .count_i(beats_in),
    .valid_o(in_valid), .count_o(i)
  );
  assign in_beat  = in_mem[(i < beats_in) ? i : 0];

  // Sink: ready on a co-prime 1,1,0,1,0,0,1 cycle; each word taken must be the next expected one.
  int o = 0, statuses = 0;
  logic out_valid, out_ready, out_last, err;
  logic [OutW-1:0] out_data;
  tb_replay_sink u_sink (.cyc_i(cyc), .gaps_i(stalls != 0), .ready_o(out_ready));

  scw_labelling #(
    .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight), .MaxTilesX(MaxTilesX),
    .MaxTilesY(MaxTilesY), .LabelsPerTile(LabelsPerTile), .MaxObjects(MaxObjects)
  ) u_dut (
    .clk_i(clk), .rst_ni(rst_n),
    .cfg_width_i(16'(width)), .cfg_height_i(16'(height)), .cfg_labelling_i(cfg_mem[0]),
    .in_valid_i(in_valid), .in_ready_o(in_ready), .in_data_i(in_beat[15:0]),
    .in_sof_i(in_beat[16]), .in_eol_i(in_beat[17]),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_data_o(out_data),
    .out_last_o(out_last), .err_o(err)
  );

  initial tb_replay_widths("object", "scw_labelling", OutW, $bits(u_dut.out_data_o));

  tb_replay_hold #(.Name("word"), .Bits(OutW + 1)) u_hold (
    .clk, .cyc_i(cyc), .valid_i(out_valid), .ready_i(out_ready), .data_i({out_last, out_data}),
    .index_i(o)
  );

  always @(posedge clk) begin
    if (cyc > max_cycles)
      $fatal(1, "timeout after %0d of %0d words (%0d of %0d beats in)", o, words_out, i, beats_in);
    if (rst_n && err !== 1'b0) $fatal(1, "err_o on a well-formed stream (cycle %0d)", cyc);
    if (out_valid && out_ready) begin
      // Bit 0 of the data tells a status word (frame end, with last) from an object.
      if ({out_last, out_data} !== exp_mem[o])
        $fatal(1, "word %0d (frame %0d, %s): got %h, expected %h", o, statuses,
               exp_mem[o][0] ? "status" : "object", {out_last, out_data}, exp_mem[o]);
      if (exp_mem[o][OutW]) statuses <= statuses + 1;
      o <= o + 1;
      if (o + 1 == words_out) begin
        if (i != beats_in)
          $fatal(1, "all words out, but only %0d of %0d beats taken", i, beats_in);
        $display("PASS: %0d words match %s (%0d frames, %0d cycles)", words_out, dir, frames,
                 cyc);
        $finish;
      end
    end
  end
endmodule
