// SPDX-License-Identifier: Apache-2.0
// Labelling: a RAM of object descriptors that stores each field at the width its values need.
`default_nettype none

// The stage computes with the descriptor's full output layout (sim/labelling_pack.hpp minus
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
  // The high bits of each field are zero by the bounds above, so they are not stored.
  /* verilator lint_off UNUSEDSIGNAL */
  input  logic [DescW-1:0] wr_data_i,
  /* verilator lint_on UNUSEDSIGNAL */
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

  // Field offsets of the full layout (area at bit 0), as sim/labelling_pack.hpp without bit 0.
  localparam int unsigned FArea = 0, FXMin = 32, FXMax = 48, FYMin = 64, FYMax = 80,
                          FDMin = 96, FDMax = 112, FCx = 128, FCy = 144, FFx = 160, FFy = 176,
                          FM10 = 192, FM01 = 256, FM20 = 320, FM11 = 384, FM02 = 448,
                          FM30 = 512, FM21 = 576, FM12 = 640, FM03 = 704;

  logic [StoredW-1:0] wr_s, rd_s;

  // Stored order: the same fields, low to high, each at its own width.
  assign wr_s = {wr_data_i[FM03 +: M03W], wr_data_i[FM12 +: M12W], wr_data_i[FM21 +: M21W],
                 wr_data_i[FM30 +: M30W], wr_data_i[FM02 +: M02W], wr_data_i[FM11 +: M11W],
                 wr_data_i[FM20 +: M20W], wr_data_i[FM01 +: M01W], wr_data_i[FM10 +: M10W],
                 wr_data_i[FFy +: PosYW], wr_data_i[FFx +: PosXW], wr_data_i[FCy +: PosYW],
                 wr_data_i[FCx +: PosXW], wr_data_i[FDMax +: 16], wr_data_i[FDMin +: 16],
                 wr_data_i[FYMax +: PosYW], wr_data_i[FYMin +: PosYW],
                 wr_data_i[FXMax +: PosXW], wr_data_i[FXMin +: PosXW],
                 wr_data_i[FArea +: AreaW]};

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
    rd_data_o = '0;
    rd_data_o[FArea +: AreaW] = rd_s[SArea +: AreaW];
    rd_data_o[FXMin +: PosXW] = rd_s[SXMin +: PosXW];
    rd_data_o[FXMax +: PosXW] = rd_s[SXMax +: PosXW];
    rd_data_o[FYMin +: PosYW] = rd_s[SYMin +: PosYW];
    rd_data_o[FYMax +: PosYW] = rd_s[SYMax +: PosYW];
    rd_data_o[FDMin +: 16]    = rd_s[SDMin +: 16];
    rd_data_o[FDMax +: 16]    = rd_s[SDMax +: 16];
    rd_data_o[FCx +: PosXW]   = rd_s[SCx +: PosXW];
    rd_data_o[FCy +: PosYW]   = rd_s[SCy +: PosYW];
    rd_data_o[FFx +: PosXW]   = rd_s[SFx +: PosXW];
    rd_data_o[FFy +: PosYW]   = rd_s[SFy +: PosYW];
    rd_data_o[FM10 +: M10W]   = rd_s[SM10 +: M10W];
    rd_data_o[FM01 +: M01W]   = rd_s[SM01 +: M01W];
    rd_data_o[FM20 +: M20W]   = rd_s[SM20 +: M20W];
    rd_data_o[FM11 +: M11W]   = rd_s[SM11 +: M11W];
    rd_data_o[FM02 +: M02W]   = rd_s[SM02 +: M02W];
    rd_data_o[FM30 +: M30W]   = rd_s[SM30 +: M30W];
    rd_data_o[FM21 +: M21W]   = rd_s[SM21 +: M21W];
    rd_data_o[FM12 +: M12W]   = rd_s[SM12 +: M12W];
    rd_data_o[FM03 +: M03W]   = rd_s[SM03 +: M03W];
  end
endmodule
