// SPDX-License-Identifier: Apache-2.0
// The worker's loop and the two threads' meeting points.
#include "sim/core/lane_thread.hpp"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace scw::sim {

namespace {
/// Spins before a waiting thread gives up its core: a few tens of microseconds, several
/// thesis-size cycles, so that within a run neither thread leaves the processor.
constexpr int kSpins = 20000;
/// The longest a sleeping worker can miss a job by (LaneThread::start).
constexpr std::chrono::milliseconds kNap{1};

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

/// Spins until `ready()`, yielding the core between looks once it has spun kSpins times.
template <typename Ready>
void spin_until(Ready ready) {
  for (int spins = 0; !ready();) {
    if (++spins < kSpins) {
      relax();
    } else {
      std::this_thread::yield();
    }
  }
}
}  // namespace

void await_count(const std::atomic<std::int64_t>& a, std::int64_t n) {
  spin_until([&] { return a.load(std::memory_order_acquire) >= n; });
}

LaneThread::LaneThread() : thread_([this] { loop(); }) {}

LaneThread::~LaneThread() {
  stop_ = true;
  static const std::function<void()> nothing = [] {};
  start(nothing);
  thread_.join();
}

void LaneThread::start(const std::function<void()>& job) {
  job_.store(&job, std::memory_order_relaxed);
  // A plain store: an atomic add here (a locked instruction) waited for the counter's cache
  // line to come back from the spinning worker, and was 6 % of a thesis-size run. A worker that
  // fell asleep just as this store was made and is not woken here wakes within kNap.
  posted_.store(posted_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
  if (sleeping_.load(std::memory_order_relaxed)) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_one();
  }
}

void LaneThread::wait() {
  const std::uint64_t want = posted_.load(std::memory_order_relaxed);
  spin_until([&] { return done_.load(std::memory_order_acquire) == want; });
  if (error_) {
    std::exception_ptr e = error_;
    error_ = nullptr;
    std::rethrow_exception(e);
  }
}

void LaneThread::loop() {
  std::uint64_t seen = 0;
  for (;;) {
    for (int spins = 0; posted_.load(std::memory_order_acquire) == seen;) {
      if (++spins < kSpins) {
        relax();
        continue;
      }
      std::unique_lock<std::mutex> lock(mutex_);
      sleeping_.store(true, std::memory_order_relaxed);
      while (posted_.load(std::memory_order_acquire) == seen) wake_.wait_for(lock, kNap);
      sleeping_.store(false, std::memory_order_relaxed);
    }
    ++seen;  // one job at a time, even if more were started meanwhile
    if (stop_) {
      done_.store(seen, std::memory_order_release);
      return;
    }
    try {
      (*job_.load(std::memory_order_relaxed))();
    } catch (...) {
      error_ = std::current_exception();
    }
    done_.store(seen, std::memory_order_release);
  }
}

}  // namespace scw::sim
