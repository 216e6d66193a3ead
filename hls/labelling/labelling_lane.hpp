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

/// Edges a lane's queue holds; the lane takes a pixel while at most kEdgeQueue - kTakeRoom are
/// queued: the pixel being taken and the five in P1 .. P5, whose edges are not queued yet, may
/// each queue two.
inline constexpr int kEdgeQueue = 16;
inline constexpr int kTakeRoom = 12;

/// A strip's first or last pixel of a row, kept for the strip-border join after the frame.
struct BorderPixel {
  int node1 = 0;  // node + 1, 0 = none
  disp_t d = 0;
};

/// The stage's RAMs and registers that every lane writes in its own bank (a lane's nodes and
/// rows) and the end-of-frame phases read across banks. Lane i's nodes are i * kLaneStride on.
template <typename Params>
struct LabellingRams {
  std::array<int, Params::kNodeSpace> parent{};   // 0: a root; else parent + 1 (a smaller node)
  std::array<Object, Params::kNodeSpace> desc{};  // each node's pixels
  std::array<int, Params::kLanes> count{};     // labels used per lane (registers)
  // Per lane: its strip's first (left) and last (right) pixel of every row.
  std::array<std::array<BorderPixel, Params::kMaxHeight>, Params::kLanes> left{}, right{};
#ifndef __SYNTHESIS__
  std::vector<std::int32_t>* node_map = nullptr;  // second-pass support, not hardware
#endif
};

/// Lane `index` of `Params::kLanes`: columns x0 .. x0 + width - 1 of the image, global tile
/// columns from index * kLaneTilesX; nodes index * kLaneStride .. + kLaneNodes - 1.
template <typename Params>
class LabellingLane {
 public:
  using Rams = LabellingRams<Params>;

  void setup(int index, const LabellingConfig& cfg, int x0, int width) {
    index_ = index;
    cfg_ = cfg;
    x0_ = x0;
    width_ = width;
  }

  /// Whether the lane takes a pixel this clock (if one is offered).
  bool can_take() const { return queue_.count() <= kEdgeQueue - kTakeRoom; }
  /// Nothing in flight: every pixel taken is in its node's descriptor and every edge merged.
  bool idle() const {
    return !p1_.valid && !p2_.valid && !p3_.valid && !p4_valid_ && !s3_valid_ && !s4_valid_ &&
           n_pend2_ == 0 && queue_.count() == 0 && uf_.idle();
  }

  /// P0: take the strip's next pixel.
  void take(disp_t d) {
    s1_next_.valid = true;
    s1_next_.d = is_valid(d, cfg_) ? d : 0;
    s1_next_.x = x_;
    s1_next_.y = y_;
    s1_next_.has_left = x_ > 0;
    s1_next_.has_up = y_ > 0;
    s1_next_.left_same = tcol_ > 0;
    s1_next_.up_same = trow_ > 0;
    if (++tcol_ == cfg_.tile_w) tcol_ = 0;
    if (++x_ == width_) {
      x_ = tcol_ = 0;
      if (++trow_ == cfg_.tile_h) trow_ = 0;
      ++y_;
    }
  }

