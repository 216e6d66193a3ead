// SPDX-License-Identifier: Apache-2.0
// Warning stage: the per-object arithmetic of evaluate() (hls/warning), one object per clock.
`default_nettype none

// Bit for bit hls::warning::evaluate<Params>() for what the fold uses (obstacle, severity,
// in_tunnel, too_close, distance and the judged distance), OutStages enabled clocks after the
// inputs. The inputs are stage 0: the object's fields and flags as the top registered them
// (measurable from the rule's disparity dq, too_close from d_max, as evaluate() has them); the
// table's recip(min(dq, table end)) comes a clock later, at stage 1. Stages (register at the
// end of each):
//   1         the six pixel offsets (Q.4)
//   2 .. 5    S = (b * recip + 2^15) >> 16 (mm/px, Q.20)
//   6 .. 9    the seven coordinates (mm): rshift_round(S * offset, 24)
//   10 .. 12  x^2, y^2, z^2; 10, 11: height, the box edges relative to the vehicle, then height
//             >= min_height and the four tunnel margins; beside 1 .. 9, with
//             cfg_road_height, the top's height above the road against min_height as well
//             (scw_warning_height), which joins the box's at stage 44
//   12, 13    the gaps across and up, then the gap to the tunnel
//   13, 14    n = x^2 + y^2 + z^2; 14: in the tunnel, gap <= near
//   15 .. 42  isqrt_round(n) (scw_warning_sqrt, one root bit per clock)
//   43        distance = root - veh_z
//   44        the thresholds (too close: judged at 0)
//   45        severity
//   46 ..     held back to OutStages
// Every DSP product has its M and P registers, and no carry chain spans more than one operand
// (the widest are n's 58 bits): about 2.5 ns of logic per clock at most.
// Ranges (every input, any configuration): |offset| < 2^20, S < 2^32, |coordinate| <= 2^28,
// so products fit 53 bits, each coordinate 29 bits (the model's int32 casts never wrap),
// n < 3 * 2^56 and the distance 29 bits. Objects that are not measurable run through with
// whatever the table gives; only obstacle (false) matters for them.
// cfg_* are static: registered here without reset (with what is derived from them), which keeps
// them off every timing path.
module scw_warning_object #(
  parameter int unsigned OutStages = 45
) (
  input  logic               clk_i,
  input  logic               en_i,
  // configuration (hls::warning::WarningConfig): scw_pkg::warning_cfg_t
  input  logic [scw_pkg::WarningCfgBits-1:0] cfg_warning_i,
  // stage 1
  input  logic [28:0]        recip_i,
  // stage 0
  input  logic [15:0]        closest_x_i,
  input  logic [15:0]        closest_y_i,
  input  logic [15:0]        x_min_i,
  input  logic [15:0]        x_max_i,
  input  logic [15:0]        y_min_i,
  input  logic [15:0]        y_max_i,
  input  logic               measurable_i,  // 1 px <= dq < 0x8000
  input  logic               too_close_i,   // d_max >= d_limit
  // stage 0, with cfg_road_height_i: the frame's road line and the rule's disparity
  input  logic               cfg_road_height_i,
  input  logic [17:0]        road_a_i,
  input  logic [31:0]        road_b_i,
  input  logic [15:0]        dq_i,
  // stage OutStages
  output logic               obstacle_o,
  output logic [1:0]         severity_o,
  output logic               in_tunnel_o,
  output logic               too_close_o,
  output logic signed [28:0] distance_o,  // from the bumper
  output logic signed [28:0] judged_o     // 0 when too close, else distance_o
);
  localparam int unsigned Stages    = 45;  // stage of the severity
  localparam int unsigned RootW     = 27;  // hls::warning::isqrt_round's loop
  localparam int unsigned SqrtStart = 14;  // stage of n
  localparam int unsigned SqrtLat   = RootW + 1;
  localparam int unsigned PxW       = 21;  // pixel offsets, Q.4 signed
  localparam int unsigned CW        = 29;  // coordinates, mm signed
  localparam int unsigned SqW       = 2 * CW - 1;
  localparam int unsigned NW        = SqW + 1;
  localparam int unsigned GW        = CW + 2;  // tunnel margins, signed
  localparam int unsigned DW        = 29;  // distance, signed
  localparam int unsigned Lanes     = 7;   // x, y, z, x0, x1, y_top, y_bot

  if (OutStages < Stages) begin : gen_bad
    $error("scw_warning_object: OutStages is at least 45");
  end
  if (SqrtStart + SqrtLat != 42) begin : gen_bad_sqrt
    $error("scw_warning_object: the square root must end at stage 42");
  end

  // ---- configuration ------------------------------------------------------------------------
  // Each offset as (+-16 * pixel) + k: k = -cu, -cu - 8, -cu + 8 across, cv, cv + 8, cv - 8 up
  // (the box edges are half a pixel outside its pixels).
  // The word's rule fields and d_limit are scw_warning's.
  /* verilator lint_off UNUSEDSIGNAL */
  scw_pkg::warning_cfg_t cfg;
  /* verilator lint_on UNUSEDSIGNAL */
  assign cfg = cfg_warning_i;
  logic signed [17:0] cu_s, cv_s;
  assign cu_s = {2'b0, cfg.cu_q4};
  assign cv_s = {2'b0, cfg.cv_q4};

  logic signed [20:0] base_q, focal_q;
  logic signed [17:0] k_x_q, k_x0_q, k_x1_q, k_y_q, k_yt_q, k_yb_q;
  logic signed [16:0] nhw_q;
  logic signed [15:0] vx_q, vy_q, vz_q;
  logic [15:0] hw_q, th_q, high_q, med_q, near_q, minh_q;
  logic med_nz_q;
  always_ff @(posedge clk_i) begin
    base_q   <= {1'b0, cfg.baseline_q8};
    focal_q  <= {5'b0, cfg.focal_q4};
    k_x_q    <= -cu_s;
    k_x0_q   <= -cu_s - 18'sd8;
    k_x1_q   <= -cu_s + 18'sd8;
    k_y_q    <= cv_s;
    k_yt_q   <= cv_s + 18'sd8;
    k_yb_q   <= cv_s - 18'sd8;
    nhw_q    <= -$signed({1'b0, cfg.tunnel_half_w_mm});
    vx_q     <= $signed(cfg.veh_x_mm);
    vy_q     <= $signed(cfg.veh_y_mm);
    vz_q     <= $signed(cfg.veh_z_mm);
    hw_q     <= cfg.tunnel_half_w_mm;
    th_q     <= cfg.tunnel_h_mm;
    high_q   <= cfg.high_mm;
    med_q    <= cfg.medium_mm;
    near_q   <= cfg.near_mm;
    minh_q   <= cfg.min_height_mm;
    med_nz_q <= cfg.medium_mm != '0;
  end

  // ---- 1 .. 5: the pixel offsets, and S = b / d ---------------------------------------------
  logic signed [32:0] s_wide;
  logic [31:0] s5;
  scw_warning_mul #(.AW(21), .BW(29), .Split(16), .Shift(16), .OutW(33)) u_mul_s (
    .clk_i, .en_i, .a_i(base_q), .b_i(recip_i), .p_o(s_wide)
  );
  assign s5 = s_wide[31:0];

  // 16 * coordinate, Q.4 signed; the offset +-16 c + k lies in -2^20 .. 2^20 - 1.
  function automatic logic signed [PxW-1:0] q4(input logic [15:0] c);
    q4 = {1'b0, c, 4'b0};
  endfunction
  function automatic logic signed [PxW-1:0] ext18(input logic signed [17:0] k);
    ext18 = {{(PxW - 18){k[17]}}, k};
  endfunction

  logic signed [PxW-1:0] px_x1, px_y1, px_x01, px_x11, px_yt1, px_yb1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      px_x1  <= q4(closest_x_i) + ext18(k_x_q);
      px_y1  <= ext18(k_y_q) - q4(closest_y_i);
      px_x01 <= q4(x_min_i) + ext18(k_x0_q);
      px_x11 <= q4(x_max_i) + ext18(k_x1_q);
      px_yt1 <= ext18(k_yt_q) - q4(y_min_i);
      px_yb1 <= ext18(k_yb_q) - q4(y_max_i);
    end
  end
  logic [6*PxW-1:0] px5;
  scw_warning_delay #(.Width(6 * PxW), .Depth(4)) u_px_delay (
    .clk_i, .en_i, .d_i({px_yb1, px_yt1, px_x11, px_x01, px_y1, px_x1}), .q_o(px5)
  );

  // ---- 6 .. 9: coordinates ------------------------------------------------------------------
  // Lane order x, y, z, x0, x1, y_top, y_bot; z's offset is the (static) focal length.
  logic [Lanes*PxW-1:0] px_lanes;
  logic [Lanes*CW-1:0] c9;
  assign px_lanes = {px5[5*PxW +: PxW], px5[4*PxW +: PxW], px5[3*PxW +: PxW], px5[2*PxW +: PxW],
                     focal_q, px5[PxW +: PxW], px5[0 +: PxW]};
  for (genvar i = 0; i < Lanes; i++) begin : gen_coord
    logic signed [CW-1:0] c;
    scw_warning_mul #(.AW(PxW), .BW(32), .Split(17), .Shift(24), .OutW(CW)) u_mul (
      .clk_i, .en_i, .a_i(px_lanes[i*PxW +: PxW]), .b_i(s5), .p_o(c)
    );
    assign c9[i*CW +: CW] = c;
  end
  logic signed [CW-1:0] x9, y9, z9, x09, x19, yt9, yb9;
  assign {yb9, yt9, x19, x09, z9, y9, x9} = c9;

  // ---- 10 .. 12: squares, height, tunnel margins -------------------------------------------
  logic [SqW-1:0] sqx12, sqy12, sqz12;
  scw_warning_square #(.XW(CW), .L(17)) u_sq_x (.clk_i, .en_i, .x_i(x9), .sq_o(sqx12));
  scw_warning_square #(.XW(CW), .L(17)) u_sq_y (.clk_i, .en_i, .x_i(y9), .sq_o(sqy12));
  scw_warning_square #(.XW(CW), .L(17)) u_sq_z (.clk_i, .en_i, .x_i(z9), .sq_o(sqz12));

  function automatic logic signed [CW:0] ext_c(input logic signed [CW-1:0] v);
    ext_c = {v[CW-1], v};
  endfunction
  function automatic logic signed [CW:0] ext_16(input logic signed [15:0] v);
    ext_16 = {{(CW + 1 - 16){v[15]}}, v};
  endfunction
  function automatic logic signed [GW-1:0] ext_g(input logic signed [CW:0] v);
    ext_g = {v[CW], v};
  endfunction

  logic signed [CW:0] height10, vx0_10, vx1_10, vyt10, vyb10;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      height10 <= ext_c(yt9) - ext_c(yb9);
      vx0_10   <= ext_c(x09) - ext_16(vx_q);
      vx1_10   <= ext_c(x19) - ext_16(vx_q);
      vyt10    <= ext_c(yt9) - ext_16(vy_q);
      vyb10    <= ext_c(yb9) - ext_16(vy_q);
    end
  end

  // gx = max(0, vx0 - hw, -hw - vx1), gy = max(0, vy_bot - h, -vy_top)
  logic signed [GW-1:0] g1_11, g2_11, g3_11, g4_11;
  logic obst_h11;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      obst_h11 <= height10 >= $signed({{(CW + 1 - 16){1'b0}}, minh_q});
      g1_11    <= ext_g(vx0_10) - $signed({{(GW - 16){1'b0}}, hw_q});
      g2_11    <= $signed({{(GW - 17){nhw_q[16]}}, nhw_q}) - ext_g(vx1_10);
      g3_11    <= ext_g(vyb10) - $signed({{(GW - 16){1'b0}}, th_q});
      g4_11    <= -ext_g(vyt10);
    end
  end

  // ---- 12 .. 14: the gap, and n -------------------------------------------------------------
  function automatic logic [GW-2:0] max0(input logic signed [GW-1:0] a,
                                          input logic signed [GW-1:0] b);
    logic signed [GW-1:0] m;
    m = (a > b) ? a : b;
    max0 = m[GW-1] ? '0 : m[GW-2:0];
  endfunction

  logic [NW-1:0] sxy13, n14;
  logic [SqW-1:0] sqz13;
  logic [GW-2:0] gx12, gy12, gap13;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      sxy13  <= {1'b0, sqx12} + {1'b0, sqy12};
      sqz13  <= sqz12;
      gx12   <= max0(g1_11, g2_11);
      gy12   <= max0(g3_11, g4_11);
      n14    <= sxy13 + {1'b0, sqz13};
      gap13  <= (gx12 > gy12) ? gx12 : gy12;
    end
  end

  logic tun14, near14;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      tun14  <= gap13 == '0;
      near14 <= gap13 <= {{(GW - 1 - 16){1'b0}}, near_q};
    end
  end

  // ---- 15 .. 42: the distance from the camera -----------------------------------------------
  logic [RootW:0] root42;
  scw_warning_sqrt #(.InW(NW), .RootW(RootW), .Latency(SqrtLat)) u_sqrt (
    .clk_i, .en_i, .n_i(n14), .root_o(root42)
  );

  // ---- 43 .. 45: distance, thresholds, severity ---------------------------------------------
  logic meas43, tc43, obst_h44, tun44, near44;
  scw_warning_delay #(.Width(2), .Depth(43)) u_flags_delay (
    .clk_i, .en_i, .d_i({measurable_i, too_close_i}), .q_o({meas43, tc43})
  );
  scw_warning_delay #(.Width(1), .Depth(33)) u_height_delay (
    .clk_i, .en_i, .d_i(obst_h11), .q_o(obst_h44)
  );

  logic above9, above44, road_q;
  always_ff @(posedge clk_i) road_q <= cfg_road_height_i;
  scw_warning_height u_road_height (
    .clk_i, .en_i,
    .baseline_i(base_q[19:0]), .min_height_i(minh_q),
    .road_a_i, .road_b_i, .dq_i, .y_min_i,
    .above_o(above9)
  );
  scw_warning_delay #(.Width(1), .Depth(35)) u_above_delay (
    .clk_i, .en_i, .d_i(above9), .q_o(above44)
  );
  scw_warning_delay #(.Width(2), .Depth(30)) u_gap_delay (
    .clk_i, .en_i, .d_i({tun14, near14}), .q_o({tun44, near44})
  );

  logic signed [DW-1:0] dist43, dist44, dj44;
  logic le_high44, lt_med44, meas44, tc44;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      dist43    <= $signed({1'b0, root42}) - $signed({{(DW - 16){vz_q[15]}}, vz_q});
      // Too close: judged at the bumper, d = 0 (<= high always, < medium unless medium = 0).
      le_high44 <= tc43 || dist43 <= $signed({{(DW - 16){1'b0}}, high_q});
      lt_med44  <= tc43 ? med_nz_q : dist43 < $signed({{(DW - 16){1'b0}}, med_q});
      dj44      <= tc43 ? '0 : dist43;
      dist44    <= dist43;
      meas44    <= meas43;
      tc44      <= tc43;
    end
  end

  logic obst;
  logic [1:0] sev;
  always_comb begin
    obst = meas44 && obst_h44 && (!road_q || above44);
    if (!obst) sev = 2'd0;                                   // none
    else if (tun44) sev = le_high44 ? 2'd3 : lt_med44 ? 2'd2 : 2'd1;
    else sev = (near44 && lt_med44) ? 2'd2 : 2'd1;
  end

  localparam int unsigned EvalW = 5 + 2 * DW;
  logic [EvalW-1:0] eval45, eval_out;
  always_ff @(posedge clk_i) begin
    if (en_i) eval45 <= {obst, sev, tun44, tc44, dist44, dj44};
  end
  if (OutStages > Stages) begin : gen_hold
    scw_warning_delay #(.Width(EvalW), .Depth(OutStages - Stages)) u_hold (
      .clk_i, .en_i, .d_i(eval45), .q_o(eval_out)
    );
  end else begin : gen_no_hold
    assign eval_out = eval45;
  end
  assign {obstacle_o, severity_o, in_tunnel_o, too_close_o, distance_o, judged_o} = eval_out;

  // S < 2^32 always (b < 2^20, recip <= 2^28): the product's sign bit is 0.
  logic unused_s;
  assign unused_s = s_wide[32];
endmodule
