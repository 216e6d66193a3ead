// SPDX-License-Identifier: Apache-2.0
// Labelling kernel: one-pass tiled connected-component labelling of a disparity stream into
// object descriptors, clock by clock as the RTL does it (docs/labelling.md).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/common/reg_fifo.hpp"
#include "hls/common/stream.hpp"
#include "hls/labelling/labelling_lane.hpp"

namespace scw::hls::labelling {

/// The width of every lane's strip but the last (which has the rest): tile_w x tile columns /
/// lanes.
inline int strip_width(const LabellingConfig& cfg, int lanes) {
  const int tx = (cfg.width + cfg.tile_w - 1) / cfg.tile_w;
  return cfg.tile_w * (tx / lanes);
}

/// Throws std::invalid_argument naming the field if `cfg` does not fit a stage built with
/// `Params`.
template <typename Params>
void check_config([[maybe_unused]] const LabellingConfig& cfg) {
#ifndef __SYNTHESIS__  // the host's check: a synthesised top trusts its registers
  auto fail = [](const std::string& m) { throw std::invalid_argument("labelling: " + m); };
  if (cfg.width < 2 || cfg.width > Params::kMaxWidthPx)
    fail("width " + std::to_string(cfg.width) + " outside 2 .. " +
         std::to_string(Params::kMaxWidthPx));
  if (cfg.height < 1 || cfg.height > Params::kMaxHeight)
    fail("height " + std::to_string(cfg.height) + " outside 1 .. " +
         std::to_string(Params::kMaxHeight));
  if (cfg.tile_w < 1 || cfg.tile_h < 1) fail("tile size must be at least 1 x 1");
  const int tx = (cfg.width + cfg.tile_w - 1) / cfg.tile_w;
  const int ty = (cfg.height + cfg.tile_h - 1) / cfg.tile_h;
  if (tx > Params::kMaxTilesX || ty > Params::kMaxTilesY)
    fail("a grid of " + std::to_string(tx) + " x " + std::to_string(ty) +
         " tiles; this build holds at most " + std::to_string(Params::kMaxTilesX) + " x " +
         std::to_string(Params::kMaxTilesY) + ": use larger tiles");
  if (cfg.floor < 0 || cfg.floor > 0x7fff) fail("floor outside 0 .. 32767");
  if (cfg.min_area < 0) fail("min_area must be >= 0");
  constexpr int n = Params::kLanes;
  if (n > 1) {
    const std::string lanes = " over " + std::to_string(n) + " lanes (pixels per beat)";
    if (cfg.width % n != 0)
      fail("width " + std::to_string(cfg.width) + " is not a whole number of beats" + lanes);
    if (tx % n != 0)
      fail(std::to_string(tx) + " tile columns do not split evenly" + lanes +
           ": choose tile_w so that ceil(width / tile_w) is a multiple of " + std::to_string(n));
    const int strip = strip_width(cfg, n);
    if (strip % n != 0)
      fail("strips of " + std::to_string(strip) + " px (tile_w x " + std::to_string(tx / n) +
           ") are not a whole number of beats" + lanes);
    if (strip > Params::kLaneWidthPx)
      fail("strips of " + std::to_string(strip) + " px; this build's lanes hold " +
           std::to_string(Params::kLaneWidthPx) + " px: use narrower tiles");
  }
#endif
}

/// The stage. Phases (docs/labelling.md):
///   kInit     after reset: clear the parent RAM (and the strip-border RAMs), one word per clock
///   kFrame    take beats. One lane: S0 takes the pixel, S1 decides its node and queues edges, S2
///             adds it to its node's descriptor, the merge unit runs alongside. Lanes: a beat
///             goes whole into the FIFO of the lane whose strip it is in, and every lane runs
///             S0 .. S2 and its merge unit on its strip, one pixel per clock
///   kDrain    after the frame's last beat (or a sof in mid-frame): wait for the lanes
///   kBorder   (lanes only) every row: the pixels either side of each strip border that join
///             queue an edge for a merge unit over the whole node space
///   kResolve  every used node in ascending order: its root (parent[] points to smaller nodes
///             only, so the parent's root is already known) and its descriptor into the root's;
///             the sweep copies each lane's label count for Emit. Then the next frame may start
/// Emit, alongside the next frame (it reads only the root and sum RAMs, which the next frame's
/// Resolve waits for): every used node again; roots of at least min_area pixels leave as
/// objects, up to MaxObjects; then the status word with `last`.
template <typename Params>
class Labelling {
 public:
  static constexpr int N = Params::kLanes;
  static constexpr int kNodes = Params::kNodes;
  /// Clocks of kInit: the parent RAM, a bank per lane cleared side by side, and with lanes the
  /// border RAMs (a row per clock), the strips' measure (a tile column per clock) and the lanes'
  /// powers of their first columns (the RTL's running moments, 8 clocks after the measure).
  static constexpr int kInitClocks =
      N == 1 ? kNodes
             : std::max({Params::kLaneStride, Params::kMaxHeight, Params::kMaxTilesX + 8});
  /// The border sweep's queue: it reads a row while it has room for the edges of that row and
  /// of the four in B1 .. B4.
  static constexpr int kBorderQueue = 16;
  static constexpr int kBorderRows = 5;
  using in_type = typename Params::in_beat;
  using out_type = LabelPacket;
  using Lane = LabellingLane<Params>;
  enum Phase { kInit, kFrame, kDrain, kBorder, kResolve };

