// SPDX-License-Identifier: Apache-2.0
// Skid buffer: registers valid, data and ready at full throughput (two entries).
`default_nettype none

// The main register feeds the output; the skid register catches the one beat that arrives
// in the cycle the consumer stalls, because in_ready_o is registered and so one cycle late.
module scw_skid_buf #(
  parameter int unsigned Width /*verilator public*/ = 10
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [Width-1:0] in_data_i,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [Width-1:0] out_data_o
);
  logic main_valid_q, main_valid_d, skid_valid_q, skid_valid_d;
  logic [Width-1:0] main_data_q, skid_data_q;
  logic accept, drain, load_main_from_in, load_main_from_skid, load_skid;

  assign in_ready_o  = !skid_valid_q;
  assign out_valid_o = main_valid_q;
  assign out_data_o  = main_data_q;
  assign accept      = in_valid_i && in_ready_o;
  // The main register may take a new beat when it is empty or being read.
  assign drain       = !main_valid_q || out_ready_i;
  assign load_main_from_skid = drain && skid_valid_q;
  assign load_main_from_in   = drain && !skid_valid_q && accept;
  assign load_skid           = !drain && accept;

  always_comb begin
    main_valid_d = main_valid_q;
    skid_valid_d = skid_valid_q;
    if (drain) begin
      main_valid_d = skid_valid_q || accept;
      skid_valid_d = 1'b0;
    end else if (accept) begin
      skid_valid_d = 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      main_valid_q <= 1'b0;
      skid_valid_q <= 1'b0;
    end else begin
      main_valid_q <= main_valid_d;
      skid_valid_q <= skid_valid_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (load_main_from_skid) main_data_q <= skid_data_q;
    else if (load_main_from_in) main_data_q <= in_data_i;
    if (load_skid) skid_data_q <= in_data_i;
  end
endmodule
