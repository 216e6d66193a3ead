// SPDX-License-Identifier: Apache-2.0
// Labelling kernel: one-pass tiled connected-component labelling of a disparity stream into
// object descriptors, clock by clock as the RTL does it (docs/labelling.md).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/labelling/edge_queue.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/labelling/union_find.hpp"

namespace scw::hls::labelling {

/// Edges the queue holds; the input is taken while at most kEdgeQueue - 4 are queued (two from
/// the pixel in decision, two from the pixel being taken).
inline constexpr int kEdgeQueue = 8;

/// Throws std::invalid_argument naming the field if `cfg` does not fit a stage built with
/// `Params`.
template <typename Params>
void check_config(const LabellingConfig& cfg) {
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
}

/// The stage. Phases (docs/labelling.md):
///   kInit     after reset: clear the parent RAM, one node per clock
///   kFrame    take beats: S0 takes a pixel and reads the row buffer; S1 decides its node and
///             queues edges; S2 adds it to its node's descriptor; the merge unit runs alongside
///   kDrain    after the frame's last pixel (or a sof in mid-frame): wait for S1, S2, the queue
///             and the merge unit
///   kResolve  every used node in ascending order: its root (parent[] points to smaller nodes
///             only, so the parent's root is already known) and its descriptor into the root's
///   kEmit     every used node again: roots of at least min_area pixels leave as objects, up to
///             MaxObjects; then the status word with `last`
template <typename Params>
class Labelling {
 public:
  static constexpr int W = Params::kMaxWidthPx;
  static constexpr int TX = Params::kMaxTilesX;
  static constexpr int TY = Params::kMaxTilesY;
  static constexpr int L = Params::kLabelsPerTile;
  static constexpr int kNodes = Params::kNodes;
  static constexpr int kTiles = TX * TY;
  using in_type = typename Params::in_beat;
  using out_type = LabelPacket;
  enum Phase { kInit, kFrame, kDrain, kResolve, kEmit };

  explicit Labelling(const LabellingConfig& cfg) : cfg_(cfg) { check_config<Params>(cfg); }

  // ---- what the ports show this clock (registers only, except the mid-frame sof check) ----
  bool in_ready(bool in_sof) const {
    return phase_ == kFrame && queue_.count() <= kEdgeQueue - 4 && !(in_frame_ && in_sof);
  }
  bool out_valid() const { return out_valid_; }
  const out_type& out() const { return out_; }
  bool error() const { return err_sticky_; }
  Phase phase() const { return phase_; }

  /// Second-pass support (not part of the hardware): if set, S1 writes each pixel's node + 1
  /// (0 = none) at y * width + x; after kResolve, root(node) gives its object's root.
  void set_node_map(std::vector<std::int32_t>* m) { node_map_ = m; }
  int root(int node) const { return root_ram_[node]; }

  /// One clock edge with the inputs of this clock.
  void clock(bool in_valid, const in_type& in, bool out_ready) {
    const bool take = in_valid && in_ready(in.sof);
    const bool sof_mid = phase_ == kFrame && in_frame_ && in_valid && in.sof;
    const bool out_en = !out_valid_ || out_ready;
    if (out_valid_ && out_ready) out_valid_ = false;
    // RAM reads issued this clock land in the read registers at the edge. Stages run in
    // pipeline order, each RAM read before that RAM's write (read-first RAMs), and every
    // decision looks at the registers of before the edge (rd_, s1_, ...).
    Reads rd = rd_;
    ParentPorts pp;
    switch (phase_) {
      case kInit:
        pp.wr = true;
        pp.wr_addr = init_;
        pp.wr_data = 0;
        if (++init_ == kNodes) phase_ = kFrame;
        break;
      case kFrame:
      case kDrain:
        frame_clock(take, sof_mid, in, rd, pp);
        break;
      case kResolve:
        resolve_clock(rd, pp);
        break;
      case kEmit:
        emit_clock(out_en, rd);
        break;
    }
    if (pp.rd) rd.parent = parent_[pp.rd_addr];
    if (pp.wr) parent_[pp.wr_addr] = pp.wr_data;
    rd_ = rd;
  }

 private:
  /// The RAMs' read registers.
  struct Reads {
    int parent = 0;
    std::uint16_t up_d = 0;
    int up_node1 = 0;
    Object desc;
    Object acc;
    int root = 0;
  };
  struct S1 {
    bool valid = false;
    disp_t d = 0;  // 0 when not an object pixel
    int x = 0, y = 0, tile = 0;
    bool has_left = false, has_up = false, left_same = false, up_same = false;
  };
  struct S2 {
    bool valid = false;
    int node = 0;
    bool init = false;
    Object pix;
  };
  struct Fwd {  // a write of the previous clock, for the read issued alongside it
    bool valid = false;
    int node = 0;
    Object value;
  };
  /// A node iterator over the used (tile, label) pairs, ascending; an empty tile costs a clock.
  struct Sweep {
    bool active = false;
    int tile = 0, label = 0;
  };

