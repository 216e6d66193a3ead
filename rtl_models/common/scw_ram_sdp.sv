// SPDX-License-Identifier: Apache-2.0
// Simple dual-port RAM with a registered read: the shape Yosys maps to RAMB18/RAMB36.
`default_nettype none

// A read in the same cycle as a write to the same address returns the old word; callers
// that can hit that case forward the written word themselves (see scw_line_buffer).
module scw_ram_sdp #(
  parameter int unsigned Width /*verilator public*/ = 8,
  parameter int unsigned Depth /*verilator public*/ = 1280,
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
  logic [Width-1:0] mem_q [Depth];

  always_ff @(posedge clk_i) begin
    if (wr_en_i) mem_q[wr_addr_i] <= wr_data_i;
  end

  always_ff @(posedge clk_i) begin
    if (rd_en_i) rd_data_o <= mem_q[rd_addr_i];
  end
endmodule
