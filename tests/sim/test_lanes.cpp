// SPDX-License-Identifier: Apache-2.0
// The simulator on two threads (Simulator(2), add_to lane 1): the same beats at the same cycles,
// the same reports and the same deadlock as on one; a lane-1 component lives on its own thread;
// an error there reaches the caller.
#include <catch2/catch.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "sim/core/components.hpp"

namespace {

using scw::sim::Component;
using scw::sim::Fifo;
using V = scw::hls::Packet<int>;

/// Adds 1000 to each beat after holding it `delay` cycles, one beat in flight at a time, and
/// notes the threads it is made, stepped and unmade on. With `fail_at` >= 0 it throws in that
/// cycle of its own.
class Delay : public Component {
 public:
  struct Threads {
    std::thread::id made, stepped, unmade;
  };
  Delay(std::string name, Fifo<V>& in, Fifo<V>& out, int delay, Threads* seen, int fail_at = -1)
      : Component(std::move(name)),
        in_(in),
        out_(out),
        delay_(delay),
        seen_(seen),
        fail_at_(fail_at) {
    connect_in(in_);
    connect_out(out_);
    if (seen_) seen_->made = std::this_thread::get_id();
  }
  ~Delay() override {
    if (seen_) seen_->unmade = std::this_thread::get_id();
  }
  void eval() override {
    if (seen_) seen_->stepped = std::this_thread::get_id();
    if (cycle_ == fail_at_) throw std::runtime_error("Delay failed on purpose");
    if (held_ && wait_ == 0 && out_.can_push()) {
      out_.push({beat_.data + 1000, beat_.last});
      held_ = false;
    } else if (!held_ && in_.can_pop()) {
      beat_ = in_.front();
      in_.pop();
      held_ = true;
      wait_ = delay_;
    }
  }
  void tick() override {
    ++cycle_;
    if (held_ && wait_ > 0) --wait_;
  }

 private:
  Fifo<V>& in_;
  Fifo<V>& out_;
  int delay_;
  Threads* seen_;
  int fail_at_;
  int cycle_ = 0;
  bool held_ = false;
  int wait_ = 0;
  V beat_{};
};

struct Run {
  std::vector<V> out;
  scw::sim::SimReport report;
};

/// source -> a (lane 0) -> b (lane 1) -> c (lane 0) -> sink, the sink stalling every third cycle,
/// so that beats wait in the FIFOs that cross between the threads.
Run run_chain(int threads, Delay::Threads* seen = nullptr, int fail_at = -1) {
  scw::sim::Simulator s(threads);
  std::vector<V> in;
  for (int i = 0; i < 40; ++i) in.push_back({i, i % 8 == 7});
  auto& f0 = s.fifo<V>("in", 2);
  auto& f1 = s.fifo<V>("a_to_b", 3);
  auto& f2 = s.fifo<V>("b_to_c", 2);
  auto& f3 = s.fifo<V>("out", 2);
  auto& src = s.add<scw::sim::Source<V>>("source", f0, in);
  s.add<Delay>("a", f0, f1, 1, nullptr);
  s.add_to(1, [&] { return std::make_unique<Delay>("b", f1, f2, 3, seen, fail_at); });
  s.add<Delay>("c", f2, f3, 0, nullptr);
  auto& sink = s.add<scw::sim::Sink<V>>("sink", f3, scw::sim::StallPattern::parse("random:4"));
  s.run_until([&] { return src.done() && sink.beats().size() == in.size(); }, 10000);
  return {sink.beats(), s.report()};
}

/// source -> a (lane 0) -> b (lane 1) -> a FIFO nobody drains: it fills, everything behind it
/// stops, and the run ends in a deadlock report; or, with a small `max_cycles`, at the limit.
std::string run_stuck(int threads, std::int64_t max_cycles) {
  scw::sim::Simulator s(threads);
  s.set_deadlock_window(50);
  std::vector<V> in(20, V{1, false});
  auto& f0 = s.fifo<V>("in", 2);
  auto& f1 = s.fifo<V>("a_to_b", 2);
  auto& f2 = s.fifo<V>("undrained", 2);
  s.add<scw::sim::Source<V>>("source", f0, in);
  s.add<Delay>("a", f0, f1, 0, nullptr);
  s.add_to(1, [&] { return std::make_unique<Delay>("b", f1, f2, 2, nullptr); });
  try {
    s.run_until([] { return false; }, max_cycles);
  } catch (const std::exception& e) {
    return e.what() + std::string(" at cycle ") + std::to_string(s.cycle());
  }
  return "no error";
}

}  // namespace

TEST_CASE("two threads: the same deadlock report and cycle limit as one", "[sim][lanes]") {
  const std::string one = run_stuck(1, 100000);
  CHECK_THAT(one, Catch::Contains("deadlock at cycle") && Catch::Contains("undrained (2/2"));
  CHECK(run_stuck(2, 100000) == one);
  const std::string limit = run_stuck(1, 30);
  CHECK_THAT(limit, Catch::Contains("did not finish within 30 cycles"));
  CHECK(run_stuck(2, 30) == limit);
}

TEST_CASE("two threads: the same beats, cycles and report as one", "[sim][lanes]") {
  const Run one = run_chain(1), two = run_chain(2);
  REQUIRE(one.out.size() == 40);
  for (int i = 0; i < 40; ++i) CHECK(one.out[static_cast<std::size_t>(i)].data == i + 3000);
  CHECK(two.out == one.out);
  CHECK(two.report.cycles == one.report.cycles);
  CHECK(two.report.text() == one.report.text());
  REQUIRE(two.report.fifos.size() == one.report.fifos.size());
  for (std::size_t i = 0; i < one.report.fifos.size(); ++i) {
    INFO(one.report.fifos[i].name);
    CHECK(two.report.fifos[i].max_occupancy == one.report.fifos[i].max_occupancy);
    CHECK(two.report.fifos[i].beats == one.report.fifos[i].beats);
  }
}

TEST_CASE("a lane-1 component is made, stepped and unmade on the second thread", "[sim][lanes]") {
  Delay::Threads seen;
  run_chain(2, &seen);
  const auto here = std::this_thread::get_id();
  CHECK(seen.made != here);
  CHECK(seen.stepped == seen.made);
  CHECK(seen.unmade == seen.made);
  Delay::Threads alone;
  run_chain(1, &alone);
  CHECK(alone.made == here);
  CHECK(alone.stepped == here);
}

TEST_CASE("an error on the second thread reaches the caller", "[sim][lanes]") {
  REQUIRE_THROWS_WITH(run_chain(2, nullptr, 25), Catch::Contains("Delay failed on purpose"));
  REQUIRE_THROWS_WITH(run_chain(1, nullptr, 25), Catch::Contains("Delay failed on purpose"));
}

TEST_CASE("the simulator takes 1 or 2 threads and a component lane 0 or 1", "[sim][lanes]") {
  REQUIRE_THROWS_WITH(scw::sim::Simulator(3), Catch::Contains("threads 3: use 1 or 2"));
  REQUIRE_THROWS_WITH(scw::sim::Simulator(0), Catch::Contains("threads 0: use 1 or 2"));
  scw::sim::Simulator s(2);
  auto& f = s.fifo<V>("f", 1);
  auto& g = s.fifo<V>("g", 1);
  REQUIRE_THROWS_WITH(s.add_to(2, [&] { return std::make_unique<Delay>("d", f, g, 0, nullptr); }),
                      Catch::Contains("lane is 0 or 1"));
}
