// SPDX-License-Identifier: Apache-2.0
// Labelling: the thesis's join of two valid 4-neighbours (combinational).
`default_nettype none

// The twin of hls::labelling::joins(): 10 |d_cur - d_nb| < d_cur, d_cur the pixel later in
// raster order, exact in integers (10 x = 8 x + 2 x).
module scw_labelling_join (
  input  logic [15:0] d_cur_i,
  input  logic [15:0] d_nb_i,
  output logic        join_o
);
  logic [15:0] diff;
  logic [19:0] ten;

  assign diff   = (d_cur_i >= d_nb_i) ? d_cur_i - d_nb_i : d_nb_i - d_cur_i;
  assign ten    = {1'b0, diff, 3'b000} + {3'b000, diff, 1'b0};
  assign join_o = ten < {4'b0000, d_cur_i};
endmodule
