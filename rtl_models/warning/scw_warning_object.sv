// SPDX-License-Identifier: Apache-2.0
// Warning stage: the per-object arithmetic of evaluate() (hls/warning), one object per clock.
`default_nettype none

// Bit for bit hls::warning::evaluate<Params>() for what the fold uses (obstacle, severity,
// in_tunnel, too_close, distance and the judged distance), OutStages enabled clocks after the
// inputs. The inputs are stage 0: the object's fields and flags as the top registered them, and
// recip(min(d_max, table end)) from the table. Stages (register at the end of each):
//   1 .. 3    S = (b * recip + 2^15) >> 16 (mm/px, Q.20); the seven pixel offsets (Q.4)
//   4 .. 6    the seven coordinates (mm): rshift_round(S * offset, 24)
//   7, 8      x^2, y^2, z^2; height, the box edges relative to the vehicle, then height >=
//             min_height and the four tunnel margins
//   9, 10     n = x^2 + y^2 + z^2; the gaps across and up, then the gap to the tunnel
//   11 .. 25  isqrt_round(n) (scw_warning_sqrt); 11: in the tunnel, gap <= near
//   26        distance = root - veh_z
//   27        the thresholds (too close: judged at 0)
//   28        severity
//   29 ..     held back to OutStages
// Ranges (every input, any configuration): |offset| < 2^20, S < 2^32, |coordinate| <= 2^28,
// so products fit 53 bits, each coordinate 29 bits (the model's int32 casts never wrap),
// n < 3 * 2^56 and the distance 29 bits. Objects that are not measurable run through with
// whatever the table gives; only obstacle (false) matters for them.
// cfg_* are static: registered here without reset (with what is derived from them), which keeps
// them off every timing path.
module scw_warning_object #(
  parameter int unsigned OutStages = 34
) (
  input  logic               clk_i,
  input  logic               en_i,
  // configuration (hls::warning::WarningConfig)
  input  logic [19:0]        cfg_baseline_q8_i,
  input  logic [15:0]        cfg_focal_q4_i,
  input  logic [15:0]        cfg_cu_q4_i,
  input  logic [15:0]        cfg_cv_q4_i,
  input  logic signed [15:0] cfg_veh_x_mm_i,
  input  logic signed [15:0] cfg_veh_y_mm_i,
  input  logic signed [15:0] cfg_veh_z_mm_i,
  input  logic [15:0]        cfg_tunnel_half_w_mm_i,
  input  logic [15:0]        cfg_tunnel_h_mm_i,
  input  logic [15:0]        cfg_high_mm_i,
  input  logic [15:0]        cfg_medium_mm_i,
  input  logic [15:0]        cfg_near_mm_i,
  input  logic [15:0]        cfg_min_height_mm_i,
  // stage 0
  input  logic [28:0]        recip_i,
  input  logic [15:0]        closest_x_i,
  input  logic [15:0]        closest_y_i,
  input  logic [15:0]        x_min_i,
  input  logic [15:0]        x_max_i,
  input  logic [15:0]        y_min_i,
  input  logic [15:0]        y_max_i,
  input  logic               measurable_i,
  input  logic               too_close_i,
  // stage OutStages
  output logic               obstacle_o,
  output logic [1:0]         severity_o,
  output logic               in_tunnel_o,
  output logic               too_close_o,
  output logic signed [28:0] distance_o,  // from the bumper
  output logic signed [28:0] judged_o     // 0 when too close, else distance_o
);
  localparam int unsigned Stages    = 28;  // stage of the severity
  localparam int unsigned RootW     = 27;  // hls::warning::isqrt_round's loop
  localparam int unsigned SqrtStart = 10;  // stage of n
  localparam int unsigned SqrtLat   = (RootW + 1) / 2 + 1;
  localparam int unsigned PxW       = 21;  // pixel offsets, Q.4 signed
  localparam int unsigned CW        = 29;  // coordinates, mm signed
  localparam int unsigned SqW       = 2 * CW - 1;
  localparam int unsigned NW        = SqW + 1;
  localparam int unsigned GW        = CW + 2;  // tunnel margins, signed
  localparam int unsigned DW        = 29;  // distance, signed
  localparam int unsigned Lanes     = 7;   // x, y, z, x0, x1, y_top, y_bot

  if (OutStages < Stages) begin : gen_bad
    $error("scw_warning_object: OutStages is at least 28");
  end
  if (SqrtStart + SqrtLat != 25) begin : gen_bad_sqrt
    $error("scw_warning_object: the square root must end at stage 25");
  end

  // ---- configuration ------------------------------------------------------------------------
  // Each offset as (+-16 * pixel) + k: k = -cu, -cu - 8, -cu + 8 across, cv, cv + 8, cv - 8 up
  // (the box edges are half a pixel outside its pixels).
  logic signed [17:0] cu_s, cv_s;
  assign cu_s = {2'b0, cfg_cu_q4_i};
  assign cv_s = {2'b0, cfg_cv_q4_i};

  logic signed [20:0] base_q, focal_q;
  logic signed [17:0] k_x_q, k_x0_q, k_x1_q, k_y_q, k_yt_q, k_yb_q;
  logic signed [16:0] nhw_q;
  logic signed [15:0] vx_q, vy_q, vz_q;
  logic [15:0] hw_q, th_q, high_q, med_q, near_q, minh_q;
  logic med_nz_q;
  always_ff @(posedge clk_i) begin
    base_q   <= {1'b0, cfg_baseline_q8_i};
    focal_q  <= {5'b0, cfg_focal_q4_i};
    k_x_q    <= -cu_s;
    k_x0_q   <= -cu_s - 18'sd8;
    k_x1_q   <= -cu_s + 18'sd8;
    k_y_q    <= cv_s;
    k_yt_q   <= cv_s + 18'sd8;
    k_yb_q   <= cv_s - 18'sd8;
    nhw_q    <= -$signed({1'b0, cfg_tunnel_half_w_mm_i});
    vx_q     <= cfg_veh_x_mm_i;
    vy_q     <= cfg_veh_y_mm_i;
    vz_q     <= cfg_veh_z_mm_i;
    hw_q     <= cfg_tunnel_half_w_mm_i;
    th_q     <= cfg_tunnel_h_mm_i;
    high_q   <= cfg_high_mm_i;
    med_q    <= cfg_medium_mm_i;
    near_q   <= cfg_near_mm_i;
    minh_q   <= cfg_min_height_mm_i;
    med_nz_q <= cfg_medium_mm_i != '0;
  end

  // ---- 1 .. 3: S = b / d, and the pixel offsets ---------------------------------------------
  logic signed [32:0] s_wide;
  logic [31:0] s3;
  scw_warning_mul #(.AW(21), .BW(29), .Split(16), .Shift(16), .OutW(33)) u_mul_s (
    .clk_i, .en_i, .a_i(base_q), .b_i(recip_i), .p_o(s_wide)
  );
  assign s3 = s_wide[31:0];

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
  logic [6*PxW-1:0] px3;
  scw_warning_delay #(.Width(6 * PxW), .Depth(2)) u_px_delay (
    .clk_i, .en_i, .d_i({px_yb1, px_yt1, px_x11, px_x01, px_y1, px_x1}), .q_o(px3)
  );

  // ---- 4 .. 6: coordinates ------------------------------------------------------------------
  // Lane order x, y, z, x0, x1, y_top, y_bot; z's offset is the (static) focal length.
  logic [Lanes*PxW-1:0] px_lanes;
  logic [Lanes*CW-1:0] c6;
  assign px_lanes = {px3[5*PxW +: PxW], px3[4*PxW +: PxW], px3[3*PxW +: PxW], px3[2*PxW +: PxW],
                     focal_q, px3[PxW +: PxW], px3[0 +: PxW]};
  for (genvar i = 0; i < Lanes; i++) begin : gen_coord
    logic signed [CW-1:0] c;
    scw_warning_mul #(.AW(PxW), .BW(32), .Split(17), .Shift(24), .OutW(CW)) u_mul (
      .clk_i, .en_i, .a_i(px_lanes[i*PxW +: PxW]), .b_i(s3), .p_o(c)
    );
    assign c6[i*CW +: CW] = c;
  end
  logic signed [CW-1:0] x6, y6, z6, x06, x16, yt6, yb6;
  assign {yb6, yt6, x16, x06, z6, y6, x6} = c6;

  // ---- 7, 8: squares, height, tunnel margins -----------------------------------------------
  logic [SqW-1:0] sqx8, sqy8, sqz8;
  scw_warning_square #(.XW(CW), .L(17)) u_sq_x (.clk_i, .en_i, .x_i(x6), .sq_o(sqx8));
  scw_warning_square #(.XW(CW), .L(17)) u_sq_y (.clk_i, .en_i, .x_i(y6), .sq_o(sqy8));
  scw_warning_square #(.XW(CW), .L(17)) u_sq_z (.clk_i, .en_i, .x_i(z6), .sq_o(sqz8));

  function automatic logic signed [CW:0] ext_c(input logic signed [CW-1:0] v);
    ext_c = {v[CW-1], v};
  endfunction
  function automatic logic signed [CW:0] ext_16(input logic signed [15:0] v);
    ext_16 = {{(CW + 1 - 16){v[15]}}, v};
  endfunction
  function automatic logic signed [GW-1:0] ext_g(input logic signed [CW:0] v);
    ext_g = {v[CW], v};
  endfunction

  logic signed [CW:0] height7, vx07, vx17, vyt7, vyb7;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      height7 <= ext_c(yt6) - ext_c(yb6);
      vx07    <= ext_c(x06) - ext_16(vx_q);
      vx17    <= ext_c(x16) - ext_16(vx_q);
      vyt7    <= ext_c(yt6) - ext_16(vy_q);
      vyb7    <= ext_c(yb6) - ext_16(vy_q);
    end
  end

  // gx = max(0, vx0 - hw, -hw - vx1), gy = max(0, vy_bot - h, -vy_top)
  logic signed [GW-1:0] g18, g28, g38, g48;
  logic obst_h8;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      obst_h8 <= height7 >= $signed({{(CW + 1 - 16){1'b0}}, minh_q});
      g18     <= ext_g(vx07) - $signed({{(GW - 16){1'b0}}, hw_q});
      g28     <= $signed({{(GW - 17){nhw_q[16]}}, nhw_q}) - ext_g(vx17);
      g38     <= ext_g(vyb7) - $signed({{(GW - 16){1'b0}}, th_q});
      g48     <= -ext_g(vyt7);
    end
  end

  // ---- 9, 10: n and the gap -----------------------------------------------------------------
  function automatic logic [GW-2:0] max0(input logic signed [GW-1:0] a,
                                          input logic signed [GW-1:0] b);
    logic signed [GW-1:0] m;
    m = (a > b) ? a : b;
    max0 = m[GW-1] ? '0 : m[GW-2:0];
  endfunction

  logic [NW-1:0] sxy9, n10;
  logic [SqW-1:0] sqz9;
  logic [GW-2:0] gx9, gy9, gap10;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      sxy9  <= {1'b0, sqx8} + {1'b0, sqy8};
      sqz9  <= sqz8;
      gx9   <= max0(g18, g28);
      gy9   <= max0(g38, g48);
      n10   <= sxy9 + {1'b0, sqz9};
      gap10 <= (gx9 > gy9) ? gx9 : gy9;
    end
  end

  logic tun11, near11;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      tun11  <= gap10 == '0;
      near11 <= gap10 <= {{(GW - 1 - 16){1'b0}}, near_q};
    end
  end

  // ---- 11 .. 25: the distance from the camera -----------------------------------------------
  logic [RootW:0] root25;
  scw_warning_sqrt #(.InW(NW), .RootW(RootW), .Latency(SqrtLat)) u_sqrt (
    .clk_i, .en_i, .n_i(n10), .root_o(root25)
  );

  // ---- 26 .. 28: distance, thresholds, severity ---------------------------------------------
  logic meas26, tc26, obst_h27, tun27, near27;
  scw_warning_delay #(.Width(2), .Depth(26)) u_flags_delay (
    .clk_i, .en_i, .d_i({measurable_i, too_close_i}), .q_o({meas26, tc26})
  );
  scw_warning_delay #(.Width(1), .Depth(19)) u_height_delay (
    .clk_i, .en_i, .d_i(obst_h8), .q_o(obst_h27)
  );
  scw_warning_delay #(.Width(2), .Depth(16)) u_gap_delay (
    .clk_i, .en_i, .d_i({tun11, near11}), .q_o({tun27, near27})
  );

  logic signed [DW-1:0] dist26, dist27, dj27;
  logic le_high27, lt_med27, meas27, tc27;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      dist26    <= $signed({1'b0, root25}) - $signed({{(DW - 16){vz_q[15]}}, vz_q});
      // Too close: judged at the bumper, d = 0 (<= high always, < medium unless medium = 0).
      le_high27 <= tc26 || dist26 <= $signed({{(DW - 16){1'b0}}, high_q});
      lt_med27  <= tc26 ? med_nz_q : dist26 < $signed({{(DW - 16){1'b0}}, med_q});
      dj27      <= tc26 ? '0 : dist26;
      dist27    <= dist26;
      meas27    <= meas26;
      tc27      <= tc26;
    end
  end

  logic obst;
  logic [1:0] sev;
  always_comb begin
    obst = meas27 && obst_h27;
    if (!obst) sev = 2'd0;                                   // none
    else if (tun27) sev = le_high27 ? 2'd3 : lt_med27 ? 2'd2 : 2'd1;
    else sev = (near27 && lt_med27) ? 2'd2 : 2'd1;
  end

  localparam int unsigned EvalW = 5 + 2 * DW;
  logic [EvalW-1:0] eval28, eval_out;
  always_ff @(posedge clk_i) begin
    if (en_i) eval28 <= {obst, sev, tun27, tc27, dist27, dj27};
  end
  if (OutStages > Stages) begin : gen_hold
    scw_warning_delay #(.Width(EvalW), .Depth(OutStages - Stages)) u_hold (
      .clk_i, .en_i, .d_i(eval28), .q_o(eval_out)
    );
  end else begin : gen_no_hold
    assign eval_out = eval28;
  end
  assign {obstacle_o, severity_o, in_tunnel_o, too_close_o, distance_o, judged_o} = eval_out;

  // S < 2^32 always (b < 2^20, recip <= 2^28): the product's sign bit is 0.
  logic unused_s;
  assign unused_s = s_wide[32];
endmodule
