// SPDX-License-Identifier: Apache-2.0
// Simple dual-port RAM with a registered read: the shape Yosys maps to RAMB18/RAMB36.
`default_nettype none

// A read in the same cycle as a write to the same address returns the old word; callers
// that can hit that case forward the written word themselves (see scw_line_buffer).
//
// Two ways to keep block RAM from being wasted, each with the same ports, the same registered
// read and the same cycle behaviour:
// - LutBits > 0 keeps the word's top LutBits bits in distributed (LUT) RAM: a 1K-deep word of
//   40 bits would take a RAMB36 (1K x 36) plus a whole RAMB18 for its last 4 bits; 4 bits x 1K
//   of LUT RAM cost about 64 LUTs.
// - BlockDepth < Depth keeps the words at addresses BlockDepth .. Depth - 1 in distributed RAM
//   (BlockDepth a power of two, Depth at most twice it). A block RAM is at most 72 bits wide, so
//   a 256-word tail of a wide RAM (1,280 words = 1,024 + 256) takes as many block RAMs as 512
//   words would. In LUT RAM a RAM64M holds 64 words x 3 bits in 4 LUTs, plus a read multiplexer:
//   the disparity stage's column sums trade 8 RAMB36 for about 3,700 LUTs (docs/disparity.md).
module scw_ram_sdp #(
  parameter int unsigned Width      /*verilator public*/ = 8,
  parameter int unsigned Depth      /*verilator public*/ = 1280,
  parameter int unsigned LutBits    /*verilator public*/ = 0,
  parameter int unsigned BlockDepth /*verilator public*/ = Depth,
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
  localparam bit          Tail   = BlockDepth < Depth;
  // With a tail: block words at addresses below BlockDepth, tail words above it; each indexed by
  // the address's low bits (Depth <= 2 BlockDepth).
  localparam int unsigned MainDepth = Tail ? BlockDepth : Depth;
  localparam int unsigned MainAW    = (MainDepth > 1) ? $clog2(MainDepth) : 1;

  if (LutBits >= Width) begin : gen_bad_split
    $error("scw_ram_sdp: LutBits must leave at least one bit for block RAM");
  end
  if (Tail && (BlockDepth != (1 << MainAW) || Depth > 2 * BlockDepth)) begin : gen_bad_tail
    $error("scw_ram_sdp: BlockDepth must be a power of two and at least half of Depth");
  end

  logic [MainAW-1:0] wr_idx, rd_idx;
  logic wr_main, wr_tail;
  if (Tail) begin : gen_split_addr
    assign wr_idx  = wr_addr_i[MainAW-1:0];
    assign rd_idx  = rd_addr_i[MainAW-1:0];
    assign wr_tail = wr_en_i && wr_addr_i[MainAW];
  end else begin : gen_whole_addr
    assign wr_idx  = MainAW'(wr_addr_i);
    assign rd_idx  = MainAW'(rd_addr_i);
    assign wr_tail = 1'b0;
  end
  assign wr_main = wr_en_i && !wr_tail;

  logic [Width-1:0] main_rd;
  logic [BlockW-1:0] mem_q [MainDepth];

  always_ff @(posedge clk_i) begin
    if (wr_main) mem_q[wr_idx] <= wr_data_i[BlockW-1:0];
  end

  always_ff @(posedge clk_i) begin
    if (rd_en_i) main_rd[BlockW-1:0] <= mem_q[rd_idx];
  end

  if (LutBits > 0) begin : gen_lut
    (* ram_style = "distributed" *) logic [LutBits-1:0] lut_q [MainDepth];

    always_ff @(posedge clk_i) begin
      if (wr_main) lut_q[wr_idx] <= wr_data_i[Width-1:BlockW];
    end

    always_ff @(posedge clk_i) begin
      if (rd_en_i) main_rd[Width-1:BlockW] <= lut_q[rd_idx];
    end
  end

  if (Tail) begin : gen_tail
    localparam int unsigned TailDepth = Depth - BlockDepth;
    localparam int unsigned TailAW    = (TailDepth > 1) ? $clog2(TailDepth) : 1;
    (* ram_style = "distributed" *) logic [Width-1:0] tail_q [TailDepth];
    logic [Width-1:0] tail_rd;
    logic tail_sel_q;

    always_ff @(posedge clk_i) begin
      if (wr_tail) tail_q[wr_addr_i[TailAW-1:0]] <= wr_data_i;
    end

    always_ff @(posedge clk_i) begin
      if (rd_en_i) begin
        tail_rd    <= tail_q[rd_addr_i[TailAW-1:0]];
        tail_sel_q <= rd_addr_i[MainAW];
      end
    end
    assign rd_data_o = tail_sel_q ? tail_rd : main_rd;
  end else begin : gen_no_tail
    assign rd_data_o = main_rd;
  end
endmodule
