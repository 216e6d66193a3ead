// SPDX-License-Identifier: Apache-2.0
// One stream of a pipeline vector set checked where it leaves its stage: every transfer
// (valid && ready) must equal the next line of the stream's expected hex file. Pixel streams
// ({eol, sof, px}) name a difference by frame, row and column; word streams ({last, word}) by
// frame (counted by last) and word. Plain SystemVerilog for Verilator 5.006 and Icarus 11
// (docs/vectors.md, "Replaying a set").
`timescale 1ns / 1ps
`default_nettype none

module tb_pipeline_stream_check #(
  parameter            Name  = "stream",  // its file is <Name>.hex (untyped: Icarus 11 prints
                                          // a sized string parameter as empty)
  parameter            Count = "disp_beats",  // the plusarg with its lines (untyped, as Name)
  parameter int        Cap   = 16384,     // the most lines it may have
  parameter int        Bits  = 18,        // a line's width: {eol, sof, px} or {last, word}
  parameter int        Pixel = 1,         // 1: {eol, sof, px}; 0: {last, word}
  parameter int        Ppc   = 1
) (
  input  wire             clk,
  input  wire             take,  // valid && ready this cycle
  input  wire  [Bits-1:0] line,
  output logic [31:0]     seen   // transfers so far
);
  logic [Bits-1:0] exp_mem [Cap];
  string dir, file;
  logic [31:0] frame = 0;
  int lines, width, height, per_row = 1, per_frame = 1;  // per_*: a pixel stream's beats
  initial begin
    seen = 0;
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "give +vectors=<vector set folder>");
    lines = tb_replay_count(Count, Cap);
    // the frames' size, for a pixel stream's rows
    if (!$value$plusargs("width=%d", width) || !$value$plusargs("height=%d", height))
      $fatal(1, "give the set's +width +height");
    per_row = width / Ppc;
    per_frame = per_row * height;
    file = $sformatf("%0s/%0s.hex", dir, Name);
    $readmemh(file, exp_mem, 0, lines - 1);
  end

  always @(posedge clk) begin
    if (take) begin
      if (seen >= lines)
        $fatal(1, "%0s: a transfer past the %0d expected lines: %h", Name, lines, line);
      else if (line !== exp_mem[seen]) begin
        if (Pixel != 0)
          $fatal(1, "%0s: beat %0d (frame %0d, row %0d, column %0d): got %h, expected %h", Name,
                 seen, seen / per_frame, (seen % per_frame) / per_row, (seen % per_row) * Ppc, line,
                 exp_mem[seen]);
        else
          $fatal(1, "%0s: word %0d (frame %0d): got %h, expected %h", Name, seen, frame, line,
                 exp_mem[seen]);
      end
      if (Pixel == 0 && line[Bits-1]) frame <= frame + 1;
      seen <= seen + 1;
    end
  end
endmodule
