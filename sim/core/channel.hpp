// SPDX-License-Identifier: Apache-2.0
// Bounded, named FIFO channel: the C++ twin of scw_fifo and the wire between sim/ components.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
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
  virtual std::uint64_t pushes() const = 0;
  virtual std::uint64_t pops() const = 0;
  /// Per frame, the push end's stamps (first_push, last_push) and the pop end's (first_pop,
  /// last_pop), each end's own table (between cycles).
  const std::vector<FrameStamp>& push_frames() const { return push_frames_; }
  const std::vector<FrameStamp>& pop_frames() const { return pop_frames_; }
  /// Per frame, both ends' stamps (between cycles): the two tables merged, made at each call
  /// (for reports; a loop over frames takes it once).
  std::vector<FrameStamp> frames() const {
    std::vector<FrameStamp> all(std::max(push_frames_.size(), pop_frames_.size()));
    for (std::size_t i = 0; i < push_frames_.size(); ++i) {
      all[i].first_push = push_frames_[i].first_push;
      all[i].last_push = push_frames_[i].last_push;
    }
    for (std::size_t i = 0; i < pop_frames_.size(); ++i) {
      all[i].first_pop = pop_frames_[i].first_pop;
      all[i].last_pop = pop_frames_[i].last_pop;
    }
    return all;
  }
  /// True if a beat entered or left during the last committed cycle.
  bool moved() const { return moved_; }

  /// The clock edge that ends cycle `cycle`: applies this cycle's pop and push.
  virtual void commit(std::int64_t cycle) = 0;

  /// A FIFO whose producer and consumer step on the simulator's two threads (Simulator,
  /// docs/sim.md, "Two threads") is split: each end commits its own half on its own thread
  /// (commit_push, commit_pop), and after both threads have, each end takes in the other's
  /// count for the next cycle (see_pops on the producer's thread, see_pushes on the
  /// consumer's). The beats, flags and stamps are those of commit(). Set between cycles.
  virtual void split(bool on) = 0;
  /// Whether a beat entered (left) in cycle `cycle`.
  virtual bool commit_push(std::int64_t cycle) = 0;
  virtual bool commit_pop(std::int64_t cycle) = 0;
  virtual void see_pops(std::int64_t cycle) = 0;
  virtual void see_pushes(std::int64_t cycle) = 0;

  // Endpoint names, filled in when components connect, so reports say who waits on whom.
  std::string producer = "?";
  std::string consumer = "?";

 protected:
  /// The stamps of frame `frame` at one end (each end writes only its own vector).
  static FrameStamp& stamp(std::vector<FrameStamp>& v, int frame) {
    if (frame >= static_cast<int>(v.size())) v.resize(static_cast<std::size_t>(frame) + 1);
    return v[static_cast<std::size_t>(frame)];
  }

  std::string name_;
  int depth_;
  int max_occupancy_ = 0;
  bool moved_ = false;
  std::vector<FrameStamp> push_frames_;
  std::vector<FrameStamp> pop_frames_;
};

/// A FIFO with registered flags, as rtl_models/common/scw_fifo.sv: `can_push()`/`can_pop()`
/// reflect the state at the start of the cycle, so a beat pushed in cycle t is visible in
/// t + 1 and a slot freed in t can be refilled in t + 1. That makes the order in which
/// components are evaluated irrelevant.
///
/// The beats are a ring of depth + 1 slots, counted by the number of beats each end has moved:
/// the producer writes a slot the consumer cannot be reading (at most depth - 1 are held when it
/// may push), so the two ends need no lock when they are on two threads.
/// `final`: commit() calls commit_pop() and commit_push() on every cycle a beat moves, and they
/// then need no virtual call.
template <typename T>
class Fifo final : public ChannelBase {
 public:
  using value_type = T;
  Fifo(std::string name, int depth)
      : ChannelBase(std::move(name), depth), ring_(static_cast<std::size_t>(depth) + 1) {}

  /// Between cycles (an end's own view during one).
  int size() const override { return static_cast<int>(push_.count - pop_.count); }
  std::uint64_t pushes() const override { return push_.count; }
  std::uint64_t pops() const override { return pop_.count; }
  bool can_push() const {
    return push_.count - push_.pops_seen < static_cast<std::uint64_t>(depth_);
  }
  bool can_pop() const { return pop_.pushes_seen != pop_.count; }
  const T& front() const {
    if (!can_pop()) throw std::logic_error("FIFO '" + name_ + "': front() on empty FIFO");
    return ring_[pop_.count % ring_.size()];
  }
  void push(const T& v) {
    if (!can_push() || push_.pending)
      throw std::logic_error("FIFO '" + name_ + "': push without space (check can_push)");
    push_.pending = true;
    ring_[push_.count % ring_.size()] = v;
  }
  /// Keeps a copy of every beat pushed from now on (a probe on the link, for pictures of a
  /// stage's output); off by default.
  void record(bool on) { push_.recording = on; }
  const std::vector<T>& recorded() const { return push_.recorded; }
  /// Forgets what was recorded so far (a long run takes its pictures frame by frame).
  void clear_recorded() { push_.recorded.clear(); }
  void pop() {
    if (!can_pop() || pop_.pending)
      throw std::logic_error("FIFO '" + name_ + "': pop of an empty FIFO (check can_pop)");
    pop_.pending = true;
  }

