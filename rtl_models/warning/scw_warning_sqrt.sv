// SPDX-License-Identifier: Apache-2.0
// Warning stage: pipelined bit-serial square root rounded to the nearest integer.
`default_nettype none

// root = isqrt_round(n) of hls/warning: floor(sqrt(n') + 1/2) with n' = min(n, 2^(2 RootW) - 1).
// The model's loop tries bits RootW-1 .. 0 (r saturates at 2^RootW - 1) and then rounds up
// when n - r^2 > r; clamping n first gives the same r, and the same rounding (both sides of the
// test exceed r for every n >= 2^(2 RootW)), so the restoring steps need only 2 RootW bits.
//
// Step k (k = 0 .. RootW-1) finds root bit b = RootW-1-k from the remainder's upper part:
//   acc = {rem, next two bits of n};  acc >= 4 R + 1 ? (acc - (4 R + 1), R = 2 R + 1) : R = 2 R
// with R the root bits found so far. The remainder after step k is at most 2 R < 2^(k+2), so
// step k's subtractor is k + 4 bits wide and the low bits of n wait for their turn. One step
// per pipeline stage (one carry chain of at most RootW + 3 bits per clock), then one stage for
// the rounding: rem > R adds one (the compare and R + 1 side by side, then a select).
// The bits of n still to come travel in SRLs; the two a step takes next come from flip-flops
// kept out of them, since an SRL's clock-to-output (about 1.5 ns) would start the carry chain.
module scw_warning_sqrt #(
  parameter int unsigned InW     /*verilator public*/ = 58,  // n
  parameter int unsigned RootW   /*verilator public*/ = 27,  // root bits before rounding
  // The caller's pipeline depth for this block: checked here, so the caller cannot misalign.
  parameter int unsigned Latency /*verilator public*/ = RootW + 1
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [InW-1:0]   n_i,
  output logic [RootW:0]   root_o  // Latency enabled clocks later
);
  localparam int unsigned NW = 2 * RootW;

  if (RootW < 2 || InW < NW) begin : gen_bad
    $error("scw_warning_sqrt: need RootW >= 2 and InW >= 2 RootW");
  end
  if (Latency != RootW + 1) begin : gen_bad_latency
    $error("scw_warning_sqrt: Latency is RootW + 1");
  end

  logic [NW-1:0] nc;
  if (InW > NW) begin : gen_clamp
    assign nc = (n_i[InW-1:NW] != '0) ? '1 : n_i[NW-1:0];
  end else begin : gen_fits
    assign nc = n_i;
  end

  for (genvar k = 0; k < RootW; k++) begin : gen_step
    localparam int unsigned B    = RootW - 1 - k;       // the root bit this step decides
    localparam int unsigned LowW = (B > 0) ? 2 * B : 1; // bits of n still to come after it
    logic [k+2:0] acc, trial;
    logic [k+3:0] diff;
    logic         ge;
    logic [k+1:0] rem_c, rem_s;
    logic [k:0]   root_c, root_s;
    logic [LowW-1:0] low_c, low_s;

    if (k == 0) begin : gen_first
      assign acc    = {1'b0, nc[NW-1 -: 2]};
      assign trial  = 3'b001;
      assign root_c = ge;
      if (B > 0) begin : gen_low
        assign low_c = nc[LowW-1:0];
      end else begin : gen_no_low
        assign low_c = '0;
      end
    end else begin : gen_next
      assign acc    = {gen_step[k-1].rem_s, gen_step[k-1].low_s[2*B+1 -: 2]};
      assign trial  = {1'b0, gen_step[k-1].root_s, 2'b01};
      assign root_c = {gen_step[k-1].root_s, ge};
      if (B > 0) begin : gen_low
        assign low_c = gen_step[k-1].low_s[LowW-1:0];
      end else begin : gen_no_low
        assign low_c = '0;
      end
    end
    assign diff  = {1'b0, acc} - {1'b0, trial};
    assign ge    = !diff[k+3];
    assign rem_c = ge ? diff[k+1:0] : acc[k+1:0];

    always_ff @(posedge clk_i) begin
      if (en_i) begin
        rem_s  <= rem_c;
        root_s <= root_c;
      end
    end
    if (B > 1) begin : gen_low_reg
      // The two bits step k + 1 takes, then the rest.
      (* keep *) always_ff @(posedge clk_i) begin
        if (en_i) low_s[LowW-1 -: 2] <= low_c[LowW-1 -: 2];
      end
      always_ff @(posedge clk_i) begin
        if (en_i) low_s[LowW-3:0] <= low_c[LowW-3:0];
      end
    end else if (B == 1) begin : gen_low_reg_next
      (* keep *) always_ff @(posedge clk_i) begin
        if (en_i) low_s <= low_c;
      end
    end else begin : gen_low_none
      assign low_s = '0;
    end

    // diff[k+2] is 0 whenever it is used (acc >= trial leaves at most k + 2 bits); the last
    // step has no bits of n left.
    logic unused_step;
    if (B > 0) begin : gen_unused
      assign unused_step = diff[k+2];
    end else begin : gen_unused_last
      assign unused_step = ^{diff[k+2], low_s, low_c};
    end
  end

  logic [RootW:0] rem_f;
  logic [RootW-1:0] root_f;
  assign rem_f  = gen_step[RootW-1].rem_s;
  assign root_f = gen_step[RootW-1].root_s;
  logic round_up;
  logic [RootW:0] root_inc;
  assign round_up = rem_f > {1'b0, root_f};
  assign root_inc = {1'b0, root_f} + 1'b1;
  always_ff @(posedge clk_i) begin
    if (en_i) root_o <= round_up ? root_inc : {1'b0, root_f};
  end
endmodule