  /// P1 .. P6 and the merge unit, after P0 (if any) this clock. Returns whether the lane ran
  /// out of labels. The RTL computes the joins in P1 and P2; they depend on the disparities only,
  /// so the model computes them where P3 uses them.
  bool step(Rams& ram) {
    Reads& rd = rd_next_;
    bool overflow = false;
    // P3: decide the node of the pixel P0 took three clocks ago; its edges queue in P5.
    S2 s2_next;
    Edge pushes[2];
    int n_push = 0;
    if (p3_.valid) overflow = decide(ram, rd, s2_next, pushes, n_push);
    // P4 .. P6: the RTL reads the node's descriptor (P3), passes it through the RAM's output
    // register (P4), adds the pixel (P5, forwarding its own last three results) and writes it
    // back (P6). The sum is the same whichever clock computes it, so the model adds in P4; only
    // the clocks until the lane is idle follow the RTL's stages.
    Fwd fwd_next;
    if (s2_.valid) {
      const Object base = (fwd_.valid && fwd_.node == s2_.node) ? fwd_.value : rd_.desc;
      const Object v = narrow(s2_.init ? s2_.pix : merge(base, s2_.pix), Params::kWidths);
      ram.desc[s2_.node] = v;
      fwd_next = {true, s2_.node, v};
    }
    s4_valid_ = s3_valid_;
    s3_valid_ = s2_.valid;
    // Merge unit: one step on the edge at the queue's head.
    ParentPorts pp;
    const bool pop = uf_.clock(queue_, rd_.parent, pp);
    if (pp.rd) rd.parent = ram.parent[pp.rd_addr];
    if (pp.wr) ram.parent[pp.wr_addr] = pp.wr_data;
    queue_.clock(pop, pend2_, n_pend2_);  // P5: the edges P3 found two clocks ago
    for (int i = 0; i < n_pend_; ++i) pend2_[i] = pend_[i];
    n_pend2_ = n_pend_;
    for (int i = 0; i < n_push; ++i) pend_[i] = pushes[i];
    n_pend_ = n_push;
    p4_valid_ = p3_.valid;
    p3_ = p2_;
    p2_ = p1_;
    p1_ = s1_next_;
    s1_next_ = {};
    s2_ = s2_next;
    fwd_ = fwd_next;
    rd_ = rd_next_;
    return overflow;
  }

  /// After the frame's status word: the next frame starts at the strip's top left.
  void end_frame() {
    x_ = y_ = tcol_ = trow_ = 0;
    has_last_edge_ = false;
  }

 private:
  struct S1 {
    bool valid = false;
    disp_t d = 0;  // 0 when not an object pixel
    int x = 0, y = 0;  // x within the strip
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
    Object desc;
  };
  struct Fwd {  // S2's write of the previous clock, for the read issued alongside it
    bool valid = false;
    int node = 0;
    Object value;
  };

  bool decide(Rams& ram, Reads& rd, S2& s2, Edge* pushes, int& n_push) {
    const S1& p = p3_;
    const bool valid = p.d != 0;
    // The row above at this column, as the RTL's row buffer (or, in a strip of 2 or 3 pixels,
    // its last pixels' registers) gives it.
    const disp_t up_d = row_d_[p.x];
    const int up_node1 = row_node1_[p.x];
    const bool jl = valid && p.has_left && left_node1_ != 0 && joins(p.d, left_d_);
    const bool ju = valid && p.has_up && up_node1 != 0 && joins(p.d, up_d);
    int node1 = 0;
    bool alloc = false, overflow = false;
    int& count = ram.count[static_cast<std::size_t>(index_)];
    if (!valid) {
      node1 = 0;
    } else if (jl && p.left_same) {
      node1 = left_node1_;
    } else if (ju && p.up_same) {
      node1 = up_node1;
    } else if (count < Params::kLaneNodes) {
      node1 = index_ * Params::kLaneStride + count + 1;
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
      if (ju && up_node1 != node1) push(up_node1);
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
#ifndef __SYNTHESIS__
    if (ram.node_map)
      (*ram.node_map)[static_cast<std::size_t>(p.y * cfg_.width + x0_ + p.x)] = node1;
#endif
    return overflow;
  }

  int index_ = 0;
  LabellingConfig cfg_;
  int x0_ = 0, width_ = 0;
  // The position of the pixel S0 takes next, within the strip.
  int x_ = 0, y_ = 0, tcol_ = 0, trow_ = 0;
  S1 s1_next_, p1_, p2_, p3_;  // P1 .. P3: taken one .. three clocks ago
  bool p4_valid_ = false;       // a pixel decided last clock
  Edge pend_[2], pend2_[2];     // the edges P3 found one and two clocks ago, queued in P5
  int n_pend_ = 0, n_pend2_ = 0;
  S2 s2_;
  bool s3_valid_ = false, s4_valid_ = false;  // the pixel's descriptor in the RTL's S3, S4
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
