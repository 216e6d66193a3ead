// SPDX-License-Identifier: Apache-2.0
// The clock: steps C++ models and Verilated RTL alike, connected by bounded FIFOs, and reports
// FIFO occupancy, per-frame stage timestamps and deadlocks by name.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sim/core/channel.hpp"
#include "sim/core/lane_thread.hpp"

namespace scw::sim {

/// Anything the clock steps. `eval()` looks at its input FIFOs' heads and its output FIFOs'
/// space and requests pops and pushes; `tick()` is its own clock edge. FIFOs commit after every
/// component has ticked, so evaluation order never matters.
class Component {
 public:
  explicit Component(std::string name) : name_(std::move(name)) {}
  virtual ~Component() = default;
  Component(const Component&) = delete;
  Component& operator=(const Component&) = delete;

  const std::string& name() const { return name_; }
  virtual void eval() = 0;
  virtual void tick() = 0;

  const std::vector<ChannelBase*>& inputs() const { return inputs_; }
  const std::vector<ChannelBase*>& outputs() const { return outputs_; }

 protected:
  void connect_in(ChannelBase& c) {
    c.consumer = name_;
    inputs_.push_back(&c);
  }
  void connect_out(ChannelBase& c) {
    c.producer = name_;
    outputs_.push_back(&c);
  }

 private:
  std::string name_;
  std::vector<ChannelBase*> inputs_;
  std::vector<ChannelBase*> outputs_;
};

/// Thrown when no beat has moved on any FIFO for the deadlock window. `stuck()` names the
/// FIFOs that hold the pipeline: the full ones (their producers wait), or if none is full, the
/// non-empty ones.
class DeadlockError : public std::runtime_error {
 public:
  DeadlockError(const std::string& report, std::vector<std::string> stuck)
      : std::runtime_error(report), stuck_(std::move(stuck)) {}
  const std::vector<std::string>& stuck() const { return stuck_; }

 private:
  std::vector<std::string> stuck_;
};

/// Per frame at one stage boundary: first and last beat in (accepted from the input FIFOs)
/// and out (pushed to the output FIFOs); -1 = not seen.
struct StageFrame {
  std::int64_t first_in = -1;
  std::int64_t last_in = -1;
  std::int64_t first_out = -1;
  std::int64_t last_out = -1;
};

struct StageReport {
  std::string name;
  std::vector<StageFrame> frames;
};

struct FifoReport {
  std::string name;
  std::string producer;
  std::string consumer;
  int depth = 0;
  int max_occupancy = 0;
  std::uint64_t beats = 0;
};

struct SimReport {
  std::int64_t cycles = 0;
  std::vector<FifoReport> fifos;
  std::vector<StageReport> stages;
  /// Human-readable tables (FIFOs, then per-frame stage timestamps).
  std::string text() const;
};

/// Throws std::invalid_argument unless `threads` is a count a Simulator takes: 1, or 2 (lane 1
/// on a second thread). `what` names the count in the message ("--threads" for a command, which
/// asks before it sets up a run).
void check_threads(int threads, const std::string& what);

class Simulator {
 public:
  /// `threads` 2: the components added to lane 1 (add_to) step on a second thread, beside the
  /// rest; every result and report is the same as with 1, since FIFOs commit after every
  /// component has ticked (docs/sim.md, "Two threads").
  explicit Simulator(int threads = 1);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  int threads() const { return lane_ ? 2 : 1; }

  /// A new bounded FIFO owned by the simulator.
  template <typename T>
  Fifo<T>& fifo(std::string name, int depth) {
    auto f = std::make_unique<Fifo<T>>(std::move(name), depth);
    Fifo<T>& ref = *f;
    channels_.push_back(std::move(f));
    return ref;
  }
  /// A new component owned by the simulator; constructor arguments are forwarded.
  template <typename C, typename... Args>
  C& add(Args&&... args) {
    return keep(std::make_unique<C>(std::forward<Args>(args)...), 0);
  }
  /// A new component on `lane` (0 or 1), made by `make()` (a std::unique_ptr to it) on the
  /// thread that will step it. With one thread, lane 1 is lane 0.
  template <typename Make>
  auto& add_to(int lane, Make&& make) {
    if (lane != 0 && lane != 1) throw std::invalid_argument("a component's lane is 0 or 1");
    decltype(make()) c;
    if (lane == 1 && lane_) {
      lane_->call([&] { c = make(); });
    } else {
      c = make();
    }
    return keep(std::move(c), lane);
  }

