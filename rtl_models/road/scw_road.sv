// SPDX-License-Identifier: Apache-2.0
// Road stage: disparities on the previous frame's fitted road leave as 0 (v-disparity road).
`default_nettype none

// The rule and its arithmetic are in docs/road.md. The C++ twin is scw::hls::road::Road
// (hls/road/road.hpp) clocked by scw::sim::RoadModel (sim/models/road_model.hpp), clock for clock: the
// same in_ready, out_valid and out data every cycle.
//
// Structure:
//  - The row registers: the road, its band and the gate band at the current row (code x 2^12),
//    loaded from the line and the bands at sof and stepped by their slopes at each eol, so a
//    pixel needs compares only. They are 33 bits: a band's intercept can be any 32-bit value
//    (band() wraps a line outside check_config's bounds, and the engine forms it so) and 1,023
//    steps of a slope below 2^19 add less than 2^29; within those bounds 32 bits would do.
//  - Per taken beat, each pixel against the bands (the sof's row values muxed in first): the road
//    band decides the zeroing, the gate band whether it joins the sums (scw_road_sums). The
//    compares use the values' integer parts (a code has no fraction), 21 bits.
//  - The output pipeline: D0 registers the zero decisions and the beat, D1 the zeroed beat; one
//    enable, adv = !out_valid || out_ready (sim::PipelineShell's shape).
//  - The line output: one word a frame, the line the frame is gated with, loaded when the stage
//    takes the frame's sof; a sof is taken only when that register is free or read in the same
//    clock (scw_frame_check's flag rule), so no frame's line is lost. The warning stage measures
//    heights above it.
//  - The fit (scw_road_fit) between frames: a sof that comes after a frame's beats (`seen`) is not
//    taken; at that edge busy loads FitClocks and counts down, the engine starts once the sums
//    have settled, and on the clock busy goes 1 -> 0 its line and bands are installed, the sums
//    cleared and seen cleared; the sof is taken from the next clock on. The pipeline behind keeps
//    draining meanwhile. After reset seen is set, so the first sof forms the nominal road's
//    bands (a fit of no pixels keeps the road).
// in_ready depends combinationally on in_valid, in_sof (a sof waiting for the fit) and
// line_ready: upstream is a registered FIFO. cfg_* are static: set them before rst_ni rises.
module scw_road #(
  parameter int unsigned Ppc        /*verilator public*/ = 1,   // disparities a beat
  parameter int unsigned MaxWidthPx /*verilator public*/ = 64,  // <= 2048
  parameter int unsigned MaxHeight  /*verilator public*/ = 48,  // <= 1024
  localparam int unsigned DispW = scw_pkg::DispBits,
  localparam int unsigned DataW = Ppc * DispW
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // static configuration (hls::road::RoadConfig): scw_pkg::road_cfg_t, lines in code x 2^12
  input  logic [scw_pkg::RoadCfgBits-1:0] cfg_road_i,
  // disparities in, pixel i in [i*16 +: 16]
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [DataW-1:0] in_data_i,
  input  logic             in_sof_i,
  input  logic             in_eol_i,
  // disparities out, road pixels 0
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [DataW-1:0] out_data_o,
  output logic             out_sof_o,
  output logic             out_eol_o,
  // the line each frame is gated with (hls::road::Line), one word a frame
  output logic             line_valid_o,
  input  logic             line_ready_i,
  output logic [17:0]      line_a_o,
  output logic [31:0]      line_b_o       // signed
);
  // Shared with C++ (hls::road::kLatency, kFitClocks, kFracBits), checked at compile time by
  // sim/rtl/road_rtl.hpp.
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency   /*verilator public*/ = 2;
  localparam int unsigned FitClocks /*verilator public*/ = 256;
  localparam int unsigned FracBits  /*verilator public*/ = 12;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned CodeW = DispW - 1;
  localparam int unsigned RowW  = 33;
  localparam int unsigned BusyW = $clog2(FitClocks + 1);
  // The engine starts this many clocks after the fit's first edge, which comes at least one clock
  // after the last taken beat: by then scw_road_sums' SumsLatency (5) edges have passed.
  localparam int unsigned FitStart = 5;

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_road: Ppc must be 1, 2 or 4");
  end
  if (MaxWidthPx < 2 || MaxWidthPx > 2048 || MaxHeight < 2 || MaxHeight > 1024) begin : gen_bad_size
    $error("scw_road: need 2 <= MaxWidthPx <= 2048 and 2 <= MaxHeight <= 1024");
  end

  scw_pkg::road_cfg_t cfg;
  assign cfg = cfg_road_i;
  if ($bits(cfg) != scw_pkg::RoadCfgBits) begin : gen_bad_cfg
    $error("scw_road: scw_pkg::RoadCfgBits is not road_cfg_t's width");
  end

  // ---- control: the fit between frames ---------------------------------------------------------
  logic [BusyW-1:0] busy_d, busy_q;
  logic             seen_d, seen_q;
  logic             adv, start_fit, take, install, out_valid_q, line_valid_q, line_free;

  assign adv        = !out_valid_q || out_ready_i;
  assign start_fit  = busy_q == '0 && in_valid_i && in_sof_i && seen_q;
  assign line_free  = !line_valid_q || line_ready_i;
  assign in_ready_o = adv && busy_q == '0 && !start_fit && (!in_sof_i || line_free);
  assign take       = in_valid_i && in_ready_o;
  assign install    = busy_q == BusyW'(1);

  always_comb begin
    busy_d = busy_q;
    seen_d = seen_q;
    if (busy_q != '0)   busy_d = busy_q - 1'b1;
    else if (start_fit) busy_d = BusyW'(FitClocks);
    if (install)        seen_d = 1'b0;
    else if (take)      seen_d = 1'b1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q <= '0;
      seen_q <= 1'b1;
    end else begin
      busy_q <= busy_d;
      seen_q <= seen_d;
    end
  end

  // ---- the road and its bands, installed by the fit -------------------------------------------
  logic        fit_done;
  logic [17:0] fit_a, fit_road_lo_a, fit_gate_lo_a;
  logic [18:0] fit_road_hi_a, fit_gate_hi_a;
  logic [31:0] fit_b, fit_road_lo_b, fit_road_hi_b, fit_gate_lo_b, fit_gate_hi_b;
  logic [17:0] line_a_q, road_lo_a_q, gate_lo_a_q;
  logic [18:0] road_hi_a_q, gate_hi_a_q;
  logic [31:0] line_b_q, road_lo_b_q, road_hi_b_q, gate_lo_b_q, gate_hi_b_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      line_a_q    <= cfg.nominal_a;
      line_b_q    <= cfg.nominal_b;
      road_lo_a_q <= '0;
      road_hi_a_q <= '0;
      road_lo_b_q <= '0;
      road_hi_b_q <= '0;
      gate_lo_a_q <= '0;
      gate_hi_a_q <= '0;
      gate_lo_b_q <= '0;
      gate_hi_b_q <= '0;
    end else if (install) begin
      line_a_q    <= fit_a;
      line_b_q    <= fit_b;
      road_lo_a_q <= fit_road_lo_a;
      road_hi_a_q <= fit_road_hi_a;
      road_lo_b_q <= fit_road_lo_b;
      road_hi_b_q <= fit_road_hi_b;
      gate_lo_a_q <= fit_gate_lo_a;
      gate_hi_a_q <= fit_gate_hi_a;
      gate_lo_b_q <= fit_gate_lo_b;
      gate_hi_b_q <= fit_gate_hi_b;
    end
  end

  // ---- the line output --------------------------------------------------------------------------
  logic [17:0] line_out_a_q;
  logic [31:0] line_out_b_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) line_valid_q <= 1'b0;
    else if (take && in_sof_i) line_valid_q <= 1'b1;
    else if (line_ready_i) line_valid_q <= 1'b0;
  end
  always_ff @(posedge clk_i) begin
    if (take && in_sof_i) begin
      line_out_a_q <= line_a_q;
      line_out_b_q <= line_b_q;
    end
  end
  assign line_valid_o = line_valid_q;
  assign line_a_o     = line_out_a_q;
  assign line_b_o     = line_out_b_q;

  // ---- row registers ---------------------------------------------------------------------------
  // A sof's beat is compared with the line's values at row 0, not with the registers. Beside each
  // low edge a flag says whether its 12 fraction bits are nonzero (for the compares below); the
  // flags of the bands' row-0 values are registered at install, those of the rows with them.
  logic signed [RowW-1:0] road_q, lo_q, hi_q, glo_q, ghi_q;
  logic signed [RowW-1:0] road_s, lo_s, hi_s, glo_s, ghi_s, lo_d, glo_d;
  logic                   lo_nz_q, glo_nz_q, lo_nz_s, glo_nz_s, road_lo_nz_q, gate_lo_nz_q;
  logic [9:0]             v_q, v_s;
  logic [19:0]            vv_q, vv_s;  // v^2 for the sums, stepped with v
  logic                   step;

  assign road_s   = in_sof_i ? RowW'(signed'(line_b_q))    : road_q;
  assign lo_s     = in_sof_i ? RowW'(signed'(road_lo_b_q)) : lo_q;
  assign hi_s     = in_sof_i ? RowW'(signed'(road_hi_b_q)) : hi_q;
  assign glo_s    = in_sof_i ? RowW'(signed'(gate_lo_b_q)) : glo_q;
  assign ghi_s    = in_sof_i ? RowW'(signed'(gate_hi_b_q)) : ghi_q;
  assign lo_nz_s  = in_sof_i ? road_lo_nz_q : lo_nz_q;
  assign glo_nz_s = in_sof_i ? gate_lo_nz_q : glo_nz_q;
  assign v_s      = in_sof_i ? '0 : v_q;
  assign vv_s     = in_sof_i ? '0 : vv_q;
  // Rows past MaxHeight - 1 keep the last row's values.
  assign step     = in_eol_i && v_s < 10'(MaxHeight - 1);
  assign lo_d     = step ? lo_s + RowW'(road_lo_a_q) : lo_s;
  assign glo_d    = step ? glo_s + RowW'(gate_lo_a_q) : glo_s;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      road_lo_nz_q <= 1'b0;
      gate_lo_nz_q <= 1'b0;
    end else if (install) begin
      road_lo_nz_q <= fit_road_lo_b[FracBits-1:0] != '0;
      gate_lo_nz_q <= fit_gate_lo_b[FracBits-1:0] != '0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      road_q   <= '0;
      lo_q     <= '0;
      hi_q     <= '0;
      glo_q    <= '0;
      ghi_q    <= '0;
      lo_nz_q  <= 1'b0;
      glo_nz_q <= 1'b0;
      v_q      <= '0;
      vv_q     <= '0;
    end else if (take) begin
      road_q   <= step ? road_s + RowW'(line_a_q)   : road_s;
      lo_q     <= lo_d;
      hi_q     <= step ? hi_s + RowW'(road_hi_a_q)  : hi_s;
      glo_q    <= glo_d;
      ghi_q    <= step ? ghi_s + RowW'(gate_hi_a_q) : ghi_s;
      lo_nz_q  <= lo_d[FracBits-1:0] != '0;
      glo_nz_q <= glo_d[FracBits-1:0] != '0;
      v_q      <= step ? v_s + 1'b1                 : v_s;
      vv_q     <= step ? vv_s + {9'b0, v_s, 1'b1}   : vv_s;  // (v + 1)^2 = v^2 + 2 v + 1
    end
  end

  // ---- per pixel: the two bands ----------------------------------------------------------------
  // A valid code d (1 .. 0x7fff) is d 2^12 in the rows' units, so against a row value r
  //   d 2^12 >= r  <=>  d >= (r >>> 12) + (r's fraction != 0)      d 2^12 <= r  <=>  d <= r >>> 12
  // which compares 21 bits instead of 33, in one carry chain each (the + 1 as the borrow in).
  // Only rows where the road is at least 1 px (2^16) are active.
  localparam int unsigned IntW = RowW - FracBits;  // 21, signed
  localparam int unsigned GeW  = IntW + 2;

  // d >= r_int + nz as the sign of 2 d - (2 r_int + nz).
  function automatic logic code_ge(input logic [CodeW-1:0] d, input logic [IntW-1:0] r_int,
                                   input logic nz);
    logic [GeW-1:0] t;
    t = {(GeW - CodeW - 1)'(0), d, 1'b0} - {r_int[IntW-1], r_int, nz};
    code_ge = !t[GeW-1];
  endfunction
  // d <= r_int as the sign of r_int - d.
  function automatic logic code_le(input logic [CodeW-1:0] d, input logic [IntW-1:0] r_int);
    logic [IntW:0] t;
    t = {r_int[IntW-1], r_int} - (IntW + 1)'(d);
    code_le = !t[IntW];
  endfunction

  logic                 active;
  logic [Ppc-1:0]       on_road, in_gate, ok;
  logic [Ppc*CodeW-1:0] codes;

  assign active = !road_s[RowW-1] && road_s[RowW-2:FracBits+4] != '0;  // >= 16 codes

  for (genvar i = 0; i < Ppc; i++) begin : gen_px
    assign codes[i*CodeW +: CodeW] = in_data_i[i*DispW +: CodeW];
    assign ok[i]      = active && in_data_i[i*DispW +: DispW] != '0 && !in_data_i[i*DispW + CodeW];
    assign on_road[i] = ok[i] && code_ge(codes[i*CodeW +: CodeW], lo_s[RowW-1:FracBits], lo_nz_s) &&
                        code_le(codes[i*CodeW +: CodeW], hi_s[RowW-1:FracBits]);
    assign in_gate[i] = ok[i] &&
                        code_ge(codes[i*CodeW +: CodeW], glo_s[RowW-1:FracBits], glo_nz_s) &&
                        code_le(codes[i*CodeW +: CodeW], ghi_s[RowW-1:FracBits]);
  end

  // ---- output pipeline: D0 the decisions, D1 the zeroed beat -----------------------------------
  logic             d0_valid_q, d0_sof_q, d0_eol_q, out_sof_q, out_eol_q;
  logic [Ppc-1:0]   d0_zero_q;
  logic [DataW-1:0] d0_data_q, zeroed, out_data_q;

  for (genvar i = 0; i < Ppc; i++) begin : gen_zero
    assign zeroed[i*DispW +: DispW] = d0_zero_q[i] ? '0 : d0_data_q[i*DispW +: DispW];
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      d0_valid_q  <= 1'b0;
      out_valid_q <= 1'b0;
    end else if (adv) begin
      d0_valid_q  <= take;
      out_valid_q <= d0_valid_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (adv) begin
      d0_data_q  <= in_data_i;
      d0_sof_q   <= in_sof_i;
      d0_eol_q   <= in_eol_i;
      d0_zero_q  <= cfg.enable ? on_road : '0;
      out_data_q <= zeroed;
      out_sof_q  <= d0_sof_q;
      out_eol_q  <= d0_eol_q;
    end
  end

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
  assign out_sof_o   = out_sof_q;
  assign out_eol_o   = out_eol_q;

  // ---- the sums and the fit --------------------------------------------------------------------
  logic [21:0] n;
  logic [30:0] sv;
  logic [40:0] svv;
  logic [35:0] sd;
  logic [45:0] svd;

  scw_road_sums #(.Ppc(Ppc)) u_sums (
    .clk_i,
    .rst_ni,
    .clear_i(install),
    .valid_i(take),
    .gate_i (in_gate),
    .d_i    (codes),
    .v_i    (v_s),
    .vv_i   (vv_s),
    .n_o    (n),
    .sv_o   (sv),
    .svv_o  (svv),
    .sd_o   (sd),
    .svd_o  (svd)
  );

  // Its results must be there on the clock busy goes 1 -> 0 (it checks MaxClocks).
  scw_road_fit #(.MaxClocks(FitClocks - FitStart - 1)) u_fit (
    .clk_i,
    .rst_ni,
    .start_i    (busy_q == BusyW'(FitClocks - FitStart)),
    .n_i        (n),
    .sv_i       (sv),
    .svv_i      (svv),
    .sd_i       (sd),
    .svd_i      (svd),
    .min_count_i(cfg.min_count),
    .a_min_i    (cfg.a_min),
    .a_max_i    (cfg.a_max),
    .h_min_i    (cfg.h_min),
    .h_max_i    (cfg.h_max),
    .tol_i      (cfg.tol_q4),
    .tol_rel_i  (cfg.tol_rel_q8),
    .gate_i     (cfg.gate_q4),
    .gate_rel_i (cfg.gate_rel_q8),
    .keep_a_i   (line_a_q),
    .keep_b_i   (line_b_q),
    .done_o     (fit_done),
    .line_a_o   (fit_a),
    .line_b_o   (fit_b),
    .road_lo_a_o(fit_road_lo_a),
    .road_hi_a_o(fit_road_hi_a),
    .road_lo_b_o(fit_road_lo_b),
    .road_hi_b_o(fit_road_hi_b),
    .gate_lo_a_o(fit_gate_lo_a),
    .gate_hi_a_o(fit_gate_hi_a),
    .gate_lo_b_o(fit_gate_lo_b),
    .gate_hi_b_o(fit_gate_hi_b)
  );

`ifdef FORMAL
  always_ff @(posedge clk_i) begin
    if (rst_ni && install) assert (fit_done);
  end
`endif
  // Without FORMAL fit_done is only read by the assertion above.
  logic unused_fit_done;
  assign unused_fit_done = fit_done;
endmodule