  explicit Labelling(const LabellingConfig& cfg) : cfg_(cfg) {
    check_config<Params>(cfg);
    const int strip = N == 1 ? cfg.width : strip_width(cfg, N);
    for (int i = 0; i < N; ++i)
      lanes_[i].setup(i, cfg, i * strip, i + 1 < N ? strip : cfg.width - (N - 1) * strip);
    strip_ = strip;
  }

  // ---- what the ports show this clock (registers only, except the mid-frame sof check) ----
  bool in_ready(bool in_sof) const {
    const bool room = N == 1 ? lanes_[0].can_take() : !fifo_[in_frame_ ? lane_ : 0].full();
    return phase_ == kFrame && room && !(in_frame_ && in_sof);
  }
  bool out_valid() const { return out_valid_; }
  const out_type& out() const { return out_; }
  bool error() const { return err_sticky_; }
  Phase phase() const { return phase_; }
  /// Emit runs beside the phases above (the previous frame's objects leave while this one streams).
  bool emitting() const { return emitting_; }

  /// Second-pass support (not part of the hardware): if set, *m holds each pixel's node + 1
  /// (0 = none) at y * width + x of the frame being emitted, and root(node) its object's root,
  /// both from the end of its Resolve until the next frame's (S1 writes a working copy, since
  /// the next frame streams in during Emit).
#ifndef __SYNTHESIS__  // the host's second pass: a heap map, no part of the hardware
  void set_node_map(std::vector<std::int32_t>* m) {
    node_map_ = m;
    live_map_.assign(m ? m->size() : 0, 0);
    ram_.node_map = m ? &live_map_ : nullptr;
  }
#endif
  int root(int node) const { return root_ram_[node]; }

  /// One clock edge with the inputs of this clock.
  void clock(bool in_valid, const in_type& in, bool out_ready) {
    const bool take = in_valid && in_ready(in.sof);
    const bool sof_mid = phase_ == kFrame && in_frame_ && in_valid && in.sof;
    const bool out_en = !out_valid_ || out_ready;
    if (out_valid_ && out_ready) out_valid_ = false;
    // RAM reads issued this clock land in the read registers at the edge. Stages run in
    // pipeline order, each RAM read before that RAM's write (read-first RAMs), and every
    // decision looks at the registers of before the edge (rd_, r1_, ...).
    Reads rd = rd_;
    ParentPorts pp;
    const bool emitting = emitting_;  // Emit's clock sees the registers of before the edge
    const bool drain_idle = N > 1 && phase_ == kDrain && lanes_idle();
    switch (phase_) {
      case kInit:
        if (++init_ == kInitClocks) phase_ = kFrame;
        break;
      case kFrame:
      case kDrain:
        frame_clock(take, sof_mid, in);
        break;
      case kBorder:
        border_clock(rd, pp);
        break;
      case kResolve:
        resolve_clock(rd, pp);
        break;
    }
    if (emitting) emit_clock(out_en);
    if (pp.rd) rd.parent = ram_.parent[pp.rd_addr];
    if (pp.wr) ram_.parent[pp.wr_addr] = pp.wr_data;
    rd_ = rd;
    drain_idle_q_ = drain_idle;
  }

