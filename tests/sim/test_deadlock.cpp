// SPDX-License-Identifier: Apache-2.0
// A fork-and-join whose short branch FIFO is shallower than the long branch's latency
// deadlocks, and the simulator names that FIFO; deep enough, the same graph completes.
#include <catch2/catch.hpp>

#include "sim/core/components.hpp"

namespace {

using scw::sim::Component;
using scw::sim::Fifo;
using V = scw::hls::Packet<int>;

/// Copies each input beat to both outputs, only when both have room (one beat per cycle).
class Fork : public Component {
 public:
  Fork(std::string name, Fifo<V>& in, Fifo<V>& a, Fifo<V>& b)
      : Component(std::move(name)), in_(in), a_(a), b_(b) {
    connect_in(in_);
    connect_out(a_);
    connect_out(b_);
  }
  void eval() override {
    if (in_.can_pop() && a_.can_push() && b_.can_push()) {
      a_.push(in_.front());
      b_.push(in_.front());
      in_.pop();
    }
  }
  void tick() override {}

 private:
  Fifo<V>& in_;
  Fifo<V>& a_;
  Fifo<V>& b_;
};

/// Holds `n` beats before it releases them: a long-latency branch (like a row of line buffer).
class Batcher : public Component {
 public:
  Batcher(std::string name, Fifo<V>& in, Fifo<V>& out, std::size_t n)
      : Component(std::move(name)), in_(in), out_(out), n_(n) {
    connect_in(in_);
    connect_out(out_);
  }
  void eval() override {
    if (draining_ && !held_.empty() && out_.can_push()) {
      out_.push(held_.front());
      held_.erase(held_.begin());
      if (held_.empty()) draining_ = false;
    } else if (!draining_ && in_.can_pop()) {
      held_.push_back(in_.front());
      in_.pop();
      if (held_.size() == n_) draining_ = true;
    }
  }
  void tick() override {}

 private:
  Fifo<V>& in_;
  Fifo<V>& out_;
  std::size_t n_;
  std::vector<V> held_;
  bool draining_ = false;
};

/// Pairs one beat from each input into their sum.
class Join : public Component {
 public:
  Join(std::string name, Fifo<V>& a, Fifo<V>& b, Fifo<V>& out)
      : Component(std::move(name)), a_(a), b_(b), out_(out) {
    connect_in(a_);
    connect_in(b_);
    connect_out(out_);
  }
  void eval() override {
    if (a_.can_pop() && b_.can_pop() && out_.can_push()) {
      out_.push({a_.front().data + b_.front().data, a_.front().last});
      a_.pop();
      b_.pop();
    }
  }
  void tick() override {}

 private:
  Fifo<V>& a_;
  Fifo<V>& b_;
  Fifo<V>& out_;
};

/// Builds source -> fork -> {short FIFO | batcher} -> join -> sink and runs 64 beats.
std::vector<V> run_fork_join(int short_depth) {
  scw::sim::Simulator s;
  s.set_deadlock_window(200);
  std::vector<V> in;
  for (int i = 0; i < 64; ++i) in.push_back({i, i % 16 == 15});
  auto& f_src = s.fifo<V>("src_to_fork", 2);
  auto& f_short = s.fifo<V>("fork_to_join", short_depth);
  auto& f_long_in = s.fifo<V>("fork_to_batcher", 2);
  auto& f_long_out = s.fifo<V>("batcher_to_join", 2);
  auto& f_out = s.fifo<V>("join_to_sink", 2);
  auto& src = s.add<scw::sim::Source<V>>("source", f_src, in);
  s.add<Fork>("fork", f_src, f_short, f_long_in);
  s.add<Batcher>("batcher", f_long_in, f_long_out, 16);
  s.add<Join>("join", f_short, f_long_out, f_out);
  auto& sink = s.add<scw::sim::Sink<V>>("sink", f_out);
  s.run_until([&] { return src.done() && sink.beats().size() == in.size(); }, 100000);
  return sink.beats();
}

}  // namespace

TEST_CASE("an undersized FIFO in a fork-and-join is reported by name", "[sim][deadlock]") {
  try {
    run_fork_join(4);
    FAIL("expected a deadlock");
  } catch (const scw::sim::DeadlockError& e) {
    INFO(e.what());
    REQUIRE(e.stuck() == std::vector<std::string>{"fork_to_join"});
    CHECK_THAT(e.what(), Catch::Contains("fork_to_join (4/4, fork -> join)"));
    CHECK_THAT(e.what(), Catch::Contains("empty (their consumers wait)"));
    CHECK_THAT(e.what(), Catch::Contains("batcher_to_join"));
  }
}

TEST_CASE("the same fork-and-join with a deep enough FIFO completes", "[sim][deadlock]") {
  const auto out = run_fork_join(20);
  REQUIRE(out.size() == 64);
  for (int i = 0; i < 64; ++i) CHECK(out[static_cast<std::size_t>(i)].data == 2 * i);
}
