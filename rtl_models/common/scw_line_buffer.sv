// SPDX-License-Identifier: Apache-2.0
// Line buffer: for every input beat, the same columns of the current row and Rows-1 rows above.
`default_nettype none

// Rows-1 earlier rows sit in one simple dual-port RAM, one word per beat column holding the
// beats of all earlier rows, so a 1280-pixel row of 8-bit pixels fills one RAMB18. Each beat
// reads its column, is emitted with the rows above, and writes the column back shifted by one
// row. Rows above the top of the frame read as 0. Rows may be shorter than MaxWidthPx (the
// row length is set by eol); a row longer than MaxWidthPx, or a sof before the previous row's
// eol, sets the sticky err_o, and the stream resynchronises on the next sof.
//
// Pipeline: two stages under one enable (RAM read, output register), Latency = 2 cycles.
// in_ready_o = !out_valid_o || out_ready_i. The C++ twin is scw::hls::LineBuffer clocked by
// scw::sim::PipelineShell<.., 2>. RdReg = 1 registers the RAM's output first (the block RAM's
// DO_REG: its clock-to-output is 2.5 ns without it, and the word goes on through the forwarding
// select into the write port), one more stage: Latency = 3, and a user that sets it clocks the
// twin with 3 slots.
module scw_line_buffer #(
  parameter int unsigned Ppc        /*verilator public*/ = 1,
  parameter int unsigned MaxWidthPx /*verilator public*/ = 64,
  parameter int unsigned Rows       /*verilator public*/ = 3,
  parameter bit           RdReg      /*verilator public*/ = 1'b0,
  localparam int unsigned BeatW = Ppc * scw_pkg::PixelBits,
  localparam int unsigned OutW  = Rows * BeatW
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [BeatW-1:0] in_data_i,
  input  logic             in_sof_i,
  input  logic             in_eol_i,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [OutW-1:0]  out_data_o,   // row k (k rows above) in bits [k*BeatW +: BeatW]
  output logic             out_sof_o,
  output logic             out_eol_o,
  output logic             err_o
);
  // Cycles from accepting a beat to presenting it; scw::hls::LineBufferParams::kLatency is
  // checked against it at compile time.
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency /*verilator public*/ = RdReg ? 3 : 2;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned Cols  = MaxWidthPx / Ppc;
  localparam int unsigned AddrW = (Cols > 1) ? $clog2(Cols) : 1;
  localparam int unsigned ColW  = $clog2(Cols + 1);
  localparam int unsigned RowW  = (Rows > 1) ? $clog2(Rows) : 1;
  localparam int unsigned RamW  = (Rows - 1) * BeatW;
  localparam logic [ColW-1:0] ColEnd = ColW'(Cols);
  localparam logic [RowW-1:0] RowTop = RowW'(Rows - 1);

  if (Rows < 2 || Cols < 2 || MaxWidthPx % Ppc != 0) begin : gen_bad_params
    $error("scw_line_buffer: need Rows >= 2, MaxWidthPx / Ppc >= 2, MaxWidthPx %% Ppc == 0");
  end

  logic out_valid_q, out_sof_q, out_eol_q;
  logic [OutW-1:0] out_data_q;

  // ---- stage 0: count position, issue the RAM read -------------------------------------
  logic adv, accept, inrange;
  logic [ColW-1:0] col_q, col_d, cur_col;
  logic [RowW-1:0] row_q, row_d, cur_row;
  logic err_q, err_d;
  logic [AddrW-1:0] rd_addr;

  assign adv        = !out_valid_q || out_ready_i;
  assign in_ready_o = adv;
  assign accept     = in_valid_i && adv;
  assign cur_col    = in_sof_i ? '0 : col_q;
  assign cur_row    = in_sof_i ? '0 : row_q;
  assign inrange    = cur_col != ColEnd;
  assign rd_addr    = inrange ? cur_col[AddrW-1:0] : '0;
  assign err_o      = err_q;

  always_comb begin
    col_d = col_q;
    row_d = row_q;
    err_d = err_q;
    if (accept) begin
      if ((in_sof_i && col_q != '0) || !inrange) err_d = 1'b1;
      if (in_eol_i) begin
        col_d = '0;
        row_d = (cur_row == RowTop) ? RowTop : cur_row + 1'b1;
      end else begin
        col_d = inrange ? cur_col + 1'b1 : cur_col;
        row_d = cur_row;
      end
    end
  end

  // ---- stage 1: RAM word available (with RdReg, stage 2); emit and write back ----------
  logic s1_valid_q, s1_sof_q, s1_eol_q, s1_inrange_q;
  logic [BeatW-1:0] s1_data_q;
  logic [AddrW-1:0] s1_addr_q;
  logic [RowW-1:0] s1_row_q;
  // e_*: the stage that emits the beat and writes its column back
  logic e_valid, e_sof, e_eol, e_inrange;
  logic [BeatW-1:0] e_data;
  logic [AddrW-1:0] e_addr;
  logic [RowW-1:0] e_row;
  logic [RamW-1:0] rd_data, e_word, above, wr_data;
  logic fwd_q;
  logic [RamW-1:0] fwd_data_q;
  logic wr_en;
  logic [OutW-1:0] window;

  scw_ram_sdp #(
    .Width(RamW),
    .Depth(Cols)
  ) u_ram (
    .clk_i,
    .wr_en_i  (wr_en),
    .wr_addr_i(e_addr),
    .wr_data_i(wr_data),
    .rd_en_i  (adv),
    .rd_addr_i(rd_addr),
    .rd_data_o(rd_data)
  );

  // The RAM returns the old word when a beat reads a column that a beat still in flight has
  // not written back yet (rows one or two beats long, a sof right after a sof); the forwarded
  // word stands in for it.
  assign above = fwd_q ? fwd_data_q : e_word;
  assign wr_en = adv && e_valid && e_inrange;

  if (RdReg) begin : gen_rd_reg
    logic s2_valid_q, s2_sof_q, s2_eol_q, s2_inrange_q;
    logic [BeatW-1:0] s2_data_q;
    logic [AddrW-1:0] s2_addr_q;
    logic [RowW-1:0] s2_row_q;
    logic [RamW-1:0] rd_q;
    // A beat reads as it enters stage 1; the beats then in stages 2 (writing on that edge) and 1
    // (writing on the next) may hold its column: f2 and f1, the later write winning.
    logic f1_q, f2_q;
    logic [RamW-1:0] f2_data_q;

    always_ff @(posedge clk_i) begin
      if (!rst_ni) s2_valid_q <= 1'b0;
      else if (adv) s2_valid_q <= s1_valid_q;
    end
    always_ff @(posedge clk_i) begin
      if (adv) begin
        rd_q         <= rd_data;
        s2_sof_q     <= s1_sof_q;
        s2_eol_q     <= s1_eol_q;
        s2_data_q    <= s1_data_q;
        s2_addr_q    <= s1_addr_q;
        s2_row_q     <= s1_row_q;
        s2_inrange_q <= s1_inrange_q;
        f2_q         <= wr_en && (s2_addr_q == rd_addr);
        f2_data_q    <= wr_data;
        f1_q         <= s1_valid_q && s1_inrange_q && (s1_addr_q == rd_addr);
        fwd_q        <= f1_q || f2_q;
        fwd_data_q   <= f1_q ? wr_data : f2_data_q;
      end
    end
    assign {e_valid, e_sof, e_eol, e_inrange} = {s2_valid_q, s2_sof_q, s2_eol_q, s2_inrange_q};
    assign e_data = s2_data_q;
    assign e_addr = s2_addr_q;
    assign e_row  = s2_row_q;
    assign e_word = rd_q;
  end else begin : gen_rd_direct
    always_ff @(posedge clk_i) begin
      if (adv) begin
        fwd_q      <= wr_en && (s1_addr_q == rd_addr);
        fwd_data_q <= wr_data;
      end
    end
    assign {e_valid, e_sof, e_eol, e_inrange} = {s1_valid_q, s1_sof_q, s1_eol_q, s1_inrange_q};
    assign e_data = s1_data_q;
    assign e_addr = s1_addr_q;
    assign e_row  = s1_row_q;
    assign e_word = rd_data;
  end

  if (Rows > 2) begin : gen_shift
    assign wr_data = {above[RamW-BeatW-1:0], e_data};
  end else begin : gen_no_shift
    assign wr_data = e_data;
    logic unused_above;
    assign unused_above = ^above;
  end

  assign window[BeatW-1:0] = e_data;
  for (genvar k = 1; k < Rows; k++) begin : gen_rows
    assign window[k*BeatW +: BeatW] =
        (e_inrange && e_row >= RowW'(k)) ? above[(k-1)*BeatW +: BeatW] : '0;
  end

  // ---- output register -------------------------------------------------------------------
  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
  assign out_sof_o   = out_sof_q;
  assign out_eol_o   = out_eol_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      col_q       <= '0;
      row_q       <= '0;
      err_q       <= 1'b0;
      s1_valid_q  <= 1'b0;
      out_valid_q <= 1'b0;
    end else begin
      col_q <= col_d;
      row_q <= row_d;
      err_q <= err_d;
      if (adv) begin
        s1_valid_q  <= in_valid_i;
        out_valid_q <= e_valid;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (adv) begin
      s1_data_q    <= in_data_i;
      s1_sof_q     <= in_sof_i;
      s1_eol_q     <= in_eol_i;
      s1_addr_q    <= rd_addr;
      s1_row_q     <= cur_row;
      s1_inrange_q <= inrange;
      out_data_q   <= window;
      out_sof_q    <= e_sof;
      out_eol_q    <= e_eol;
    end
  end
endmodule