 private:
  /// The end-of-frame phases' RAM read registers.
  struct Reads {
    int parent = 0;
    Object desc;
    Object acc;
    int root = 0;
    std::array<BorderPixel, N> left{}, right{};
  };
  /// One beat for one lane.
  using LaneBeat = std::array<disp_t, N>;
  struct LaneHead {  // the beat a lane takes its pixels from, filled from its FIFO
    bool valid = false;
    LaneBeat beat{};
  };
  /// A node iterator over the used nodes, ascending: each lane's, lane by lane; a lane that
  /// used none costs a clock.
  struct Sweep {
    bool active = false;
    int lane = 0, label = 0;
  };
  struct Fwd {  // a write of the previous clock, for the read issued alongside it
    bool valid = false;
    int node = 0;
    Object value;
  };

  // ---------------------------------------------------------------- kFrame and kDrain
  /// Every lane, its FIFO and the registers in front of it empty.
  bool lanes_idle() const {
    for (int i = 0; i < N; ++i)
      if (!lanes_[i].idle() ||
          (N > 1 && (!fifo_[i].empty() || ahead_[i].valid || head_[i].valid)))
        return false;
    return true;
  }

  void frame_clock(bool take, bool sof_mid, const in_type& in) {
    // With lanes the RTL registers the idle test (an AND over every lane): Border starts a
    // clock after the last lane went idle.
    const bool drained = phase_ == kDrain && (N == 1 ? lanes_idle() : drain_idle_q_);
    // The beat: one lane takes its pixel (S0), or with lanes it goes into its lane's FIFO.
    int push_lane = -1;
    if (take) push_lane = accept(in);
    // Each lane: S0 from its head register (lanes), then S1, S2 and its merge unit. The FIFO
    // fills the head register through one more (the RTL's FIFO is a block RAM: that register is
    // its read register, the head its output register); each moves on when the next is empty
    // or moves on itself, the head when the lane takes its last pixel.
    for (int i = 0; i < N; ++i) {
      Lane& lane = lanes_[i];
      bool head_pop = false;
      if (N > 1 && head_[i].valid && lane.can_take()) {
        lane.take(head_[i].beat[static_cast<std::size_t>(sub_[i])]);
        head_pop = ++sub_[i] == N;
        if (head_pop) sub_[i] = 0;
      }
      if (lane.step(ram_)) tile_overflow_ = true;
      if (N > 1) {
        const bool ahead_pop = ahead_[i].valid && (!head_[i].valid || head_pop);
        const bool pop = !fifo_[i].empty() && (!ahead_[i].valid || ahead_pop);
        if (ahead_pop) {
          head_[i] = ahead_[i];
        } else if (head_pop) {
          head_[i].valid = false;
        }
        if (pop) {
          ahead_[i] = {true, fifo_[i].head()};
        } else if (ahead_pop) {
          ahead_[i].valid = false;
        }
        LaneBeat b{};
        const bool push = push_lane == i;
        if (push) std::copy(in.px.begin(), in.px.end(), b.begin());
        fifo_[i].clock(pop, &b, push ? 1 : 0);
      }
    }
    if (sof_mid) {  // a sof in mid-frame: close the frame early, take the sof afterwards
      err_frame_ = err_sticky_ = true;
      in_frame_ = false;
      phase_ = kDrain;
    }
    if (drained) {
      if (N == 1) {
        if (!emitting_) start_resolve();  // the last frame's Emit still reads the sums
      } else {
        phase_ = kBorder;
        border_row_ = 0;
        border_active_ = true;
      }
    }
  }

  /// Frames the beat; one lane takes its pixel now, or with lanes returns the lane whose FIFO
  /// it goes into (-1: dropped).
  int accept(const in_type& in) {
    if (!in_frame_) {
      if (!in.sof) {  // a beat outside any frame: dropped, flagged on the next frame
        err_pending_ = err_sticky_ = true;
        return -1;
      }
      in_frame_ = true;
      err_frame_ = err_pending_;
      err_pending_ = false;
      x_ = y_ = lane_ = lane_col_ = 0;
    }
    if (in.eol != (x_ + N == cfg_.width)) err_frame_ = err_sticky_ = true;
    const int lane = lane_;
    if (N == 1) lanes_[0].take(in.px[0]);
    x_ += N;
    lane_col_ += N;
    if (lane_col_ == strip_) lane_col_ = 0, ++lane_;
    if (x_ == cfg_.width) {
      x_ = lane_ = lane_col_ = 0;
      if (++y_ == cfg_.height) {  // the frame's last beat
        in_frame_ = false;
        phase_ = kDrain;
      }
    }
    return lane;
  }

