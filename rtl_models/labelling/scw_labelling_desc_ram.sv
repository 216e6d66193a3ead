// SPDX-License-Identifier: Apache-2.0
// Labelling: a RAM of object descriptors that stores each field at the width its values need.
`default_nettype none

// The stage computes with scw_pkg::label_desc_t (sim/labelling_pack.hpp's object word minus
// the is_status bit: 32-bit area, 16-bit coordinates and disparities, 64-bit moments), but no
// value at MaxWidthPx x MaxHeight fills those widths: area < 2^AreaW, a coordinate < 2^PosXW or
// 2^PosYW, m_pq < area * W^p * H^q < 2^(AreaW + p PosXW + q PosYW). So the words are narrowed on
// the way in and zero-extended on the way out, losing no bit: a 1280 x 480 descriptor takes 512
// bits instead of 768. A scw_ram_sdp underneath: registered read, read-first.
module scw_labelling_desc_ram #(
  parameter int unsigned MaxWidthPx = 32,
  parameter int unsigned MaxHeight  = 24,
  parameter int unsigned Depth      = 64,
  localparam int unsigned DescW = 32 + 10 * 16 + 9 * 64,
  localparam int unsigned AddrW = (Depth > 1) ? $clog2(Depth) : 1
) (
  input  logic             clk_i,
  input  logic             wr_en_i,
  input  logic [AddrW-1:0] wr_addr_i,
  input  logic [DescW-1:0] wr_data_i,
  input  logic             rd_en_i,
  input  logic [AddrW-1:0] rd_addr_i,
  output logic [DescW-1:0] rd_data_o
);
  localparam int unsigned AreaW = $clog2(MaxWidthPx * MaxHeight + 1);
  localparam int unsigned PosXW = (MaxWidthPx > 1) ? $clog2(MaxWidthPx) : 1;
  localparam int unsigned PosYW = (MaxHeight > 1) ? $clog2(MaxHeight) : 1;
  // m_pq for p = 0 .. 3, q = 0 .. 3 - p, in the layout's order m10 m01 m20 m11 m02 m30 m21 m12
  // m03; at most 64 bits.
  localparam int unsigned M10W = (AreaW + PosXW > 64) ? 64 : AreaW + PosXW;
  localparam int unsigned M01W = (AreaW + PosYW > 64) ? 64 : AreaW + PosYW;
  localparam int unsigned M20W = (AreaW + 2 * PosXW > 64) ? 64 : AreaW + 2 * PosXW;
  localparam int unsigned M11W = (AreaW + PosXW + PosYW > 64) ? 64 : AreaW + PosXW + PosYW;
  localparam int unsigned M02W = (AreaW + 2 * PosYW > 64) ? 64 : AreaW + 2 * PosYW;
  localparam int unsigned M30W = (AreaW + 3 * PosXW > 64) ? 64 : AreaW + 3 * PosXW;
  localparam int unsigned M21W = (AreaW + 2 * PosXW + PosYW > 64) ? 64
                                                                   : AreaW + 2 * PosXW + PosYW;
  localparam int unsigned M12W = (AreaW + PosXW + 2 * PosYW > 64) ? 64
                                                                   : AreaW + PosXW + 2 * PosYW;
  localparam int unsigned M03W = (AreaW + 3 * PosYW > 64) ? 64 : AreaW + 3 * PosYW;
  localparam int unsigned StoredW = AreaW + 4 * PosXW + 4 * PosYW + 32 + M10W + M01W + M20W +
                                    M11W + M02W + M30W + M21W + M12W + M03W;

  // The high bits of each field are zero by the bounds above, so they are not stored.
  /* verilator lint_off UNUSEDSIGNAL */
  scw_pkg::label_desc_t wr_d;
  /* verilator lint_on UNUSEDSIGNAL */
  scw_pkg::label_desc_t rd_d;
  logic [StoredW-1:0] wr_s, rd_s;

  // Stored order: the same fields, area lowest, each at its own width.
  assign wr_d = wr_data_i;
  assign wr_s = {wr_d.m03[M03W-1:0], wr_d.m12[M12W-1:0], wr_d.m21[M21W-1:0],
                 wr_d.m30[M30W-1:0], wr_d.m02[M02W-1:0], wr_d.m11[M11W-1:0],
                 wr_d.m20[M20W-1:0], wr_d.m01[M01W-1:0], wr_d.m10[M10W-1:0],
                 wr_d.first_y[PosYW-1:0], wr_d.first_x[PosXW-1:0],
                 wr_d.closest_y[PosYW-1:0], wr_d.closest_x[PosXW-1:0], wr_d.d_max, wr_d.d_min,
                 wr_d.y_max[PosYW-1:0], wr_d.y_min[PosYW-1:0], wr_d.x_max[PosXW-1:0],
                 wr_d.x_min[PosXW-1:0], wr_d.area[AreaW-1:0]};

  scw_ram_sdp #(.Width(StoredW), .Depth(Depth)) u_ram (
    .clk_i,
    .wr_en_i,
    .wr_addr_i,
    .wr_data_i(wr_s),
    .rd_en_i,
    .rd_addr_i,
    .rd_data_o(rd_s)
  );

  // Stored offsets, low to high.
  localparam int unsigned SArea = 0;
  localparam int unsigned SXMin = SArea + AreaW;
  localparam int unsigned SXMax = SXMin + PosXW;
  localparam int unsigned SYMin = SXMax + PosXW;
  localparam int unsigned SYMax = SYMin + PosYW;
  localparam int unsigned SDMin = SYMax + PosYW;
  localparam int unsigned SDMax = SDMin + 16;
  localparam int unsigned SCx = SDMax + 16;
  localparam int unsigned SCy = SCx + PosXW;
  localparam int unsigned SFx = SCy + PosYW;
  localparam int unsigned SFy = SFx + PosXW;
  localparam int unsigned SM10 = SFy + PosYW;
  localparam int unsigned SM01 = SM10 + M10W;
  localparam int unsigned SM20 = SM01 + M01W;
  localparam int unsigned SM11 = SM20 + M20W;
  localparam int unsigned SM02 = SM11 + M11W;
  localparam int unsigned SM30 = SM02 + M02W;
  localparam int unsigned SM21 = SM30 + M30W;
  localparam int unsigned SM12 = SM21 + M21W;
  localparam int unsigned SM03 = SM12 + M12W;

  always_comb begin
    rd_d = '0;
    rd_d.area      = 32'(rd_s[SArea +: AreaW]);
    rd_d.x_min     = 16'(rd_s[SXMin +: PosXW]);
    rd_d.x_max     = 16'(rd_s[SXMax +: PosXW]);
    rd_d.y_min     = 16'(rd_s[SYMin +: PosYW]);
    rd_d.y_max     = 16'(rd_s[SYMax +: PosYW]);
    rd_d.d_min     = rd_s[SDMin +: 16];
    rd_d.d_max     = rd_s[SDMax +: 16];
    rd_d.closest_x = 16'(rd_s[SCx +: PosXW]);
    rd_d.closest_y = 16'(rd_s[SCy +: PosYW]);
    rd_d.first_x   = 16'(rd_s[SFx +: PosXW]);
    rd_d.first_y   = 16'(rd_s[SFy +: PosYW]);
    rd_d.m10       = 64'(rd_s[SM10 +: M10W]);
    rd_d.m01       = 64'(rd_s[SM01 +: M01W]);
    rd_d.m20       = 64'(rd_s[SM20 +: M20W]);
    rd_d.m11       = 64'(rd_s[SM11 +: M11W]);
    rd_d.m02       = 64'(rd_s[SM02 +: M02W]);
    rd_d.m30       = 64'(rd_s[SM30 +: M30W]);
    rd_d.m21       = 64'(rd_s[SM21 +: M21W]);
    rd_d.m12       = 64'(rd_s[SM12 +: M12W]);
    rd_d.m03       = 64'(rd_s[SM03 +: M03W]);
  end
  assign rd_data_o = rd_d;
endmodule
