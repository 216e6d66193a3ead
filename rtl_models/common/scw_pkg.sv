// SPDX-License-Identifier: Apache-2.0
// Constants shared by every scw RTL module (Yosys 0.23 needs scoped names: no import).
`default_nettype none

package scw_pkg;
  // Grey level width on every pixel stream (the thesis scales its 10-bit camera to 8 bits).
  localparam int unsigned PixelBits = 8;
  // A beat packed into one word, as FIFOs carry it and hex vectors store it:
  // {eol, sof, px[P-1], ..., px[0]}.
  localparam int unsigned BeatFlagBits = 2;
endpackage
