// SPDX-License-Identifier: Apache-2.0
// Ground-plane removal: a disparity leaves as 0 when its causal 11 x 1 column window is a ramp.
`default_nettype none

// The rule, the defaults and the trade-offs are in docs/ground.md. The C++ twin is
// scw::hls::ground::Ground (hls/ground/ground.hpp) clocked by scw::sim::GroundModel, clock for
// clock: same in_ready, out_valid and out data every cycle.
//
// Structure: the shared line buffer, then a two-register decision pipeline.
//  - scw_line_buffer gives every beat the same column of the 10 rows above it (0 above the top
//    of the frame), with its RAM's output registered (RdReg: a block RAM's clock-to-output is
//    2.5 ns, and the word goes on into the RAM's write port). Its lanes are 8-bit (scw_pkg::PixelBits), so a 16-bit disparity travels as
//    two lanes of one beat (Ppc = 2, 2 * MaxWidthPx lanes): the RAM word is one column's
//    10 x 16 bits, MaxWidthPx deep, and row k of the window sits in bits [k*16 +: 16] exactly as
//    for a one-pixel beat of 16-bit pixels. Row length (eol), the two geometry errors (a row
//    longer than MaxWidthPx, a sof before eol), the sticky err_o and the resync at the next sof
//    are the line buffer's (docs/streaming.md).
//  - D0 registers the 12 comparisons (10 steps, the rise's two bounds) and the window's
//    validity; D1 ANDs them and zeroes the pixel. Each comparison is x + y >= z of three
//    operands in one carry chain (a carry-save step in the LUTs before it): an add, then a
//    compare, would be two chains in a row (3 ns).
// The two pipelines have one enable each (in_ready = !out_valid || out_ready, the line buffer's
// out_ready being D's enable), so a bubble in the line buffer's output register is filled while
// D waits. Latency = line buffer (3) + D (2) = 5 clocks from accepting a beat to presenting it.
// cfg_* are static: set them before rst_ni rises.
module scw_ground #(
  parameter int unsigned MaxWidthPx /*verilator public*/ = 64,
  localparam int unsigned DispW = scw_pkg::DispBits
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // static configuration (hls::ground::GroundConfig), Q11.4 values 0 .. 32767
  input  logic             cfg_enable_i,
  input  logic [14:0]      cfg_step_tol_i,
  input  logic [14:0]      cfg_min_rise_i,
  input  logic [14:0]      cfg_max_rise_i,
  // disparities in
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [DispW-1:0] in_data_i,
  input  logic             in_sof_i,
  input  logic             in_eol_i,
  // disparities out, ground pixels 0
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [DispW-1:0] out_data_o,
  output logic             out_sof_o,
  output logic             out_eol_o,
  output logic             err_o
);
  // Shared with C++ (hls::ground::GroundParams, kDecideLatency) and checked at compile time by
  // sim/rtl/ground_rtl.hpp.
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Rows          /*verilator public*/ = 11;
  localparam int unsigned LineLatency   /*verilator public*/ = 3;  // scw_line_buffer's Latency
  localparam int unsigned DecideLatency /*verilator public*/ = 2;
  localparam int unsigned Latency       /*verilator public*/ = LineLatency + DecideLatency;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned Steps = Rows - 1;
  localparam int unsigned WinW  = Rows * DispW;

  if (MaxWidthPx < 2) begin : gen_bad_params
    $error("scw_ground: need MaxWidthPx >= 2");
  end

  // ---- line buffer: the column of the 10 rows above ----------------------------------------
  logic            lb_valid, lb_sof, lb_eol, d_adv;
  logic [WinW-1:0] win;  // row k (k rows above the current pixel) in [k*DispW +: DispW]

  scw_line_buffer #(
    .Ppc       (2),
    .MaxWidthPx(2 * MaxWidthPx),
    .Rows      (Rows),
    .RdReg     (1'b1)
  ) u_line_buffer (
    .clk_i,
    .rst_ni,
    .in_valid_i,
    .in_ready_o,
    .in_data_i,
    .in_sof_i,
    .in_eol_i,
    .out_valid_o(lb_valid),
    .out_ready_i(d_adv),
    .out_data_o (win),
    .out_sof_o  (lb_sof),
    .out_eol_o  (lb_eol),
    .err_o
  );

  // ---- D0: comparisons ----------------------------------------------------------------------
  // Valid disparities are 1 .. 0x7fff, so on them the low 15 bits are the value. On an invalid
  // window the comparisons are don't-care.
  // x + y >= z for x, z in 0 .. 2^15 - 1 and y in -2^15 .. 2^15 - 1, as the sign of
  // x + y - z = x + y + ~z + 1 in 18 bits: the three operands reduce bit by bit to a sum and a
  // carry word, and their sum (the + 1 in the carry word's free low bit) is one carry chain.
  localparam int unsigned CmpW = 18;
  function automatic logic ge3(input logic [DispW-2:0] x, input logic signed [DispW-1:0] y,
                               input logic [DispW-2:0] z);
    logic [CmpW-1:0] a, b, c, sum, d;
    logic [CmpW-2:0] carry;  // its top bit would leave the 18 bits
    a     = {{(CmpW - DispW + 1){1'b0}}, x};
    b     = {{(CmpW - DispW){y[DispW-1]}}, y};
    c     = ~{{(CmpW - DispW + 1){1'b0}}, z};
    sum   = a ^ b ^ c;
    carry = (a[CmpW-2:0] & b[CmpW-2:0]) | (a[CmpW-2:0] & c[CmpW-2:0]) |
            (b[CmpW-2:0] & c[CmpW-2:0]);
    d     = sum + {carry, 1'b1};
    ge3   = !d[CmpW-1];
  endfunction

  logic [Rows-1:0]  valid_row;
  logic [Steps-1:0] step_ok;
  logic [DispW-2:0] r [Rows];  // r_k = the pixel k rows above (r_0 the current one)
  logic             rise_lo_ok, rise_hi_ok;

  for (genvar k = 0; k < Rows; k++) begin : gen_valid
    assign valid_row[k] = !win[k*DispW + DispW-1] && (win[k*DispW +: DispW] != '0);
    assign r[k] = win[k*DispW +: DispW-1];
  end
  // Step r_{k+1} -> r_k, one row down: r_k - r_{k+1} >= -tol, i.e. r_k + tol >= r_{k+1}.
  for (genvar k = 0; k < Steps; k++) begin : gen_steps
    assign step_ok[k] = ge3(r[k], {1'b0, cfg_step_tol_i}, r[k+1]);
  end
  // Rise r_0 - r_10 within [min, max]: r_0 - min >= r_10 and r_10 + max >= r_0.
  logic signed [DispW-1:0] neg_min_q;
  always_ff @(posedge clk_i) neg_min_q <= -$signed({1'b0, cfg_min_rise_i});
  assign rise_lo_ok = ge3(r[0], neg_min_q, r[Steps]);
  assign rise_hi_ok = ge3(r[Steps], {1'b0, cfg_max_rise_i}, r[0]);

  logic             d0_valid_q, d0_sof_q, d0_eol_q, d0_rows_ok_q, d0_lo_q, d0_hi_q;
  logic [Steps-1:0] d0_step_q;
  logic [DispW-1:0] d0_pix_q;

  // ---- D1: output register ------------------------------------------------------------------
  logic             out_valid_q, out_sof_q, out_eol_q, ground;
  logic [DispW-1:0] out_data_q;

  assign d_adv  = !out_valid_q || out_ready_i;
  assign ground = cfg_enable_i && d0_rows_ok_q && (&d0_step_q) && d0_lo_q && d0_hi_q;

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
  assign out_sof_o   = out_sof_q;
  assign out_eol_o   = out_eol_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      d0_valid_q  <= 1'b0;
      out_valid_q <= 1'b0;
    end else if (d_adv) begin
      d0_valid_q  <= lb_valid;
      out_valid_q <= d0_valid_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (d_adv) begin
      d0_sof_q     <= lb_sof;
      d0_eol_q     <= lb_eol;
      d0_pix_q     <= win[0 +: DispW];
      d0_rows_ok_q <= &valid_row;
      d0_step_q    <= step_ok;
      d0_lo_q      <= rise_lo_ok;
      d0_hi_q      <= rise_hi_ok;
      out_sof_q    <= d0_sof_q;
      out_eol_q    <= d0_eol_q;
      out_data_q   <= ground ? '0 : d0_pix_q;
    end
  end
endmodule
