// SPDX-License-Identifier: Apache-2.0
// What every replay testbench shares, so that each holds only its block's ports and checks:
// the clock, the reset and the cycle count (tb_replay_clock), a source that offers beats on a
// fixed pattern of cycles and holds a beat until it is taken (tb_replay_source), and a sink's
// ready on another pattern (tb_replay_sink).
`timescale 1ns / 1ps
`default_nettype none

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
// when gaps_i is low), until Count beats are taken; a beat once offered stays offered until it is
// taken (AXI4-Stream). count_o is the index of the beat on offer (Count when all are taken).
// Sources of one testbench use co-prime periods (4 and 5) so that their gaps drift apart.
module tb_replay_source #(
  parameter int Count  = 1,
  parameter int Period = 4,
  parameter int Idle   = 3
) (
  input  logic   clk,
  input  logic   run_i,
  input  longint cyc_i,
  input  logic   gaps_i,
  input  logic   ready_i,
  output logic   valid_o,
  output int     count_o
);
  logic held;
  initial begin
    held = 1'b0;
    count_o = 0;
  end
  assign valid_o = run_i && (count_o < Count) && (((cyc_i % Period) != Idle) || held || !gaps_i);
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