  /// One clock cycle: every component evaluates, every component ticks, every FIFO commits.
  void step();
  /// Steps until `done()` holds. Throws DeadlockError when no FIFO moves for the deadlock
  /// window, std::runtime_error after `max_cycles`. With two threads, `done()` is asked while
  /// lane 1 may still be taking in the cycle: it reads only lane 0's components.
  void run_until(const std::function<bool()>& done, std::int64_t max_cycles);

  std::int64_t cycle() const { return cycle_; }
  /// Cycles without any FIFO transfer after which the run counts as deadlocked. Set it above
  /// the longest internal latency of any component (default 65,536).
  void set_deadlock_window(std::int64_t cycles) { deadlock_window_ = cycles; }

  SimReport report() const;
  /// The text of a deadlock report for the current state.
  std::string deadlock_report(std::vector<std::string>* stuck = nullptr) const;

 private:
  template <typename C>
  C& keep(std::unique_ptr<C> c, int lane) {
    C& ref = *c;
    lanes_[lane_ ? lane : 0].push_back(&ref);
    components_.push_back(std::move(c));
    return ref;
  }
  /// A lane's part of a cycle: its components evaluate and tick, the FIFOs only they use commit
  /// and so do the lane's ends of the split FIFOs (ChannelBase::split), on the thread that
  /// touched them; whether a beat moved.
  bool step_lane(int lane, std::int64_t cycle);
  /// The lane's ends of the split FIFOs take in the other lane's part of `cycle`.
  void see_lane(int lane, std::int64_t cycle);
  /// Lane 1's part of a cycle on its thread, meeting lane 0 after both have committed.
  void lane_cycle();
  /// One cycle; with two threads, lane 1 may still be taking in the cycle when it returns.
  void step_once();
  /// run_until on two threads: lane 0 decides on the next cycle as soon as its part of this one
  /// is done, and lane 1 starts it without waiting to be told.
  void run_two(const std::function<bool()>& done, std::int64_t limit, std::int64_t max_cycles);
  /// Lane 0's part of the cycle, lane 1's having been started: whether a beat moved in it.
  bool lane0_part();
  /// Lane 0's part of the meeting point of `cycle`, whose own part moved beats or not.
  void meet(std::int64_t cycle, bool moved);
  /// Throws DeadlockError, or std::runtime_error at the cycle limit.
  void check_progress(std::int64_t limit, std::int64_t max_cycles);
  /// Waits until lane 1's thread is idle (rethrowing its error), before anything else touches
  /// its components or FIFOs.
  void settle_lane();
  /// Which FIFOs each lane commits, and which are split between the two.
  void assign_fifos();
  /// assign_fifos() again if a component or FIFO was added since it last ran.
  void reassign_if_added();

  std::vector<std::unique_ptr<ChannelBase>> channels_;
  std::vector<std::unique_ptr<Component>> components_;  // in the order added (reports)
  std::vector<Component*> lanes_[2];                    // what each thread steps
  std::vector<ChannelBase*> own_fifos_[2];              // used by one lane's components only
  std::vector<ChannelBase*> push_ends_[2];              // split FIFOs fed from each lane
  std::vector<ChannelBase*> pop_ends_[2];               // split FIFOs drained by each lane
  std::size_t assigned_ = 0;                            // components when assign_fifos ran
  std::size_t assigned_fifos_ = 0;                      // FIFOs when assign_fifos ran
  std::unique_ptr<LaneThread> lane_;                    // lane 1's thread, with 2 threads
  std::function<void()> lane_step_;                     // lane_cycle
  // The two lanes' meeting point: the cycles each has committed, each on a line of its own
  // (one lane writes it, the other reads it).
  struct alignas(64) Committed {
    std::atomic<std::int64_t> cycles{0};
  };
  Committed done_[2];
  // Lane 1's own: the next cycle it steps, whether a beat moved in each cycle (by its parity:
  // lane 1 may be a cycle ahead when lane 0 reads it), what its components threw.
  alignas(64) std::int64_t lane_next_ = 0;
  bool lane_moved_[2] = {false, false};
  std::exception_ptr lane_error_;
  std::int64_t cycle_ = 0;
  std::int64_t quiet_ = 0;
  std::int64_t deadlock_window_ = 65536;
};

}  // namespace scw::sim