  // ---------------------------------------------------------------- kBorder (lanes)
  // B0 reads a row, B1 passes the words through the RTL's RAM output registers, B2 forms the
  // join's multiples (the model tests the join in B3 with joins(), the same integers), B3 drops
  // a repeat of the border's last edge, B4 queues the edges.
  void border_clock(Reads& rd, ParentPorts& pp) {
    const bool done = !border_active_ && !b1_valid_ && !b2_.valid && !b3_.valid && !b4_.valid &&
                      queue_.count() == 0 && uf_.idle();
    // B0: read (and clear for the next frame) both sides of every border in the next row.
    const bool read =
        border_active_ && queue_.count() <= kBorderQueue - kBorderRows * (N - 1);
    // B4: the edges B3 kept, in border order.
    const BorderPushes b4 = b4_;
    // B3: an edge for every border whose two pixels join, unless it repeats its last.
    BorderPushes b4_next;
    if (b3_.valid) {
      b4_next.valid = true;
      for (int b = 0; b + 1 < N; ++b) {
        const BorderPixel& lp = b3_.right[b];     // the left strip's last pixel
        const BorderPixel& rp = b3_.left[b + 1];  // the right strip's first pixel (later)
        if (lp.node1 == 0 || rp.node1 == 0 || !joins(rp.d, lp.d)) continue;
        const Edge e{lp.node1 - 1, rp.node1 - 1};
        if (border_has_last_[b] && e == border_last_[b]) continue;  // as this border's last
        b4_next.edge[b4_next.n++] = e;
        border_last_[b] = e;
        border_has_last_[b] = true;
      }
    }
    // B1, B2: the row read last clock, registered twice.
    b3_ = b2_;
    b2_ = {b1_valid_, rd_.left, rd_.right};
    b4_ = b4_next;
    if (read) {
      for (int b = 0; b < N; ++b) {
        rd.left[b] = ram_.left[b][border_row_];
        rd.right[b] = ram_.right[b][border_row_];
        ram_.left[b][border_row_] = {};
        ram_.right[b][border_row_] = {};
      }
      if (++border_row_ == cfg_.height) border_active_ = false;
    }
    b1_valid_ = read;
    const bool pop = uf_.clock(queue_, rd_.parent, pp);
    queue_.clock(pop, b4.edge, b4.n);
    if (done && !emitting_) start_resolve();  // the last frame's Emit still reads the sums
  }

  void start_resolve() {
    phase_ = kResolve;
    sweep_ = {true, 0, 0};
  }

  // ---------------------------------------------------------------- kResolve
  void resolve_clock(Reads& rd, ParentPorts& pp) {
    const bool done =
        !sweep_.active && !r1_.valid && !r2_.valid && !r3_.valid && !r4_valid_ && !r5_valid_;
    // R0: the next node; read its parent[].
    R1 r1_next;
    int node = 0;
    if (next_node(node, true)) {
      r1_next = {true, node};
      pp.rd = true;
      pp.rd_addr = node;
    }
    // R1: parent[] of the node read last clock: read the parent's root; clear parent[] for the
    // next frame.
    R2 r2_next;
    if (r1_.valid) {
      const int q = rd_.parent;
      r2_next = {true, r1_.node, q == 0, q - 1};
      if (q != 0) rd.root = root_ram_[q - 1];
      pp.wr = true;
      pp.wr_addr = r1_.node;
      pp.wr_data = 0;
    }
    // R2: the node's root: itself, or its parent's (read last clock, or written by R2 last
    // clock: the one write that read could not see). Read the node's and the root's
    // descriptors.
    R3 r3_next;
    RootFwd rfwd_next;
    if (r2_.valid) {
      const int root = r2_.self                                      ? r2_.node
                       : (rfwd_.valid && rfwd_.node == r2_.parent) ? rfwd_.root
                                                                    : rd_.root;
      root_ram_[r2_.node] = root;
      rfwd_next = {true, r2_.node, root};
      rd.desc = ram_.desc[r2_.node];
      rd.acc = acc_[root];
      r3_next = {true, r2_.node, root};
    }
    // R3: the node's descriptor into its root's (a root starts its own). The RTL passes the
    // reads through the RAMs' output registers (R3), adds (R4) and writes (R5): the same sums,
    // two clocks later, so the model adds here and counts the RTL's R4 and R5 for `done`.
    Fwd afwd_next;
    if (r3_.valid) {
      Object v;
      if (r3_.root == r3_.node) {
        v = rd_.desc;
      } else {
        const Object base = (afwd_.valid && afwd_.node == r3_.root) ? afwd_.value : rd_.acc;
        v = merge(base, rd_.desc);
      }
      v = narrow(v, Params::kWidths);
      acc_[r3_.root] = v;
      afwd_next = {true, r3_.root, v};
    }
    if (done) start_emit();
    r5_valid_ = r4_valid_;
    r4_valid_ = r3_.valid;
    r1_ = r1_next;
    r2_ = r2_next;
    r3_ = r3_next;
    afwd_ = afwd_next;
    rfwd_ = rfwd_next;
  }

