// SPDX-License-Identifier: Apache-2.0
// A long, wide value held back a fixed number of enables, in a ring of distributed RAM.
`default_nettype none

// The same delay as a shift chain of Depth registers (Depth enables from d_i to q_o), for wide
// lines: the warning stage's object word beside the distance rule and beside the arithmetic
// (10,395 and 5,016 bits as chains), the disparity decision's SADs beside its argmin tree
// (6,885 bits at 45 candidates). A chain copies every bit at every enable, which costs a
// simulator the whole line each clock, idle or busy (the warning stage's two were a fifth of the
// thesis pipeline's Verilated time); the ring writes one word and reads one. On a 7-series part
// it is the smaller too: a RAM64M holds 64 x 3 bits in 4 LUTs, an SRL32 32 x 1 in one.
// 2^AddrW >= Depth - 1 words, written at `wr` and read Depth - 1 words behind it, read-first (so
// when Depth - 1 = 2^AddrW and the two meet, the old word is read). The read address is a
// register of its own, so the path into q_o is a register, the RAM's read and q_o (a plain
// flip-flop, like a chain's last step). The two pointers are reset (the project's
// rule for pointers): a 4-state simulator would otherwise keep them X for ever after one X
// enable. The words are not: whatever they hold after reset is masked by the user's valid
// pipeline, as the chains' were.
module scw_delay_ring #(
  parameter int unsigned Width = 32,  // the defaults: a line like the stage's (rtl.yosys.* test)
  parameter int unsigned Depth = 64   // >= 2
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             en_i,
  input  logic [Width-1:0] d_i,
  output logic [Width-1:0] q_o
);
  localparam int unsigned Line = Depth - 1;  // words before q_o
  localparam int unsigned AddrW = Line > 1 ? $clog2(Line) : 1;

  if (Width < 1 || Depth < 2) begin : gen_bad
    $error("scw_delay_ring: Width >= 1 and Depth >= 2");
  end

  (* ram_style = "distributed" *) logic [Width-1:0] ring [2**AddrW];
  logic [AddrW-1:0] wr, rd;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr <= '0;
      rd <= AddrW'(0) - AddrW'(Line);  // Line words behind wr, from the first enable on
    end else if (en_i) begin
      wr <= wr + 1'b1;
      rd <= rd + 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) ring[wr] <= d_i;
  end

  (* keep *) always_ff @(posedge clk_i) begin
    if (en_i) q_o <= ring[rd];
  end
endmodule
