// SPDX-License-Identifier: Apache-2.0
// Labelling: the descriptor of the union of two disjoint pixel sets (combinational).
`default_nettype none

// The twin of hls::labelling::merge(): sums wrap as the C++ unsigned sums do, ties in the
// closest and first points go to the earlier pixel in raster order, so the result is symmetric.
// A descriptor is the object part of sim/labelling_pack.hpp's output word, area in the low bits.
module scw_labelling_merge #(
  localparam int unsigned DescW = 32 + 10 * 16 + 9 * 64
) (
  input  logic [DescW-1:0] a_i,
  input  logic [DescW-1:0] b_i,
  output logic [DescW-1:0] o_o
);

  scw_pkg::label_desc_t a, b, o;
  logic a_closest, a_first;

  assign a = a_i;
  assign b = b_i;
  assign o_o = o;

  always_comb begin
    a_closest = (a.d_max > b.d_max) ||
                ((a.d_max == b.d_max) &&
                 ((a.closest_y < b.closest_y) ||
                  ((a.closest_y == b.closest_y) && (a.closest_x < b.closest_x))));
    a_first = (a.first_y < b.first_y) || ((a.first_y == b.first_y) && (a.first_x < b.first_x));

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
  end
endmodule
