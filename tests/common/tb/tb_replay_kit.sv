// SPDX-License-Identifier: Apache-2.0
// What every replay testbench shares, so that each holds only its block's ports and checks:
// the clock, the reset and the cycle count (tb_replay_clock), a source that offers beats on a
// fixed pattern of cycles and holds a beat until it is taken (tb_replay_source), a sink's ready
// on another pattern (tb_replay_sink), the check that a stalled output holds (tb_replay_hold), a
// set's counts given at run time (tb_replay_count) and the refusal of a set made at other word
// widths (tb_replay_widths).
`timescale 1ns / 1ps
`default_nettype none

// A count of the set's lines (beats, words, frames), given at run time as +NAME=N (replay.sh
// reads it from the manifest), so that one build of a testbench replays every set of its block
// at one size. The arrays it indexes are built with Cap lines, a parameter.
function automatic int tb_replay_count(input string name, input int cap);
  int n;
  if (!$value$plusargs({name, "=%d"}, n))
    $fatal(1, "give +%s=N, the set's count (its manifest)", name);
  if (n < 1 || n > cap)
    $fatal(1, "+%s=%0d: this build of the testbench holds 1 to %0d: build it with -GCap=%0d",
           name, n, cap, n);
  return n;
endfunction

// A set made at other scw_pkg widths (a field's width changed since) holds words this RTL cannot
// match: say so before the first clock, rather than fail on the first word that differs.
function automatic void tb_replay_widths(input string words, input string block, input int set_bits,
                                         input int rtl_bits);
  if (set_bits != rtl_bits)
    $fatal(1, "the set's %s words are %0d bits, this %s's %0d: the set was made at other scw_pkg widths; regenerate it (scripts/regen_vectors.sh) or replay it on the RTL it was made for",
           words, set_bits, block, rtl_bits);
endfunction

// 125 MHz. The reset is released between two clock edges (20 and 24 ns): on an edge, simulators
// order it differently (Icarus once stored an X; Verilator and Icarus then start a cycle apart).
// A block's static configuration holds its value from time 0, before reset ends.
module tb_replay_clock (
  output logic   clk,
  output logic   rst_n,
  output longint cyc  // rising edges so far
);
  // The ports are the variables themselves, not assigns from inner ones: an assign is one more
  // event at every edge, and the longest Icarus replay ran slower with them (docs/vectors.md).
  initial begin
    clk = 1'b0;
    rst_n = 1'b0;
    cyc = 0;
  end
  always #4 clk = ~clk;
  initial #22 rst_n = 1'b1;
  always @(posedge clk) cyc <= cyc + 1;
endmodule

// Offers a beat while run_i is high on every cycle but cycle Idle of each Period (all of them
// when gaps_i is low), until count_i beats are taken; a beat once offered stays offered until it is
// taken (AXI4-Stream). count_o is the index of the beat on offer (count_i when all are taken).
// Sources of one testbench use co-prime periods (4 and 5) so that their gaps drift apart.
module tb_replay_source #(
  parameter int Period = 4,
  parameter int Idle   = 3
) (
  input  logic   clk,
  input  logic   run_i,
  input  longint cyc_i,
  input  logic   gaps_i,
  input  logic   ready_i,
  input  int     count_i,  // the set's beats
  output logic   valid_o,
  output int     count_o
);
  logic held;
  initial begin
    held = 1'b0;
    count_o = 0;
  end
  assign valid_o = run_i && (count_o < count_i) && (((cyc_i % Period) != Idle) || held || !gaps_i);
  always @(posedge clk) begin
    held <= valid_o && !ready_i;
    if (valid_o && ready_i) count_o <= count_o + 1;
  end
endmodule

// A sink's ready: the pattern 1,1,0,1,0,0,1 (bit k of 7'b1001011 is the ready of cycles k mod 7,
// co-prime with the sources' periods 4 and 5 and with any row length), Phase cycles on; always
// ready while gaps_i is low.
module tb_replay_sink #(
  parameter int Phase = 0
) (
  input  longint cyc_i,
  input  logic   gaps_i,
  output logic   ready_o
);
  localparam logic [6:0] Pattern = 7'b1001011;
  assign ready_o = Pattern[(cyc_i + Phase) % 7] || !gaps_i;
endmodule

// AXI4-Stream's rule on an output: a beat offered and not taken stays offered, unchanged, on the
// next clock, whatever the stalls do. Stops naming the beat's index (Name: beat, word, result;
// untyped, as Icarus 11 prints a sized string parameter as empty).
module tb_replay_hold #(
  parameter     Name = "beat",
  parameter int Bits = 1
) (
  input logic            clk,
  input longint          cyc_i,
  input logic            valid_i,
  input logic            ready_i,
  input logic [Bits-1:0] data_i,  // every bit offered with valid: data and its sideband
  input int              index_i  // the index of the beat on offer
);
  logic stalled = 1'b0;
  logic [Bits-1:0] held;
  always @(posedge clk) begin
    if (stalled && (valid_i !== 1'b1 || data_i !== held))
      $fatal(1, "%0s %0d: valid or the %0s changed while stalled (cycle %0d)", Name, index_i, Name,
             cyc_i);
    stalled <= valid_i && !ready_i;
    held <= data_i;
  end
endmodule
