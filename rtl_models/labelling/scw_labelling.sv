// SPDX-License-Identifier: Apache-2.0
// Labelling: one-pass tiled connected-component labelling of a disparity stream into objects.
`default_nettype none

// The C++ twin is scw::hls::labelling::Labelling (hls/labelling/labelling.hpp) clocked by
// scw::sim::LabellingModel, clock for clock: same in_ready, out_valid and out data every cycle.
// The rules, the join and the descriptor are in docs/labelling.md. Phases:
//   Init     after reset: clear the parent RAM, one node per clock
//   Frame    S0 takes a pixel and reads the row buffer; S1 decides its node (a tile's label
//            table: node = tile * LabelsPerTile + label) and queues edges to other nodes; S2
//            adds the pixel to its node's descriptor; the merge unit (union-find) runs alongside
//   Drain    after the frame's last pixel or a sof in mid-frame: wait for S1, S2, the edge queue
//            and the merge unit
//   Resolve  every used node in ascending order (R0 .. R3): its root (parents point to smaller
//            nodes, so the parent's root is already known) and its descriptor into the root's
//   Emit     every used node again (E0, E1): roots of at least cfg_min_area_i pixels leave as
//            objects, up to MaxObjects; then the status word with out_last_o
// Every RAM is a scw_ram_sdp with a registered read (read-first: a read in the clock of a write
// to the same address returns the old word); where the model's next stage needs that word it
// forwards the previous clock's write, as the model does.
// A sof in mid-frame closes the frame early (it is taken afterwards); a beat before any sof is
// dropped and flags the frame it precedes; a misplaced eol flags its frame. err_o is sticky.
// cfg_* are static: set them before rst_ni rises.
module scw_labelling #(
  parameter int unsigned MaxWidthPx    /*verilator public*/ = 32,
  parameter int unsigned MaxHeight     /*verilator public*/ = 24,
  parameter int unsigned MaxTilesX     /*verilator public*/ = 2,
  parameter int unsigned MaxTilesY     /*verilator public*/ = 2,
  parameter int unsigned LabelsPerTile /*verilator public*/ = 16,
  parameter int unsigned MaxObjects    /*verilator public*/ = 16,
  localparam int unsigned OutW = 1 + 32 + 10 * 16 + 9 * 64  // sim/labelling_pack.hpp
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  // static configuration (hls::labelling::LabellingConfig)
  input  logic [15:0]     cfg_width_i,
  input  logic [15:0]     cfg_height_i,
  input  logic [15:0]     cfg_tile_w_i,
  input  logic [15:0]     cfg_tile_h_i,
  input  logic [15:0]     cfg_floor_i,
  input  logic [31:0]     cfg_min_area_i,
  // disparities, Q11.4
  input  logic            in_valid_i,
  output logic            in_ready_o,
  input  logic [15:0]     in_data_i,
  input  logic            in_sof_i,
  input  logic            in_eol_i,
  // objects, then the frame's status word with last
  output logic            out_valid_o,
  input  logic            out_ready_i,
  output logic [OutW-1:0] out_data_o,
  output logic            out_last_o,
  output logic            err_o
);
  localparam int unsigned Tiles = MaxTilesX * MaxTilesY;
  localparam int unsigned Nodes /*verilator public*/ = Tiles * LabelsPerTile;
  // hls::labelling::kEdgeQueue: the input is taken while at most EdgeQueue - 4 edges are queued
  // (two from the pixel in decision, two from the pixel being taken).
  localparam int unsigned EdgeQueue /*verilator public*/ = 8;
  localparam int unsigned DescW  = OutW - 1;
  localparam int unsigned XW     = $clog2(MaxWidthPx);       // 0 .. MaxWidthPx - 1
  localparam int unsigned YW     = $clog2(MaxHeight + 1);    // 0 .. MaxHeight
  localparam int unsigned TXW    = (MaxTilesX > 1) ? $clog2(MaxTilesX) : 1;
  localparam int unsigned TYW    = $clog2(MaxTilesY + 1);
  localparam int unsigned TileW  = (Tiles > 1) ? $clog2(Tiles) : 1;
  localparam int unsigned LabW   = (LabelsPerTile > 1) ? $clog2(LabelsPerTile) : 1;
  localparam int unsigned CntW   = $clog2(LabelsPerTile + 1);
  localparam int unsigned NodeW  = (Nodes > 1) ? $clog2(Nodes) : 1;
  localparam int unsigned N1W    = $clog2(Nodes + 1);         // node + 1, 0 = none
  localparam int unsigned ObjW   = $clog2(MaxObjects + 1);
  localparam int unsigned QCntW  = $clog2(EdgeQueue + 1);
  localparam int unsigned RowW   = 16 + N1W;                  // row buffer word {node + 1, d}
  localparam logic [N1W-1:0] LabelsN1  = N1W'(LabelsPerTile);
  localparam logic [TileW-1:0] TilesXT = TileW'(MaxTilesX);

  if (MaxWidthPx < 2 || MaxHeight < 1 || MaxWidthPx > 65535 || MaxHeight > 65535)
  begin : gen_bad_size
    $error("scw_labelling: an image of 2 x 1 .. 65535 x 65535");
  end
  if (MaxTilesX < 1 || MaxTilesY < 1 || LabelsPerTile < 1 || MaxObjects < 1) begin : gen_bad_cap
    $error("scw_labelling: capacities are at least 1");
  end

  // Descriptors (hls::labelling::Object) are scw_pkg::label_desc_t.
  typedef enum logic [2:0] {PhInit, PhFrame, PhDrain, PhResolve, PhEmit} phase_e;

  // The thesis's join: 10 |d_cur - d_nb| < d_cur, d_cur the later pixel in raster order.
  function automatic logic joins(input logic [15:0] d_cur, input logic [15:0] d_nb);
    logic [15:0] diff;
    logic [19:0] ten;
    diff  = (d_cur >= d_nb) ? d_cur - d_nb : d_nb - d_cur;
    ten   = {1'b0, diff, 3'b000} + {3'b000, diff, 1'b0};
    joins = ten < {4'b0000, d_cur};
  endfunction

  // ---- registers ---------------------------------------------------------------------------
  phase_e phase_q, phase_d;
  logic [NodeW-1:0] init_q, init_d;
  // frame position and flags
  logic in_frame_q, in_frame_d;
  logic [XW-1:0] x_q, x_d, tcol_q, tcol_d;
  logic [YW-1:0] y_q, y_d, trow_q, trow_d;
  logic [TXW-1:0] tx_q, tx_d;
  logic [TYW-1:0] ty_q, ty_d;
  logic err_pending_q, err_pending_d, err_frame_q, err_frame_d, err_sticky_q, err_sticky_d;
  logic tile_ovf_q, tile_ovf_d, obj_ovf_q, obj_ovf_d;
  logic [ObjW-1:0] emitted_q, emitted_d;
  // S1: the pixel S0 took last clock
  logic s1_valid_q, s1_valid_d;
  logic [15:0] s1_d_q, s1_d_d;  // 0 when not an object pixel
  logic [XW-1:0] s1_x_q, s1_x_d;
  logic [YW-1:0] s1_y_q, s1_y_d;
  logic [TileW-1:0] s1_tile_q, s1_tile_d;
  logic s1_has_left_q, s1_has_left_d, s1_has_up_q, s1_has_up_d;
  logic s1_left_same_q, s1_left_same_d, s1_up_same_q, s1_up_same_d;
  // S2: the pixel S1 decided last clock
  logic s2_valid_q, s2_valid_d, s2_init_q, s2_init_d;
  logic [NodeW-1:0] s2_node_q, s2_node_d;
  logic [XW-1:0] s2_x_q, s2_x_d;
  logic [YW-1:0] s2_y_q, s2_y_d;
  logic [15:0] s2_d_q, s2_d_d;
  // the left neighbour and the edge queued last
  logic [15:0] left_d_q, left_d_d;
  logic [N1W-1:0] left1_q, left1_d;
  logic has_last_q, has_last_d;
  logic [NodeW-1:0] last_a_q, last_a_d, last_b_q, last_b_d;
  // labels used per tile
  logic [CntW-1:0] count_q [Tiles];
  logic count_clear, count_inc;
  // The descriptor written last clock (S2's into desc in Frame and Drain, R3's into acc in
  // Resolve): the model's fwd_ and afwd_, never live in the same phase, so one register.
  logic fwd_valid_q, fwd_valid_d;
  logic [NodeW-1:0] fwd_node_q;
  logic [DescW-1:0] fwd_value_q;
  // R2's root written last clock
  logic rfwd_valid_q, rfwd_valid_d;
  logic [NodeW-1:0] rfwd_node_q, rfwd_root_q;
  // the node sweep of Resolve and Emit
  logic sweep_active_q, sweep_active_d;
  logic [TileW-1:0] sweep_tile_q, sweep_tile_d;
  logic [LabW-1:0] sweep_label_q, sweep_label_d;
  // Resolve and Emit pipelines
  logic r1_valid_q, r1_valid_d, r2_valid_q, r2_valid_d, r2_self_q, r2_self_d;
  logic r3_valid_q, r3_valid_d, e1_valid_q, e1_valid_d;
  logic [NodeW-1:0] r1_node_q, r1_node_d, r2_node_q, r2_node_d, r2_parent_q, r2_parent_d;
  logic [NodeW-1:0] r3_node_q, r3_node_d, r3_root_q, r3_root_d, e1_node_q, e1_node_d;
  // output register
  logic out_valid_q, out_valid_d, out_load, out_last_q, out_last_d;
  logic [OutW-1:0] out_data_q, out_data_d;

  // ---- RAM ports ---------------------------------------------------------------------------
  logic row_re, row_we;
  logic [XW-1:0] row_raddr, row_waddr;
  logic [RowW-1:0] row_wdata, row_rd;
  logic par_re, par_we;
  logic [NodeW-1:0] par_raddr, par_waddr;
  logic [N1W-1:0] par_wdata, par_rd;
  logic root_re, root_we;
  logic [NodeW-1:0] root_raddr, root_waddr, root_wdata, root_rd;
  logic desc_re, desc_we;
  logic [NodeW-1:0] desc_raddr;
  logic [DescW-1:0] desc_rd;
  logic acc_re, acc_we;
  logic [NodeW-1:0] acc_raddr;
  scw_pkg::label_desc_t acc_rd;

  // ---- phases ------------------------------------------------------------------------------
  logic ph_frame, ph_pixels, ph_resolve, ph_emit;
  assign ph_frame   = phase_q == PhFrame;
  assign ph_pixels  = (phase_q == PhFrame) || (phase_q == PhDrain);
  assign ph_resolve = phase_q == PhResolve;
  assign ph_emit    = phase_q == PhEmit;

  // ---- merge unit and edge queue -----------------------------------------------------------
  logic [QCntW-1:0] q_count;
  logic [NodeW-1:0] q_head_a, q_head_b;
  logic [1:0] push_n;
  logic [NodeW-1:0] push0_a, push0_b, push1_a, push1_b;
  logic q_nonempty;
  logic uf_pop, uf_idle, uf_rd_en, uf_wr_en;
  logic [NodeW-1:0] uf_rd_addr, uf_wr_addr;
  logic [N1W-1:0] uf_wr_data;

  // A named signal, not an expression, on the port: Yosys 0.23 re-elaborates a module with an
  // expression on a port of a module it has not read yet, and loses a chparam'd top's name.
  assign q_nonempty = q_count != '0;

  scw_labelling_union_find #(.Nodes(Nodes)) u_union_find (
    .clk_i,
    .rst_ni,
    .en_i        (ph_pixels),
    .q_nonempty_i(q_nonempty),
    .head_a_i    (q_head_a),
    .head_b_i    (q_head_b),
    .rd_data_i   (par_rd),
    .pop_o       (uf_pop),
    .idle_o      (uf_idle),
    .rd_en_o     (uf_rd_en),
    .rd_addr_o   (uf_rd_addr),
    .wr_en_o     (uf_wr_en),
    .wr_addr_o   (uf_wr_addr),
    .wr_data_o   (uf_wr_data)
  );

  scw_labelling_edge_queue #(.Depth(EdgeQueue), .NodeW(NodeW)) u_edge_queue (
    .clk_i,
    .rst_ni,
    .pop_i    (uf_pop),
    .push_n_i (push_n),
    .push0_a_i(push0_a),
    .push0_b_i(push0_b),
    .push1_a_i(push1_a),
    .push1_b_i(push1_b),
    .count_o  (q_count),
    .head_a_o (q_head_a),
    .head_b_o (q_head_b)
  );

  // ---- S0: take a beat, read the row buffer ------------------------------------------------
  logic take, sof_mid, frame_start, beat_drop, beat_in, eol_err, frame_last;
  logic [XW-1:0] xe, tcole;
  logic [YW-1:0] ye, trowe;
  logic [TXW-1:0] txe;
  logic [TYW-1:0] tye;
  logic [16:0] x1, tcol1, y1, trow1;
  logic x_wrap, tcol_wrap, trow_wrap, px_valid;

  assign in_ready_o  = ph_frame && (q_count <= QCntW'(EdgeQueue - 4)) && !(in_frame_q && in_sof_i);
  assign take        = in_valid_i && in_ready_o;
  assign sof_mid     = ph_frame && in_frame_q && in_valid_i && in_sof_i;
  assign frame_start = take && !in_frame_q && in_sof_i;
  assign beat_drop   = take && !in_frame_q && !in_sof_i;  // outside any frame
  assign beat_in     = take && (in_frame_q || in_sof_i);  // a pixel of the frame

  // The taken pixel's position: a sof restarts the counters.
  assign xe    = frame_start ? '0 : x_q;
  assign ye    = frame_start ? '0 : y_q;
  assign txe   = frame_start ? '0 : tx_q;
  assign tye   = frame_start ? '0 : ty_q;
  assign tcole = frame_start ? '0 : tcol_q;
  assign trowe = frame_start ? '0 : trow_q;

  assign x1         = 17'(xe) + 17'd1;
  assign tcol1      = 17'(tcole) + 17'd1;
  assign y1         = 17'(ye) + 17'd1;
  assign trow1      = 17'(trowe) + 17'd1;
  assign x_wrap     = x1 == {1'b0, cfg_width_i};
  assign tcol_wrap  = tcol1 == {1'b0, cfg_tile_w_i};
  assign trow_wrap  = trow1 == {1'b0, cfg_tile_h_i};
  assign frame_last = beat_in && x_wrap && (y1 == {1'b0, cfg_height_i});
  assign eol_err    = beat_in && (in_eol_i != x_wrap);
  assign px_valid   = (in_data_i != 16'd0) && !in_data_i[15] && (in_data_i > cfg_floor_i);

  always_comb begin
    x_d    = x_q;
    y_d    = y_q;
    tx_d   = tx_q;
    ty_d   = ty_q;
    tcol_d = tcol_q;
    trow_d = trow_q;
    if (beat_in) begin
      if (x_wrap) begin
        x_d    = '0;
        tcol_d = '0;
        tx_d   = '0;
        y_d    = YW'(y1);
        trow_d = trow_wrap ? '0 : YW'(trow1);
        ty_d   = trow_wrap ? tye + 1'b1 : tye;
      end else begin
        x_d    = XW'(x1);
        tcol_d = tcol_wrap ? '0 : XW'(tcol1);
        tx_d   = tcol_wrap ? txe + 1'b1 : txe;
        y_d    = ye;
        trow_d = trowe;
        ty_d   = tye;
      end
    end
  end

  assign s1_valid_d     = beat_in;
  assign s1_d_d         = px_valid ? in_data_i : 16'd0;
  assign s1_x_d         = xe;
  assign s1_y_d         = ye;
  assign s1_tile_d      = TileW'(tye) * TilesXT + TileW'(txe);
  assign s1_has_left_d  = xe != '0;
  assign s1_has_up_d    = ye != '0;
  assign s1_left_same_d = tcole != '0;
  assign s1_up_same_d   = trowe != '0;

  assign row_re    = beat_in;
  assign row_raddr = xe;

  // ---- S1: decide the pixel's node, queue its edges ----------------------------------------
  logic [15:0] up_d;
  logic [N1W-1:0] up1, node1;
  logic [CntW-1:0] s1_count;
  logic s1_px, jl, ju, alloc, s1_ovf;
  logic want0, want1, push0, push1, has0;
  logic [NodeW-1:0] e0_a, e1_a, e_b, last0_a, last0_b;

  assign up_d     = row_rd[15:0];
  assign up1      = row_rd[RowW-1:16];
  assign s1_count = count_q[s1_tile_q];
  assign s1_px    = s1_valid_q && (s1_d_q != 16'd0);
  assign jl       = s1_px && s1_has_left_q && (left1_q != '0) && joins(s1_d_q, left_d_q);
  assign ju       = s1_px && s1_has_up_q && (up1 != '0) && joins(s1_d_q, up_d);

  always_comb begin
    node1  = '0;
    alloc  = 1'b0;
    s1_ovf = 1'b0;
    if (!s1_px) begin
      node1 = '0;
    end else if (jl && s1_left_same_q) begin
      node1 = left1_q;
    end else if (ju && s1_up_same_q) begin
      node1 = up1;
    end else if (s1_count < CntW'(LabelsPerTile)) begin
      node1 = N1W'(s1_tile_q) * LabelsN1 + N1W'(s1_count) + 1'b1;
      alloc = 1'b1;
    end else begin
      s1_ovf = 1'b1;
    end
  end

  // Edges {from, node}: an edge equal to the one queued just before is dropped.
  assign e0_a    = NodeW'(left1_q - 1'b1);
  assign e1_a    = NodeW'(up1 - 1'b1);
  assign e_b     = NodeW'(node1 - 1'b1);
  assign want0   = jl && (left1_q != node1) && (node1 != '0);
  assign want1   = ju && (up1 != node1) && (node1 != '0);
  assign push0   = want0 && !(has_last_q && e0_a == last_a_q && e_b == last_b_q);
  assign has0    = has_last_q || push0;
  assign last0_a = push0 ? e0_a : last_a_q;
  assign last0_b = push0 ? e_b : last_b_q;
  assign push1   = want1 && !(has0 && e1_a == last0_a && e_b == last0_b);
  assign push_n  = {1'b0, push0} + {1'b0, push1};
  assign push0_a = push0 ? e0_a : e1_a;
  assign push0_b = e_b;
  assign push1_a = e1_a;
  assign push1_b = e_b;

  always_comb begin
    has_last_d = has_last_q;
    last_a_d   = last_a_q;
    last_b_d   = last_b_q;
    if (push1) begin
      has_last_d = 1'b1;
      last_a_d   = e1_a;
      last_b_d   = e_b;
    end else if (push0) begin
      has_last_d = 1'b1;
      last_a_d   = e0_a;
      last_b_d   = e_b;
    end
    if (count_clear) has_last_d = 1'b0;  // end of frame
  end

  assign count_inc  = alloc;
  assign s2_valid_d = s1_valid_q && (node1 != '0);
  assign s2_node_d  = e_b;
  assign s2_init_d  = alloc;
  assign s2_x_d     = s1_x_q;
  assign s2_y_d     = s1_y_q;
  assign s2_d_d     = s1_d_q;
  assign left_d_d   = s1_valid_q ? s1_d_q : left_d_q;
  assign left1_d    = s1_valid_q ? node1 : left1_q;

  assign row_we    = s1_valid_q;
  assign row_waddr = s1_x_q;
  assign row_wdata = {node1, s1_d_q};

  // ---- S2 (Frame, Drain) and R3 (Resolve): one descriptor into another ---------------------
  // S2: desc[node] = the pixel (a new label) or desc[node] + the pixel.
  // R3: acc[root] = desc[node] (the root itself) or acc[root] + desc[node].
  scw_pkg::label_desc_t pix;
  logic [2*XW-1:0] uu;
  logic [XW+YW-1:0] uv;
  logic [2*YW-1:0] vv;
  logic w_valid, w_fresh;
  logic [NodeW-1:0] w_node;
  logic [DescW-1:0] w_a, w_b, w_merged, w_value;

  // pixel_object(x, y, d): moments from the coordinates' own widths, zero-extended.
  assign uu = (2 * XW)'(s2_x_q) * (2 * XW)'(s2_x_q);
  assign uv = (XW + YW)'(s2_x_q) * (XW + YW)'(s2_y_q);
  assign vv = (2 * YW)'(s2_y_q) * (2 * YW)'(s2_y_q);
  always_comb begin
    pix.area      = 32'd1;
    pix.x_min     = 16'(s2_x_q);
    pix.x_max     = 16'(s2_x_q);
    pix.closest_x = 16'(s2_x_q);
    pix.first_x   = 16'(s2_x_q);
    pix.y_min     = 16'(s2_y_q);
    pix.y_max     = 16'(s2_y_q);
    pix.closest_y = 16'(s2_y_q);
    pix.first_y   = 16'(s2_y_q);
    pix.d_min     = s2_d_q;
    pix.d_max     = s2_d_q;
    pix.m10       = 64'(s2_x_q);
    pix.m01       = 64'(s2_y_q);
    pix.m20       = 64'(uu);
    pix.m11       = 64'(uv);
    pix.m02       = 64'(vv);
    pix.m30       = 64'(uu) * 64'(s2_x_q);
    pix.m21       = 64'(uu) * 64'(s2_y_q);
    pix.m12       = 64'(uv) * 64'(s2_y_q);
    pix.m03       = 64'(vv) * 64'(s2_y_q);
  end

  assign w_valid = ph_pixels ? s2_valid_q : (ph_resolve && r3_valid_q);
  assign w_node  = ph_pixels ? s2_node_q : r3_root_q;
  assign w_fresh = ph_pixels ? s2_init_q : (r3_root_q == r3_node_q);
  assign w_b     = ph_pixels ? pix : desc_rd;
  assign w_a     = (fwd_valid_q && fwd_node_q == w_node) ? fwd_value_q
                 : ph_pixels ? desc_rd : acc_rd;

  scw_labelling_merge u_merge (
    .a_i(w_a),
    .b_i(w_b),
    .o_o(w_merged)
  );

  assign w_value     = w_fresh ? w_b : w_merged;
  assign fwd_valid_d = w_valid;
  assign desc_we     = ph_pixels && s2_valid_q;
  assign acc_we      = ph_resolve && r3_valid_q;

  // ---- the node sweep (Resolve and Emit): used nodes ascending, an empty tile costs a clock -
  logic [CntW-1:0] sw_count;
  logic sw_yields, sw_step, sw_start;
  logic [NodeW-1:0] sw_node;

  assign sw_count  = count_q[sweep_tile_q];
  assign sw_yields = sweep_active_q && (sw_count != '0);
  assign sw_node   = NodeW'(N1W'(sweep_tile_q) * LabelsN1 + N1W'(sweep_label_q));

  always_comb begin
    sweep_active_d = sweep_active_q;
    sweep_tile_d   = sweep_tile_q;
    sweep_label_d  = sweep_label_q;
    if (sw_start) begin
      sweep_active_d = 1'b1;
      sweep_tile_d   = '0;
      sweep_label_d  = '0;
    end else if (sw_step && sweep_active_q) begin
      if (sw_yields && ((CntW + 1)'(sweep_label_q) + 1'b1 < (CntW + 1)'(sw_count))) begin
        sweep_label_d = sweep_label_q + 1'b1;
      end else begin
        sweep_label_d = '0;
        sweep_tile_d  = sweep_tile_q + 1'b1;
        if (sweep_tile_q == TileW'(Tiles - 1)) sweep_active_d = 1'b0;
      end
    end
  end

  // ---- Resolve: R0 reads parent[], R1 reads the parent's root, R2 the root and descriptors --
  logic res_done, r1_root;
  logic [NodeW-1:0] r2_root;

  assign res_done    = !sweep_active_q && !r1_valid_q && !r2_valid_q && !r3_valid_q;
  assign r1_valid_d  = ph_resolve && sw_yields;
  assign r1_node_d   = sw_node;
  assign r1_root     = par_rd == '0;
  assign r2_valid_d  = ph_resolve && r1_valid_q;
  assign r2_node_d   = r1_node_q;
  assign r2_self_d   = r1_root;
  assign r2_parent_d = NodeW'(par_rd - 1'b1);
  // The parent's root: read last clock, or written by R2 last clock (the one write that read
  // could not see).
  assign r2_root     = r2_self_q ? r2_node_q
                     : (rfwd_valid_q && rfwd_node_q == r2_parent_q) ? rfwd_root_q : root_rd;
  assign rfwd_valid_d = ph_resolve && r2_valid_q;
  assign r3_valid_d  = ph_resolve && r2_valid_q;
  assign r3_node_d   = r2_node_q;
  assign r3_root_d   = r2_root;

  // ---- Emit: E0 reads a node's root and sum, E1 sends it if it is an object ----------------
  logic swept, is_object, objects_full, consumed, emit_read, emit_status, emit_object, out_en;

  assign out_en       = !out_valid_q || out_ready_i;

  assign swept        = !sweep_active_q && !e1_valid_q;
  assign is_object    = (root_rd == e1_node_q) && (acc_rd.area >= cfg_min_area_i);
  assign objects_full = emitted_q >= ObjW'(MaxObjects);
  assign emit_object  = ph_emit && e1_valid_q && is_object && !objects_full && out_en;
  // The read registers hold a node that waits for the output register.
  assign consumed     = !e1_valid_q || !is_object || objects_full || out_en;
  assign emit_read    = ph_emit && consumed && sw_yields;
  assign emit_status  = ph_emit && consumed && !sw_yields && swept && out_en;
  assign e1_valid_d   = ph_emit && consumed ? sw_yields : e1_valid_q;
  assign e1_node_d    = ph_emit && consumed ? sw_node : e1_node_q;

  // ---- control -----------------------------------------------------------------------------
  logic drained;
  assign drained = (phase_q == PhDrain) && !s1_valid_q && !s2_valid_q && (q_count == '0) &&
                   uf_idle;
  assign count_clear = emit_status;
  assign sw_start    = drained || (ph_resolve && res_done);
  assign sw_step     = ph_resolve || (ph_emit && consumed);

  always_comb begin
    phase_d       = phase_q;
    init_d        = init_q;
    in_frame_d    = in_frame_q;
    err_pending_d = err_pending_q;
    err_frame_d   = err_frame_q;
    err_sticky_d  = err_sticky_q;
    tile_ovf_d    = tile_ovf_q || s1_ovf;
    obj_ovf_d     = obj_ovf_q || (ph_emit && e1_valid_q && is_object && objects_full);
    emitted_d     = emitted_q + ObjW'(emit_object);
    unique case (phase_q)
      PhInit: begin
        init_d = init_q + 1'b1;
        if (init_q == NodeW'(Nodes - 1)) phase_d = PhFrame;
      end
      PhFrame, PhDrain: begin
        if (beat_drop) begin
          err_pending_d = 1'b1;
          err_sticky_d  = 1'b1;
        end
        if (frame_start) begin
          in_frame_d    = 1'b1;
          err_frame_d   = err_pending_q;
          err_pending_d = 1'b0;
        end
        if (eol_err) begin
          err_frame_d  = 1'b1;
          err_sticky_d = 1'b1;
        end
        if (frame_last) begin
          in_frame_d = 1'b0;
          phase_d    = PhDrain;
        end
        if (sof_mid) begin  // close the frame early, take the sof afterwards
          err_frame_d  = 1'b1;
          err_sticky_d = 1'b1;
          in_frame_d   = 1'b0;
          phase_d      = PhDrain;
        end
        if (drained) phase_d = PhResolve;
      end
      PhResolve: begin
        if (res_done) phase_d = PhEmit;
      end
      PhEmit: begin
        if (emit_status) begin
          phase_d     = PhFrame;
          emitted_d   = '0;
          tile_ovf_d  = 1'b0;
          obj_ovf_d   = 1'b0;
          err_frame_d = 1'b0;
        end
      end
      default: phase_d = PhInit;
    endcase
  end

  // The output register: an object's sum, or the status word (sim/labelling_pack.hpp).
  always_comb begin
    out_valid_d = out_valid_q && !out_ready_i;
    out_load    = emit_object || emit_status;
    out_last_d  = emit_status;
    out_data_d  = {acc_rd, 1'b0};
    if (emit_status) begin
      out_data_d = '0;
      out_data_d[0] = 1'b1;
      out_data_d[32:1] = 32'(emitted_q);
      out_data_d[33] = tile_ovf_q;
      out_data_d[34] = obj_ovf_q;
      out_data_d[35] = err_frame_q;
    end
    if (out_load) out_valid_d = 1'b1;
  end

  assign out_valid_o = out_valid_q;
  assign out_data_o  = out_data_q;
  assign out_last_o  = out_last_q;
  assign err_o       = err_sticky_q;

  // ---- RAM port multiplexers ---------------------------------------------------------------
  always_comb begin
    par_re    = 1'b0;
    par_raddr = sw_node;
    par_we    = 1'b0;
    par_waddr = r1_node_q;
    par_wdata = '0;
    unique case (phase_q)
      PhInit: begin
        par_we    = 1'b1;
        par_waddr = init_q;
      end
      PhFrame, PhDrain: begin
        par_re    = uf_rd_en;
        par_raddr = uf_rd_addr;
        par_we    = uf_wr_en;
        par_waddr = uf_wr_addr;
        par_wdata = uf_wr_data;
      end
      PhResolve: begin
        par_re = sw_yields;     // R0
        par_we = r1_valid_q;    // R1 clears parent[] for the next frame
      end
      default: ;
    endcase
  end

  assign root_re    = (ph_resolve && r1_valid_q && !r1_root) || emit_read;
  assign root_raddr = ph_resolve ? r2_parent_d : sw_node;
  assign root_we    = ph_resolve && r2_valid_q;
  assign root_waddr = r2_node_q;
  assign root_wdata = r2_root;

  assign desc_re    = ph_pixels ? (s1_valid_q && node1 != '0) : (ph_resolve && r2_valid_q);
  assign desc_raddr = ph_pixels ? e_b : r2_node_q;
  assign acc_re     = (ph_resolve && r2_valid_q) || emit_read;
  assign acc_raddr  = ph_resolve ? r2_root : sw_node;

  scw_ram_sdp #(.Width(RowW), .Depth(MaxWidthPx)) u_row_ram (
    .clk_i,
    .wr_en_i  (row_we),
    .wr_addr_i(row_waddr),
    .wr_data_i(row_wdata),
    .rd_en_i  (row_re),
    .rd_addr_i(row_raddr),
    .rd_data_o(row_rd)
  );

  scw_ram_sdp #(.Width(N1W), .Depth(Nodes)) u_parent_ram (
    .clk_i,
    .wr_en_i  (par_we),
    .wr_addr_i(par_waddr),
    .wr_data_i(par_wdata),
    .rd_en_i  (par_re),
    .rd_addr_i(par_raddr),
    .rd_data_o(par_rd)
  );

  scw_ram_sdp #(.Width(NodeW), .Depth(Nodes)) u_root_ram (
    .clk_i,
    .wr_en_i  (root_we),
    .wr_addr_i(root_waddr),
    .wr_data_i(root_wdata),
    .rd_en_i  (root_re),
    .rd_addr_i(root_raddr),
    .rd_data_o(root_rd)
  );

  // Descriptors at their values' widths (scw_labelling_desc_ram), full width on the ports.
  scw_labelling_desc_ram #(
    .MaxWidthPx(MaxWidthPx),
    .MaxHeight (MaxHeight),
    .Depth     (Nodes)
  ) u_desc_ram (
    .clk_i,
    .wr_en_i  (desc_we),
    .wr_addr_i(s2_node_q),
    .wr_data_i(w_value),
    .rd_en_i  (desc_re),
    .rd_addr_i(desc_raddr),
    .rd_data_o(desc_rd)
  );

  scw_labelling_desc_ram #(
    .MaxWidthPx(MaxWidthPx),
    .MaxHeight (MaxHeight),
    .Depth     (Nodes)
  ) u_acc_ram (
    .clk_i,
    .wr_en_i  (acc_we),
    .wr_addr_i(r3_root_q),
    .wr_data_i(w_value),
    .rd_en_i  (acc_re),
    .rd_addr_i(acc_raddr),
    .rd_data_o(acc_rd)
  );

  // ---- registers ---------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      phase_q        <= PhInit;
      init_q         <= '0;
      in_frame_q     <= 1'b0;
      err_pending_q  <= 1'b0;
      err_frame_q    <= 1'b0;
      err_sticky_q   <= 1'b0;
      tile_ovf_q     <= 1'b0;
      obj_ovf_q      <= 1'b0;
      emitted_q      <= '0;
      s1_valid_q     <= 1'b0;
      s2_valid_q     <= 1'b0;
      left1_q        <= '0;
      has_last_q     <= 1'b0;
      fwd_valid_q    <= 1'b0;
      rfwd_valid_q   <= 1'b0;
      sweep_active_q <= 1'b0;
      r1_valid_q     <= 1'b0;
      r2_valid_q     <= 1'b0;
      r3_valid_q     <= 1'b0;
      e1_valid_q     <= 1'b0;
      out_valid_q    <= 1'b0;
    end else begin
      phase_q        <= phase_d;
      init_q         <= init_d;
      in_frame_q     <= in_frame_d;
      err_pending_q  <= err_pending_d;
      err_frame_q    <= err_frame_d;
      err_sticky_q   <= err_sticky_d;
      tile_ovf_q     <= tile_ovf_d;
      obj_ovf_q      <= obj_ovf_d;
      emitted_q      <= emitted_d;
      s1_valid_q     <= s1_valid_d;
      s2_valid_q     <= s2_valid_d;
      left1_q        <= left1_d;
      has_last_q     <= has_last_d;
      fwd_valid_q    <= fwd_valid_d;
      rfwd_valid_q   <= rfwd_valid_d;
      sweep_active_q <= sweep_active_d;
      r1_valid_q     <= r1_valid_d;
      r2_valid_q     <= r2_valid_d;
      r3_valid_q     <= r3_valid_d;
      e1_valid_q     <= e1_valid_d;
      out_valid_q    <= out_valid_d;
    end
  end

  // Labels per tile: one block per tile (no delayed array writes in a for loop), all cleared
  // when a frame's status word leaves.
  for (genvar t = 0; t < Tiles; t++) begin : gen_count
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        count_q[t] <= '0;
      end else if (count_clear) begin
        count_q[t] <= '0;
      end else if (count_inc && s1_tile_q == TileW'(t)) begin
        count_q[t] <= count_q[t] + 1'b1;
      end
    end
  end

  // Datapath registers: meaningful only under their valid bits.
  always_ff @(posedge clk_i) begin
    x_q           <= x_d;
    y_q           <= y_d;
    tx_q          <= tx_d;
    ty_q          <= ty_d;
    tcol_q        <= tcol_d;
    trow_q        <= trow_d;
    s1_d_q        <= s1_d_d;
    s1_x_q        <= s1_x_d;
    s1_y_q        <= s1_y_d;
    s1_tile_q     <= s1_tile_d;
    s1_has_left_q <= s1_has_left_d;
    s1_has_up_q   <= s1_has_up_d;
    s1_left_same_q <= s1_left_same_d;
    s1_up_same_q  <= s1_up_same_d;
    s2_node_q     <= s2_node_d;
    s2_init_q     <= s2_init_d;
    s2_x_q        <= s2_x_d;
    s2_y_q        <= s2_y_d;
    s2_d_q        <= s2_d_d;
    left_d_q      <= left_d_d;
    last_a_q      <= last_a_d;
    last_b_q      <= last_b_d;
    fwd_node_q    <= w_node;
    fwd_value_q   <= w_value;
    rfwd_node_q   <= r2_node_q;
    rfwd_root_q   <= r2_root;
    sweep_tile_q  <= sweep_tile_d;
    sweep_label_q <= sweep_label_d;
    r1_node_q     <= r1_node_d;
    r2_node_q     <= r2_node_d;
    r2_self_q     <= r2_self_d;
    r2_parent_q   <= r2_parent_d;
    r3_node_q     <= r3_node_d;
    r3_root_q     <= r3_root_d;
    e1_node_q     <= e1_node_d;
    if (out_load) begin
      out_data_q <= out_data_d;
      out_last_q <= out_last_d;
    end
  end
endmodule
