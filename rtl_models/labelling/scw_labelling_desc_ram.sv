// SPDX-License-Identifier: Apache-2.0
// Labelling: a RAM of object descriptors, each field at the width its values need.
`default_nettype none

// Words are descriptors in scw_labelling_merge's layout, DescW bits (hls::labelling::DescWidths:
// a 1280 x 480 descriptor takes 569 bits). A scw_ram_sdp underneath: registered read, read-first.
// With OutReg = 1 a second register (the block RAM's output register) follows, so rd_data_o is
// the word read two clocks before; it loads while rd_next_i, so a stalled reader can hold it.
module scw_labelling_desc_ram #(
  parameter int unsigned DescW  = 251,
  parameter int unsigned Depth  = 64,
  parameter bit          OutReg = 1'b0,
  localparam int unsigned AddrW = (Depth > 1) ? $clog2(Depth) : 1
) (
  input  logic             clk_i,
  input  logic             wr_en_i,
  input  logic [AddrW-1:0] wr_addr_i,
  input  logic [DescW-1:0] wr_data_i,
  input  logic             rd_en_i,
  input  logic [AddrW-1:0] rd_addr_i,
  input  logic             rd_next_i,
  output logic [DescW-1:0] rd_data_o
);
  logic [DescW-1:0] rd_q;

  scw_ram_sdp #(.Width(DescW), .Depth(Depth)) u_ram (
    .clk_i,
    .wr_en_i,
    .wr_addr_i,
    .wr_data_i,
    .rd_en_i,
    .rd_addr_i,
    .rd_data_o(rd_q)
  );

  if (OutReg) begin : gen_out_reg
    // No reset: a datapath register the block RAM's own output register can take.
    logic [DescW-1:0] out_q;
    always_ff @(posedge clk_i) begin
      if (rd_next_i) out_q <= rd_q;
    end
    assign rd_data_o = out_q;
  end else begin : gen_no_out_reg
    logic unused_next;
    assign unused_next = rd_next_i;
    assign rd_data_o = rd_q;
  end
endmodule
