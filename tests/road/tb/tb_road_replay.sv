// SPDX-License-Identifier: Apache-2.0
// Self-checking replay of a road golden vector set against scw_road: disparity frames driven
// back to back with idle cycles, output backpressure, every output beat compared.
`timescale 1ns / 1ps
`default_nettype none

// Run with +vectors=<set folder> +width +height +beats +frames (the manifest's config; beats are
// the lines of in.hex and expected.hex): the stage's configuration is the set's cfg.hex, one
// word for cfg_road_i (scw_pkg::road_cfg_t; its fields in the manifest's layout). Parameters:
// config.ppc, max_width_px, max_height (the build), fit_clocks (for the timeout only), CfgW
// (cfg.hex's width), and Cap, the most beats a set may have. +stalls=0 turns the idle input
// cycles and the backpressure off (to tell a stall bug from another).
// Plain SystemVerilog that Verilator 5.006 and Icarus Verilog 11 (-g2012) both take: no `inside`,
// no `int unsigned` parameters, no concurrent assertions.
module tb_road_replay #(
  parameter int Ppc        = 2,
  parameter int MaxWidthPx = 64,
  parameter int MaxHeight  = 48,
  parameter int Cap        = 16384,
  parameter int FitClocks  = 256,
  parameter int CfgW       = 173   // scw_pkg::RoadCfgBits
);
  localparam int DataW = Ppc * 16;
  logic [DataW+1:0] in_mem  [Cap];  // {eol, sof, px[Ppc-1] .. px[0]}, 16-bit Q11.4 pixels
  logic [DataW+1:0] exp_mem [Cap];
  string dir;
  int width, height, beats, frames, max_cycles;
  logic [CfgW-1:0] cfg_mem [1];
  int stalls = 1;
  int per_row = 1, per_frame = 1;  // beats
  initial begin
    if ($value$plusargs("stalls=%d", stalls)) begin end
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    beats = tb_replay_count("beats", Cap);
    frames = tb_replay_count("frames", Cap);
    // Generous: a beat a clock, a fit before every frame; the source idles 1 clock in 4 and the
    // sink 3 in 7.
    max_cycles = 8 * beats + 4 * (frames + 1) * (FitClocks + 16) + 10000;
    if (!$value$plusargs("width=%d", width) || !$value$plusargs("height=%d", height))
      $fatal(1, "give the set's config: +width +height");
    if (width % Ppc != 0 || width > MaxWidthPx || height > MaxHeight)
      $fatal(1, "a %0d x %0d frame does not fit the build (Ppc %0d, MaxWidthPx %0d, MaxHeight %0d)",
             width, height, Ppc, MaxWidthPx, MaxHeight);
    per_row = width / Ppc;
    per_frame = per_row * height;
    if (per_frame * frames != beats)
      $fatal(1, "%0d frames of %0d x %0d at %0d px a beat are not %0d beats", frames, width,
             height, Ppc, beats);
    $readmemh({dir, "/cfg.hex"}, cfg_mem, 0, 0);
    $readmemh({dir, "/in.hex"}, in_mem, 0, beats - 1);
    $readmemh({dir, "/expected.hex"}, exp_mem, 0, beats - 1);
  end

  logic clk, rst_n;
  longint cyc;
  tb_replay_clock u_clock (.clk, .rst_n, .cyc);

  // Source: offers on 3 of 4 cycles; a beat once offered is held until taken (the stage holds a
  // sof for the fit between frames).
  int i;
  logic in_valid, in_ready;
  logic [DataW+1:0] in_beat;
  tb_replay_source #(.Period(4), .Idle(3)) u_in (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(stalls != 0), .ready_i(in_ready), .count_i(beats),
    .valid_o(in_valid), .count_o(i)
  );
  assign in_beat  = in_mem[(i < beats) ? i : 0];

  // Sink: each beat taken must be the next line of expected.hex.
  int o = 0;
  logic out_valid, out_ready, out_sof, out_eol;
  logic [DataW-1:0] out_data;
  tb_replay_sink u_sink (.cyc_i(cyc), .gaps_i(stalls != 0), .ready_o(out_ready));

  logic        line_valid;  // read every clock: not part of the set
  logic [17:0] line_a;
  logic [31:0] line_b;
  scw_road #(
    .Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .MaxHeight(MaxHeight)
  ) u_dut (
    .clk_i(clk), .rst_ni(rst_n),
    .cfg_road_i(cfg_mem[0]),
    .in_valid_i(in_valid), .in_ready_o(in_ready), .in_data_i(in_beat[DataW-1:0]),
    .in_sof_i(in_beat[DataW]), .in_eol_i(in_beat[DataW+1]),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_data_o(out_data),
    .out_sof_o(out_sof), .out_eol_o(out_eol),
    // the line output is always read here (the set checks the disparities it leaves)
    .line_valid_o(line_valid), .line_ready_i(1'b1), .line_a_o(line_a), .line_b_o(line_b)
  );

  // Names beat `k` by frame, row and first column, and the first pixel that differs with its
  // input value (a removed pixel leaves as 0).
  task automatic mismatch(input int k, input logic [DataW+1:0] got);
    int p, first;
    first = -1;
    for (p = Ppc - 1; p >= 0; p = p - 1)
      if (got[p*16 +: 16] !== exp_mem[k][p*16 +: 16]) first = p;
    if (first >= 0)
      $display("  pixel %0d (column %0d): got %h, expected %h, input %h", first,
               (k % per_row) * Ppc + first, got[first*16 +: 16], exp_mem[k][first*16 +: 16],
               in_mem[k][first*16 +: 16]);
    $fatal(1, "beat %0d (frame %0d, row %0d, columns %0d..%0d): got %h, expected %h (eol, sof, px)",
           k, k / per_frame, (k % per_frame) / per_row, (k % per_row) * Ppc,
           (k % per_row) * Ppc + Ppc - 1, got, exp_mem[k]);
  endtask

  tb_replay_hold #(.Name("beat"), .Bits(DataW + 2)) u_hold (
    .clk, .cyc_i(cyc), .valid_i(out_valid), .ready_i(out_ready),
    .data_i({out_eol, out_sof, out_data}), .index_i(o)
  );

  // Checkers are plain `always`: Icarus warns about system tasks inside always_ff.
  always @(posedge clk) begin
    if (cyc > max_cycles)
      $fatal(1, "timeout after %0d of %0d beats out (%0d in, cycle %0d)", o, beats, i, cyc);
    if (rst_n && out_valid === 1'bx) $fatal(1, "out_valid is x (cycle %0d)", cyc);
    if (out_valid && out_ready) begin
      if ({out_eol, out_sof, out_data} !== exp_mem[o]) mismatch(o, {out_eol, out_sof, out_data});
      o <= o + 1;
      if (o + 1 == beats) begin
        if (i != beats) $fatal(1, "all beats out, but only %0d of %0d taken", i, beats);
        $display("PASS: %0d beats match %s (%0d frames, %0d cycles)", beats, dir, frames, cyc);
        $finish;
      end
    end
  end
endmodule
