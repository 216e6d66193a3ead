// SPDX-License-Identifier: Apache-2.0
// Self-checking replay of a line_buffer golden vector set against scw_line_buffer, with idle
// input cycles and output backpressure, in plain SystemVerilog (any simulator).
`timescale 1ns / 1ps
`default_nettype none

// Run: +vectors=<set folder> +beats=<N> (input.hex's beats); parameters from the set's
// manifest.json (config), and Cap, the most beats a set may have.
module tb_line_buffer_replay #(
  parameter int Ppc        = 2,
  parameter int MaxWidthPx = 1280,
  parameter int Rows       = 3,
  parameter int Cap        = 16384
);
  localparam int BeatW = Ppc * 8;
  localparam int OutW  = Rows * BeatW;

  logic [BeatW+1:0] in_mem  [Cap];
  logic [OutW+1:0]  exp_mem [Cap];
  string dir;
  int beats;
  initial begin
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    beats = tb_replay_count("beats", Cap);
    $readmemh({dir, "/input.hex"}, in_mem, 0, beats - 1);
    $readmemh({dir, "/expected.hex"}, exp_mem, 0, beats - 1);
  end

  logic clk, rst_n;
  longint cyc;
  tb_replay_clock u_clock (.clk, .rst_n, .cyc);

  // Source: offers on 3 of 4 cycles; holds a beat until it is accepted.
  int i;
  logic in_valid, in_ready;
  tb_replay_source #(.Period(4), .Idle(3)) u_in (
    .clk, .run_i(rst_n), .cyc_i(cyc), .gaps_i(1'b1), .ready_i(in_ready), .count_i(beats),
    .valid_o(in_valid), .count_o(i)
  );

  // Sink: ready on a co-prime 1,1,0,1,0,0,1 cycle; each output must be the next expected line.
  int o = 0;
  logic out_valid, out_ready, out_sof, out_eol, err;
  logic [OutW-1:0] out_data;
  tb_replay_sink u_sink (.cyc_i(cyc), .gaps_i(1'b1), .ready_o(out_ready));

  scw_line_buffer #(.Ppc(Ppc), .MaxWidthPx(MaxWidthPx), .Rows(Rows)) u_dut (
    .clk_i(clk), .rst_ni(rst_n),
    .in_valid_i(in_valid), .in_ready_o(in_ready), .in_data_i(in_mem[i < beats ? i : 0][BeatW-1:0]),
    .in_sof_i(in_mem[i < beats ? i : 0][BeatW]), .in_eol_i(in_mem[i < beats ? i : 0][BeatW+1]),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_data_o(out_data),
    .out_sof_o(out_sof), .out_eol_o(out_eol), .err_o(err)
  );

  tb_replay_hold #(.Bits(OutW + 2)) u_hold (
    .clk, .cyc_i(cyc), .valid_i(out_valid), .ready_i(out_ready),
    .data_i({out_eol, out_sof, out_data}), .index_i(o)
  );

  // A bound in clocks, not a delay: Verilator 5.006 keeps a delay in 32 bits of the time
  // precision (ps), so a large set's delay wrapped and fired early.
  always @(posedge clk)
    if (cyc > beats * 20 + 125) $fatal(1, "timeout after %0d of %0d beats", o, beats);
  always @(posedge clk) begin
    if (out_valid && out_ready) begin
      if ({out_eol, out_sof, out_data} !== exp_mem[o])
        $fatal(1, "beat %0d: got %h, expected %h", o, {out_eol, out_sof, out_data}, exp_mem[o]);
      if (err) $fatal(1, "err_o set on a well-formed stream");
      o <= o + 1;
      if (o + 1 == beats) begin
        $display("PASS: %0d beats match %s", beats, dir);
        $finish;
      end
    end
  end
endmodule
