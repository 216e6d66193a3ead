// SPDX-License-Identifier: Apache-2.0
// One lane of the labelling stage: a strip of whole tile columns labelled one pixel per clock
// (S0 .. S2 and the merge unit), clock by clock as the RTL's scw_labelling_lane does it
// (docs/labelling.md).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hls/labelling/edge_queue.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/labelling/union_find.hpp"

namespace scw::hls::labelling {

/// Edges a lane's queue holds; the lane takes a pixel while at most kEdgeQueue - 4 are queued
/// (two from the pixel in decision, two from the pixel being taken).
inline constexpr int kEdgeQueue = 8;

/// A strip's first or last pixel of a row, kept for the strip-border join after the frame.
struct BorderPixel {
  int node1 = 0;  // node + 1, 0 = none
  disp_t d = 0;
};

/// The stage's RAMs and registers that every lane writes in its own bank (a lane's nodes, tiles
/// and rows) and the end-of-frame phases read across banks. Nodes are global numbers, in the
/// order of a one-lane stage, so the objects leave in the same order at any lane count.
template <typename Params>
struct LabellingRams {
  static constexpr int kTiles = Params::kMaxTilesX * Params::kMaxTilesY;
  std::array<int, Params::kNodes> parent{};    // 0: a root; else parent + 1 (a smaller node)
  std::array<Object, Params::kNodes> desc{};   // each node's pixels
  std::array<int, kTiles> count{};             // labels used per tile (registers)
  // Per lane: its strip's first (left) and last (right) pixel of every row.
  std::array<std::array<BorderPixel, Params::kMaxHeight>, Params::kLanes> left{}, right{};
  std::vector<std::int32_t>* node_map = nullptr;  // second-pass support, not hardware
};

/// Lane `index` of `Params::kLanes`: columns x0 .. x0 + width - 1 of the image, global tile
/// columns from index * kLaneTilesX (so its nodes are a bit field away from the lane number).
template <typename Params>
class LabellingLane {
 public:
  static constexpr int TX = Params::kMaxTilesX;
  static constexpr int L = Params::kLabelsPerTile;
  using Rams = LabellingRams<Params>;

  void setup(int index, const LabellingConfig& cfg, int x0, int width) {
    index_ = index;
    cfg_ = cfg;
    x0_ = x0;
    width_ = width;
  }

  /// Whether the lane takes a pixel this clock (if one is offered).
  bool can_take() const { return queue_.count() <= kEdgeQueue - 4; }
  /// Nothing in flight: every pixel taken is in its node's descriptor and every edge merged.
  bool idle() const { return !s1_.valid && !s2_.valid && queue_.count() == 0 && uf_.idle(); }

  /// S0: take the strip's next pixel and read the row buffer.
  void take(disp_t d) {
    s1_next_.valid = true;
    s1_next_.d = is_valid(d, cfg_) ? d : 0;
    s1_next_.x = x_;
    s1_next_.y = y_;
    s1_next_.tile = ty_ * TX + index_ * Params::kLaneTilesX + tx_;
    s1_next_.has_left = x_ > 0;
    s1_next_.has_up = y_ > 0;
    s1_next_.left_same = tcol_ > 0;
    s1_next_.up_same = trow_ > 0;
    rd_next_.up_d = row_d_[x_];
    rd_next_.up_node1 = row_node1_[x_];
    if (++tcol_ == cfg_.tile_w) tcol_ = 0, ++tx_;
    if (++x_ == width_) {
      x_ = tcol_ = tx_ = 0;
      if (++trow_ == cfg_.tile_h) trow_ = 0, ++ty_;
      ++y_;
    }
  }

