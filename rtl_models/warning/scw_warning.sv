// SPDX-License-Identifier: Apache-2.0
// Warning: the labelling stage's object table in, one collision-warning result per frame out.
`default_nettype none

// The C++ twin is scw::hls::warning::Warning (hls/warning/warning.hpp) clocked by
// scw::sim::WarningModel, clock for clock: same in_ready, out_valid and out data every cycle.
// The handshake's enable, en = !out_valid || out_ready, and the pipeline's, en_p (en while a
// word is in the pipeline or at its input; the same edges whenever a word moves): a word taken
// at an edge is in
// R1 after it, in S(Latency-RuleLatency-2) Latency-2 enabled edges later, and the next enabled
// edge folds it into the frame's accumulator; the word that closes the frame (its status word,
// or a `last` without one) loads the output register on that edge. Stages:
//   R1 .. R(RL)     the distance rule (scw_warning_rule): the disparity dq that places the
//                   object, from its area, sum d, sum d^2 and d_max; beside it the word's
//                   fields (a status word's in the same bits), its flags and too_close
//                   (d_max >= d_limit), delayed (scw_delay_ring)
//   S0              the fields and flags, measurable (dq), and the reciprocal table read at
//                   min(dq, table end) (scw_warning_recip; its output register holds the entry
//                   in S1)
//   S1 .. S(L-RL-2) the per-object arithmetic (scw_warning_object) beside the fields
//   fold            obstacles counted; the deciding one is the worse severity, then the smaller
//                   judged distance, then the earlier; on close the result is the accumulator
//                   with the status word's flags, and stream_error when the table broke the
//                   packet rules (status without last, last without status, object count)
// With cfg_road_height the first word of each frame (after reset or a `last`) is taken with a
// road line from the road_* port, and waits for one (hls::warning::Warning):
//   in_ready = en && (!first || road_valid), road_ready = en && first && in_valid;
// the line travels with the frame's words through the rule's delay to scw_warning_object, which
// measures the top's height above it. Without it the road port is never read.
// Output word: sim/words/warning_pack.hpp. Input word: sim/words/labelling_pack.hpp (label_desc_t above
// the is_status bit; a status word's objects and flags sit where area and x_min are).
// cfg_* are static: registered without reset, so set them at least a clock before the first
// word (the C++ adapter sets them before reset).
module scw_warning #(
  parameter int unsigned MaxDisparityPx /*verilator public*/ = 64,
  localparam int unsigned InW  = scw_pkg::ObjWordBits,
  localparam int unsigned OutW = scw_pkg::ResultWordBits
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  // static configuration (hls::warning::WarningConfig)
  // static configuration (hls::warning::WarningConfig): scw_pkg::warning_cfg_t
  input  logic [scw_pkg::WarningCfgBits-1:0] cfg_warning_i,
  input  logic               cfg_road_height_i,  // heights above the road line of each frame
  // the labelling stage's objects, then its status word with last
  input  logic               in_valid_i,
  output logic               in_ready_o,
  input  logic [InW-1:0]     in_data_i,
  input  logic               in_last_i,
  // with cfg_road_height: a road line (hls::road::Line) with each frame's first word
  input  logic               road_valid_i,
  output logic               road_ready_o,
  input  logic [17:0]        road_a_i,
  input  logic [31:0]        road_b_i,
  // one result per frame
  output logic               out_valid_o,
  input  logic               out_ready_i,
  output logic [OutW-1:0]    out_data_o,
  output logic               out_last_o
);
  // hls::warning::kRuleLatency and kLatency: clocks from a word's acceptance to its effect on
  // the result.
  localparam int unsigned RuleLatency /*verilator public*/ = 64;
  localparam int unsigned Latency     /*verilator public*/ = RuleLatency + 47;
  localparam int unsigned TableSize   /*verilator public*/ = 16 * MaxDisparityPx;
  localparam int unsigned Stages    = Latency - 1;      // R1 .. R(RL), S0 .. , then the fold
  localparam int unsigned ObjStages = Stages - RuleLatency;  // S0 .. S(ObjStages-1)
  localparam int unsigned AddrW  = $clog2(TableSize);
  localparam int unsigned FW     = 7 * scw_pkg::CoordBits;  // the result_box_t a result reports
  localparam int unsigned CW     = scw_pkg::CountBits;      // objects, obstacles, index
  localparam int unsigned DW     = 29;            // distances, signed

  if (MaxDisparityPx < 2 || MaxDisparityPx > 2048) begin : gen_bad
    $error("scw_warning: MaxDisparityPx is 2 .. 2048 (codes in Q11.4)");
  end

  logic en, first_q, need_road, take;
  assign en           = !out_valid_o || out_ready_i;
  assign need_road    = cfg_road_height_i && first_q;
  assign in_ready_o   = en && (!need_road || road_valid_i);
  assign road_ready_o = en && need_road && in_valid_i;
  assign take         = in_valid_i && in_ready_o;

  // The pipeline's own enable, en_p: en while a word is in it or waits at its input. Between
  // tables (most of a frame: the labelling stage sends its table at the frame's end) the
  // pipeline holds rather than shifting empty slots: no valid word moves either way, so the
  // results are the same clock for clock, nothing toggles, and a simulator skips its updates.
  // The fold and the output register stay on en (a result is handed over while the pipeline
  // is idle).
  logic [Stages-1:0] valid_q;
  logic en_p;
  assign en_p = en && (in_valid_i || |valid_q);

  // The frame's road: taken with its first word, held for the rest.
  logic [49:0] road_q, road_w;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) first_q <= 1'b1;
    else if (take) first_q <= in_last_i;
  end
  always_ff @(posedge clk_i) begin
    if (take && need_road) road_q <= {road_b_i, road_a_i};
  end
  assign road_w = need_road ? {road_b_i, road_a_i} : road_q;

  // ---- input word ---------------------------------------------------------------------------
  scw_pkg::label_desc_t desc;
  scw_pkg::label_status_t st;
  logic in_status;
  assign in_status = in_data_i[0];
  assign desc = in_data_i[InW-1:1];
  assign st   = in_data_i[$bits(st):1];

  // The fields a result reports (scw_pkg::result_box_t); a status word puts {flags, objects}
  // in their place.
  scw_pkg::result_box_t box;
  always_comb begin
    box.y_max     = desc.y_max;
    box.y_min     = desc.y_min;
    box.x_max     = desc.x_max;
    box.x_min     = desc.x_min;
    box.d_max     = desc.d_max;
    box.closest_y = desc.closest_y;
    box.closest_x = desc.closest_x;
  end
  logic [FW-1:0] fields;
  assign fields = in_status
      ? FW'({st.stream_error, st.object_overflow, st.tile_overflow, st.objects}) : box;

  // The word's other fields are scw_warning_object's.
  /* verilator lint_off UNUSEDSIGNAL */
  scw_pkg::warning_cfg_t cfg;
  /* verilator lint_on UNUSEDSIGNAL */
  assign cfg = cfg_warning_i;
  if ($bits(cfg) != scw_pkg::WarningCfgBits) begin : gen_bad_cfg
    $error("scw_warning: scw_pkg::WarningCfgBits is not warning_cfg_t's width");
  end

  logic [15:0] d_limit_q;
  always_ff @(posedge clk_i) d_limit_q <= cfg.d_limit_q4;

  // ---- R1 .. R(RuleLatency): the distance rule ----------------------------------------------
  logic [15:0] r_dq;
  scw_warning_rule #(.Latency(RuleLatency)) u_rule (
    .clk_i,
    .en_i        (en_p),
    .cfg_rule_i  (cfg.rule),
    .cfg_spread_i(cfg.spread_q4),
    .area_i      (20'(desc.area)),
    .sum_d_i     (desc.sum_d[34:0]),
    .sum_dd_i    (desc.sum_dd[49:0]),
    .d_max_i     (desc.d_max),
    .dq_o        (r_dq)
  );

  logic [FW-1:0] r_fields;
  logic [49:0] r_road;
  logic r_status, r_last, r_tc;
  scw_delay_ring #(.Width(FW + 53), .Depth(RuleLatency)) u_rule_delay (
    .clk_i, .rst_ni, .en_i(en_p), .d_i({road_w, in_status, in_last_i, desc.d_max >= d_limit_q, fields}),
    .q_o({r_road, r_status, r_last, r_tc, r_fields})
  );

  // ---- S0 -----------------------------------------------------------------------------------
  logic [AddrW-1:0] addr;
  assign addr = (r_dq < 16'(TableSize)) ? r_dq[AddrW-1:0] : AddrW'(TableSize - 1);

  logic [FW-1:0] s0_fields_q;
  logic [49:0] s0_road_q;
  logic [15:0] s0_dq_q;
  logic s0_status_q, s0_last_q, s0_meas_q, s0_tc_q;
  always_ff @(posedge clk_i) begin
    if (en_p) begin
      s0_fields_q <= r_fields;
      s0_road_q   <= r_road;
      s0_dq_q     <= r_dq;
      s0_status_q <= r_status;
      s0_last_q   <= r_last;
      // measurable: 1 px <= dq, and dq >= 0 as int16 (labelling's invalid codes)
      s0_meas_q   <= !r_dq[15] && r_dq[14:4] != '0;
      s0_tc_q     <= r_tc;  // too close: d_max (not dq) >= d_limit
    end
  end

  logic [28:0] s1_recip;
  scw_warning_recip #(.Entries(TableSize)) u_recip (
    .clk_i, .en_i(en_p), .addr_i(addr), .data_o(s1_recip)
  );

  // ---- S1 .. S(ObjStages-1) -----------------------------------------------------------------
  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_q <= '0;
    else if (en_p) valid_q <= Stages'({valid_q, take});
  end

  logic [FW-1:0] w_fields;
  logic w_status, w_last;
  scw_delay_ring #(.Width(FW + 2), .Depth(ObjStages - 1)) u_word_delay (
    .clk_i, .rst_ni, .en_i(en_p), .d_i({s0_status_q, s0_last_q, s0_fields_q}),
    .q_o({w_status, w_last, w_fields})
  );

  logic w_obst, w_tun, w_tc;
  logic [1:0] w_sev;
  logic signed [DW-1:0] w_dist, w_dj;
  scw_warning_object #(.OutStages(ObjStages - 1)) u_object (
    .clk_i,
    .en_i                  (en_p),
    .cfg_warning_i,
    .recip_i               (s1_recip),
    .closest_x_i           (s0_fields_q[0 +: 16]),
    .closest_y_i           (s0_fields_q[16 +: 16]),
    .x_min_i               (s0_fields_q[48 +: 16]),
    .x_max_i               (s0_fields_q[64 +: 16]),
    .y_min_i               (s0_fields_q[80 +: 16]),
    .y_max_i               (s0_fields_q[96 +: 16]),
    .measurable_i          (s0_meas_q),
    .too_close_i           (s0_tc_q),
    .cfg_road_height_i,
    .road_a_i              (s0_road_q[17:0]),
    .road_b_i              (s0_road_q[49:18]),
    .dq_i                  (s0_dq_q),
    .obstacle_o            (w_obst),
    .severity_o            (w_sev),
    .in_tunnel_o           (w_tun),
    .too_close_o           (w_tc),
    .distance_o            (w_dist),
    .judged_o              (w_dj)
  );

  // ---- fold ---------------------------------------------------------------------------------
  // The accumulator is the model's FrameResult acc_ (without the flags, which only the closing
  // word sets) plus whether an obstacle was seen and the deciding one's judged distance.
  logic [scw_pkg::SeverityBits-1:0] sev_q, sev_d, sev_f;
  logic tun_q, tun_d, tun_f, tc_q, tc_d, tc_f, best_q, best_d;
  logic [CW-1:0] objs_q, objs_d, objs_f, obst_q, obst_d, obst_f, idx_q, idx_d, idx_f;
  logic signed [DW-1:0] dist_q, dist_d, dist_f, dj_q, dj_d;
  logic [FW-1:0] fld_q, fld_d, fld_f;
  logic out_valid_q, out_valid_d;
  logic [OutW-1:0] out_q;
  scw_pkg::warning_result_t out_d;
  if ($bits(out_d) != OutW) begin : gen_bad_result
    $error("scw_warning: scw_pkg::ResultWordBits is not warning_result_t's width");
  end

  logic w_valid, w_obj, better, upd, close, st_err;
  logic [scw_pkg::AreaBits-1:0] st_objects;
  logic [2:0] st_flags;
  assign w_valid    = valid_q[Stages-1];
  assign w_obj      = w_valid && !w_status;
  assign st_objects = w_fields[scw_pkg::AreaBits-1:0];
  assign st_flags   = w_fields[scw_pkg::AreaBits +: 3];  // {stream_error, object_overflow, tile_overflow}

  // Which obstacle decides, as one unsigned compare (a single carry chain into the enables of
  // the whole accumulator): severity above the judged distance, whose sign bit is flipped (signed
  // order) and the rest inverted (the smaller distance is the larger key).
  logic [DW+1:0] w_key, key_q;
  assign w_key = {w_sev, w_dj[DW-1], ~w_dj[DW-2:0]};
  assign key_q = {sev_q, dj_q[DW-1], ~dj_q[DW-2:0]};

  always_comb begin
    better = !best_q || w_key > key_q;
    upd    = w_obj && w_obst && better;
    close  = w_valid && (w_status || w_last);
    st_err = st_flags[2] || !w_last || st_objects != scw_pkg::AreaBits'(objs_q);

    // _f: the accumulator with the word folded in
    objs_f = objs_q + CW'(w_obj);
    obst_f = obst_q + CW'(w_obj && w_obst);
    sev_f  = upd ? w_sev : sev_q;
    tun_f  = upd ? w_tun : tun_q;
    tc_f   = upd ? w_tc : tc_q;
    idx_f  = upd ? objs_q : idx_q;
    dist_f = upd ? w_dist : dist_q;
    fld_f  = upd ? w_fields : fld_q;
    dj_d   = upd ? w_dj : dj_q;

    // the frame's result, taken when it closes
    out_d.box             = fld_f;
    out_d.distance_mm     = {{(scw_pkg::DistMmBits - DW){dist_f[DW-1]}}, dist_f};
    out_d.index           = idx_f;
    out_d.obstacles       = obst_f;
    out_d.objects         = objs_f;
    out_d.stream_error    = w_status ? st_err : 1'b1;
    out_d.object_overflow = w_status && st_flags[1];
    out_d.tile_overflow   = w_status && st_flags[0];
    out_d.too_close       = tc_f;
    out_d.in_tunnel       = tun_f;
    out_d.severity        = sev_f;
    out_valid_d = close || (out_valid_q && !out_ready_i);

    // a closed frame leaves the next one FrameResult{}
    sev_d  = close ? '0 : sev_f;
    tun_d  = close ? 1'b0 : tun_f;
    tc_d   = close ? 1'b0 : tc_f;
    best_d = close ? 1'b0 : best_q || upd;
    objs_d = close ? '0 : objs_f;
    obst_d = close ? '0 : obst_f;
    idx_d  = close ? '1 : idx_f;
    dist_d = close ? '0 : dist_f;
    fld_d  = close ? '0 : fld_f;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      out_valid_q <= 1'b0;
      sev_q  <= '0;
      tun_q  <= 1'b0;
      tc_q   <= 1'b0;
      best_q <= 1'b0;
      objs_q <= '0;
      obst_q <= '0;
      idx_q  <= '1;
      dist_q <= '0;
      fld_q  <= '0;
    end else if (en) begin
      out_valid_q <= out_valid_d;
      sev_q  <= sev_d;
      tun_q  <= tun_d;
      tc_q   <= tc_d;
      best_q <= best_d;
      objs_q <= objs_d;
      obst_q <= obst_d;
      idx_q  <= idx_d;
      dist_q <= dist_d;
      fld_q  <= fld_d;
    end
  end

  // Only read while best_q is set, which a reset or a closed frame clears.
  always_ff @(posedge clk_i) begin
    if (en) dj_q <= dj_d;
  end
  always_ff @(posedge clk_i) begin
    if (en && close) out_q <= out_d;
  end

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_q;
  assign out_last_o  = 1'b1;  // one word per frame

  // A status word carries no more than objects and three flags; the other descriptor fields
  // (moments, first pixel, d_min) are not part of the warning, and the distance rule reads only
  // the low kRuleAreaBits, kRuleSumBits and kRuleSquareBits of area, sum_d and sum_dd.
  logic unused_in;
  assign unused_in = ^{desc.m03, desc.m12, desc.m21, desc.m30, desc.m02, desc.m11, desc.m20,
                       desc.m01, desc.m10, desc.first_y, desc.first_x, desc.d_min,
                       desc.area, desc.sum_d[63:35], desc.sum_dd[63:50]};
endmodule
