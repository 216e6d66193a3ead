// SPDX-License-Identifier: Apache-2.0
// Constants shared by every scw RTL module (Yosys 0.23 needs scoped names: no import).
`default_nettype none

package scw_pkg;
  // Grey level width on every pixel stream (the thesis scales its 10-bit camera to 8 bits).
  localparam int unsigned PixelBits = 8;
  // A beat packed into one word, as FIFOs carry it and hex vectors store it:
  // {eol, sof, px[P-1], ..., px[0]}.
  localparam int unsigned BeatFlagBits = 2;
  // One disparity on the disparity, road and labelling streams: Q11.4 two's complement, invalid
  // = 0 or negative (hls::disparity::disp_t).
  localparam int unsigned DispBits /*verilator public*/ = 16;
  // The words between the stages, as sim/ packs them (the one list of their widths in RTL):
  // the labelling stage's object word, {is_status, label_desc_t} (sim/words/labelling_pack.hpp, 897),
  // the warning stage's frame result (sim/words/warning_pack.hpp, 199) and the top's result word, the
  // frame result and both cameras' input flags (sim/words/pipeline_pack.hpp). Verilator exports them
  // (V<prefix>_scw_pkg), and sim/builds/pipeline_small_rtl.hpp checks them against the C++ packs.
  localparam int unsigned ObjWordBits    /*verilator public*/ = 1 + 32 + 10 * 16 + 11 * 64;
  localparam int unsigned ResultWordBits /*verilator public*/ = 2 + 5 + 3 * 16 + 32 + 7 * 16;
  localparam int unsigned PipeResultBits /*verilator public*/ = ResultWordBits + 2;
  // One labelling object descriptor: the object word of sim/words/labelling_pack.hpp without its
  // is_status bit, declared most significant first (area is bits [31:0], sum_dd the top 64 bits).
  typedef struct packed {
    logic [63:0] sum_dd;
    logic [63:0] sum_d;
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
