// SPDX-License-Identifier: Apache-2.0
// Labelling: the descriptor of the union of two disjoint pixel sets, registered.
`default_nettype none

// The twin of hls::labelling::merge() on descriptors stored at their fields' widths
// (hls::labelling::DescWidths; scw_labelling passes the widths, the defaults are a 32 x 24
// frame's). Ties in the closest and first points go to the earlier pixel in raster order, so the
// result is symmetric. No sum can overflow its width at the frame size the widths were derived for.
// o_o is the union of the a_i and b_i of the last clock with en_i (a datapath register, no reset).
// Layout, area in the low bits: {sum_dd, sum_d, m03, m12, m21, m30, m02, m11, m20, m01, m10,
// first_y, first_x, closest_y, closest_x, d_max, d_min, y_max, y_min, x_max, x_min, area}.
module scw_labelling_merge #(
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
  localparam int unsigned DescW = AreaW + 4 * PosXW + 4 * PosYW + 2 * DispW + M10W + M01W +
                                  M20W + M11W + M02W + M30W + M21W + M12W + M03W + SumDW +
                                  SumDDW
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [DescW-1:0] a_i,
  input  logic [DescW-1:0] b_i,
  output logic [DescW-1:0] o_o
);
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

  desc_t a, b, o, o_q;
  logic a_closest, a_first;

  assign a = a_i;
  assign b = b_i;
  assign o_o = o_q;

  always_ff @(posedge clk_i) begin
    if (en_i) o_q <= o;
  end

  always_comb begin
    // Larger d_max first, then the earlier pixel (row, then column): one compare of the keys
    // {d_max, ~y, ~x} is one carry chain, where the chain of compares and equalities mapped to
    // LUT and MUXF levels (the default-build top's worst path, R4's sum in scw_labelling).
    a_closest = {a.d_max, ~a.closest_y, ~a.closest_x} > {b.d_max, ~b.closest_y, ~b.closest_x};
    a_first   = {a.first_y, a.first_x} < {b.first_y, b.first_x};

    o.area      = a.area + b.area;
    o.x_min     = (a.x_min < b.x_min) ? a.x_min : b.x_min;
    o.x_max     = (a.x_max > b.x_max) ? a.x_max : b.x_max;
    o.y_min     = (a.y_min < b.y_min) ? a.y_min : b.y_min;
    o.y_max     = (a.y_max > b.y_max) ? a.y_max : b.y_max;
    o.d_min     = (a.d_min < b.d_min) ? a.d_min : b.d_min;
    o.d_max     = (a.d_max > b.d_max) ? a.d_max : b.d_max;
    o.closest_x = a_closest ? a.closest_x : b.closest_x;
    o.closest_y = a_closest ? a.closest_y : b.closest_y;
    o.first_x   = a_first ? a.first_x : b.first_x;
    o.first_y   = a_first ? a.first_y : b.first_y;
    o.m10       = a.m10 + b.m10;
    o.m01       = a.m01 + b.m01;
    o.m20       = a.m20 + b.m20;
    o.m11       = a.m11 + b.m11;
    o.m02       = a.m02 + b.m02;
    o.m30       = a.m30 + b.m30;
    o.m21       = a.m21 + b.m21;
    o.m12       = a.m12 + b.m12;
    o.m03       = a.m03 + b.m03;
    o.sum_d     = a.sum_d + b.sum_d;
    o.sum_dd    = a.sum_dd + b.sum_dd;
  end
endmodule
