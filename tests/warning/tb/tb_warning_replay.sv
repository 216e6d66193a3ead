// SPDX-License-Identifier: Apache-2.0
// Self-checking replay of a warning golden vector set against scw_warning: object tables driven
// with idle cycles, output backpressure, every result word compared.
`timescale 1ns / 1ps
`default_nettype none

// Run with +vectors=<set folder> +words_in +words_out (the manifest's config; words_out =
// frames: one result a frame): the stage's configuration is the set's cfg.hex, one word for
// cfg_warning_i (scw_pkg::warning_cfg_t; its fields in the manifest's layout).
// Parameters: config.max_disparity_px (the build), the words' widths, and Cap, the most words a
// set may have.
// +stalls=0 turns the idle input cycles and the backpressure off (to tell a stall bug from
// another).
module tb_warning_replay #(
  parameter int MaxDisparityPx = 128,
  parameter int Cap            = 16384,
  // The words' widths: the manifest's in.hex and expected.hex width_bits less the last bit (the
  // labelling object word and the frame result at scw_pkg's widths).
  parameter int InW            = 897,
  parameter int OutW           = 199,
  parameter int CfgW           = 237   // cfg.hex's width_bits: scw_pkg::WarningCfgBits
);
  localparam int Latency = 64 + 47;  // hls::warning::kLatency (kRuleLatency + 47)
  logic [InW:0]  in_mem  [Cap];  // {last, data[InW-1:0]}
  logic [OutW:0] exp_mem [Cap];  // {last, data[OutW-1:0]}
  string dir;
  int stalls = 1, words_in, words_out;
  longint max_cycles;
  logic [CfgW-1:0] cfg_mem [1];
  // cfg_warning_i is static: it takes its value at time 0, long before the first word.
  initial begin
    if ($value$plusargs("stalls=%d", stalls)) begin end
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    words_in = tb_replay_count("words_in", Cap);
    words_out = tb_replay_count("words_out", Cap);
    // Generous: the stage takes a word a clock unless its result waits; the source idles 1
    // clock in 4 and the sink 3 in 7.
    max_cycles = 8 * (words_in + words_out) + 8 * Latency + 1000;
    $readmemh({dir, "/cfg.hex"}, cfg_mem, 0, 0);
    $readmemh({dir, "/in.hex"}, in_mem, 0, words_in - 1);
    $readmemh({dir, "/expected.hex"}, exp_mem, 0, words_out - 1);
  end

  logic clk, rst_n;
  longint cyc;
  tb_replay_clock u_clock (.clk, .rst_n, .cyc);

  // Source: offers on 3 of 4 cycles; a word once offered is held until taken.
  int i;
  logic in_valid, in_ready;
  logic [InW:0] in_word;
  tb_replay_source #(.Period(4), .Idle(3)) u_in (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(stalls != 0), .ready_i(in_ready), .count_i(words_in),
    .valid_o(in_valid), .count_o(i)
  );
  assign in_word  = in_mem[(i < words_in) ? i : 0];

  // Sink: ready on a co-prime 1,1,0,1,0,0,1 cycle; each word taken must be the next expected one.
  int o = 0;
  logic out_valid, out_ready, out_last;
  logic [OutW-1:0] out_data;
  tb_replay_sink u_sink (.cyc_i(cyc), .gaps_i(stalls != 0), .ready_o(out_ready));

  logic road_ready;  // never asked for a line here
  scw_warning #(.MaxDisparityPx(MaxDisparityPx)) u_dut (
    .clk_i(clk), .rst_ni(rst_n),
    .cfg_warning_i(cfg_mem[0]),
    // the sets judge box heights: no road line comes with their frames
    .cfg_road_height_i(1'b0), .road_valid_i(1'b0), .road_ready_o(road_ready),
    .road_a_i(18'd0), .road_b_i(32'd0),
    .in_valid_i(in_valid), .in_ready_o(in_ready), .in_data_i(in_word[InW-1:0]),
    .in_last_i(in_word[InW]),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_data_o(out_data),
    .out_last_o(out_last)
  );

  initial begin
    tb_replay_widths("object", "scw_warning", InW, $bits(u_dut.in_data_i));
    tb_replay_widths("result", "scw_warning", OutW, $bits(u_dut.out_data_o));
  end

  tb_replay_hold #(.Name("result"), .Bits(OutW + 1)) u_hold (
    .clk, .cyc_i(cyc), .valid_i(out_valid), .ready_i(out_ready), .data_i({out_last, out_data}),
    .index_i(o)
  );

  always @(posedge clk) begin
    if (cyc > max_cycles)
      $fatal(1, "timeout after %0d of %0d results (%0d of %0d words in)", o, words_out, i,
             words_in);
    if (rst_n && (in_ready === 1'bx || out_valid === 1'bx))
      $fatal(1, "in_ready_o or out_valid_o is X (cycle %0d)", cyc);
    if (out_valid && out_ready) begin
      // One result a frame: frame o. Fields, lsb first: severity[1:0], in_tunnel, too_close,
      // tile_overflow, object_overflow, stream_error, objects, obstacles, index, distance_mm, ...
      if ({out_last, out_data} !== exp_mem[o])
        $fatal(1, "frame %0d: got %h (severity %0d, index %0d, distance %0d mm), expected %h ",
               o, {out_last, out_data}, out_data[1:0], out_data[54:39],
               $signed(out_data[86:55]), exp_mem[o],
               "(severity %0d, index %0d, distance %0d mm); see expected.csv row %0d",
               exp_mem[o][1:0], exp_mem[o][54:39], $signed(exp_mem[o][86:55]), o);
      o <= o + 1;
      if (o + 1 == words_out) begin
        if (i != words_in)
          $fatal(1, "all results out, but only %0d of %0d words taken", i, words_in);
        $display("PASS: %0d beats match %s (%0d words in, %0d cycles)", words_out, dir, words_in,
                 cyc);
        $finish;
      end
    end
  end
endmodule
