// SPDX-License-Identifier: Apache-2.0
// Road stage: the least-squares sums of a frame's gated pixels, accumulated in a short pipeline.
`default_nettype none

// n, sum v, sum v^2, sum d and sum v d over the pixels in the gate (hls::road::FitSums): per beat
// a gate bit, the 15-bit code and the row v (and v^2, which the stage steps per row) of every
// pixel. Free-running, not under the stage's output enable: a beat counts once, when it is taken,
// even while the output stalls. A beat taken at an edge is in every sum SumsLatency edges later;
// the fit starts later than that (scw_road) and the sums then hold, as no beat is taken while it
// runs. clear_i (the fit installing its road) zeroes them.
//   A0  the beat's gate bits (0 unless taken), codes, v, v^2
//   A1  gated codes added in pairs; gate bits counted; 3 v and 3 v^2
//   A2  the beat's code sum (up to 4 x 0x7fff, 17 bits); count x v and count x v^2 picked from
//       0, 1, 2, 3, 4 times (no add: two adds in a row after an adder were 4.9 ns at Ppc = 4)
//   A3  v x code sum (a DSP's multiplier register); n, sum d, sum v, sum v^2
//   A4  v x code sum (the DSP's output register)
//   A5  sum v d
// All the pixels of a beat share v, so sum v d takes one product a beat, not Ppc.
// Widths (docs/road.md, "Widths"): up to 2^21 pixels (2048 x 1024) of v <= 1023, d <= 0x7fff.
module scw_road_sums #(
  parameter int unsigned Ppc = 1,
  localparam int unsigned CodeW = 15,
  localparam int unsigned CntW  = $clog2(Ppc + 1)
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 clear_i,
  input  logic                 valid_i,
  input  logic [Ppc-1:0]       gate_i,
  input  logic [Ppc*CodeW-1:0] d_i,  // pixel i in [i*CodeW +: CodeW]
  input  logic [9:0]           v_i,
  input  logic [19:0]          vv_i,
  output logic [21:0]          n_o,
  output logic [30:0]          sv_o,
  output logic [40:0]          svv_o,
  output logic [35:0]          sd_o,
  output logic [45:0]          svd_o
);
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned SumsLatency /*verilator public*/ = 5;
  /* verilator lint_on UNUSEDPARAM */
  localparam int unsigned Half = (Ppc + 1) / 2;  // pixels in A1's first pair sum

  // ---- A0 .. A2: the beat's gated code sum and count, count x v and count x v^2 ---------------
  logic [Ppc-1:0]       g0_q;
  logic [Ppc*CodeW-1:0] d0_q;
  logic [9:0]           v0_q, v1_q, v2_q;
  logic [19:0]          vv0_q, vv1_q;
  logic [11:0]          v3_1_q;   // 3 v
  logic [21:0]          vv3_1_q;  // 3 v^2
  logic [CodeW:0]       pair_a, pair_b, pair_a_q, pair_b_q;
  logic [CntW-1:0]      cnt, cnt1_q, cnt2_q;
  // keep: at Ppc >= 2 bsum2_q = pair_a_q + pair_b_q feeds both the DSP's multiplier and sum d.
  // Yosys 0.23's xilinx_dsp packed that add and its register into the DSP48E1 as the pre-adder
  // and its AD register, and left the fabric's bsum2_q undriven (x): sum d became constant 0 in
  // the netlist, and with it the fit's S_v S_d product (found by replaying road/street on the
  // synthesized netlist, scripts/replay.sh --simulator netlist; docs/road.md, "Synthesis").
  // Kept, the register stays in the fabric and feeds both.
  (* keep *) logic [CodeW+1:0] bsum2_q;
  logic [12:0]          cv, cv2_q;
  logic [22:0]          cvv, cvv2_q;

  always_comb begin
    pair_a = '0;
    pair_b = '0;
    cnt    = '0;
    for (int i = 0; i < Ppc; i++) begin
      if (g0_q[i]) begin
        if (i < Half) pair_a = pair_a + (CodeW + 1)'(d0_q[i*CodeW +: CodeW]);
        else          pair_b = pair_b + (CodeW + 1)'(d0_q[i*CodeW +: CodeW]);
        cnt = cnt + 1'b1;
      end
    end
  end

  // A count of at most 4 (Ppc): a multiple of v by a 5-way pick.
  always_comb begin
    unique case (3'(cnt1_q))
      3'd0:    begin cv = '0;                 cvv = '0;                  end
      3'd1:    begin cv = 13'(v1_q);          cvv = 23'(vv1_q);          end
      3'd2:    begin cv = 13'({v1_q, 1'b0});  cvv = 23'({vv1_q, 1'b0});  end
      3'd3:    begin cv = 13'(v3_1_q);        cvv = 23'(vv3_1_q);        end
      default: begin cv = 13'({v1_q, 2'b0});  cvv = 23'({vv1_q, 2'b0});  end
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) g0_q <= '0;
    else         g0_q <= valid_i ? gate_i : '0;
  end

  always_ff @(posedge clk_i) begin
    d0_q     <= d_i;
    v0_q     <= v_i;
    vv0_q    <= vv_i;
    pair_a_q <= pair_a;
    pair_b_q <= pair_b;
    cnt1_q   <= cnt;
    v1_q     <= v0_q;
    vv1_q    <= vv0_q;
    v3_1_q   <= 12'(v0_q) + {1'b0, v0_q, 1'b0};
    vv3_1_q  <= 22'(vv0_q) + {1'b0, vv0_q, 1'b0};
    bsum2_q  <= (CodeW + 2)'(pair_a_q) + (CodeW + 2)'(pair_b_q);
    cnt2_q   <= cnt1_q;
    v2_q     <= v1_q;
    cv2_q    <= cv;
    cvv2_q   <= cvv;
  end

  // ---- A3 .. A5: products and sums -------------------------------------------------------------
  logic [26:0] m3_q, p4_q;

  // No reset and no enable, so Yosys can pack the two product registers into the DSP48E1 as its
  // M and P registers; zeros flow through them when no beat is taken.
  always_ff @(posedge clk_i) begin
    m3_q <= v2_q * bsum2_q;
    p4_q <= m3_q;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni || clear_i) begin
      n_o   <= '0;
      sv_o  <= '0;
      svv_o <= '0;
      sd_o  <= '0;
      svd_o <= '0;
    end else begin
      n_o   <= n_o + 22'(cnt2_q);
      sd_o  <= sd_o + 36'(bsum2_q);
      sv_o  <= sv_o + 31'(cv2_q);
      svv_o <= svv_o + 41'(cvv2_q);
      svd_o <= svd_o + 46'(p4_q);
    end
  end
endmodule