  void commit(std::int64_t cycle) override {
    if (!pop_.pending && !push_.pending) {
      // Most FIFOs are idle most cycles: nothing is written then.
      if (moved_) moved_ = false;
      return;
    }
    moved_ = true;
    commit_pop(cycle);
    commit_push(cycle);
    push_.pops_seen = pop_.count;
    pop_.pushes_seen = push_.count;
    if (size() > max_occupancy_) max_occupancy_ = size();
  }

  void split(bool on) override { split_ = on; }
  bool commit_push(std::int64_t cycle) override {
    const bool pushed = push_.pending;
    if (pushed) {
      const T& v = ring_[push_.count % ring_.size()];
      push_.side.note(push_frames_, v, cycle, &FrameStamp::first_push, &FrameStamp::last_push);
      if (push_.recording) push_.recorded.push_back(v);
      ++push_.count;
      push_.pending = false;
    }
    if (split_) published_pushes_[cycle & 1].store(push_.count, std::memory_order_relaxed);
    return pushed;
  }
  bool commit_pop(std::int64_t cycle) override {
    const bool popped = pop_.pending;
    if (popped) {
      pop_.side.note(pop_frames_, ring_[pop_.count % ring_.size()], cycle, &FrameStamp::first_pop,
                     &FrameStamp::last_pop);
      ++pop_.count;
      pop_.pending = false;
    }
    if (split_) published_pops_[cycle & 1].store(pop_.count, std::memory_order_relaxed);
    return popped;
  }
  // Split, each end publishes its count after every cycle in one of two slots by the cycle's
  // parity, and the other end reads that cycle's slot: an end a cycle ahead writes the other
  // slot, and it can be no further ahead (the simulator's meeting points order these accesses).
  // Each also fetches the slot its end touches next, which the other thread wrote or read last:
  // the fetch runs beside the rest of the cycle instead of stalling the push or front() in it.
  void see_pops(std::int64_t cycle) override {
    push_.pops_seen = published_pops_[cycle & 1].load(std::memory_order_relaxed);
    if (size_seen() > max_occupancy_) max_occupancy_ = size_seen();
    if (can_push()) __builtin_prefetch(&ring_[push_.count % ring_.size()], 1);
  }
  void see_pushes(std::int64_t cycle) override {
    pop_.pushes_seen = published_pushes_[cycle & 1].load(std::memory_order_relaxed);
    if (can_pop()) __builtin_prefetch(&ring_[pop_.count % ring_.size()]);
  }

 private:
  /// Frame tracking of one end (push or pop) of the FIFO.
  struct Side {
    int frame = -1;
    bool after_last = true;  // a packet stream's first beat starts a frame
    void note(std::vector<FrameStamp>& stamps, const T& v, std::int64_t cycle,
              std::int64_t FrameStamp::*first, std::int64_t FrameStamp::*last) {
      if (hls::starts_frame(v, after_last)) ++frame;
      after_last = hls::ends_burst(v);
      if (frame < 0) return;  // beats before the first frame start are not stamped
      FrameStamp& s = stamp(stamps, frame);
      if (s.*first < 0) s.*first = cycle;
      s.*last = cycle;
    }
  };
  int size_seen() const { return static_cast<int>(push_.count - push_.pops_seen); }

  std::vector<T> ring_;
  // What each end writes, on cache lines of its own: with the two on different threads neither
  // takes the other's lines away while both evaluate.
  struct alignas(64) PushEnd {
    std::uint64_t count = 0;      // beats pushed
    std::uint64_t pops_seen = 0;  // beats popped by the start of this cycle
    bool pending = false;
    bool recording = false;
    std::vector<T> recorded;
    Side side;
  };
  struct alignas(64) PopEnd {
    std::uint64_t count = 0;        // beats popped
    std::uint64_t pushes_seen = 0;  // beats pushed by the start of this cycle
    bool pending = false;
    Side side;
  };
  PushEnd push_;
  PopEnd pop_;
  bool split_ = false;
  alignas(64) std::atomic<std::uint64_t> published_pushes_[2] = {};
  alignas(64) std::atomic<std::uint64_t> published_pops_[2] = {};
};

}  // namespace scw::sim
