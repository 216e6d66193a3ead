// SPDX-License-Identifier: Apache-2.0
// Labelling: one lane, a strip of whole tile columns labelled one pixel per clock.
`default_nettype none

// The twin of hls::labelling::LabellingLane (hls/labelling/labelling_lane.hpp), clock for clock.
// A pixel moves one stage a clock:
//   P0     take the strip's next pixel, read the row buffer (the row above)
//   P1     9 d, 10 d, 11 d
//   P2     the row buffer's word through its output register; the joins with the left and the
//          upper neighbour, 9 d < 10 d_nb < 11 d (the thesis's 10 |d - d_nb| < d)
//   P3     decide the pixel's node (the left's, the upper's or a new one from the lane's pool);
//          write the row buffer; read the node's descriptor
//   P4     the edges to the other joined nodes (an edge equal to the last is dropped), queued
//          in P5; the descriptor read passes the RAM's output register, P5's forwarding chosen
//   P5     add the pixel to its node's descriptor (a pixel comes after every pixel already in
//          its node in raster order, so the first point stays and y_max is the pixel's row)
//   P6     write the descriptor back
//   merge  the union-find unit on the lane's edge queue, alongside
// The pixel's moments u^p v^q come from running sums stepped with the pixel counters (forward
// differences: additions only, no multiplier on the pixel path); its d^2 (for sum_dd) from one
// 15 x 15 product pipelined through P1 .. P3 (a DSP's A/B, M and P registers). A strip of 2 or
// 3 pixels has its upper neighbour still in P3 .. P6 when P0 reads the row buffer: P2 and P3
// take it from the last pixels' registers instead.
// Nodes are the stage's global numbers: lane i draws its nodes from i * LaneStride up, in the
// order its pixels need them, and keeps their parents and descriptors in its own banks, addressed
// by node - i * LaneStride (a power of two with lanes: the low bits). While !en_i (Init, Border, Resolve) the stage reaches the banks
// through the par_* and desc_* ports.
module scw_labelling_lane #(
  parameter int unsigned MaxWidthPx    = 32,
  parameter int unsigned MaxHeight     = 24,
  parameter int unsigned MaxTilesX     = 2,
  parameter int unsigned MaxTilesY     = 2,
  parameter int unsigned LabelsPerTile = 16,
  parameter int unsigned Lanes         = 1,
  parameter int unsigned Lane          = 0,
  parameter int unsigned EdgeQueue     = 16,  // the stage's: see scw_labelling
  parameter int unsigned TakeRoom      = 12,  // likewise
  // descriptor field widths (hls::labelling::DescWidths; scw_labelling passes its own, the
  // defaults are a 32 x 24 frame's)
  parameter int unsigned AreaW = 10,
  parameter int unsigned PosXW = 5,
  parameter int unsigned PosYW = 5,
  parameter int unsigned DispW = 15,
  parameter int unsigned M10W  = 14,
  parameter int unsigned M01W  = 14,
  parameter int unsigned M20W  = 18,
  parameter int unsigned M11W  = 18,
  parameter int unsigned M02W  = 18,
  parameter int unsigned M30W  = 23,
  parameter int unsigned M21W  = 22,
  parameter int unsigned M12W  = 22,
  parameter int unsigned M03W  = 22,
  parameter int unsigned SumDW = 25,
  parameter int unsigned SumDDW = 40,
  localparam int unsigned Nodes      = MaxTilesX * MaxTilesY * LabelsPerTile,
  localparam int unsigned LaneNodes  = Nodes / Lanes,
  localparam int unsigned LaneStride = (Lanes == 1) ? LaneNodes : (1 << $clog2(LaneNodes)),
  localparam int unsigned NodeSpace  = Lanes * LaneStride,  // node numbers (see scw_labelling)
  localparam int unsigned NodeW      = (NodeSpace > 1) ? $clog2(NodeSpace) : 1,
  localparam int unsigned N1W        = $clog2(NodeSpace + 1),  // node + 1, 0 = none
  localparam int unsigned PW         = NodeW + 1,  // a parent word {linked, parent}
  localparam int unsigned LNodeW     = (LaneStride > 1) ? $clog2(LaneStride) : 1,
  localparam int unsigned CntW       = $clog2(LaneNodes + 1),
  localparam int unsigned YW         = $clog2(MaxHeight + 1),
  localparam int unsigned DescW      = AreaW + 4 * PosXW + 4 * PosYW + 2 * DispW + M10W + M01W +
                                       M20W + M11W + M02W + M30W + M21W + M12W + M03W + SumDW +
                                       SumDDW
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic [15:0]       cfg_tile_w_i,
  input  logic [15:0]       cfg_tile_h_i,
  input  logic [15:0]       cfg_floor_i,
  input  logic [15:0]       x0_i,         // the strip: columns x0_i .. x0_i + width_i - 1
  input  logic [15:0]       width_i,
  input  logic              en_i,         // Frame, Drain: the pixel pipeline owns the banks
  input  logic              frame_end_i,  // the frame's status word left: back to the top left
  // the strip's pixels
  input  logic              take_i,
  input  logic [15:0]       d_i,
  output logic              can_take_o,
  output logic              idle_o,
  output logic              ovf_o,        // the lane ran out of labels this clock
  // the strip's first (left) and last (right) pixel of every row, {node + 1, d}
  output logic              left_we_o,
  output logic              right_we_o,
  output logic [YW-1:0]     border_row_o,
  output logic [N1W+15:0]   border_word_o,
  // the banks while !en_i, by global node: the lane whose node it is answers
  input  logic              init_i,        // Init: clear the parent bank at init_addr_i
  input  logic [LNodeW-1:0] init_addr_i,
  input  logic              par_re_i,
  input  logic [NodeW-1:0]  par_raddr_i,
  input  logic              par_we_i,
  input  logic [NodeW-1:0]  par_waddr_i,
  input  logic [PW-1:0]     par_wdata_i,
  output logic [PW-1:0]     par_rd_o,      // the word read last clock if this lane's, else 0
  // Border: the border merge unit's own read port into the parent bank (lanes only), read every
  // clock at the node's low bits; the stage picks the lane
  input  logic [LNodeW-1:0] bpar_raddr_i,
  output logic [PW-1:0]     bpar_rd_o,     // the word at last clock's bpar_raddr_i
  input  logic              desc_re_i,
  input  logic [NodeW-1:0]  desc_raddr_i,
  output logic [DescW-1:0]  desc_rd_o,     // likewise
  // labels the lane used this frame
  output logic [CntW-1:0]   count_o
);
  localparam int unsigned LaneWidthPx = MaxWidthPx / Lanes;
  localparam int unsigned XW     = (LaneWidthPx > 1) ? $clog2(LaneWidthPx) : 1;
  localparam int unsigned QCntW  = $clog2(EdgeQueue + 1);
  localparam logic [NodeW-1:0] First = NodeW'(Lane * LaneStride);  // the lane's first node

  // A global node's address in the lane's banks, and whether it is this lane's.
  /* verilator lint_off UNUSEDSIGNAL */  // the lane bits above LNodeW
  function automatic logic [LNodeW-1:0] to_local(input logic [NodeW-1:0] g);
    to_local = LNodeW'(g);  // (with lanes First is a multiple of 2^LNodeW)
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */
  function automatic logic owns(input logic [NodeW-1:0] g);
    owns = (Lanes == 1) || ((32'(g) >> LNodeW) == Lane);
  endfunction

  // ---- registers ---------------------------------------------------------------------------
  // the position of the pixel P0 takes next, within the strip
  logic [XW-1:0] x_q, x_d, tcol_q, tcol_d;
  logic [YW-1:0] y_q, y_d, trow_q, trow_d;
  // P1 .. P3: the pixel taken one .. three clocks ago
  logic p1_valid_q, p2_valid_q, p3_valid_q;
  logic [15:0] p1_d_q, p2_d_q, p3_d_q, p1_d_d;  // 0 when not an object pixel
  logic [XW-1:0] p1_x_q, p2_x_q, p3_x_q;
  logic p3_xlast_q;  // P3's pixel is the strip's last column (compared in P2)
  logic [YW-1:0] p1_y_q, p2_y_q, p3_y_q;
  logic p1_has_left_q, p1_has_up_q, p1_left_same_q, p1_up_same_q;
  logic p2_has_left_q, p2_has_up_q, p2_left_same_q, p2_up_same_q, p3_left_same_q, p3_up_same_q;
  logic p3_jl_q, p3_ju_q;  // the joins, before the neighbours' nodes are known
  logic p3_obj_q;          // an object pixel
  logic [19:0] p2_d9_q, p2_d10_q, p2_d11_q, p3_d10_q;
  // the last three pixels' 10 d through P2 (h10_1: the left neighbour's)
  logic [19:0] h10_1_q, h10_2_q, h10_3_q;
  // P3's upper neighbour from the row buffer, and the last three decided nodes (hist1 = left)
  logic [N1W-1:0] p3_up1_q, left1_q, hist2_q, hist3_q;
  logic p3_up_nz_q, left_nz_q, hist2_nz_q, hist3_nz_q;
  // their descriptors' addresses in the lane's bank (node - the lane's first - 1)
  logic [LNodeW-1:0] p3_up_a_q, left_a_q, hist2_a_q, hist3_a_q, up_a, desc_addr;
  // strips of 2 or 3 pixels (static while en_i)
  logic narrow2_q, narrow3_q;
  // the lane's node pool: labels used, the next node + 1, and whether none is left
  logic [CntW-1:0] count_q;
  logic [N1W-1:0] next1_q;
  logic full_q;
  // P4: the decided pixel's edges
  logic p4_valid_q, p4_want0_q, p4_want1_q, p4_up_left_q;
  logic [N1W-1:0] p4_node1_q, p4_left1_q, p4_up1_q;
  logic has_last_q, has_last_d, has_last;  // has_last: a copy without reset (see the stage's
                                           // phase flags)
  logic [N1W-1:0] last_a_q, last_a_d, last_b_q, last_b_d;
  // P4 .. P7: the decided pixel's descriptor (P7 only for forwarding)
  logic a4_valid_q, a4_init_q, a5_valid_q, a5_init_q, a6_valid_q, a7_valid_q;
  logic [LNodeW-1:0] a4_node_q, a5_node_q, a6_node_q, a7_node_q;

  // ---- RAM ports ---------------------------------------------------------------------------
  localparam int unsigned RowW = 20 + N1W;  // row buffer word {node + 1, 10 d}
  logic row_we;
  logic [RowW-1:0] row_wdata, row_rd, row_q;
  logic par_re, par_we;
  logic [LNodeW-1:0] par_raddr, par_waddr;
  logic [PW-1:0] par_wdata;
  logic desc_re;
  logic [LNodeW-1:0] desc_raddr;

  // ---- merge unit ----------------------------------------------------------------------------
  logic [QCntW-1:0] q_count;
  logic q_room;
  logic [1:0] push_n, q_push_n_q;
  logic [NodeW-1:0] push0_a, push0_b, push1_a, push1_b;
  logic [2*NodeW-1:0] q_push_a_q, q_push_b_q;
  logic uf_idle, uf_rd_en, uf_wr_en;
  logic [NodeW-1:0] uf_rd_addr, uf_wr_addr;
  logic [PW-1:0] uf_wr_data;


  scw_labelling_merge_unit #(
    .Nodes  (NodeSpace),
    .Depth  (EdgeQueue),
    .MaxPush(2),
    .Room   (TakeRoom)
  ) u_merge_unit (
    .clk_i,
    .rst_ni,
    .en_i,
    .push_n_i (q_push_n_q),
    .push_a_i (q_push_a_q),
    .push_b_i (q_push_b_q),
    .rd_data_i(par_rd),
    .count_o  (q_count),
    .room_o   (q_room),
    .idle_o   (uf_idle),
    .rd_en_o  (uf_rd_en),
    .rd_addr_o(uf_rd_addr),
    .wr_en_o  (uf_wr_en),
    .wr_addr_o(uf_wr_addr),
    .wr_data_o(uf_wr_data)
  );

  // A pixel taken now and the five before it (P1 .. P5) may each still queue two edges.
  assign can_take_o = q_room;
  assign idle_o     = !p1_valid_q && !p2_valid_q && !p3_valid_q && !p4_valid_q && !a5_valid_q &&
                      !a6_valid_q && (q_push_n_q == '0) && (q_count == '0) && uf_idle;

  // ---- P0: take a pixel, read the row buffer -----------------------------------------------
  logic x_wrap, tcol_wrap, trow_wrap, px_valid;
  // the last column of the strip and of a tile, the last row of a tile (static while en_i)
  logic [15:0] width_m1_q, tile_w_m1_q, tile_h_m1_q;

  assign x_wrap    = 16'(x_q) == width_m1_q;
  assign tcol_wrap = 16'(tcol_q) == tile_w_m1_q;
  assign trow_wrap = 16'(trow_q) == tile_h_m1_q;
  assign px_valid  = (d_i != 16'd0) && !d_i[15] && (d_i > cfg_floor_i);

  always_comb begin
    x_d    = x_q;
    y_d    = y_q;
    tcol_d = tcol_q;
    trow_d = trow_q;
    // While the stage is not labelling (Init, Border, Resolve) the next frame's first pixel.
    if (!en_i) begin
      x_d    = '0;
      y_d    = '0;
      tcol_d = '0;
      trow_d = '0;
    end else if (take_i) begin
      if (x_wrap) begin
        x_d    = '0;
        tcol_d = '0;
        y_d    = y_q + 1'b1;
        trow_d = trow_wrap ? '0 : trow_q + 1'b1;
      end else begin
        x_d    = x_q + 1'b1;
        tcol_d = tcol_wrap ? '0 : tcol_q + 1'b1;
      end
    end
  end

  assign p1_d_d = px_valid ? d_i : 16'd0;

  // ---- P1: the multiples of d the joins compare -------------------------------------------
  logic [19:0] p1_d8, p1_d10;

  assign p1_d8  = {1'b0, p1_d_q, 3'b000};
  assign p1_d10 = p1_d8 + {3'b000, p1_d_q, 1'b0};

  // ---- P2: the joins, 9 d < 10 d_nb < 11 d ------------------------------------------------
  logic [19:0] up10;
  logic [N1W-1:0] up1_ram;
  logic join_left, join_up;

  assign up1_ram   = row_q[RowW-1:20];
  assign up10      = narrow2_q ? h10_2_q : (narrow3_q ? h10_3_q : row_q[19:0]);
  assign join_left = (h10_1_q > p2_d9_q) && (h10_1_q < p2_d11_q);
  assign join_up   = (up10 > p2_d9_q) && (up10 < p2_d11_q);

  // ---- P3: decide the pixel's node ---------------------------------------------------------
  logic [N1W-1:0] up1, node1;
  logic p3_px, up_nz, jl, ju, use_left, use_up, alloc, node_nz, eq_ul;

  assign p3_px    = p3_valid_q && p3_obj_q;
  assign eq_ul    = up1 == left1_q;
  assign up1      = narrow2_q ? hist2_q : (narrow3_q ? hist3_q : p3_up1_q);
  assign up_nz    = narrow2_q ? hist2_nz_q : (narrow3_q ? hist3_nz_q : p3_up_nz_q);
  assign jl       = p3_jl_q && left_nz_q;  // P2 checked the pixel and its left neighbour
  assign ju       = p3_ju_q && up_nz;
  assign use_left = jl && p3_left_same_q;
  assign use_up   = ju && p3_up_same_q && !use_left;
  assign alloc    = p3_px && !use_left && !use_up && !full_q;
  assign ovf_o    = p3_px && !use_left && !use_up && full_q;
  assign node_nz  = use_left || use_up || alloc;
  assign node1    = use_left ? left1_q : (use_up ? up1 : (alloc ? next1_q : '0));
  assign up_a      = narrow2_q ? hist2_a_q : (narrow3_q ? hist3_a_q : p3_up_a_q);
  assign desc_addr = use_left ? left_a_q : (use_up ? up_a : LNodeW'(count_q));

  assign row_we    = p3_valid_q;
  assign row_wdata = {node1, p3_d10_q};

  // The strip's edge columns, for the join across strip borders after the frame.
  assign left_we_o     = (Lane > 0) && p3_valid_q && (p3_x_q == '0);
  assign right_we_o    = (Lane + 1 < Lanes) && p3_valid_q && p3_xlast_q;
  assign border_row_o  = p3_y_q;
  assign border_word_o = {node1, p3_d_q};

  // ---- P4: the edges {from, node}; one equal to the edge queued just before is dropped ------
  // (P3 compared the pixel's nodes: want0, want1 and whether both edges are one, up == left)
  logic push0, push1, eq0, eq1;

  assign eq0     = has_last && (p4_left1_q == last_a_q) && (p4_node1_q == last_b_q);
  assign eq1     = has_last && (p4_up1_q == last_a_q) && (p4_node1_q == last_b_q);
  assign push0   = p4_valid_q && p4_want0_q && !eq0;
  assign push1   = p4_valid_q && p4_want1_q && !(push0 ? p4_up_left_q : eq1);
  assign push_n  = {1'b0, push0} + {1'b0, push1};
  // (both decrements stand beside the duplicate check; push0 only picks one)
  assign push0_a = push0 ? NodeW'(p4_left1_q - 1'b1) : push1_a;
  assign push0_b = NodeW'(p4_node1_q - 1'b1);
  assign push1_a = NodeW'(p4_up1_q - 1'b1);
  assign push1_b = push0_b;

  always_comb begin
    has_last_d = has_last_q;
    last_a_d   = last_a_q;
    last_b_d   = last_b_q;
    if (push1) begin
      has_last_d = 1'b1;
      last_a_d   = p4_up1_q;
      last_b_d   = p4_node1_q;
    end else if (push0) begin
      has_last_d = 1'b1;
      last_a_d   = p4_left1_q;
      last_b_d   = p4_node1_q;
    end
    if (frame_end_i) has_last_d = 1'b0;
  end

  // ---- the pixel's moments: running sums stepped with S0's counters -------------------------
  // For the pixel S0 takes next, (u, v) = (x0 + x, y): u, v and u^p v^q; along a row the
  // forward differences d2 = 2u + 1, d3 = 3u^2 + 3u + 1, dd3 = 6u + 6, d21 = (2u + 1) v step
  // them; at a row's end they restart from the strip's first column (x0: constants of the
  // configuration, multiplied out once while the stage is not labelling), the row's own
  // (x0 v, x0^2 v, (2 x0 + 1) v, x0 v^2, x0 (2 v + 1)) stepped by one row. While !en_i they hold
  // the frame's first pixel. Sums wrap at their widths, which hold every true value, so they
  // stay exact.
  localparam int unsigned SqW  = 2 * PosXW;  // x0^2 < 2^SqW (and SqW <= M20W: (W-1)^2 <= S2(W))
  localparam int unsigned D2W  = PosXW + 1;
  localparam int unsigned D3W  = 2 * PosXW + 2;
  localparam int unsigned DD3W = PosXW + 3;
  localparam int unsigned D21W = PosXW + PosYW + 1;
  localparam int unsigned E2W  = PosYW + 1;
  localparam int unsigned E3W  = 2 * PosYW + 2;
  localparam int unsigned EE3W = PosYW + 3;

  // the strip's first column and its powers; x0_i is static while en_i
  // (each product through the DSP's A/B, M and P registers and one more; 8 clocks in all)
  logic [PosXW-1:0] c_x0_q, c_a_q, c_b_q;
  logic [M20W-1:0] c_sq_m_q, c_sq_p_q, c_sq_q;
  logic [M30W-1:0] c_cu_m_q, c_cu_p_q, c_cu_q;
  logic [SqW-1:0] c_sq_b_q;  // at its width: the cube is one DSP (22 x 11 bits at 1280 px)
  logic [D2W-1:0] c_d2_q;
  logic [D3W-1:0] c_d3_q, c_3sq_q, c_3x1_q;
  logic [DD3W-1:0] c_dd3_q;

  always_ff @(posedge clk_i) begin
    c_x0_q   <= PosXW'(x0_i);
    c_a_q    <= c_x0_q;
    c_sq_m_q <= M20W'(c_a_q) * M20W'(c_a_q);
    c_sq_p_q <= c_sq_m_q;
    c_sq_q   <= c_sq_p_q;
    c_sq_b_q <= SqW'(c_sq_q);
    c_b_q    <= c_x0_q;
    c_cu_m_q <= M30W'(c_sq_b_q) * M30W'(c_b_q);
    c_cu_p_q <= c_cu_m_q;
    c_cu_q   <= c_cu_p_q;
    c_d2_q   <= D2W'({c_x0_q, 1'b1});
    c_3sq_q  <= D3W'(c_sq_q) + D3W'({c_sq_q, 1'b0});
    c_3x1_q  <= D3W'(c_x0_q) + D3W'({c_x0_q, 1'b0}) + D3W'(1);
    c_d3_q   <= c_3sq_q + c_3x1_q;
    c_dd3_q  <= DD3W'({c_x0_q, 2'b00}) + DD3W'({c_x0_q, 1'b0}) + DD3W'(6);
  end

  // running sums of the next pixel
  logic [PosXW-1:0] g_u_q;
  logic [PosYW-1:0] g_v_q;
  logic [M20W-1:0] g_u2_q;
  logic [M11W-1:0] g_uv_q;
  logic [M02W-1:0] g_v2_q;
  logic [M30W-1:0] g_u3_q;
  logic [M21W-1:0] g_u2v_q;
  logic [M12W-1:0] g_uv2_q;
  logic [M03W-1:0] g_v3_q;
  logic [D2W-1:0] g_d2_q;
  logic [D3W-1:0] g_d3_q;
  logic [DD3W-1:0] g_dd3_q;
  logic [D21W-1:0] g_d21_q;
  logic [E2W-1:0] g_e2_q;
  logic [E3W-1:0] g_e3_q;
  logic [EE3W-1:0] g_ee3_q;
  // the row's start
  logic [M11W-1:0] r_uv_q, r_uv_n;
  logic [M21W-1:0] r_u2v_q, r_u2v_n;
  logic [D21W-1:0] r_d21_q, r_d21_n;
  logic [M12W-1:0] r_uv2_q, r_uv2_n;
  logic [D21W-1:0] r_x0e2_q;

  assign r_uv_n  = r_uv_q + M11W'(c_x0_q);
  assign r_u2v_n = r_u2v_q + M21W'(c_sq_q);
  assign r_d21_n = r_d21_q + D21W'(c_d2_q);
  assign r_uv2_n = r_uv2_q + M12W'(r_x0e2_q);

  always_ff @(posedge clk_i) begin
    if (!en_i) begin
      g_u_q    <= c_x0_q;
      g_v_q    <= '0;
      g_u2_q   <= c_sq_q;
      g_uv_q   <= '0;
      g_v2_q   <= '0;
      g_u3_q   <= c_cu_q;
      g_u2v_q  <= '0;
      g_uv2_q  <= '0;
      g_v3_q   <= '0;
      g_d2_q   <= c_d2_q;
      g_d3_q   <= c_d3_q;
      g_dd3_q  <= c_dd3_q;
      g_d21_q  <= '0;
      g_e2_q   <= E2W'(1);
      g_e3_q   <= E3W'(1);
      g_ee3_q  <= EE3W'(6);
      r_uv_q   <= '0;
      r_u2v_q  <= '0;
      r_d21_q  <= '0;
      r_uv2_q  <= '0;
      r_x0e2_q <= D21W'(c_x0_q);
    end else if (take_i) begin
      if (x_wrap) begin  // the next row's first pixel
        g_u_q    <= c_x0_q;
        g_v_q    <= g_v_q + 1'b1;
        g_u2_q   <= c_sq_q;
        g_u3_q   <= c_cu_q;
        g_d2_q   <= c_d2_q;
        g_d3_q   <= c_d3_q;
        g_dd3_q  <= c_dd3_q;
        g_v2_q   <= g_v2_q + M02W'(g_e2_q);
        g_e2_q   <= g_e2_q + E2W'(2);
        g_v3_q   <= g_v3_q + M03W'(g_e3_q);
        g_e3_q   <= g_e3_q + E3W'(g_ee3_q);
        g_ee3_q  <= g_ee3_q + EE3W'(6);
        g_uv_q   <= r_uv_n;
        r_uv_q   <= r_uv_n;
        g_u2v_q  <= r_u2v_n;
        r_u2v_q  <= r_u2v_n;
        g_d21_q  <= r_d21_n;
        r_d21_q  <= r_d21_n;
        g_uv2_q  <= r_uv2_n;
        r_uv2_q  <= r_uv2_n;
        r_x0e2_q <= r_x0e2_q + D21W'({c_x0_q, 1'b0});
      end else begin     // the next column
        g_u_q   <= g_u_q + 1'b1;
        g_u2_q  <= g_u2_q + M20W'(g_d2_q);
        g_d2_q  <= g_d2_q + D2W'(2);
        g_u3_q  <= g_u3_q + M30W'(g_d3_q);
        g_d3_q  <= g_d3_q + D3W'(g_dd3_q);
        g_dd3_q <= g_dd3_q + DD3W'(6);
        g_uv_q  <= g_uv_q + M11W'(g_v_q);
        g_u2v_q <= g_u2v_q + M21W'(g_d21_q);
        g_d21_q <= g_d21_q + D21W'({g_v_q, 1'b0});
        g_uv2_q <= g_uv2_q + M12W'(g_v2_q);
      end
    end
  end

  // ---- P4 .. P6: desc[node] = the pixel (a new label) or desc[node] + the pixel -------------
  typedef struct packed {
    logic [SumDDW-1:0] sum_dd;
    logic [SumDW-1:0]  sum_d;
    logic [M03W-1:0]  m03;
    logic [M12W-1:0]  m12;
    logic [M21W-1:0]  m21;
    logic [M30W-1:0]  m30;
    logic [M02W-1:0]  m02;
    logic [M11W-1:0]  m11;
    logic [M20W-1:0]  m20;
    logic [M01W-1:0]  m01;
    logic [M10W-1:0]  m10;
    logic [PosYW-1:0] first_y;
    logic [PosXW-1:0] first_x;
    logic [PosYW-1:0] closest_y;
    logic [PosXW-1:0] closest_x;
    logic [DispW-1:0] d_max;
    logic [DispW-1:0] d_min;
    logic [PosYW-1:0] y_max;
    logic [PosYW-1:0] y_min;
    logic [PosXW-1:0] x_max;
    logic [PosXW-1:0] x_min;
    logic [AreaW-1:0] area;
  } desc_t;
  // The pixel: its coordinates, disparity and moments (its descriptor's fields) per stage.
  typedef struct packed {
    logic [M03W-1:0]  v3;
    logic [M12W-1:0]  uv2;
    logic [M21W-1:0]  u2v;
    logic [M30W-1:0]  u3;
    logic [M02W-1:0]  v2;
    logic [M11W-1:0]  uv;
    logic [M20W-1:0]  u2;
    logic [PosYW-1:0] v;
    logic [PosXW-1:0] u;
    logic [DispW-1:0] d;
  } px_t;

  px_t p1_px_q, p2_px_q, p3_px_q, a4_px_q, a5_px_q;
  // The pixel's d^2 (< 2^30: d < 0x8000), a 15 x 15 product in a DSP's A/B (P1), M (P2) and P
  // (P3) registers, then on with the pixel (P4, P5).
  localparam int unsigned DDW = 2 * DispW;
  logic [DispW-1:0] dd_a_q;
  logic [DDW-1:0] dd_m_q, dd_p_q, a4_dd_q, a5_dd_q;
  desc_t desc_rd, ram_q, res_q, res2_q, old_q, old_d, base, v;
  logic m1_q, m1_d, old_hit_q, old_hit_d, a6_match, a7_match, a_closest;

  // P4: where P5 finds the node's descriptor: the result P5 computes now (m1), the results of the
  // two clocks before (written after P3's read: old_q), the RAM, or none (a new label).
  assign a6_match  = a6_valid_q && (a6_node_q == a4_node_q);
  assign a7_match  = a7_valid_q && (a7_node_q == a4_node_q);
  assign m1_d      = a5_valid_q && (a5_node_q == a4_node_q) && !a4_init_q;
  assign old_hit_d = a4_init_q || a6_match || a7_match;
  assign old_d     = a4_init_q ? '0 : (a6_match ? res_q : res2_q);

  // P5: the sum. A new label adds to zeros (old_q) and takes the pixel's min, max and points.
  assign base      = m1_q ? res_q : (old_hit_q ? old_q : ram_q);
  assign a_closest = base.d_max >= a5_px_q.d;
  always_comb begin
    v.area      = base.area + 1'b1;
    v.x_min     = (a5_init_q || a5_px_q.u < base.x_min) ? a5_px_q.u : base.x_min;
    v.x_max     = (a5_init_q || a5_px_q.u > base.x_max) ? a5_px_q.u : base.x_max;
    v.y_min     = a5_init_q ? a5_px_q.v : base.y_min;
    v.y_max     = a5_px_q.v;
    v.d_min     = (a5_init_q || a5_px_q.d < base.d_min) ? a5_px_q.d : base.d_min;
    v.d_max     = (a5_init_q || !a_closest) ? a5_px_q.d : base.d_max;
    v.closest_x = (a5_init_q || !a_closest) ? a5_px_q.u : base.closest_x;
    v.closest_y = (a5_init_q || !a_closest) ? a5_px_q.v : base.closest_y;
    v.first_x   = a5_init_q ? a5_px_q.u : base.first_x;
    v.first_y   = a5_init_q ? a5_px_q.v : base.first_y;
    v.m10       = base.m10 + M10W'(a5_px_q.u);
    v.m01       = base.m01 + M01W'(a5_px_q.v);
    v.m20       = base.m20 + M20W'(a5_px_q.u2);
    v.m11       = base.m11 + M11W'(a5_px_q.uv);
    v.m02       = base.m02 + M02W'(a5_px_q.v2);
    v.m30       = base.m30 + M30W'(a5_px_q.u3);
    v.m21       = base.m21 + M21W'(a5_px_q.u2v);
    v.m12       = base.m12 + M12W'(a5_px_q.uv2);
    v.m03       = base.m03 + M03W'(a5_px_q.v3);
    v.sum_d     = base.sum_d + SumDW'(a5_px_q.d);
    v.sum_dd    = base.sum_dd + SumDDW'(a5_dd_q);
  end

  // A pixel is the last of its node in raster order: the old y_max is never needed. The strip's
  // first column is below MaxWidthPx.
  logic unused_px;
  assign unused_px = ^{base.y_max, x0_i};

  // Datapath registers of P1 .. P7 (meaningful under their valid bits).
  always_ff @(posedge clk_i) begin
    // (each stage loads under the valid bit of the one before: no chain of shift registers)
    if (take_i) begin
      p1_px_q <= {g_v3_q, g_uv2_q, g_u2v_q, g_u3_q, g_v2_q, g_uv_q, g_u2_q, g_v_q, g_u_q,
                  DispW'(p1_d_d)};
      dd_a_q  <= DispW'(p1_d_d);
    end
    if (p1_valid_q) begin
      p2_px_q <= p1_px_q;
      dd_m_q  <= DDW'(dd_a_q) * DDW'(dd_a_q);
    end
    if (p2_valid_q) begin
      p3_px_q <= p2_px_q;
      dd_p_q  <= dd_m_q;
    end
    if (p3_valid_q) begin
      a4_px_q <= p3_px_q;
      a4_dd_q <= dd_p_q;
    end
    if (a4_valid_q) begin
      a5_px_q <= a4_px_q;
      a5_dd_q <= a4_dd_q;
    end
    ram_q     <= desc_rd;
    m1_q      <= m1_d;
    old_hit_q <= old_hit_d;
    old_q     <= old_d;
    if (a4_valid_q) begin
      a5_node_q <= a4_node_q;
      a5_init_q <= a4_init_q;
    end
    res_q     <= v;
    if (a5_valid_q) a6_node_q <= a5_node_q;
    res2_q    <= res_q;
    a7_node_q <= a6_node_q;
  end

  // ---- the banks: the pixel pipeline's ports while en_i, the stage's otherwise -------------
  logic par_mine_q, desc_mine_q;
  logic [PW-1:0] par_rd;

  always_comb begin
    par_re     = par_re_i && owns(par_raddr_i);
    par_raddr  = to_local(par_raddr_i);
    par_we     = par_we_i && owns(par_waddr_i);
    par_waddr  = to_local(par_waddr_i);
    par_wdata  = par_wdata_i;
    desc_re    = desc_re_i && owns(desc_raddr_i);
    desc_raddr = to_local(desc_raddr_i);
    if (en_i) begin
      par_re     = uf_rd_en;
      par_raddr  = to_local(uf_rd_addr);
      par_we     = uf_wr_en;
      par_waddr  = to_local(uf_wr_addr);
      par_wdata  = uf_wr_data;
      desc_re    = p3_valid_q && node_nz;
      desc_raddr = desc_addr;
    end else if (init_i) begin
      par_we    = 1'b1;
      par_waddr = init_addr_i;
      par_wdata = '0;
    end
  end

  // The stage ORs the lanes' answers: only the lane that was read answers.
  assign par_rd_o  = par_mine_q ? par_rd : '0;
  assign desc_rd_o = desc_mine_q ? desc_rd : '0;
  assign count_o   = count_q;

  scw_ram_sdp #(.Width(RowW), .Depth(LaneWidthPx)) u_row_ram (
    .clk_i,
    .wr_en_i  (row_we),
    .wr_addr_i(p3_x_q),
    .wr_data_i(row_wdata),
    .rd_en_i  (take_i),
    .rd_addr_i(x_q),
    .rd_data_o(row_rd)
  );

  // The parent bank in distributed RAM: the union-find's next address follows from the word
  // read the clock before, which a block RAM's 2.5 ns clock-to-output leaves no time for.
  (* ram_style = "distributed" *) logic [PW-1:0] par_mem_q [LaneStride];
  always_ff @(posedge clk_i) begin
    if (par_we) par_mem_q[par_waddr] <= par_wdata;
  end
  always_ff @(posedge clk_i) begin
    if (par_re) par_rd <= par_mem_q[par_raddr];
  end
  // The border merge unit's loop across the lanes closes only without the port multiplexers
  // between its next address and the bank (a distributed RAM's extra read port costs little).
  if (Lanes > 1) begin : gen_bpar
    always_ff @(posedge clk_i) bpar_rd_o <= par_mem_q[bpar_raddr_i];
  end else begin : gen_no_bpar
    assign bpar_rd_o = '0;
    logic unused_bpar;
    assign unused_bpar = ^bpar_raddr_i;
  end

  scw_labelling_desc_ram #(.DescW(DescW), .Depth(LaneStride)) u_desc_ram (
    .clk_i,
    .wr_en_i  (en_i && a6_valid_q),
    .wr_addr_i(a6_node_q),
    .wr_data_i(res_q),
    .rd_en_i  (desc_re),
    .rd_addr_i(desc_raddr),
    .rd_next_i(1'b1),
    .rd_data_o(desc_rd)
  );

  // ---- registers ---------------------------------------------------------------------------
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      p1_valid_q  <= 1'b0;
      p2_valid_q  <= 1'b0;
      p3_valid_q  <= 1'b0;
      p4_valid_q  <= 1'b0;
      a4_valid_q  <= 1'b0;
      a5_valid_q  <= 1'b0;
      a6_valid_q  <= 1'b0;
      a7_valid_q  <= 1'b0;
      has_last_q  <= 1'b0;
      q_push_n_q  <= '0;
      count_q     <= '0;
      next1_q     <= N1W'(First) + 1'b1;
      full_q      <= 1'b0;
      par_mine_q  <= 1'b0;
      desc_mine_q <= 1'b0;
    end else begin
      p1_valid_q  <= take_i;
      p2_valid_q  <= p1_valid_q;
      p3_valid_q  <= p2_valid_q;
      p4_valid_q  <= p3_valid_q;
      a4_valid_q  <= p3_valid_q && node_nz;
      a5_valid_q  <= a4_valid_q;
      a6_valid_q  <= a5_valid_q;
      a7_valid_q  <= a6_valid_q;
      has_last_q  <= has_last_d;
      q_push_n_q  <= push_n;  // P5 queues them
      // the pool, refilled when a frame's status word leaves
      if (frame_end_i) begin
        count_q <= '0;
        next1_q <= N1W'(First) + 1'b1;
        full_q  <= 1'b0;
      end else if (alloc) begin
        count_q <= count_q + 1'b1;
        next1_q <= next1_q + 1'b1;
        full_q  <= count_q == CntW'(LaneNodes - 1);
      end
      par_mine_q  <= !en_i && par_re;
      desc_mine_q <= !en_i && desc_re;
    end
  end

  // Datapath registers: meaningful only under their valid bits (the position restarts while
  // !en_i, before every frame).
  always_ff @(posedge clk_i) begin
    x_q            <= x_d;
    y_q            <= y_d;
    tcol_q         <= tcol_d;
    trow_q         <= trow_d;
    width_m1_q     <= width_i - 1'b1;
    tile_w_m1_q    <= cfg_tile_w_i - 1'b1;
    tile_h_m1_q    <= cfg_tile_h_i - 1'b1;
    if (take_i) begin
      p1_d_q         <= p1_d_d;
      p1_x_q         <= x_q;
      p1_y_q         <= y_q;
      p1_has_left_q  <= x_q != '0;
      p1_has_up_q    <= y_q != '0;
      p1_left_same_q <= tcol_q != '0;
      p1_up_same_q   <= trow_q != '0;
    end
    if (p1_valid_q) begin
      p2_d_q         <= p1_d_q;
      p2_x_q         <= p1_x_q;
      p2_y_q         <= p1_y_q;
      p2_has_left_q  <= p1_has_left_q;
      p2_has_up_q    <= p1_has_up_q;
      p2_left_same_q <= p1_left_same_q;
      p2_up_same_q   <= p1_up_same_q;
      p2_d9_q        <= p1_d8 + {4'b0000, p1_d_q};
      p2_d10_q       <= p1_d10;
      p2_d11_q       <= p1_d10 + {4'b0000, p1_d_q};
    end
    row_q          <= row_rd;
    if (p2_valid_q) begin
      h10_1_q <= p2_d10_q;
      h10_2_q <= h10_1_q;
      h10_3_q <= h10_2_q;
    end
    if (p2_valid_q) begin
      p3_d_q         <= p2_d_q;
      p3_obj_q       <= p2_d_q != 16'd0;
      p3_x_q         <= p2_x_q;
      p3_xlast_q     <= 16'(p2_x_q) == width_m1_q;  // (width_i holds while pixels flow)
      p3_y_q         <= p2_y_q;
      p3_left_same_q <= p2_left_same_q;
      p3_up_same_q   <= p2_up_same_q;
      p3_jl_q        <= (p2_d_q != 16'd0) && p2_has_left_q && join_left;
      p3_ju_q        <= (p2_d_q != 16'd0) && p2_has_up_q && join_up;
      p3_d10_q       <= p2_d10_q;
      p3_up1_q       <= up1_ram;
      p3_up_nz_q     <= up1_ram != '0;
      p3_up_a_q      <= LNodeW'(up1_ram - 1'b1);  // (First is a multiple of 2^LNodeW)
    end
    // an edge for each joined neighbour whose node is not the pixel's (a new node is no one's)
    p4_want0_q     <= jl && !use_left && (alloc || (use_up && !eq_ul));
    p4_want1_q     <= ju && !use_up && (alloc || (use_left && !eq_ul));
    p4_up_left_q   <= eq_ul;
    p4_node1_q     <= node1;
    p4_left1_q     <= left1_q;
    p4_up1_q       <= up1;
    if (p3_valid_q) begin
      a4_node_q <= desc_addr;
      a4_init_q <= alloc;
    end
    q_push_a_q     <= {push1_a, push0_a};
    q_push_b_q     <= {push1_b, push0_b};
    has_last       <= has_last_d;  // (reset holds has_last_d at 0: no edge while !en_i)
    last_a_q       <= last_a_d;
    last_b_q       <= last_b_d;
    // The decided pixel is the next one's left neighbour (a strip's first pixel has none, and
    // its first row no upper one, so these need no reset).
    if (p3_valid_q) begin
      left1_q    <= node1;
      left_nz_q  <= node_nz;
      left_a_q   <= desc_addr;
      hist2_q    <= left1_q;
      hist2_nz_q <= left_nz_q;
      hist2_a_q  <= left_a_q;
      hist3_q    <= hist2_q;
      hist3_nz_q <= hist2_nz_q;
      hist3_a_q  <= hist2_a_q;
    end
    narrow2_q      <= width_i == 16'd2;
    narrow3_q      <= width_i == 16'd3;
  end
endmodule
