// SPDX-License-Identifier: Apache-2.0
// Bounded, named FIFO channel: the C++ twin of scw_fifo and the wire between sim/ components.
#pragma once

#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hls/common/beat.hpp"

namespace scw::sim {

/// Cycle stamps of one frame on one channel; -1 = not seen. A transfer in cycle c is the
/// valid && ready of cycle c.
struct FrameStamp {
  std::int64_t first_push = -1;
  std::int64_t last_push = -1;
  std::int64_t first_pop = -1;
  std::int64_t last_pop = -1;
};

/// Type-erased view of a channel, for the simulator's reports and deadlock detection.
class ChannelBase {
 public:
  ChannelBase(std::string name, int depth) : name_(std::move(name)), depth_(depth) {
    if (depth_ < 1) throw std::invalid_argument("FIFO '" + name_ + "' needs a depth >= 1");
  }
  virtual ~ChannelBase() = default;
  ChannelBase(const ChannelBase&) = delete;
  ChannelBase& operator=(const ChannelBase&) = delete;

  const std::string& name() const { return name_; }
  int depth() const { return depth_; }
  virtual int size() const = 0;
  int max_occupancy() const { return max_occupancy_; }
  std::uint64_t pushes() const { return pushes_; }
  std::uint64_t pops() const { return pops_; }
  const std::vector<FrameStamp>& frames() const { return frames_; }
  /// True if a beat entered or left during the last committed cycle.
  bool moved() const { return moved_; }

  /// The clock edge that ends cycle `cycle`: applies this cycle's pop and push.
  virtual void commit(std::int64_t cycle) = 0;

  // Endpoint names, filled in when components connect, so reports say who waits on whom.
  std::string producer = "?";
  std::string consumer = "?";

 protected:
  FrameStamp& stamp(int frame) {
    if (frame >= static_cast<int>(frames_.size())) frames_.resize(static_cast<std::size_t>(frame) + 1);
    return frames_[static_cast<std::size_t>(frame)];
  }

  std::string name_;
  int depth_;
  int max_occupancy_ = 0;
  std::uint64_t pushes_ = 0;
  std::uint64_t pops_ = 0;
  bool moved_ = false;
  std::vector<FrameStamp> frames_;
};

/// A FIFO with registered flags, as rtl_models/common/scw_fifo.sv: `can_push()`/`can_pop()`
/// reflect the state at the start of the cycle, so a beat pushed in cycle t is visible in
/// t + 1 and a slot freed in t can be refilled in t + 1. That makes the order in which
/// components are evaluated irrelevant.
template <typename T>
class Fifo : public ChannelBase {
 public:
  using value_type = T;
  using ChannelBase::ChannelBase;

  int size() const override { return static_cast<int>(q_.size()); }
  bool can_push() const { return size() < depth_; }
  bool can_pop() const { return !q_.empty(); }
  const T& front() const {
    if (q_.empty()) throw std::logic_error("FIFO '" + name_ + "': front() on empty FIFO");
    return q_.front();
  }
  void push(const T& v) {
    if (!can_push() || push_.pending)
      throw std::logic_error("FIFO '" + name_ + "': push without space (check can_push)");
    push_.pending = true;
    push_.beat = v;
  }
  /// Keeps a copy of every beat pushed from now on (a probe on the link, for pictures of a
  /// stage's output); off by default.
  void record(bool on) { recording_ = on; }
  const std::vector<T>& recorded() const { return recorded_; }
  /// Forgets what was recorded so far (a long run takes its pictures frame by frame).
  void clear_recorded() { recorded_.clear(); }
  void pop() {
    if (!can_pop() || pop_.pending)
      throw std::logic_error("FIFO '" + name_ + "': pop of an empty FIFO (check can_pop)");
    pop_.pending = true;
  }

  void commit(std::int64_t cycle) override {
    if (!pop_.pending && !push_.pending) {
      // Most FIFOs are idle most cycles: nothing is written then, so a FIFO between two threads
      // (Simulator's lanes) keeps its cache lines where they are.
      if (moved_) moved_ = false;
      return;
    }
    moved_ = true;
    if (pop_.pending) {
      pop_side_.note(*this, q_.front(), cycle, &FrameStamp::first_pop, &FrameStamp::last_pop);
      q_.pop_front();
      ++pops_;
    }
    if (push_.pending) {
      push_side_.note(*this, push_.beat, cycle, &FrameStamp::first_push, &FrameStamp::last_push);
      if (recording_) recorded_.push_back(push_.beat);
      q_.push_back(push_.beat);
      ++pushes_;
    }
    pop_.pending = false;
    push_.pending = false;
    if (size() > max_occupancy_) max_occupancy_ = size();
  }

 private:
  std::deque<T> q_;
  // What the producer and the consumer write in a cycle, each on cache lines of its own: with
  // the two on different threads (Simulator's lanes) neither then takes the other's lines away
  // while both evaluate.
  struct alignas(64) PushSide {
    T beat{};
    bool pending = false;
  };
  struct alignas(64) PopSide {
    bool pending = false;
  };
  PushSide push_;
  PopSide pop_;
  bool recording_ = false;
  std::vector<T> recorded_;
  /// Frame tracking of one end (push or pop) of the FIFO.
  struct Side {
    int frame = -1;
    bool after_last = true;  // a packet stream's first beat starts a frame
    void note(Fifo& f, const T& v, std::int64_t cycle, std::int64_t FrameStamp::*first,
              std::int64_t FrameStamp::*last) {
      if (hls::starts_frame(v, after_last)) ++frame;
      after_last = hls::ends_burst(v);
      if (frame < 0) return;  // beats before the first frame start are not stamped
      FrameStamp& s = f.stamp(frame);
      if (s.*first < 0) s.*first = cycle;
      s.*last = cycle;
    }
  };
  Side push_side_;
  Side pop_side_;
};

}  // namespace scw::sim
