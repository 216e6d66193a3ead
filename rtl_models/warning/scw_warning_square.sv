// SPDX-License-Identifier: Apache-2.0
// Warning stage: the exact square of a signed coordinate, in three pipeline stages.
`default_nettype none

// x = xh * 2^L + xl with xl = x[L-1:0] unsigned and xh = x[XW-1:L] signed, so
//   x^2 = xh^2 * 2^(2L) + xh * xl * 2^(L+1) + xl^2
// from three products that each fit one DSP48E1 (stages 1 and 2: the multiplier and output
// registers M and P; without P, the path from one DSP's M into the next one's adder is 3 ns).
// xh^2 and xl^2 do not overlap, so stage 3 needs one carry chain, above bit L (the bits below
// come from xl^2 alone).
module scw_warning_square #(
  parameter int unsigned XW = 29,  // x, signed
  parameter int unsigned L  = 17   // low part: up to 17 bits for one DSP
) (
  input  logic                clk_i,
  input  logic                en_i,
  input  logic signed [XW-1:0] x_i,
  output logic [2*XW-2:0]     sq_o  // x^2 <= 2^(2 XW - 2), three enabled clocks later
);
  localparam int unsigned H   = XW - L;
  localparam int unsigned HHW = 2 * H;          // xh^2, signed product; its top bit is 0
  localparam int unsigned HLW = H + L + 1;      // xh * xl, signed
  localparam int unsigned LLW = 2 * L;          // xl^2
  localparam int unsigned UpW = 2 * XW - 2 - L; // x^2 >> (L + 1)

  if (L < 2 || H < 2 || L > 17 || H > 17) begin : gen_bad
    $error("scw_warning_square: need 2 <= L <= 17 and 2 <= XW - L <= 17");
  end

  logic signed [HHW-1:0] hh_a;
  logic signed [HLW-1:0] hl_a, hl_b;
  logic [LLW-1:0] ll_a;
  assign hh_a = {{H{x_i[XW-1]}}, x_i[XW-1:L]};
  assign hl_a = {{(L + 1){x_i[XW-1]}}, x_i[XW-1:L]};
  assign hl_b = {{(H + 1){1'b0}}, x_i[L-1:0]};
  assign ll_a = {{L{1'b0}}, x_i[L-1:0]};

  logic signed [HHW-1:0] hh_m, hh_q;
  logic signed [HLW-1:0] hl_m, hl_q;
  logic [LLW-1:0] ll_m, ll_q;
  logic signed [UpW:0] up;  // one bit of headroom for the signed add
  assign up = {1'b0, hh_q[HHW-2:0], ll_q[LLW-1:L+1]} + {{(UpW + 1 - HLW){hl_q[HLW-1]}}, hl_q};

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      hh_m <= hh_a * hh_a;
      hl_m <= hl_a * hl_b;
      ll_m <= ll_a * ll_a;
      hh_q <= hh_m;
      hl_q <= hl_m;
      ll_q <= ll_m;
      sq_o <= {up[UpW-1:0], ll_q[L:0]};
    end
  end

  // hh's sign bit (a square is >= 0) and the sum's headroom bit are always 0.
  logic unused_zero;
  assign unused_zero = ^{hh_q[HHW-1], up[UpW]};
endmodule