  /// S1, S2 and the merge unit, after S0 (if any) this clock. Returns whether a tile ran out
  /// of labels.
  bool step(Rams& ram) {
    Reads& rd = rd_next_;
    bool overflow = false;
    // S1: decide the node of the pixel S0 took last clock; queue its edges.
    S2 s2_next;
    Edge pushes[2];
    int n_push = 0;
    if (s1_.valid) overflow = decide(ram, rd, s2_next, pushes, n_push);
    // S2: add the pixel S1 decided last clock to its node's descriptor.
    Fwd fwd_next;
    if (s2_.valid) {
      const Object base = (fwd_.valid && fwd_.node == s2_.node) ? fwd_.value : rd_.desc;
      const Object v = s2_.init ? s2_.pix : merge(base, s2_.pix);
      ram.desc[s2_.node] = v;
      fwd_next = {true, s2_.node, v};
    }
    // Merge unit: one step on the edge at the queue's head.
    ParentPorts pp;
    const bool pop = uf_.clock(queue_, rd_.parent, pp);
    if (pp.rd) rd.parent = ram.parent[pp.rd_addr];
    if (pp.wr) ram.parent[pp.wr_addr] = pp.wr_data;
    queue_.clock(pop, pushes, n_push);
    s1_ = s1_next_;
    s1_next_ = {};
    s2_ = s2_next;
    fwd_ = fwd_next;
    rd_ = rd_next_;
    return overflow;
  }

  /// After the frame's status word: the next frame starts at the strip's top left.
  void end_frame() {
    x_ = y_ = tx_ = ty_ = tcol_ = trow_ = 0;
    has_last_edge_ = false;
  }

 private:
  struct S1 {
    bool valid = false;
    disp_t d = 0;  // 0 when not an object pixel
    int x = 0, y = 0, tile = 0;  // x within the strip
    bool has_left = false, has_up = false, left_same = false, up_same = false;
  };
  struct S2 {
    bool valid = false;
    int node = 0;
    bool init = false;
    Object pix;
  };
  /// The RAMs' read registers: rd_ as of the last edge, rd_next_ what this clock's reads load.
  struct Reads {
    int parent = 0;
    disp_t up_d = 0;
    int up_node1 = 0;
    Object desc;
  };
  struct Fwd {  // S2's write of the previous clock, for the read issued alongside it
    bool valid = false;
    int node = 0;
    Object value;
  };

  bool decide(Rams& ram, Reads& rd, S2& s2, Edge* pushes, int& n_push) {
    const S1& p = s1_;
    const bool valid = p.d != 0;
    const bool jl = valid && p.has_left && left_node1_ != 0 && joins(p.d, left_d_);
    const bool ju = valid && p.has_up && rd_.up_node1 != 0 && joins(p.d, rd_.up_d);
    int node1 = 0;
    bool alloc = false, overflow = false;
    int& count = ram.count[p.tile];
    if (!valid) {
      node1 = 0;
    } else if (jl && p.left_same) {
      node1 = left_node1_;
    } else if (ju && p.up_same) {
      node1 = rd_.up_node1;
    } else if (count < L) {
      node1 = p.tile * L + count + 1;
      ++count;
      alloc = true;
    } else {
      overflow = true;
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
      s2.pix = pixel_object(x0_ + p.x, p.y, p.d);
      rd.desc = ram.desc[node1 - 1];
    }
    row_d_[p.x] = p.d;
    row_node1_[p.x] = node1;
    left_d_ = p.d;
    left_node1_ = node1;
    // The strip's edge columns, for the join across strip borders after the frame.
    if constexpr (Params::kLanes > 1) {
      if (p.x == 0 && index_ > 0) ram.left[index_][p.y] = {node1, p.d};
      if (p.x == width_ - 1 && index_ + 1 < Params::kLanes) ram.right[index_][p.y] = {node1, p.d};
    }
    if (ram.node_map)
      (*ram.node_map)[static_cast<std::size_t>(p.y * cfg_.width + x0_ + p.x)] = node1;
    return overflow;
  }

  int index_ = 0;
  LabellingConfig cfg_;
  int x0_ = 0, width_ = 0;
  // The position of the pixel S0 takes next, within the strip.
  int x_ = 0, y_ = 0, tx_ = 0, ty_ = 0, tcol_ = 0, trow_ = 0;
  S1 s1_, s1_next_;
  S2 s2_;
  Fwd fwd_;
  disp_t left_d_ = 0;
  int left_node1_ = 0;
  Edge last_edge_;
  bool has_last_edge_ = false;
  EdgeQueue<kEdgeQueue> queue_;
  UnionFind uf_;
  std::array<disp_t, Params::kLaneWidthPx> row_d_{};
  std::array<int, Params::kLaneWidthPx> row_node1_{};
  Reads rd_, rd_next_;
};

}  // namespace scw::hls::labelling
