// SPDX-License-Identifier: Apache-2.0
// Bounded FIFO with registered flags: no fall-through, no bypass, one push and one pop per cycle.
`default_nettype none

// The C++ twin is scw::sim::Fifo: a beat pushed in cycle t can be popped in t + 1 at the
// earliest, and a slot freed by a pop can be refilled in t + 1. Keeping both flags free of
// combinational paths lets any number of FIFOs be chained without long ready chains.
//
// OutReg = 1 takes out_data_o from a register instead of the storage's read port, with the same
// behaviour clock for clock (so the twin is unchanged): the register loads what the read port
// will show next clock, the word at rd_ptr or at rd_ptr + 1 (both read at registered addresses)
// or the word being pushed there, picked by pop. A consumer whose control decodes the head word
// (sof, eol) then starts at a flip-flop, not behind a LUT RAM's write-clock-to-output arc.
module scw_fifo #(
  parameter int unsigned Width /*verilator public*/ = 10,
  parameter int unsigned Depth /*verilator public*/ = 4,
  parameter bit          OutReg /*verilator public*/ = 1'b0,
  localparam int unsigned PtrW = (Depth > 1) ? $clog2(Depth) : 1,
  localparam int unsigned CntW = $clog2(Depth + 1)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [Width-1:0] in_data_i,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [Width-1:0] out_data_o,
  output logic [CntW-1:0]  count_o
);
  localparam logic [CntW-1:0] Full = CntW'(Depth);
  localparam logic [PtrW-1:0] LastPtr = PtrW'(Depth - 1);

  logic [Width-1:0] mem_q [Depth];
  logic [PtrW-1:0] wr_ptr_q, wr_ptr_d, rd_ptr_q, rd_ptr_d;
  logic [CntW-1:0] count_q, count_d;
  logic push, pop;

  assign in_ready_o  = count_q != Full;
  assign out_valid_o = count_q != '0;
  assign count_o     = count_q;
  assign push        = in_valid_i && in_ready_o;
  assign pop         = out_valid_o && out_ready_i;

  always_comb begin
    wr_ptr_d = wr_ptr_q;
    rd_ptr_d = rd_ptr_q;
    count_d  = count_q;
    if (push) wr_ptr_d = (wr_ptr_q == LastPtr) ? '0 : wr_ptr_q + 1'b1;
    if (pop) rd_ptr_d = (rd_ptr_q == LastPtr) ? '0 : rd_ptr_q + 1'b1;
    if (push && !pop) count_d = count_q + 1'b1;
    else if (pop && !push) count_d = count_q - 1'b1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_ptr_q <= '0;
      rd_ptr_q <= '0;
      count_q  <= '0;
    end else begin
      wr_ptr_q <= wr_ptr_d;
      rd_ptr_q <= rd_ptr_d;
      count_q  <= count_d;
    end
  end

  // Storage has no reset so that it can map to distributed RAM.
  always_ff @(posedge clk_i) begin
    if (push) mem_q[wr_ptr_q] <= in_data_i;
  end

  if (OutReg) begin : gen_out_reg
    logic [PtrW-1:0]  rd_next_q;  // rd_ptr_q + 1, wrapped
    logic [Width-1:0] head_q, stay, advance;
    assign stay    = (push && wr_ptr_q == rd_ptr_q) ? in_data_i : mem_q[rd_ptr_q];
    assign advance = (push && wr_ptr_q == rd_next_q) ? in_data_i : mem_q[rd_next_q];
    always_ff @(posedge clk_i) begin
      if (!rst_ni) rd_next_q <= (Depth > 1) ? PtrW'(1) : '0;
      else if (pop) rd_next_q <= (rd_next_q == LastPtr) ? '0 : rd_next_q + 1'b1;
    end
    // No reset: out_data_o means nothing while out_valid_o is low.
    always_ff @(posedge clk_i) begin
      head_q <= pop ? advance : stay;
    end
    assign out_data_o = head_q;
  end else begin : gen_out_ram
    assign out_data_o = mem_q[rd_ptr_q];
  end
endmodule