  /// Steps the sweep; returns whether this clock yields a node (a lane that used none yields
  /// none). Resolve's sweep reads the lanes' label counts and copies them for Emit's.
  bool next_node(int& node, bool resolve) {
    if (!sweep_.active) return false;
    const int t = sweep_.lane;
    const int count = resolve ? ram_.count[t] : emit_count_[t];
    if (resolve) emit_count_[t] = count;
    const bool yields = count > 0;
    node = t * Params::kLaneStride + sweep_.label;
    if (yields && sweep_.label + 1 < count) {
      ++sweep_.label;
    } else {
      sweep_.label = 0;
      if (++sweep_.lane == N) sweep_.active = false;
    }
    return yields;
  }

  /// The end of Resolve: Emit takes the frame's flags, the stage the next frame.
  void start_emit() {
    emitting_ = true;
    sweep_ = {true, 0, 0};
    emit_tile_overflow_ = tile_overflow_;
    emit_err_ = err_frame_;
#ifndef __SYNTHESIS__
    if (node_map_) *node_map_ = live_map_;
#endif
    phase_ = kFrame;
    ram_.count.fill(0);
    tile_overflow_ = err_frame_ = false;
    for (Lane& lane : lanes_) lane.end_frame();
    border_has_last_.fill(false);
  }

  // ---------------------------------------------------------------- Emit
  void emit_clock(bool out_en) {
    // E0 reads a node's root and sum, E1 (the RTL's decision whether it is an object) and E2
    // (sends it) follow; a node that waits for the output register holds E1 and E2.
    const bool swept = !sweep_.active && !e1_.valid && !e2_.valid;
    bool adv = !e2_.valid;
    if (e2_.valid) {
      const bool is_object = e2_.root == e2_.node &&
                             e2_.acc.area >= static_cast<std::uint32_t>(cfg_.min_area);
      if (!is_object) {
        adv = true;
      } else if (emitted_ >= Params::kMaxObjects) {
        object_overflow_ = true;
        adv = true;
      } else if (out_en) {
        load_out(LabelWord{false, e2_.acc, {}}, false);
        ++emitted_;
        adv = true;
      }
    }
    if (!adv) return;
    if (swept) {
      if (!out_en) return;
      FrameStatus st;  // all nodes out: the status word
      st.objects = static_cast<std::uint32_t>(emitted_);
      st.tile_overflow = emit_tile_overflow_;
      st.object_overflow = object_overflow_;
      st.stream_error = emit_err_;
      load_out(LabelWord{true, {}, st}, true);
      emitting_ = false;
      emitted_ = 0;
      object_overflow_ = false;
      return;
    }
    e2_ = e1_;
    E1 e1_next;
    int node = 0;
    if (next_node(node, false)) e1_next = {true, node, root_ram_[node], acc_[node]};
    e1_ = e1_next;
  }

  void load_out(const LabelWord& w, bool last) {
    out_valid_ = true;
    out_.data = w;
    out_.last = last;
  }

  struct R1 {
    bool valid = false;
    int node = 0;
  };
  struct R2 {
    bool valid = false;
    int node = 0;
    bool self = false;
    int parent = 0;
  };
  struct R3 {
    bool valid = false;
    int node = 0, root = 0;
  };
  struct RootFwd {
    bool valid = false;
    int node = 0, root = 0;
  };
  struct BorderRow {  // a row's border words in B2 and B3
    bool valid = false;
    std::array<BorderPixel, N> left{}, right{};
  };
  struct BorderPushes {  // B4: the edges of a row, in border order
    bool valid = false;
    int n = 0;
    Edge edge[N > 1 ? N - 1 : 1]{};
  };
  struct E1 {  // a node Emit read: its root and sum
    bool valid = false;
    int node = 0, root = 0;
    Object acc;
  };

