// SPDX-License-Identifier: Apache-2.0
// Simple dual-port RAM with a registered read: the shape Yosys maps to RAMB18/RAMB36.
`default_nettype none

// A read in the same cycle as a write to the same address returns the old word; callers
// that can hit that case forward the written word themselves (see scw_line_buffer).
//
// LutBits > 0 keeps the word's top LutBits bits in distributed (LUT) RAM instead: a 1K-deep
// word of 40 bits would take a RAMB36 (1K x 36) plus a whole RAMB18 for its last 4 bits; 4 bits
// x 1K of LUT RAM cost about 64 LUTs. Same ports, same registered read, same cycle behaviour.
module scw_ram_sdp #(
  parameter int unsigned Width   /*verilator public*/ = 8,
  parameter int unsigned Depth   /*verilator public*/ = 1280,
  parameter int unsigned LutBits = 0,
  localparam int unsigned AddrW = (Depth > 1) ? $clog2(Depth) : 1
) (
  input  logic             clk_i,
  input  logic             wr_en_i,
  input  logic [AddrW-1:0] wr_addr_i,
  input  logic [Width-1:0] wr_data_i,
  input  logic             rd_en_i,
  input  logic [AddrW-1:0] rd_addr_i,
  output logic [Width-1:0] rd_data_o
);
  localparam int unsigned BlockW = Width - LutBits;

  if (LutBits >= Width) begin : gen_bad_split
    $error("scw_ram_sdp: LutBits must leave at least one bit for block RAM");
  end

  logic [BlockW-1:0] mem_q [Depth];

  always_ff @(posedge clk_i) begin
    if (wr_en_i) mem_q[wr_addr_i] <= wr_data_i[BlockW-1:0];
  end

  always_ff @(posedge clk_i) begin
    if (rd_en_i) rd_data_o[BlockW-1:0] <= mem_q[rd_addr_i];
  end

  if (LutBits > 0) begin : gen_lut
    (* ram_style = "distributed" *) logic [LutBits-1:0] lut_q [Depth];

    always_ff @(posedge clk_i) begin
      if (wr_en_i) lut_q[wr_addr_i] <= wr_data_i[Width-1:BlockW];
    end

    always_ff @(posedge clk_i) begin
      if (rd_en_i) rd_data_o[Width-1:BlockW] <= lut_q[rd_addr_i];
    end
  end
endmodule
