// SPDX-License-Identifier: Apache-2.0
// Labelling: one lane, a strip of whole tile columns labelled one pixel per clock.
`default_nettype none

// The twin of hls::labelling::LabellingLane (hls/labelling/labelling_lane.hpp), clock for clock:
//   S0     take the strip's next pixel, read the row buffer
//   S1     decide the pixel's node (its tile's label table) and queue edges to other nodes
//   S2     add the pixel to its node's descriptor
//   merge  the union-find unit on the lane's edge queue, alongside
// Nodes are the stage's global numbers (node = tile * LabelsPerTile + label, the tile global),
// so the words leave in a one-lane stage's order. With Lanes > 1, MaxTilesX and LabelsPerTile
// are powers of two and a node's lane is a bit field: global {ty, lane, tx, label}, the lane's
// parent and descriptor banks addressed by the rest, {ty, tx, label}. While !en_i (Init,
// Border, Resolve) the stage reaches the banks through the par_* and desc_* ports.
module scw_labelling_lane #(
  parameter int unsigned MaxWidthPx    = 32,
  parameter int unsigned MaxHeight     = 24,
  parameter int unsigned MaxTilesX     = 2,
  parameter int unsigned MaxTilesY     = 2,
  parameter int unsigned LabelsPerTile = 16,
  parameter int unsigned Lanes         = 1,
  parameter int unsigned Lane          = 0,
  parameter int unsigned EdgeQueue     = 8,  // the stage's: see scw_labelling
  localparam int unsigned Tiles      = MaxTilesX * MaxTilesY,
  localparam int unsigned Nodes      = Tiles * LabelsPerTile,
  localparam int unsigned LaneTilesX = MaxTilesX / Lanes,
  localparam int unsigned LaneTiles  = LaneTilesX * MaxTilesY,
  localparam int unsigned LaneNodes  = LaneTiles * LabelsPerTile,
  localparam int unsigned NodeW      = (Nodes > 1) ? $clog2(Nodes) : 1,
  localparam int unsigned N1W        = $clog2(Nodes + 1),  // node + 1, 0 = none
  localparam int unsigned LNodeW     = (LaneNodes > 1) ? $clog2(LaneNodes) : 1,
  localparam int unsigned LTileW     = (LaneTiles > 1) ? $clog2(LaneTiles) : 1,
  localparam int unsigned TileW      = (Tiles > 1) ? $clog2(Tiles) : 1,
  localparam int unsigned CntW       = $clog2(LabelsPerTile + 1),
  localparam int unsigned YW         = $clog2(MaxHeight + 1),
  localparam int unsigned DescW      = 32 + 10 * 16 + 9 * 64
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
  output logic              ovf_o,        // a tile ran out of labels this clock
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
  input  logic [N1W-1:0]    par_wdata_i,
  output logic [N1W-1:0]    par_rd_o,      // the word read last clock if this lane's, else 0
  input  logic              desc_re_i,
  input  logic [NodeW-1:0]  desc_raddr_i,
  output logic [DescW-1:0]  desc_rd_o,     // likewise
  // labels used in a tile (global), 0 if not this lane's
  input  logic [TileW-1:0]  count_tile_i,
  output logic [CntW-1:0]   count_o
);
  localparam int unsigned LaneWidthPx = MaxWidthPx / Lanes;
  localparam int unsigned XW     = (LaneWidthPx > 1) ? $clog2(LaneWidthPx) : 1;
  localparam int unsigned GXW    = $clog2(MaxWidthPx);    // a global column
  localparam int unsigned TXW    = (LaneTilesX > 1) ? $clog2(LaneTilesX) : 1;
  localparam int unsigned TYW    = $clog2(MaxTilesY + 1);
  localparam int unsigned QCntW  = $clog2(EdgeQueue + 1);
  localparam int unsigned RowW   = 16 + N1W;               // row buffer word {node + 1, d}
  // The lane's bit field in a node: LaneLo bits below it, LaneB bits wide (none for one lane,
  // where a lane's numbers are the global ones).
  localparam int unsigned LaneB  = $clog2(Lanes);
  localparam int unsigned LaneLo = $clog2(LaneTilesX * LabelsPerTile);
  localparam logic [NodeW-1:0] LoMask = NodeW'((64'd1 << LaneLo) - 64'd1);
  localparam logic [NodeW-1:0] LaneBits = NodeW'(64'(Lane) << LaneLo);
  localparam logic [LNodeW-1:0] LabelsL = LNodeW'(LabelsPerTile);
  localparam logic [LTileW-1:0] TilesXL = LTileW'(LaneTilesX);

  // A global node's address in its lane's banks, a bank address's global node, and whether a
  // node or a tile is this lane's (every one is, with one lane).
  localparam int unsigned LaneLoT = $clog2(LaneTilesX);
  localparam logic [TileW-1:0] LoMaskT = TileW'((64'd1 << LaneLoT) - 64'd1);
  function automatic logic [LNodeW-1:0] to_local(input logic [NodeW-1:0] g);
    to_local = LNodeW'(((g >> (LaneLo + LaneB)) << LaneLo) | (g & LoMask));
  endfunction
  function automatic logic [NodeW-1:0] to_global(input logic [LNodeW-1:0] l);
    logic [NodeW-1:0] w;
    w         = NodeW'(l);
    to_global = ((w >> LaneLo) << (LaneLo + LaneB)) | LaneBits | (w & LoMask);
  endfunction
  function automatic logic owns(input logic [NodeW-1:0] g);
    owns = (Lanes == 1) || (((g >> LaneLo) & NodeW'(Lanes - 1)) == NodeW'(Lane));
  endfunction
  function automatic logic owns_tile(input logic [TileW-1:0] t);
    owns_tile = (Lanes == 1) || (((t >> LaneLoT) & TileW'(Lanes - 1)) == TileW'(Lane));
  endfunction
  function automatic logic [LTileW-1:0] to_local_tile(input logic [TileW-1:0] t);
    to_local_tile = LTileW'(((t >> (LaneLoT + LaneB)) << LaneLoT) | (t & LoMaskT));
  endfunction

  // ---- registers ---------------------------------------------------------------------------
  // the position of the pixel S0 takes next, within the strip
  logic [XW-1:0] x_q, x_d, tcol_q, tcol_d;
  logic [YW-1:0] y_q, y_d, trow_q, trow_d;
  logic [TXW-1:0] tx_q, tx_d;
  logic [TYW-1:0] ty_q, ty_d;
  // S1: the pixel S0 took last clock
  logic s1_valid_q;
  logic [15:0] s1_d_q, s1_d_d;  // 0 when not an object pixel
  logic [XW-1:0] s1_x_q;
  logic [YW-1:0] s1_y_q;
  logic [LTileW-1:0] s1_tile_q, s1_tile_d;
  logic s1_has_left_q, s1_has_up_q, s1_left_same_q, s1_up_same_q;
  // S2: the pixel S1 decided last clock
  logic s2_valid_q, s2_valid_d, s2_init_q;
  logic [NodeW-1:0] s2_node_q;
  logic [XW-1:0] s2_x_q;
  logic [YW-1:0] s2_y_q;
  logic [15:0] s2_d_q;
  // S2's write of last clock, for the read issued alongside it
  logic fwd_valid_q;
  logic [NodeW-1:0] fwd_node_q;
  logic [DescW-1:0] fwd_value_q;
  // the left neighbour and the edge queued last
  logic [15:0] left_d_q, left_d_d;
  logic [N1W-1:0] left1_q, left1_d;
  logic has_last_q, has_last_d;
  logic [NodeW-1:0] last_a_q, last_a_d, last_b_q, last_b_d;
  // labels used per tile of the strip
  logic [CntW-1:0] count_q [LaneTiles];

  // ---- RAM ports ---------------------------------------------------------------------------
  logic row_we;
  logic [RowW-1:0] row_wdata, row_rd;
  logic par_re, par_we;
  logic [LNodeW-1:0] par_raddr, par_waddr;
  logic [N1W-1:0] par_wdata;
  logic desc_re;
  logic [LNodeW-1:0] desc_raddr;

  // ---- merge unit ----------------------------------------------------------------------------
  logic [QCntW-1:0] q_count;
  logic [1:0] push_n;
  logic [NodeW-1:0] push0_a, push0_b, push1_a, push1_b;
  logic uf_idle, uf_rd_en, uf_wr_en;
  logic [NodeW-1:0] uf_rd_addr, uf_wr_addr;
  logic [N1W-1:0] uf_wr_data;
  logic [2*NodeW-1:0] push_a, push_b;

  assign push_a = {push1_a, push0_a};
  assign push_b = {push1_b, push0_b};

  scw_labelling_merge_unit #(.Nodes(Nodes), .Depth(EdgeQueue), .MaxPush(2)) u_merge_unit (
    .clk_i,
    .rst_ni,
    .en_i,
    .push_n_i (push_n),
    .push_a_i (push_a),
    .push_b_i (push_b),
    .rd_data_i(par_rd),
    .count_o  (q_count),
    .idle_o   (uf_idle),
    .rd_en_o  (uf_rd_en),
    .rd_addr_o(uf_rd_addr),
    .wr_en_o  (uf_wr_en),
    .wr_addr_o(uf_wr_addr),
    .wr_data_o(uf_wr_data)
  );

  assign can_take_o = q_count <= QCntW'(EdgeQueue - 4);
  assign idle_o     = !s1_valid_q && !s2_valid_q && (q_count == '0) && uf_idle;

  // ---- S0: take a pixel, read the row buffer -----------------------------------------------
  logic [16:0] x1, tcol1, trow1;
  logic x_wrap, tcol_wrap, trow_wrap, px_valid;

  assign x1        = 17'(x_q) + 17'd1;
  assign tcol1     = 17'(tcol_q) + 17'd1;
  assign trow1     = 17'(trow_q) + 17'd1;
  assign x_wrap    = x1 == {1'b0, width_i};
  assign tcol_wrap = tcol1 == {1'b0, cfg_tile_w_i};
  assign trow_wrap = trow1 == {1'b0, cfg_tile_h_i};
  assign px_valid  = (d_i != 16'd0) && !d_i[15] && (d_i > cfg_floor_i);

  always_comb begin
    x_d    = x_q;
    y_d    = y_q;
    tx_d   = tx_q;
    ty_d   = ty_q;
    tcol_d = tcol_q;
    trow_d = trow_q;
    if (frame_end_i) begin
      x_d    = '0;
      y_d    = '0;
      tx_d   = '0;
      ty_d   = '0;
      tcol_d = '0;
      trow_d = '0;
    end else if (take_i) begin
      if (x_wrap) begin
        x_d    = '0;
        tcol_d = '0;
        tx_d   = '0;
        y_d    = y_q + 1'b1;
        trow_d = trow_wrap ? '0 : YW'(trow1);
        ty_d   = trow_wrap ? ty_q + 1'b1 : ty_q;
      end else begin
        x_d    = XW'(x1);
        tcol_d = tcol_wrap ? '0 : XW'(tcol1);
        tx_d   = tcol_wrap ? tx_q + 1'b1 : tx_q;
      end
    end
  end

  assign s1_d_d    = px_valid ? d_i : 16'd0;
  assign s1_tile_d = LTileW'(ty_q) * TilesXL + LTileW'(tx_q);

  // ---- S1: decide the pixel's node, queue its edges ----------------------------------------
  logic [15:0] up_d;
  logic [N1W-1:0] up1, node1;
  logic [CntW-1:0] s1_count;
  logic s1_px, jl, ju, alloc, join_left, join_up;
  logic want0, want1, push0, push1, has0;
  logic [NodeW-1:0] e0_a, e1_a, e_b, last0_a, last0_b;

  assign up_d     = row_rd[15:0];
  assign up1      = row_rd[RowW-1:16];
  assign s1_count = count_q[s1_tile_q];
  assign s1_px    = s1_valid_q && (s1_d_q != 16'd0);
  assign jl       = s1_px && s1_has_left_q && (left1_q != '0) && join_left;
  assign ju       = s1_px && s1_has_up_q && (up1 != '0) && join_up;

  scw_labelling_join u_join_left (.d_cur_i(s1_d_q), .d_nb_i(left_d_q), .join_o(join_left));
  scw_labelling_join u_join_up (.d_cur_i(s1_d_q), .d_nb_i(up_d), .join_o(join_up));

  always_comb begin
    node1 = '0;
    alloc = 1'b0;
    ovf_o = 1'b0;
    if (!s1_px) begin
      node1 = '0;
    end else if (jl && s1_left_same_q) begin
      node1 = left1_q;
    end else if (ju && s1_up_same_q) begin
      node1 = up1;
    end else if (s1_count < CntW'(LabelsPerTile)) begin
      node1 = N1W'(to_global(LNodeW'(s1_tile_q) * LabelsL + LNodeW'(s1_count))) + 1'b1;
      alloc = 1'b1;
    end else begin
      ovf_o = 1'b1;
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
    if (frame_end_i) has_last_d = 1'b0;
  end

  assign s2_valid_d = s1_valid_q && (node1 != '0);
  assign left_d_d   = s1_valid_q ? s1_d_q : left_d_q;
  assign left1_d    = s1_valid_q ? node1 : left1_q;
  assign row_we     = s1_valid_q;
  assign row_wdata  = {node1, s1_d_q};

  // The strip's edge columns, for the join across strip borders after the frame.
  assign left_we_o     = (Lane > 0) && s1_valid_q && (s1_x_q == '0);
  assign right_we_o    = (Lane + 1 < Lanes) && s1_valid_q &&
                         (17'(s1_x_q) + 17'd1 == {1'b0, width_i});
  assign border_row_o  = s1_y_q;
  assign border_word_o = {node1, s1_d_q};

  // ---- S2: desc[node] = the pixel (a new label) or desc[node] + the pixel ------------------
  scw_pkg::label_desc_t pix;
  logic [GXW-1:0] gx;
  logic [2*GXW-1:0] uu;
  logic [GXW+YW-1:0] uv;
  logic [2*YW-1:0] vv;
  logic [DescW-1:0] desc_rd, w_a, w_merged, w_value;

  // pixel_object(x, y, d): moments from the coordinates' own widths, zero-extended.
  assign gx = GXW'(x0_i + 16'(s2_x_q));
  assign uu = (2 * GXW)'(gx) * (2 * GXW)'(gx);
  assign uv = (GXW + YW)'(gx) * (GXW + YW)'(s2_y_q);
  assign vv = (2 * YW)'(s2_y_q) * (2 * YW)'(s2_y_q);
  always_comb begin
    pix.area      = 32'd1;
    pix.x_min     = 16'(gx);
    pix.x_max     = 16'(gx);
    pix.closest_x = 16'(gx);
    pix.first_x   = 16'(gx);
    pix.y_min     = 16'(s2_y_q);
    pix.y_max     = 16'(s2_y_q);
    pix.closest_y = 16'(s2_y_q);
    pix.first_y   = 16'(s2_y_q);
    pix.d_min     = s2_d_q;
    pix.d_max     = s2_d_q;
    pix.m10       = 64'(gx);
    pix.m01       = 64'(s2_y_q);
    pix.m20       = 64'(uu);
    pix.m11       = 64'(uv);
    pix.m02       = 64'(vv);
    pix.m30       = 64'(uu) * 64'(gx);
    pix.m21       = 64'(uu) * 64'(s2_y_q);
    pix.m12       = 64'(uv) * 64'(s2_y_q);
    pix.m03       = 64'(vv) * 64'(s2_y_q);
  end

  assign w_a = (fwd_valid_q && fwd_node_q == s2_node_q) ? fwd_value_q : desc_rd;

  scw_labelling_merge u_merge (
    .a_i(w_a),
    .b_i(pix),
    .o_o(w_merged)
  );

  assign w_value = s2_init_q ? pix : w_merged;

  // ---- the banks: the pixel pipeline's ports while en_i, the stage's otherwise -------------
  logic par_mine_q, desc_mine_q;
  logic [N1W-1:0] par_rd;

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
      desc_re    = s1_valid_q && (node1 != '0);
      desc_raddr = to_local(e_b);
    end else if (init_i) begin
      par_we    = 1'b1;
      par_waddr = init_addr_i;
      par_wdata = '0;
    end
  end

  // The stage ORs the lanes' answers: only the lane that was read answers.
  assign par_rd_o  = par_mine_q ? par_rd : '0;
  assign desc_rd_o = desc_mine_q ? desc_rd : '0;
  assign count_o   = owns_tile(count_tile_i) ? count_q[to_local_tile(count_tile_i)] : '0;

  scw_ram_sdp #(.Width(RowW), .Depth(LaneWidthPx)) u_row_ram (
    .clk_i,
    .wr_en_i  (row_we),
    .wr_addr_i(s1_x_q),
    .wr_data_i(row_wdata),
    .rd_en_i  (take_i),
    .rd_addr_i(x_q),
    .rd_data_o(row_rd)
  );

  scw_ram_sdp #(.Width(N1W), .Depth(LaneNodes)) u_parent_ram (
    .clk_i,
    .wr_en_i  (par_we),
    .wr_addr_i(par_waddr),
    .wr_data_i(par_wdata),
    .rd_en_i  (par_re),
    .rd_addr_i(par_raddr),
    .rd_data_o(par_rd)
  );

  // Descriptors at their values' widths (scw_labelling_desc_ram), full width on the ports.
  scw_labelling_desc_ram #(
    .MaxWidthPx(MaxWidthPx),
    .MaxHeight (MaxHeight),
    .Depth     (LaneNodes)
  ) u_desc_ram (
    .clk_i,
    .wr_en_i  (en_i && s2_valid_q),
    .wr_addr_i(to_local(s2_node_q)),
    .wr_data_i(w_value),
    .rd_en_i  (desc_re),
    .rd_addr_i(desc_raddr),
    .rd_data_o(desc_rd)
  );

  // ---- registers ---------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      x_q         <= '0;
      y_q         <= '0;
      tx_q        <= '0;
      ty_q        <= '0;
      tcol_q      <= '0;
      trow_q      <= '0;
      s1_valid_q  <= 1'b0;
      s2_valid_q  <= 1'b0;
      left1_q     <= '0;
      has_last_q  <= 1'b0;
      fwd_valid_q <= 1'b0;
      par_mine_q  <= 1'b0;
      desc_mine_q <= 1'b0;
    end else begin
      x_q         <= x_d;
      y_q         <= y_d;
      tx_q        <= tx_d;
      ty_q        <= ty_d;
      tcol_q      <= tcol_d;
      trow_q      <= trow_d;
      s1_valid_q  <= take_i;
      s2_valid_q  <= s2_valid_d;
      left1_q     <= left1_d;
      has_last_q  <= has_last_d;
      fwd_valid_q <= en_i && s2_valid_q;
      par_mine_q  <= !en_i && par_re;
      desc_mine_q <= !en_i && desc_re;
    end
  end

  // Labels per tile: one block per tile (no delayed array writes in a for loop), all cleared
  // when a frame's status word leaves.
  for (genvar t = 0; t < LaneTiles; t++) begin : gen_count
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        count_q[t] <= '0;
      end else if (frame_end_i) begin
        count_q[t] <= '0;
      end else if (alloc && s1_tile_q == LTileW'(t)) begin
        count_q[t] <= count_q[t] + 1'b1;
      end
    end
  end

  // Datapath registers: meaningful only under their valid bits.
  always_ff @(posedge clk_i) begin
    s1_d_q         <= s1_d_d;
    s1_x_q         <= x_q;
    s1_y_q         <= y_q;
    s1_tile_q      <= s1_tile_d;
    s1_has_left_q  <= x_q != '0;
    s1_has_up_q    <= y_q != '0;
    s1_left_same_q <= tcol_q != '0;
    s1_up_same_q   <= trow_q != '0;
    s2_node_q      <= e_b;
    s2_init_q      <= alloc;
    s2_x_q         <= s1_x_q;
    s2_y_q         <= s1_y_q;
    s2_d_q         <= s1_d_q;
    left_d_q       <= left_d_d;
    last_a_q       <= last_a_d;
    last_b_q       <= last_b_d;
    fwd_node_q     <= s2_node_q;
    fwd_value_q    <= w_value;
  end
endmodule