  // ---------------------------------------------------------------- kFrame and kDrain
  void frame_clock(bool take, bool sof_mid, const in_type& in, Reads& rd, ParentPorts& pp) {
    const bool drained = phase_ == kDrain && !s1_.valid && !s2_.valid &&
                         queue_.count() == 0 && uf_.idle();
    // S0: take a beat, read the row buffer.
    S1 s1_next;
    if (take) accept(in, rd, s1_next);
    // S1: decide the node of the pixel S0 took last clock; queue its edges.
    S2 s2_next;
    Edge pushes[2];
    int n_push = 0;
    if (s1_.valid) decide(rd, s2_next, pushes, n_push);
    // S2: add the pixel S1 decided last clock to its node's descriptor.
    Fwd fwd_next;
    if (s2_.valid) {
      const Object base = (fwd_.valid && fwd_.node == s2_.node) ? fwd_.value : rd_.desc;
      const Object v = s2_.init ? s2_.pix : merge(base, s2_.pix);
      desc_[s2_.node] = v;
      fwd_next = {true, s2_.node, v};
    }
    // Merge unit: one step on the edge at the queue's head.
    const bool pop = uf_.clock(queue_, rd_.parent, pp);
    queue_.clock(pop, pushes, n_push);
    if (sof_mid) {  // a sof in mid-frame: close the frame early, take the sof afterwards
      err_frame_ = err_sticky_ = true;
      in_frame_ = false;
      phase_ = kDrain;
    }
    if (drained) {
      phase_ = kResolve;
      sweep_ = {true, 0, 0};
    }
    s1_ = s1_next;
    s2_ = s2_next;
    fwd_ = fwd_next;
  }

  void accept(const in_type& in, Reads& rd, S1& s1) {
    if (!in_frame_) {
      if (!in.sof) {  // a beat outside any frame: dropped, flagged on the next frame
        err_pending_ = err_sticky_ = true;
        return;
      }
      in_frame_ = true;
      err_frame_ = err_pending_;
      err_pending_ = false;
      x_ = y_ = tx_ = ty_ = tcol_ = trow_ = 0;
    }
    if (in.eol != (x_ == cfg_.width - 1)) err_frame_ = err_sticky_ = true;
    const disp_t d = in.px[0];
    s1.valid = true;
    s1.d = is_valid(d, cfg_) ? d : 0;
    s1.x = x_;
    s1.y = y_;
    s1.tile = ty_ * TX + tx_;
    s1.has_left = x_ > 0;
    s1.has_up = y_ > 0;
    s1.left_same = tcol_ > 0;
    s1.up_same = trow_ > 0;
    rd.up_d = row_d_[x_];
    rd.up_node1 = row_node1_[x_];
    // Advance the raster and tile counters.
    if (++tcol_ == cfg_.tile_w) tcol_ = 0, ++tx_;
    if (++x_ == cfg_.width) {
      x_ = tcol_ = tx_ = 0;
      if (++trow_ == cfg_.tile_h) trow_ = 0, ++ty_;
      if (++y_ == cfg_.height) {  // the frame's last pixel
        in_frame_ = false;
        phase_ = kDrain;
      }
    }
  }

  void decide(Reads& rd, S2& s2, Edge* pushes, int& n_push) {
    const S1& p = s1_;
    const bool valid = p.d != 0;
    const bool jl = valid && p.has_left && left_node1_ != 0 && joins(p.d, left_d_);
    const bool ju = valid && p.has_up && rd_.up_node1 != 0 && joins(p.d, rd_.up_d);
    int node1 = 0;
    bool alloc = false;
    if (!valid) {
      node1 = 0;
    } else if (jl && p.left_same) {
      node1 = left_node1_;
    } else if (ju && p.up_same) {
      node1 = rd_.up_node1;
    } else if (count_[p.tile] < L) {
      node1 = p.tile * L + count_[p.tile] + 1;
      ++count_[p.tile];
      alloc = true;
    } else {
      tile_overflow_ = true;
    }
    if (node1 != 0) {
      auto push = [&](int from1) {
        const Edge e{from1 - 1, node1 - 1};
        if (has_last_edge_ && e == last_edge_) return;  // same as the edge just queued
        pushes[n_push++] = e;
        last_edge_ = e;
        has_last_edge_ = true;
      };
      if (jl && left_node1_ != node1) push(left_node1_);
      if (ju && rd_.up_node1 != node1) push(rd_.up_node1);
      s2.valid = true;
      s2.node = node1 - 1;
      s2.init = alloc;
      s2.pix = pixel_object(p.x, p.y, p.d);
      rd.desc = desc_[node1 - 1];
    }
    row_d_[p.x] = p.d;
    row_node1_[p.x] = node1;
    left_d_ = p.d;
    left_node1_ = node1;
    if (node_map_) (*node_map_)[static_cast<std::size_t>(p.y * cfg_.width + p.x)] = node1;
  }

