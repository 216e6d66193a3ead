// SPDX-License-Identifier: Apache-2.0
// Warning stage: the reciprocal table round(2^32 / dq) as a ROM read through two registers.
`default_nettype none

// recip(dq) of hls/warning for the Q11.4 disparity codes 16 .. Entries - 1; the entries below
// 16 (under one pixel) are never measurable, so they hold 0 (recip(0) would divide by zero).
// The contents come from an initial loop: Verilator runs it at time 0, Yosys 0.23 evaluates it
// into the memory's init value, and the registered read (with the pipeline enable as read
// enable) lets it map the table to block RAM. The second register is
// the block RAM's output register (DO_REG): without it the RAM's clock-to-output, 2.5 ns,
// starts the path into the multiplier. No reset on either, so it can move into the RAM.
module scw_warning_recip #(
  parameter int unsigned Entries = 1024,  // 16 * MaxDisparityPx
  localparam int unsigned AddrW = $clog2(Entries)
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [AddrW-1:0] addr_i,  // < Entries (the caller clamps)
  output logic [28:0]      data_o   // recip(addr_i), two enabled clocks later
);
  if (Entries < 32 || Entries > 32768) begin : gen_bad
    $error("scw_warning_recip: Entries is 16 * MaxDisparityPx, 32 .. 32768");
  end

  // (2^32 + dq / 2) / dq <= 2^28 for dq >= 16: 29 bits. An expression, not a function called
  // 2,048 times: Yosys evaluates a constant function's call by copying its body, 2.8 of the 5 s
  // it took to read the thesis-size warning stage (the same table, docs/performance.md).
  logic [28:0] rom [Entries];
  initial begin
    for (int i = 0; i < Entries; i++)
      rom[i] = (i < 16) ? '0 : 29'(((64'd1 << 32) + (64'(i) >> 1)) / 64'(i));
  end

  logic [28:0] rd_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rd_q   <= rom[addr_i];
      data_o <= rd_q;
    end
  end
endmodule
