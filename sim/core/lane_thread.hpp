// SPDX-License-Identifier: Apache-2.0
// A second thread that steps some of the simulator's components in each cycle, beside the
// thread that steps the rest.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace scw::sim {

/// Waits until `a` holds at least `n`: spins, then yields the core between looks once it has
/// spun for long (more threads than free cores: the thread it waits for may not be running).
void await_count(const std::atomic<std::int64_t>& a, std::int64_t n);

/// One worker thread that runs a job when asked and says when it is done: the simulator hands
/// it lane 1's part of each cycle (Simulator::lane_cycle), and the making and unmaking of lane
/// 1's components, since Verilator wants a model evaluated by the thread that built it.
///
/// A cycle of the thesis pipeline is microseconds of work, so the two threads meet by spinning
/// on two counters rather than through the kernel. A thread that has spun for long (the other
/// thread is busy elsewhere: writing pictures between frames, or the machine has fewer free
/// cores than threads) yields its core, and the worker then sleeps until the next job.
class LaneThread {
 public:
  LaneThread();
  ~LaneThread();
  LaneThread(const LaneThread&) = delete;
  LaneThread& operator=(const LaneThread&) = delete;

  /// Starts `job` on the worker, after the one it is running if any (then `job` must be that
  /// one: another is started only when the worker is idle, after wait()); it must live until
  /// wait() returns.
  void start(const std::function<void()>& job);
  /// Waits until the worker has run every job started, and rethrows what one threw.
  void wait();
  /// start(job), then wait().
  void call(const std::function<void()>& job) {
    start(job);
    wait();
  }

 private:
  void loop();

  // The worker's counters on their own cache lines: each is written by one thread and read by
  // the other, once a cycle.
  alignas(64) std::atomic<std::uint64_t> posted_{0};  // jobs started (main thread)
  alignas(64) std::atomic<std::uint64_t> done_{0};    // jobs finished (worker)
  alignas(64) std::atomic<bool> sleeping_{false};
  std::atomic<const std::function<void()>*> job_{nullptr};
  std::exception_ptr error_;
  bool stop_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace scw::sim
