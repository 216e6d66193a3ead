// SPDX-License-Identifier: Apache-2.0
// Two-input stages (rectify: raw pixels + map; disparity: left + right) as cycle models, a
// checked run with two drivers, and their simulator component.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sim/core/simulator.hpp"
#include "sim/core/stream_check.hpp"

namespace scw::sim {

/// What a two-input, one-output block presents in a cycle. A join model `M` has `a_type`,
/// `b_type`, `out_type`,
///   JoinOutputs<out_type> eval(bool a_valid, const a_type&, bool b_valid, const b_type&,
///                              bool out_ready);
///   void tick();
/// with the same meaning as the one-input cycle models (cycle_model.hpp).
template <typename Out>
struct JoinOutputs {
  bool a_ready = false;
  bool b_ready = false;
  bool out_valid = false;
  Out out{};
};

/// run_stream for a join: both inputs driven under `pattern` (the second driver's random
/// stalls use another seed, so the two inputs do not idle in step).
template <typename Model>
RunResult<typename Model::out_type> run_join(Model& model, std::vector<typename Model::a_type> a,
                                             std::vector<typename Model::b_type> b,
                                             const StallPattern& pattern,
                                             std::size_t expected_out,
                                             std::int64_t max_cycles = 1'000'000) {
  using A = typename Model::a_type;
  using B = typename Model::b_type;
  using Out = typename Model::out_type;
  RunResult<Out> r;
  OutputCheck<Out> check(r);
  const StallPattern pb = pattern.other_stream(17);  // the second input idles on its own
  StreamDriver<A> da(std::move(a), pattern);
  StreamDriver<B> db(std::move(b), pb);
  StreamMonitor<Out> mon(pattern);
  for (std::int64_t c = 0; c < max_cycles; ++c) {
    if (da.done() && db.done() && r.out.size() >= expected_out) {
      r.cycles = c;
      return r;
    }
    const bool av = da.valid();
    const bool bv = db.valid();
    const auto lo = model.eval(av, da.data(), bv, db.data(), false);
    const auto hi = model.eval(av, da.data(), bv, db.data(), true);
    const bool out_ready = mon.ready();
    const auto o = model.eval(av, da.data(), bv, db.data(), out_ready);
    CycleRecord rec{av, o.a_ready, false, false, {}, bv, o.b_ready};
    check.cycle(c, lo, hi, o, out_ready, std::move(rec));
    model.tick();
    da.clock(av && o.a_ready);
    db.clock(bv && o.b_ready);
  }
  r.timed_out = true;
  r.cycles = max_cycles;
  return r;
}

/// Streams `a` and `b` through a join model as fast as it takes them (no stalls, output always
/// ready, no checks or trace: the whole-image runners' loop) until `expected_out` beats are out.
/// Throws std::logic_error if the model stops producing output. `cycles` gets the cycle count.
template <typename Model>
std::vector<typename Model::out_type> drain_join(Model& model,
                                                 const std::vector<typename Model::a_type>& a,
                                                 const std::vector<typename Model::b_type>& b,
                                                 std::size_t expected_out,
                                                 std::int64_t* cycles = nullptr) {
  std::vector<typename Model::out_type> out;
  out.reserve(expected_out);
  std::size_t ia = 0, ib = 0;
  std::int64_t c = 0;
  const auto limit = static_cast<std::int64_t>(4 * (a.size() + b.size() + expected_out)) + 100000;
  for (; out.size() < expected_out; ++c) {
    if (c > limit)
      throw std::logic_error("drain_join: the model stopped producing output (" +
                             std::to_string(out.size()) + " of " + std::to_string(expected_out) +
                             " beats)");
    const bool av = ia < a.size(), bv = ib < b.size();
    const auto o = model.eval(av, a[av ? ia : 0], bv, b[bv ? ib : 0], true);
    if (av && o.a_ready) ++ia;
    if (bv && o.b_ready) ++ib;
    if (o.out_valid) out.push_back(o.out);
    model.tick();
  }
  if (cycles != nullptr) *cycles = c;
  return out;
}

/// Puts a join model between two input FIFOs and one output FIFO.
template <typename Model>
class JoinComponent : public Component {
 public:
  using A = typename Model::a_type;
  using B = typename Model::b_type;
  using Out = typename Model::out_type;

  JoinComponent(std::string name, Model model, Fifo<A>& a, Fifo<B>& b, Fifo<Out>& out)
      : Component(std::move(name)), model_(std::move(model)), a_(a), b_(b), out_(out) {
    connect_in(a_);
    connect_in(b_);
    connect_out(out_);
  }

  void eval() override {
    const bool av = a_.can_pop();
    const bool bv = b_.can_pop();
    const A abeat = av ? a_.front() : A{};
    const B bbeat = bv ? b_.front() : B{};
    const bool out_ready = out_.can_push();
    const auto o = model_.eval(av, abeat, bv, bbeat, out_ready);
    if (av && o.a_ready) a_.pop();
    if (bv && o.b_ready) b_.pop();
    if (o.out_valid && out_ready) out_.push(o.out);
  }
  void tick() override { model_.tick(); }

  Model& model() { return model_; }

 private:
  Model model_;
  Fifo<A>& a_;
  Fifo<B>& b_;
  Fifo<Out>& out_;
};

}  // namespace scw::sim