  // ---------------------------------------------------------------- kResolve
  void resolve_clock(Reads& rd, ParentPorts& pp) {
    const bool done = !sweep_.active && !r1_.valid && !r2_.valid && !r3_.valid;
    // R0: the next node; read its parent[].
    R1 r1_next;
    int node = 0;
    if (next_node(node)) {
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
      rd.desc = desc_[r2_.node];
      rd.acc = acc_[root];
      r3_next = {true, r2_.node, root};
    }
    // R3: the node's descriptor into its root's (a root starts its own).
    Fwd afwd_next;
    if (r3_.valid) {
      Object v;
      if (r3_.root == r3_.node) {
        v = rd_.desc;
      } else {
        const Object base = (afwd_.valid && afwd_.node == r3_.root) ? afwd_.value : rd_.acc;
        v = merge(base, rd_.desc);
      }
      acc_[r3_.root] = v;
      afwd_next = {true, r3_.root, v};
    }
    if (done) {
      phase_ = kEmit;
      sweep_ = {true, 0, 0};
    }
    r1_ = r1_next;
    r2_ = r2_next;
    r3_ = r3_next;
    afwd_ = afwd_next;
    rfwd_ = rfwd_next;
  }

  /// Steps the sweep; returns whether this clock yields a node (an empty tile yields none).
  bool next_node(int& node) {
    if (!sweep_.active) return false;
    const int t = sweep_.tile;
    const bool yields = count_[t] > 0;
    node = t * L + sweep_.label;
    if (yields && sweep_.label + 1 < count_[t]) {
      ++sweep_.label;
    } else {
      sweep_.label = 0;
      if (++sweep_.tile == kTiles) sweep_.active = false;
    }
    return yields;
  }

  // ---------------------------------------------------------------- kEmit
  void emit_clock(bool out_en, Reads& rd) {
    const bool swept = !sweep_.active && !e1_.valid;
    bool consumed = !e1_.valid;
    if (e1_.valid) {
      const bool is_object = rd_.root == e1_.node && rd_.acc.area >= static_cast<std::uint32_t>(
                                                                         cfg_.min_area);
      if (!is_object) {
        consumed = true;
      } else if (emitted_ >= Params::kMaxObjects) {
        object_overflow_ = true;
        consumed = true;
      } else if (out_en) {
        load_out(LabelWord{false, rd_.acc, {}}, false);
        ++emitted_;
        consumed = true;
      }
    }
    if (!consumed) return;  // the read registers hold the stalled node's words
    E1 e1_next;
    int node = 0;
    if (next_node(node)) {
      e1_next = {true, node};
      rd.root = root_ram_[node];
      rd.acc = acc_[node];
    } else if (swept && out_en) {  // all nodes out: the status word
      FrameStatus st;
      st.objects = static_cast<std::uint32_t>(emitted_);
      st.tile_overflow = tile_overflow_;
      st.object_overflow = object_overflow_;
      st.stream_error = err_frame_;
      load_out(LabelWord{true, {}, st}, true);
      end_frame();
      return;
    }
    e1_ = e1_next;
  }

  void load_out(const LabelWord& w, bool last) {
    out_valid_ = true;
    out_.data = w;
    out_.last = last;
  }

  void end_frame() {
    phase_ = kFrame;
    e1_ = {};
    count_.fill(0);
    emitted_ = 0;
    tile_overflow_ = object_overflow_ = err_frame_ = false;
    has_last_edge_ = false;
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
  using E1 = R1;

  const LabellingConfig cfg_;
  Phase phase_ = kInit;
  int init_ = 0;
  // Frame position and errors.
  bool in_frame_ = false;
  int x_ = 0, y_ = 0, tx_ = 0, ty_ = 0, tcol_ = 0, trow_ = 0;
  bool err_pending_ = false, err_frame_ = false, err_sticky_ = false;
  bool tile_overflow_ = false, object_overflow_ = false;
  int emitted_ = 0;
  // Pixel pipeline.
  S1 s1_;
  S2 s2_;
  Fwd fwd_, afwd_;
  RootFwd rfwd_;
  disp_t left_d_ = 0;
  int left_node1_ = 0;
  Edge last_edge_;
  bool has_last_edge_ = false;
  std::array<int, kTiles> count_{};
  EdgeQueue<kEdgeQueue> queue_;
  UnionFind uf_;
  // Sweeps.
  Sweep sweep_;
  R1 r1_;
  R2 r2_;
  R3 r3_;
  E1 e1_;
  // RAMs and their read registers.
  std::array<disp_t, W> row_d_{};
  std::array<int, W> row_node1_{};
  std::array<int, kNodes> parent_{};
  std::array<int, kNodes> root_ram_{};
  std::array<Object, kNodes> desc_{};
  std::array<Object, kNodes> acc_{};
  Reads rd_;
  // Output register.
  bool out_valid_ = false;
  out_type out_;
  std::vector<std::int32_t>* node_map_ = nullptr;
};

}  // namespace scw::hls::labelling