  const LabellingConfig cfg_;
  int strip_ = 0;
  Phase phase_ = kInit;
  int init_ = 0;
  // Frame position (of the next beat) and errors.
  bool in_frame_ = false;
  int x_ = 0, y_ = 0, lane_ = 0, lane_col_ = 0;
  bool err_pending_ = false, err_frame_ = false, err_sticky_ = false;
  bool tile_overflow_ = false;
  // Emit: its frame's flags and label counts, objects sent.
  bool drain_idle_q_ = false;  // the RTL's drain_idle_q (lanes only)
  bool emitting_ = false, emit_tile_overflow_ = false, emit_err_ = false, object_overflow_ = false;
  int emitted_ = 0;
  std::array<int, N> emit_count_{};
#ifndef __SYNTHESIS__
  std::vector<std::int32_t>* node_map_ = nullptr;  // second pass, not hardware
  std::vector<std::int32_t> live_map_;
#endif
  // Lanes, and with lanes their FIFOs and the pixel each takes next from its FIFO's head.
  std::array<Lane, N> lanes_{};
  std::array<RegFifo<LaneBeat, Params::kLaneFifo>, N> fifo_{};
  std::array<LaneHead, N> ahead_{}, head_{};
  std::array<int, N> sub_{};
  // The border sweep and its merge unit over the whole node space.
  bool border_active_ = false, b1_valid_ = false;
  int border_row_ = 0;
  BorderRow b2_, b3_;
  BorderPushes b4_;
  std::array<Edge, N> border_last_{};
  std::array<bool, N> border_has_last_{};
  EdgeQueue<kBorderQueue> queue_;
  UnionFind uf_;
  // Sweeps.
  Sweep sweep_;
  R1 r1_;
  R2 r2_;
  R3 r3_;
  E1 e1_, e2_;
  bool r4_valid_ = false, r5_valid_ = false;  // the RTL's R4, R5
  Fwd afwd_;
  RootFwd rfwd_;
  // RAMs and their read registers.
  LabellingRams<Params> ram_;
  std::array<int, Params::kNodeSpace> root_ram_{};
  std::array<Object, Params::kNodeSpace> acc_{};
  Reads rd_;
  // Output register.
  bool out_valid_ = false;
  out_type out_;
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// Frames of beats through the stage with no output stalls: beats from `in` (`frames` whole
/// frames back to back), every object and status word to `out` (room for `max_out`), in order;
/// returns how many words were written. The loop is one clock of the stage an iteration: it offers
/// the next beat, which the stage takes when it is ready (in its frame phase, with room in the
/// lane), and writes each word as it leaves, until `frames` status words have left or
/// `max_clocks` run out. The stage's ready looks at the beat's sof, so the beat waits in a
/// look-ahead register (a stream cannot be peeked). What an HLS tool synthesises as the stage's
/// top: the ports are hls::stream (or ArrayIn / ArrayOut).
template <typename Params, typename In, typename Out, if_port<Out> = 0>
int labelling_frame(Labelling<Params>& k, In& in, Out& out, int max_out, int frames,
                    long max_clocks) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=max_out
#pragma HLS INTERFACE s_axilite port=frames
#pragma HLS INTERFACE s_axilite port=max_clocks
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  Lookahead<typename Params::in_beat> next;
  int written = 0, closed = 0;
loop_clock:
  for (long c = 0; c < max_clocks && closed < frames && written < max_out; ++c) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    next.fill(in);
    const bool valid = next.valid;
    if (valid && k.in_ready(next.beat.sof)) next.take();
    k.clock(valid, next.beat, true);
    if (k.out_valid()) {
      out.write(k.out());
      ++written;
      closed += k.out().data.is_status ? 1 : 0;
    }
  }
  return written;
}
#pragma GCC diagnostic pop

/// The frame function over arrays (tests).
template <typename Params>
int labelling_frame(Labelling<Params>& k, const typename Params::in_beat* in, int n,
                    LabelPacket* out, int max_out, int frames, long max_clocks) {
  ArrayIn<typename Params::in_beat> i(in, n);
  ArrayOut<LabelPacket> o(out);
  return labelling_frame(k, i, o, max_out, frames, max_clocks);
}

}  // namespace scw::hls::labelling
