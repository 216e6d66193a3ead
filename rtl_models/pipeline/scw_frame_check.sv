// SPDX-License-Identifier: Apache-2.0
// Frame check: raw pixels pass through one register; one flag per frame says if its geometry broke.
`default_nettype none

// The C++ twin is scw::hls::pipeline::FrameCheck (hls/pipeline/frame_check.hpp) clocked by
// scw::sim::FrameCheckModel, clock for clock.
//
// Why: the rectifiers repair broken frames (they always emit whole W x H frames), so a geometry
// error must be caught at the pipeline input, one of these per camera, and carried to the
// frame result as this flag. Rules, per accepted beat (beats per row = cfg_width_i / Ppc;
// counting follows the configuration, never eol):
//  - not in a frame: a sof beat starts one (beat 0 of row 0); a beat without sof is stray and
//    marks the next frame erroneous;
//  - in a frame, a sof beat closes the frame early (its flag, error = 1, is loaded with this
//    beat) and starts a new, clean frame;
//  - every beat of a frame must carry eol exactly when it is the last beat of its row;
//  - the last beat of the last row (without sof) closes the frame: its flag is loaded with it.
// Timing: the pixel path is one register under adv = !out_valid || out_ready; the flag is one
// register. A beat that emits a flag needs the flag register free or being read, so
//   in_ready = adv && (!emits || !flag_valid || flag_ready),
// emits looking at in_sof_i and the counters. Both valids are registered; in_ready depends
// combinationally on out_ready_i, flag_ready_i and in_sof_i.
// cfg_* are static: set them before rst_ni rises. cfg_width_i is a multiple of Ppc, 1 .. Max,
// and a frame has at least two beats (checked by the C++ check_frame_check_config).
module scw_frame_check #(
  parameter int unsigned Ppc        /*verilator public*/ = 2,
  parameter int unsigned MaxWidthPx /*verilator public*/ = 64,
  parameter int unsigned MaxHeight  /*verilator public*/ = 48,
  localparam int unsigned WidthW  = $clog2(MaxWidthPx + 1),
  localparam int unsigned HeightW = $clog2(MaxHeight + 1),
  localparam int unsigned DataW   = Ppc * scw_pkg::PixelBits
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  // static configuration (hls::pipeline::FrameCheckConfig)
  input  logic [WidthW-1:0]  cfg_width_i,   // pixels per row
  input  logic [HeightW-1:0] cfg_height_i,  // rows per frame
  // raw pixels in
  input  logic               in_valid_i,
  output logic               in_ready_o,
  input  logic [DataW-1:0]   in_data_i,
  input  logic               in_sof_i,
  input  logic               in_eol_i,
  // the same beats out
  output logic               out_valid_o,
  input  logic               out_ready_i,
  output logic [DataW-1:0]   out_data_o,
  output logic               out_sof_o,
  output logic               out_eol_o,
  // one flag per frame
  output logic               flag_valid_o,
  input  logic               flag_ready_i,
  output logic               flag_error_o
);
  // Shared with C++ (hls::pipeline::FrameCheckParams::kLatency), checked at compile time by
  // sim/rtl/frame_check_rtl.hpp.
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency /*verilator public*/ = 1;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned PpcLog2 = $clog2(Ppc);

  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_frame_check: Ppc must be 1, 2 or 4");
  end
  if (MaxWidthPx < Ppc || MaxWidthPx % Ppc != 0 || MaxHeight < 1) begin : gen_bad_size
    $error("scw_frame_check: need MaxWidthPx a positive multiple of Ppc and MaxHeight >= 1");
  end

  // Geometry state. col_q/row_q: place of the next beat of the current frame.
  logic               in_frame_d, in_frame_q;
  logic               err_d, err_q;      // the current frame's error so far
  logic               stray_d, stray_q;  // stray beats since the last frame
  logic [WidthW-1:0]  col_d, col_q;
  logic [HeightW-1:0] row_d, row_q;
  // col_q/row_q at their last value, kept beside the counters so the ready path has no compare.
  logic               col_last_d, col_last_q;
  logic               row_last_d, row_last_q;
  logic               flag_valid_d, flag_valid_q;
  logic               flag_err_d, flag_err_q;
  logic               out_valid_q;

  logic [WidthW-1:0]  last_col_idx;  // beats per row - 1
  logic [HeightW-1:0] last_row_idx;  // rows - 1
  logic               one_col, one_row;  // rows of one beat, frames of one row
  logic               two_col, two_row;  // rows of two beats, frames of two rows
  // The counters' next values and whether they are the last, from registers only: the beat's
  // sof (read from the FIFO in front, a LUT RAM) only picks between them, so no adder or compare
  // sits behind the FIFO read (docs/timing.md).
  logic [WidthW-1:0]  col_inc;
  logic [HeightW-1:0] row_inc;
  logic               col_inc_last, row_inc_last;
  logic               adv, emits, take;
  // The offered beat's last-place flags and error (a sof restarts the count).
  logic               cur_last_col, cur_last_row, beat_err;

  // The configuration is static, so its derived limits are registered: the subtractions stay
  // off the ready path. They load on every clock, reset included, hence cfg before rst_ni rises.
  always_ff @(posedge clk_i) begin
    last_col_idx <= (cfg_width_i >> PpcLog2) - WidthW'(1);
    last_row_idx <= cfg_height_i - HeightW'(1);
    one_col      <= (cfg_width_i >> PpcLog2) == WidthW'(1);
    one_row      <= cfg_height_i == HeightW'(1);
    two_col      <= (cfg_width_i >> PpcLog2) == WidthW'(2);
    two_row      <= cfg_height_i == HeightW'(2);
  end

  assign col_inc      = col_q + WidthW'(1);
  assign row_inc      = row_q + HeightW'(1);
  assign col_inc_last = col_inc == last_col_idx;
  assign row_inc_last = row_inc == last_row_idx;

  assign adv   = !out_valid_q || out_ready_i;
  assign emits = in_frame_q && (in_sof_i || (col_last_q && row_last_q));
  assign in_ready_o = adv && (!emits || !flag_valid_q || flag_ready_i);
  assign take  = in_valid_i && in_ready_o;

  assign cur_last_col = in_sof_i ? one_col : col_last_q;
  assign cur_last_row = in_sof_i ? one_row : row_last_q;
  // A new frame inherits stray beats only when it follows a gap between frames.
  assign beat_err = (in_sof_i ? (!in_frame_q && stray_q) : err_q) || (in_eol_i != cur_last_col);

  always_comb begin
    in_frame_d   = in_frame_q;
    err_d        = err_q;
    stray_d      = stray_q;
    col_d        = col_q;
    row_d        = row_q;
    flag_valid_d = flag_valid_q && !flag_ready_i;
    flag_err_d   = flag_err_q;
    col_last_d   = col_last_q;
    row_last_d   = row_last_q;
    if (take) begin
      if (!in_frame_q && !in_sof_i) begin
        stray_d = 1'b1;
      end else begin
        if (in_sof_i) stray_d = 1'b0;
        if (in_frame_q && in_sof_i) begin
          flag_valid_d = 1'b1;
          flag_err_d   = 1'b1;  // cut short
        end
        if (!in_sof_i && cur_last_col && cur_last_row) begin
          flag_valid_d = 1'b1;
          flag_err_d   = beat_err;
          in_frame_d   = 1'b0;
        end else begin
          in_frame_d = 1'b1;
          err_d      = beat_err;
          // As col_d = cur_last_col ? 0 : cur_col + 1, row_d = cur_last_col ? cur_row + 1 : cur_row
          // and their compares with the last index, with cur_* = 0 on a sof.
          if (in_sof_i) begin
            col_d      = one_col ? '0 : WidthW'(1);
            row_d      = one_col ? HeightW'(1) : '0;
            col_last_d = one_col ? one_col : two_col;
            row_last_d = one_col ? two_row : one_row;
          end else begin
            col_d      = col_last_q ? '0 : col_inc;
            row_d      = col_last_q ? row_inc : row_q;
            col_last_d = col_last_q ? one_col : col_inc_last;
            row_last_d = col_last_q ? row_inc_last : row_last_q;
          end
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_frame_q   <= 1'b0;
      err_q        <= 1'b0;
      stray_q      <= 1'b0;
      col_q        <= '0;
      row_q        <= '0;
      col_last_q   <= 1'b0;
      row_last_q   <= 1'b0;
      flag_valid_q <= 1'b0;
      flag_err_q   <= 1'b0;
      out_valid_q  <= 1'b0;
    end else begin
      in_frame_q   <= in_frame_d;
      err_q        <= err_d;
      stray_q      <= stray_d;
      col_q        <= col_d;
      row_q        <= row_d;
      col_last_q   <= col_last_d;
      row_last_q   <= row_last_d;
      flag_valid_q <= flag_valid_d;
      flag_err_q   <= flag_err_d;
      if (adv) out_valid_q <= take;
    end
  end

  // Datapath without reset: read only while out_valid_q.
  logic [DataW-1:0] data_q;
  logic             sof_q, eol_q;
  always_ff @(posedge clk_i) begin
    if (take) begin
      data_q <= in_data_i;
      sof_q  <= in_sof_i;
      eol_q  <= in_eol_i;
    end
  end

  assign out_valid_o  = out_valid_q;
  assign out_data_o   = data_q;
  assign out_sof_o    = sof_q;
  assign out_eol_o    = eol_q;
  assign flag_valid_o = flag_valid_q;
  assign flag_error_o = flag_err_q;
endmodule
