// SPDX-License-Identifier: Apache-2.0
// Road stage: a restoring divider, one quotient bit in two clocks, with an overflow check.
`default_nettype none

// For a dividend X = r0 * 2^QW + x and a divisor d > 0:
//   ovf_o = r0 >= d (the quotient would need more than QW bits), else q_o = floor(X / d).
// The fit engine needs a quotient of known width (the slope's 18 bits, -b's 28) and treats a
// larger one as an implausible road, so the check comes free as the first step, which compares
// r0 itself with d; each later step doubles the remainder, brings in the next bit of x and
// subtracts d when it fits. The remainder is up to DW + 1 bits (64 for the slope's division), so
// each step's subtraction is split: the low LoW bits in the first clock, the rest with the borrow
// in the second. q_o and ovf_o are valid 2 (QW + 1) clocks after start_i (busy_o falls) and hold
// until the next start_i; d_i must hold meanwhile. With ovf_o set q_o is meaningless.
module scw_road_div #(
  parameter int unsigned DW  = 63,  // divisor, and r0
  parameter int unsigned QW  = 18,  // quotient
  parameter int unsigned LoW = 32,  // the first clock's part of each subtraction
  localparam int unsigned RW   = DW + 1,
  localparam int unsigned CntW = $clog2(QW + 2)
) (
  input  logic          clk_i,
  input  logic          rst_ni,
  input  logic          start_i,
  input  logic [DW-1:0] r0_i,
  input  logic [QW-1:0] x_i,
  input  logic [DW-1:0] d_i,
  output logic          busy_o,
  output logic [QW-1:0] q_o,
  output logic          ovf_o
);
  if (QW < 2 || LoW < 1 || LoW >= DW) begin : gen_bad_params
    $error("scw_road_div: need QW >= 2 and 1 <= LoW < DW");
  end

  // ---- control: QW + 1 steps of two clocks ---------------------------------------------------
  logic [CntW-1:0] cnt_d, cnt_q;
  logic            hi_phase_d, hi_phase_q;

  always_comb begin
    cnt_d      = cnt_q;
    hi_phase_d = 1'b0;
    if (start_i) begin
      cnt_d = CntW'(QW + 1);
    end else if (cnt_q != '0) begin
      hi_phase_d = !hi_phase_q;
      if (hi_phase_q) cnt_d = cnt_q - 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      cnt_q      <= '0;
      hi_phase_q <= 1'b0;
    end else begin
      cnt_q      <= cnt_d;
      hi_phase_q <= hi_phase_d;
    end
  end

  assign busy_o = cnt_q != '0;

  // ---- datapath ------------------------------------------------------------------------------
  // s: this step's partial remainder (< 2 d). z: x's bits not yet brought in, MSB first, the
  // quotient bits (first the check's) shifting in behind them; after the last step it holds
  // {ovf, q}.
  logic [RW-1:0]     s_d, s_q;
  logic [QW:0]       z_d, z_q;
  logic [LoW:0]      lo;
  logic [LoW-1:0]    lo_q;
  logic              borrow_q;
  logic [RW-LoW+1:0] hi;  // {borrow out, difference, bit 0 only carrying the borrow in}
  logic              fits;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [RW-1:0]     rem;  // < d: its top bit is 0
  /* verilator lint_on UNUSEDSIGNAL */

  assign lo   = {1'b0, s_q[LoW-1:0]} - {1'b0, d_i[LoW-1:0]};
  assign hi   = {1'b0, s_q[RW-1:LoW], 1'b0} - {1'b0, {(RW - DW){1'b0}}, d_i[DW-1:LoW], borrow_q};
  assign fits = !hi[RW-LoW+1];
  assign rem  = fits ? {hi[RW-LoW:1], lo_q} : s_q;  // < d

  always_comb begin
    s_d = s_q;
    z_d = z_q;
    if (start_i) begin
      s_d = {1'b0, r0_i};
      z_d = {x_i, 1'b0};
    end else if (cnt_q != '0 && hi_phase_q) begin
      s_d = {rem[DW-1:0], z_q[QW]};
      z_d = {z_q[QW-1:0], fits};
    end
  end

  always_ff @(posedge clk_i) begin
    s_q <= s_d;
    z_q <= z_d;
    lo_q     <= lo[LoW-1:0];  // used in the step's second clock
    borrow_q <= lo[LoW];
  end

  assign q_o   = z_q[QW-1:0];
  assign ovf_o = z_q[QW];
endmodule
