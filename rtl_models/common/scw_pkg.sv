// SPDX-License-Identifier: Apache-2.0
// Constants shared by every scw RTL module (Yosys 0.23 needs scoped names: no import).
`default_nettype none

package scw_pkg;
  // Grey level width on every pixel stream (the thesis scales its 10-bit camera to 8 bits).
  localparam int unsigned PixelBits = 8;
  // A beat packed into one word, as FIFOs carry it and hex vectors store it:
  // {eol, sof, px[P-1], ..., px[0]}.
  localparam int unsigned BeatFlagBits = 2;
  // One labelling object descriptor: the object word of sim/labelling_pack.hpp without its
  // is_status bit, declared most significant first (area is bits [31:0], m03 the top 64 bits).
  typedef struct packed {
    logic [63:0] m03;
    logic [63:0] m12;
    logic [63:0] m21;
    logic [63:0] m30;
    logic [63:0] m02;
    logic [63:0] m11;
    logic [63:0] m20;
    logic [63:0] m01;
    logic [63:0] m10;
    logic [15:0] first_y;
    logic [15:0] first_x;
    logic [15:0] closest_y;
    logic [15:0] closest_x;
    logic [15:0] d_max;
    logic [15:0] d_min;
    logic [15:0] y_max;
    logic [15:0] y_min;
    logic [15:0] x_max;
    logic [15:0] x_min;
    logic [31:0] area;
  } label_desc_t;
endpackage
