// SPDX-License-Identifier: Apache-2.0
// Disparity decision: the winning candidate of one pixel, the rejection rules and the value.
`default_nettype none

// Twin of scw::hls::disparity::decide<NumDisp>(sad, texture, cfg) (hls/disparity/disparity.hpp),
// bit for bit for every input, behind a free-running pipeline (no enable, no stall):
//
//   t1 .. tT  argmin tree, T = ceil(log2(NumDisp) / 2): two comparator levels per register (the
//             first stage has one when the level count is odd, as its inputs come from
//             outside). Each node carries its winner's neighbours sad[best +- 1], so the
//             sub-pixel fit needs no NumDisp-wide select afterwards.
//   A   p = m * U, m > limit, d = dmin + best, the uniqueness mask (|d - best| > 1, d < n),
//       |diff| and mx = max(prev, next) - m
//   B   floor(p / 100) by a reciprocal multiply, d - 1, quotient bits 2 and 1
//   C   thresh = m + floor(p / 100) against every candidate's delayed SAD; quotient bit 0 and
//       whether the bits below it are nonzero
//   D   the OR of every rejection and the value, registered on disp_o
//   Latency = T + 4 = scw::hls::disparity::decide_latency(NumDisp) (decide_latency.hpp).
//
// Sub-pixel: when the fit applies, next > m (a tie at best + 1 would have won) and prev >= m,
// so den = prev + next - 2m + |diff| = 2 mx > 0 and frac = sign(diff) q with
// q = floor(|diff| 128 / mx) <= 128. The output needs only (frac + 15) >>> 4, which is
// ceil(q / 16) for diff > 0 and -floor(q / 16) otherwise: qhi = floor(|diff| 8 / mx) from three
// restoring steps, and whether q mod 16 != 0, which is 16 r >= mx for their remainder r.
// |diff| = mx (q = 128) happens only for diff < 0, when prev = m ("full"): the three steps give
// qhi = 7 there, so full picks -8 directly, and no fourth step. The adjustment is in -8 .. 8, so
// d * 16 + adj = {adj < 0 ? d - 1 : d, adj[3:0]}: no adder at the output.
//
// Uniqueness: floor(p / 100) = floor(floor(p / 4) / 25), and floor(x / 25) = (x RecipMul) >>
// RecipShift exactly for every x up to floor((2^SadBits - 1) 255 / 4) (the elaboration-time
// search below; the unit test checks every x). The rejection rules all give the same invalid
// code, so their order does not matter and one OR decides.
//
// cfg_* are static: registered here without reset (with what is derived from them), which keeps
// them off every timing path; set them at least a clock before the first input that uses them.
// cfg_num_i 0 or above NumDisp means NumDisp, as candidates<NumDisp>(cfg) does.
//
// The left edge: limit_i is the pixel's count of candidates whose window lies inside the right
// image (decide()'s `limit`), band_i the same as a mask, bit d = d < limit_i, formed by the
// caller into a register so the leaves' select starts at a register as in_use_q does. A
// candidate takes part when it is in use and in the band; limit_i rides beside the tree to
// stage A for the uniqueness mask and the sub-pixel fit's last candidate. Away from the edge
// the caller drives all ones and NumDisp.
// cfg_sad_limit_i and cfg_texture_i are the C++ int fields, so one with bit 31 set (negative)
// is off. DminBits <= 12: only d's low 12 bits reach the 16-bit d * 16.
module scw_disparity_decide #(
  parameter int unsigned NumDisp  /*verilator public*/ = 8,   // built candidates, 2 .. 128
  parameter int unsigned SadBits  /*verilator public*/ = 12,  // one SAD and the texture sum
  parameter int unsigned DminBits /*verilator public*/ = 8    // cfg_dmin_i, 1 .. 12
) (
  input  logic                         clk_i,
  input  logic                         rst_ni,  // resets only the valid pipeline
  input  logic [$clog2(NumDisp+1)-1:0] cfg_num_i,
  input  logic [DminBits-1:0]          cfg_dmin_i,
  input  logic [31:0]                  cfg_sad_limit_i,   // 0 = off: reject min SAD > limit
  input  logic [31:0]                  cfg_texture_i,     // 0 = off: reject texture < it
  input  logic [7:0]                   cfg_uniqueness_i,  // 0 = off: ratio in percent
  input  logic                         cfg_subpixel_i,
  input  logic [15:0]                  cfg_invalid_i,     // the invalid code
  input  logic                         valid_i,
  input  logic                         region_i,  // 0: the invalid code (outside the region)
  input  logic [NumDisp*SadBits-1:0]   sad_i,     // candidate d at [d*SadBits +: SadBits]
  input  logic [NumDisp-1:0]           band_i,    // d < limit_i, from a register
  input  logic [$clog2(NumDisp+1)-1:0] limit_i,   // candidates inside the right image
  input  logic [SadBits-1:0]           texture_i,
  output logic                         valid_o,
  output logic [15:0]                  disp_o
);
  localparam int unsigned NumW       = $clog2(NumDisp + 1);
  localparam int unsigned Levels     = $clog2(NumDisp);
  localparam int unsigned Leaves     = 1 << Levels;
  localparam int unsigned IdxW       = Levels;
  localparam int unsigned TreeStages = Levels;
  localparam int unsigned SadW       = NumDisp * SadBits;
  localparam int unsigned NodeW      = 1 + IdxW + 3 * SadBits;
  localparam int unsigned ThrW       = SadBits + 2;  // thresh <= 3.55 m
  localparam int unsigned DispW      = 12;           // the bits of d that reach d * 16
  /* verilator lint_off UNUSEDPARAM */
  localparam int unsigned Latency    /*verilator public*/ = TreeStages + 6;
  /* verilator lint_on UNUSEDPARAM */
  // floor(m U / 100) = (m K) >> KShift with K = ceil(U 2^KShift / 100): with
  // e = 100 K - U 2^KShift in 0 .. 99, m K / 2^KShift = m U / 100 + m e / (100 2^KShift), and
  // frac(m U / 100) <= 99 / 100, so the floor holds when m e < 2^KShift, true for every
  // m < 2^SadBits at KShift = SadBits + 7. K < 2.56 2^KShift: KShift + 2 bits, split at 17
  // bits so that each part is one DSP48E1 product (the unit test checks every m and U).
  localparam int unsigned KShift     /*verilator public*/ = SadBits + 7;
  localparam int unsigned KW         = KShift + 2;
  localparam int unsigned KSplit     = 17;
  localparam int unsigned LoW        = SadBits + KSplit;       // m K[16:0]
  localparam int unsigned HiW        = SadBits + KW - KSplit;  // m K[KW-1:17]
  localparam int unsigned SumW       = SadBits + KW;

  if (NumDisp < 2 || NumDisp > 128) begin : gen_bad_num
    $error("scw_disparity_decide: NumDisp must be 2 .. 128");
  end
  if (SadBits < 2 || SadBits > 24 || DminBits < 1 || DminBits > 12) begin : gen_bad_width
    $error("scw_disparity_decide: need SadBits 2 .. 24 and DminBits 1 .. 12");
  end

  // ---- configuration --------------------------------------------------------------------
  logic [NumW-1:0] n_eff;
  logic [NumDisp-1:0] in_use;
  logic num_over;
  if ((1 << NumW) - 1 > NumDisp) begin : gen_num_over
    assign num_over = cfg_num_i > NumW'(NumDisp);
  end else begin : gen_num_fits  // NumDisp = 2^NumW - 1: no value above it
    assign num_over = 1'b0;
  end
  assign n_eff = (cfg_num_i == '0 || num_over) ? NumW'(NumDisp) : cfg_num_i;
  for (genvar d = 0; d < NumDisp; d++) begin : gen_in_use
    assign in_use[d] = NumW'(d) < n_eff;
  end

  logic [NumDisp-1:0] in_use_q;
  logic [IdxW-1:0] last_q;
  logic [SadBits-1:0] lim_q, tex_q;
  logic lim_en_q, tex_en_q, tex_all_q, uniq_en_q, sub_q;
  logic [DminBits-1:0] dmin_q;
  logic [15:0] invalid_q;
  always_ff @(posedge clk_i) begin
    in_use_q  <= in_use;
    last_q    <= IdxW'(n_eff - 1'b1);
    // A limit at or above 2^SadBits can never be exceeded.
    lim_en_q  <= !cfg_sad_limit_i[31] && cfg_sad_limit_i != '0 &&
                 cfg_sad_limit_i[30:SadBits] == '0;
    lim_q     <= cfg_sad_limit_i[SadBits-1:0];
    // A threshold at or above 2^SadBits rejects every texture sum.
    tex_en_q  <= !cfg_texture_i[31] && cfg_texture_i != '0;
    tex_all_q <= !cfg_texture_i[31] && cfg_texture_i[30:SadBits] != '0;
    tex_q     <= cfg_texture_i[SadBits-1:0];
    uniq_en_q <= cfg_uniqueness_i != '0;
    sub_q     <= cfg_subpixel_i;
    dmin_q    <= cfg_dmin_i;
    invalid_q <= cfg_invalid_i;
  end

  // K for every U: a 256-word ROM in LUTs (U is static, so K is too). A table filled once
  // rather than a function that searches it: the search ran its 256 compares at every clock in a
  // simulator (a third of this block's simulation time). A memory with its contents set by an
  // initial loop, not an array of 256 constant assigns: Yosys 0.23 turned those into a shift of
  // one 8,181-bit constant and spent 12 s mapping it, a third of the stage's synthesis (the CI's
  // guard); as a memory kept in logic it maps by its address bits (docs/performance.md).
  (* rom_style = "logic" *) logic [KW-1:0] k_rom [256];
  initial begin
    for (int i = 0; i < 256; i++) k_rom[i] = KW'(((64'(i) << KShift) + 64'd99) / 64'd100);
  end
  logic [KSplit-1:0] k_lo_q;
  logic [KW-KSplit-1:0] k_hi_q;
  always_ff @(posedge clk_i) begin
    {k_hi_q, k_lo_q} <= k_rom[cfg_uniqueness_i];
  end

  // ---- valid pipeline and the per-pixel side signals ------------------------------------
  logic [Latency-1:0] valid_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_q <= '0;
    else valid_q <= Latency'({valid_q, valid_i});
  end
  assign valid_o = valid_q[Latency-1];

  // {region, texture rejected} travels beside the tree, plain shifts without reset, so they
  // map to SRLs. The SADs wait for the uniqueness compare in stage C in a ring of distributed
  // RAM (SadW bits, TreeStages + 3 clocks: 6,885 bits at 45 candidates of 17 bits, which a
  // shift chain made a simulator copy at every clock).
  logic tex_rej;
  logic [2*TreeStages-1:0] side_q;
  logic [SadW-1:0] sads_late;  // sad_i of TreeStages + 3 clocks before
  assign tex_rej = tex_all_q || (tex_en_q && texture_i < tex_q);
  always_ff @(posedge clk_i) begin
    side_q <= (2 * TreeStages)'({side_q, region_i, tex_rej});
  end
  // The limit ends in a flip-flop, not at an SRL's slow clock-to-out: it starts stage A's
  // compares (the sub-pixel fit's last candidate), 3,655 ps from an SRL in the thesis-size stage.
  logic [NumW-1:0] t_limit_q;
  if (TreeStages > 1) begin : gen_limit_line
    logic [(TreeStages-1)*NumW-1:0] line_q;
    always_ff @(posedge clk_i) line_q <= ((TreeStages - 1) * NumW)'({line_q, limit_i});
    (* keep *) always_ff @(posedge clk_i) t_limit_q <= line_q[(TreeStages-1)*NumW-1 -: NumW];
  end else begin : gen_limit_reg
    (* keep *) always_ff @(posedge clk_i) t_limit_q <= limit_i;
  end
  scw_delay_ring #(.Width(SadW), .Depth(TreeStages + 3)) u_sads (
    .clk_i, .rst_ni, .en_i(1'b1), .d_i(sad_i), .q_o(sads_late)
  );

  // ---- t1 .. tT: argmin tree ------------------------------------------------------------
  typedef struct packed {
    logic               unused;  // not a candidate in use: loses every compare, ties included
    logic [IdxW-1:0]    idx;
    logic [SadBits-1:0] sad;   // all ones when the candidate is not in use
    logic [SadBits-1:0] prev;  // sad[idx - 1]
    logic [SadBits-1:0] next;  // sad[idx + 1]
  } node_t;
  localparam int unsigned NodeSad = 2 * SadBits;  // node_t's sad field, {unused, idx} above it
  localparam int unsigned NodeKey = NodeW - 1;    // node_t's unused bit, the compare's top

  // Level 0 holds the leaves (candidate d at node d, padded to a power of two), level l the
  // winners of pairs of level l - 1, level Levels the root. A candidate not in use (and a padding
  // leaf) is marked unused and reads all ones: the compare key {unused, sad} puts it above every
  // candidate in use, even one whose SAD is all ones, so the winner is always in use. One array per level, each level reading the one below by
  // name (Yosys 0.23 resolves only names of generate blocks already elaborated, so the levels
  // count up from the leaves): a single vector for the whole tree is circular logic to the
  // simulator, and a wide vector per level costs it wide concatenations every clock.
  for (genvar l = 0; l <= Levels; l++) begin : gen_lvl
    localparam int unsigned Nodes = 1 << (Levels - l);
    logic [NodeW-1:0] v [Nodes];
    if (l == 0) begin : gen_leaves
      for (genvar d = 0; d < Nodes; d++) begin : gen_leaf
        logic [SadBits-1:0] sad, prev, next;
        logic unused;
        if (d < NumDisp) begin : gen_cand
          assign unused = !(in_use_q[d] && band_i[d]);
          assign sad = (in_use_q[d] && band_i[d]) ? sad_i[d*SadBits +: SadBits] : '1;
        end else begin : gen_pad
          assign unused = 1'b1;
          assign sad = '1;
        end
        if (d > 0 && d < NumDisp) begin : gen_prev
          assign prev = sad_i[(d-1)*SadBits +: SadBits];
        end else begin : gen_no_prev
          assign prev = '0;
        end
        if (d + 1 < NumDisp) begin : gen_next
          assign next = sad_i[(d+1)*SadBits +: SadBits];
        end else begin : gen_no_next
          assign next = '0;
        end
        assign v[d] = {unused, IdxW'(d), sad, prev, next};
      end
    end else begin : gen_pairs
      for (genvar k = 0; k < Nodes; k++) begin : gen_node
        // Plain vectors: Yosys 0.23 cannot resolve a member of a struct declared in a generate
        // block ("Failed to resolve identifier").
        logic [NodeW-1:0] a, b, win;
        assign a   = gen_lvl[l-1].v[2*k];
        assign b   = gen_lvl[l-1].v[2*k+1];
        // <=: on a tie the right child, the larger d, wins, as in decide()'s loop and in
        // cv::StereoBM (its candidate index runs from the largest d down, keeping the first).
        assign win = ({b[NodeKey], b[NodeSad +: SadBits]} <= {a[NodeKey], a[NodeSad +: SadBits]})
                         ? b : a;
        // Every level registered: two compare-and-select levels in a row are too long a path.
        always_ff @(posedge clk_i) v[k] <= win;
      end
    end
  end

  // The root's unused bit is never read: a candidate is always in use (cfg_num_i 0 means all),
  // so the root is one.
  /* verilator lint_off UNUSEDSIGNAL */
  node_t root;
  /* verilator lint_on UNUSEDSIGNAL */
  logic t_region, t_tex_rej;
  assign root = gen_lvl[Levels].v[0];
  assign {t_region, t_tex_rej} = side_q[2*TreeStages-1 -: 2];

  // ---- A: products, limits, the uniqueness mask, sub-pixel set-up -----------------------
  logic [NumDisp-1:0] far;
  logic [SadBits-1:0] pn, np, pm, nm;
  logic neg;
  for (genvar d = 0; d < NumDisp; d++) begin : gen_far
    logic above, below;  // best > d + 1, best < d - 1 (constant where impossible)
    if (d + 2 < Leaves) begin : gen_above
      assign above = root.idx > IdxW'(d + 1);
    end else begin : gen_no_above
      assign above = 1'b0;
    end
    if (d >= 2) begin : gen_below
      assign below = root.idx < IdxW'(d - 1);
    end else begin : gen_no_below
      assign below = 1'b0;
    end
    assign far[d] = uniq_en_q && in_use_q[d] && NumW'(d) < t_limit_q && (above || below);
  end
  // Both differences and both distances to m, registered; the sign picks them in B.
  assign neg = root.prev < root.next;
  assign pn  = root.prev - root.next;
  assign np  = root.next - root.prev;
  assign pm  = root.prev - root.sad;
  assign nm  = root.next - root.sad;

  logic [LoW-1:0] a_lo_q;
  logic [HiW-1:0] a_hi_q;
  logic [SadBits-1:0] a_m_q, a_pn_q, a_np_q, a_pm_q, a_nm_q;
  logic [DispW-1:0] a_d_q;
  logic [NumDisp-1:0] a_far_q;
  logic a_inv_q, a_fit_q, a_neg_q, a_full_q;
  always_ff @(posedge clk_i) begin
    a_lo_q  <= LoW'(root.sad) * LoW'(k_lo_q);  // the DSPs' M registers
    a_hi_q  <= HiW'(root.sad) * HiW'(k_hi_q);
    a_m_q   <= root.sad;
    a_inv_q <= !t_region || t_tex_rej || (lim_en_q && root.sad > lim_q);
    a_d_q   <= DispW'(dmin_q) + DispW'(root.idx);
    // The winner is below both n and the limit, so it is the last of the min of the two
    // exactly when it is the last of either.
    a_fit_q <= sub_q && root.idx != '0 && root.idx != last_q &&
               NumW'(root.idx) + 1'b1 != t_limit_q;
    a_far_q <= far;
    a_neg_q <= neg;
    a_full_q <= neg && root.prev == root.sad;
    a_pn_q  <= pn;
    a_np_q  <= np;
    a_pm_q  <= pm;
    a_nm_q  <= nm;
  end

  // ---- B: the products out of the DSPs; |diff| and mx -----------------------------------
  logic [LoW-1:0] b_lo_q;
  logic [HiW-1:0] b_hi_q;
  logic [SadBits-1:0] b_m_q, b_a_q, b_mx_q;
  logic [DispW-1:0] b_d_q;
  logic [NumDisp-1:0] b_far_q;
  logic b_inv_q, b_fit_q, b_neg_q, b_full_q;
  always_ff @(posedge clk_i) begin
    b_lo_q  <= a_lo_q;  // the DSPs' P registers
    b_hi_q  <= a_hi_q;
    b_m_q   <= a_m_q;
    b_inv_q <= a_inv_q;
    b_d_q   <= a_d_q;
    b_fit_q <= a_fit_q;
    b_far_q <= a_far_q;
    b_neg_q <= a_neg_q;
    b_full_q <= a_full_q;
    b_a_q   <= a_neg_q ? a_np_q : a_pn_q;
    b_mx_q  <= a_neg_q ? a_nm_q : a_pm_q;
  end

  // One restoring division step: {quotient bit, remainder} of 2 r / mx, given r <= mx.
  function automatic logic [SadBits:0] div_step(input logic [SadBits-1:0] r,
                                                input logic [SadBits-1:0] mx);
    logic [SadBits:0] t;
    t = {r, 1'b0};
    if (t >= {1'b0, mx}) div_step = {1'b1, SadBits'(t - {1'b0, mx})};
    else div_step = {1'b0, t[SadBits-1:0]};
  endfunction

  // ---- C: floor(m U / 100) = (lo + hi 2^17) >> KShift, quotient bit 2, 17 mx, d - 1 ------
  logic [SadBits:0] c_s2;
  assign c_s2 = div_step(b_a_q, b_mx_q);

  logic [ThrW-1:0] c_q100_q;
  logic [SadBits-1:0] c_m_q, c_r_q, c_mx_q;
  logic [SadBits+4:0] c_mx17_q;
  logic [DispW-1:0] c_d_q, c_dm1_q;
  logic [NumDisp-1:0] c_far_q;
  logic c_qhi_q, c_inv_q, c_fit_q, c_neg_q, c_full_q;
  always_ff @(posedge clk_i) begin
    c_q100_q <= ThrW'((SumW'(b_lo_q) + (SumW'(b_hi_q) << KSplit)) >> KShift);
    c_m_q    <= b_m_q;
    c_inv_q  <= b_inv_q;
    c_d_q    <= b_d_q;
    c_dm1_q  <= b_d_q - 1'b1;
    c_fit_q  <= b_fit_q;
    c_far_q  <= b_far_q;
    c_neg_q  <= b_neg_q;
    c_full_q <= b_full_q;
    c_qhi_q  <= c_s2[SadBits];
    c_r_q    <= c_s2[SadBits-1:0];
    c_mx_q   <= b_mx_q;
    c_mx17_q <= (SadBits + 5)'(b_mx_q) + {b_mx_q, 4'b0};
  end

  // ---- D: thresh = m + floor(m U / 100), quotient bit 1 ---------------------------------
  logic [SadBits:0] d_s1;
  assign d_s1 = div_step(c_r_q, c_mx_q);

  // The SADs leave their ring's output register into plain registers here, those of
  // candidates the uniqueness test skips as all ones, above every thresh. One word a
  // candidate, so that a simulator compares them without cutting a wide vector.
  logic [ThrW-1:0] d_sad_q [NumDisp];
  for (genvar d = 0; d < NumDisp; d++) begin : gen_dsad
    always_ff @(posedge clk_i) begin
      d_sad_q[d] <= c_far_q[d] ? ThrW'(sads_late[d*SadBits +: SadBits]) : '1;
    end
  end

  logic [ThrW-1:0] d_thresh_q;
  logic [SadBits-1:0] d_r_q, d_mx_q;
  logic [SadBits+4:0] d_mx17_q;
  logic [DispW-1:0] d_d_q, d_dm1_q;
  logic [1:0] d_qhi_q;
  logic d_inv_q, d_fit_q, d_neg_q, d_full_q;
  always_ff @(posedge clk_i) begin
    d_thresh_q <= ThrW'(c_m_q) + c_q100_q;
    d_inv_q    <= c_inv_q;
    d_d_q      <= c_d_q;
    d_dm1_q    <= c_dm1_q;
    d_fit_q    <= c_fit_q;
    d_neg_q    <= c_neg_q;
    d_full_q   <= c_full_q;
    d_qhi_q    <= {c_qhi_q, d_s1[SadBits]};
    d_r_q      <= d_s1[SadBits-1:0];
    d_mx_q     <= c_mx_q;
    d_mx17_q   <= c_mx17_q;
  end

  // ---- E: thresh against every candidate; quotient bit 0 and the low bits ----------------
  // With t = 2 r: bit 0 is t >= mx and the remainder r0 = t - bit0 mx; q mod 16 != 0 is
  // 16 r0 >= mx, that is 32 r >= 17 mx when bit 0 is set and 32 r >= mx otherwise: three
  // compares side by side instead of a subtraction and a compare behind it.
  logic [NumDisp-1:0] urej, e_urej_q;
  for (genvar d = 0; d < NumDisp; d++) begin : gen_urej
    assign urej[d] = d_sad_q[d] <= d_thresh_q;
  end

  logic [DispW-1:0] e_d_q, e_dm1_q;
  logic [1:0] e_qhi_q;
  logic e_inv_q, e_fit_q, e_neg_q, e_full_q, e_q0_q, e_ge17_q, e_ge1_q;
  // Flip-flops, not the ends of SRLs (full's and qhi's registers are plain delay lines): an
  // SRL's clock-to-output in front of the output select measured 3,398 ps alone, 3,557 in the
  // small top.
  (* keep *) always_ff @(posedge clk_i) begin
    e_qhi_q  <= d_qhi_q;
    e_full_q <= d_full_q;
  end
  always_ff @(posedge clk_i) begin
    e_urej_q <= urej;
    e_inv_q  <= d_inv_q;
    e_d_q    <= d_d_q;
    e_dm1_q  <= d_dm1_q;
    e_fit_q  <= d_fit_q;
    e_neg_q  <= d_neg_q;
    e_q0_q   <= {d_r_q, 1'b0} >= {1'b0, d_mx_q};
    e_ge17_q <= {d_r_q, 5'b0} >= d_mx17_q;
    e_ge1_q  <= {d_r_q, 5'b0} >= (SadBits + 5)'(d_mx_q);
  end

  // ---- F: the value, or the invalid code on any rejection -------------------------------
  logic [2:0] qhi;
  logic [4:0] adj;  // (frac + 15) >>> 4, -8 .. 8
  logic [15:0] value, disp_q;
  assign qhi   = {e_qhi_q, e_q0_q};
  assign adj   = e_neg_q ? (e_full_q ? 5'b11000 : -{2'b0, qhi})  // 5'b11000: -8
                       : {2'b0, qhi} + {4'b0, e_q0_q ? e_ge17_q : e_ge1_q};
  assign value = !e_fit_q ? {e_d_q, 4'b0} : {adj[4] ? e_dm1_q : e_d_q, adj[3:0]};
  always_ff @(posedge clk_i) begin
    disp_q <= (e_inv_q || |e_urej_q) ? invalid_q : value;
  end
  assign disp_o = disp_q;
endmodule
