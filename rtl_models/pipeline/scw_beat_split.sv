// SPDX-License-Identifier: Apache-2.0
// Beat split: Ppc pixels per beat in, one pixel per beat out, one output beat per clock.
`default_nettype none

// The C++ twin is scw::hls::pipeline::BeatSplit (hls/pipeline/beat_split.hpp) clocked by
// scw::sim::BeatSplitModel, clock for clock.
//
// One register holds an input beat; its pixels leave one per clock, pixel 0 (the low bits)
// first. The data register shifts right by one pixel per output beat, so the output is always
// its low PixW bits: no Ppc-way output multiplexer. The pixel-0 beat carries the input's sof,
// the last pixel's beat its eol. The register takes the next beat in the cycle its last pixel
// is taken (in_ready = !valid || (out_ready && last)), so a continuous input gives one output
// beat every clock. out_valid and out data are registered; in_ready depends combinationally on
// out_ready (as scw_stream_reg). Ppc = 1 is scw_stream_reg itself.
module scw_beat_split #(
  parameter int unsigned Ppc  /*verilator public*/ = 4,
  parameter int unsigned PixW /*verilator public*/ = 16,
  localparam int unsigned DataW = Ppc * PixW
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [DataW-1:0] in_data_i,
  input  logic             in_sof_i,
  input  logic             in_eol_i,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [PixW-1:0]  out_data_o,
  output logic             out_sof_o,
  output logic             out_eol_o
);
  if (Ppc != 1 && Ppc != 2 && Ppc != 4) begin : gen_bad_ppc
    $error("scw_beat_split: Ppc must be 1, 2 or 4");
  end

  if (Ppc == 1) begin : gen_reg
    // {eol, sof, pixel}: the packed-beat layout of scw_pkg.
    logic [PixW+1:0] out_word;

    scw_stream_reg #(
      .Width(PixW + 2)
    ) u_reg (
      .clk_i,
      .rst_ni,
      .in_valid_i,
      .in_ready_o,
      .in_data_i  ({in_eol_i, in_sof_i, in_data_i}),
      .out_valid_o,
      .out_ready_i,
      .out_data_o (out_word)
    );

    assign out_data_o = out_word[PixW-1:0];
    assign out_sof_o  = out_word[PixW];
    assign out_eol_o  = out_word[PixW+1];
  end else begin : gen_split
    localparam int unsigned IdxW = $clog2(Ppc);
    localparam logic [IdxW-1:0] LastIdx = IdxW'(Ppc - 1);

    logic valid_d, valid_q;
    logic [IdxW-1:0] idx_d, idx_q;  // the pixel presented
    logic [DataW-1:0] data_q;       // pixel idx_q in the low bits
    logic sof_q, eol_q;
    logic last, take, pop;

    assign last = idx_q == LastIdx;
    assign in_ready_o = !valid_q || (out_ready_i && last);
    assign take = in_valid_i && in_ready_o;
    assign pop = valid_q && out_ready_i;

    assign out_valid_o = valid_q;
    assign out_data_o  = data_q[PixW-1:0];
    assign out_sof_o   = sof_q && idx_q == '0;
    assign out_eol_o   = eol_q && last;

    always_comb begin
      valid_d = valid_q;
      idx_d   = idx_q;
      if (take) begin
        valid_d = 1'b1;
        idx_d   = '0;
      end else if (pop) begin
        valid_d = !last;
        idx_d   = idx_q + 1'b1;
      end
    end

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        valid_q <= 1'b0;
        idx_q   <= '0;
      end else begin
        valid_q <= valid_d;
        idx_q   <= idx_d;
      end
    end

    // Datapath without reset: read only while valid_q.
    always_ff @(posedge clk_i) begin
      if (take) begin
        data_q <= in_data_i;
        sof_q  <= in_sof_i;
        eol_q  <= in_eol_i;
      end else if (pop) begin
        data_q <= data_q >> PixW;
      end
    end
  end
endmodule
