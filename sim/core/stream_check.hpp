// SPDX-License-Identifier: Apache-2.0
// Stream driver and monitor with stall patterns, and a harness-free run that checks the
// AXI-Stream handshake rules every cycle and records a cycle trace to compare models with.
#pragma once

#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "sim/core/cycle_model.hpp"
#include "sim/core/stall.hpp"
#include "sim/words/bits.hpp"
#include "sim/words/pack.hpp"

namespace scw::sim {

/// Offers beats in order; idles on the cycles its pattern says; once valid, holds valid and
/// data until the beat is accepted (the producer's half of the handshake).
template <typename T>
class StreamDriver {
 public:
  StreamDriver(std::vector<T> beats, const StallPattern& p)
      : beats_(std::move(beats)), gen_(p, StallGen::Side::kInput) {}

  /// Decides this cycle's valid; call once per cycle before evaluating the consumer.
  bool valid() {
    if (!offering_ && next_ < beats_.size()) offering_ = gen_.next();
    return offering_;
  }
  const T& data() const { return beats_[next_ < beats_.size() ? next_ : 0]; }
  /// The clock edge: `accepted` = valid && ready in the cycle that ends.
  void clock(bool accepted) {
    if (accepted) {
      ++next_;
      offering_ = false;
    }
  }
  bool done() const { return next_ >= beats_.size(); }
  std::size_t sent() const { return next_; }

 private:
  std::vector<T> beats_;
  StallGen gen_;
  std::size_t next_ = 0;
  bool offering_ = false;
};

/// Takes beats when its pattern allows and collects them.
template <typename T>
class StreamMonitor {
 public:
  explicit StreamMonitor(const StallPattern& p) : gen_(p, StallGen::Side::kOutput) {}
  /// Decides this cycle's ready; call once per cycle.
  bool ready() { return gen_.next(); }
  void take(const T& beat) { beats_.push_back(beat); }
  const std::vector<T>& beats() const { return beats_; }

 private:
  StallGen gen_;
  std::vector<T> beats_;
};

/// One cycle at a block's ports.
struct CycleRecord {
  bool in_valid = false;
  bool in_ready = false;
  bool out_valid = false;
  bool out_ready = false;
  Bits out;  // packed output beat, only when out_valid
  bool b_valid = false;  // second input of a join (two-input stage); false otherwise
  bool b_ready = false;

  friend bool operator==(const CycleRecord& a, const CycleRecord& b) {
    return a.in_valid == b.in_valid && a.in_ready == b.in_ready && a.out_valid == b.out_valid &&
           a.out_ready == b.out_ready && (!a.out_valid || a.out == b.out) &&
           a.b_valid == b.b_valid && a.b_ready == b.b_ready;
  }
};

template <typename Out>
struct RunResult {
  std::vector<Out> out;              // beats taken by the monitor, in order
  std::vector<CycleRecord> trace;    // every cycle
  std::vector<std::string> violations;  // handshake rules broken (empty = clean)
  bool timed_out = false;
  std::int64_t cycles = 0;
};

/// Drives `model` with `beats` under `pattern` until `expected_out` beats have come out or
/// `max_cycles` pass. Every cycle it checks the consumer-visible rules: out_valid and out data
/// do not depend on out_ready (evaluated both ways), and a stalled output keeps valid and data.
/// The consumer-side rules, checked once per cycle on a block's output: out_valid and out data
/// do not depend on out_ready (`lo`/`hi`: evaluated with ready low and high), and a stalled
/// output keeps valid and data. Records the cycle and collects the beats taken.
template <typename Out>
class OutputCheck {
 public:
  explicit OutputCheck(RunResult<Out>& r) : r_(r) {}

  template <typename O>
  void cycle(std::int64_t c, const O& lo, const O& hi, const O& o, bool out_ready,
             CycleRecord rec) {
    auto fail = [&](const std::string& what) {
      std::ostringstream s;
      s << "cycle " << c << ": " << what;
      if (r_.violations.size() < 20) r_.violations.push_back(s.str());
    };
    if (lo.out_valid != hi.out_valid) fail("out_valid depends on out_ready");
    if (lo.out_valid && hi.out_valid && pack(lo.out) != pack(hi.out))
      fail("out data depends on out_ready");
    rec.out_valid = o.out_valid;
    rec.out_ready = out_ready;
    if (o.out_valid) rec.out = pack(o.out);
    if (prev_stalled_ && !o.out_valid) fail("out_valid dropped while stalled");
    if (prev_stalled_ && o.out_valid && rec.out != prev_out_) fail("out data changed while stalled");
    prev_stalled_ = o.out_valid && !out_ready;
    prev_out_ = rec.out;
    if (o.out_valid && out_ready) r_.out.push_back(o.out);
    r_.trace.push_back(std::move(rec));
  }

 private:
  RunResult<Out>& r_;
  bool prev_stalled_ = false;
  Bits prev_out_;
};

/// Drives `model` with `beats` under `pattern` until all are sent and `enough(outputs so far)`
/// holds, or `max_cycles` pass, checking the handshake rules every cycle (OutputCheck).
template <typename Model>
RunResult<typename Model::out_type> run_stream_until(
    Model& model, std::vector<typename Model::in_type> beats, const StallPattern& pattern,
    const std::function<bool(const std::vector<typename Model::out_type>&)>& enough,
    std::int64_t max_cycles = 1'000'000) {
  using In = typename Model::in_type;
  using Out = typename Model::out_type;
  RunResult<Out> r;
  OutputCheck<Out> check(r);
  StreamDriver<In> drv(std::move(beats), pattern);
  StreamMonitor<Out> mon(pattern);
  for (std::int64_t c = 0; c < max_cycles; ++c) {
    if (drv.done() && enough(r.out)) {
      r.cycles = c;
      return r;
    }
    const bool in_valid = drv.valid();
    const In& in = drv.data();
    const auto lo = model.eval(in_valid, in, false);
    const auto hi = model.eval(in_valid, in, true);
    const bool out_ready = mon.ready();
    const auto o = model.eval(in_valid, in, out_ready);
    check.cycle(c, lo, hi, o, out_ready, CycleRecord{in_valid, o.in_ready, false, false, {}});
    model.tick();
    drv.clock(in_valid && o.in_ready);
  }
  r.timed_out = true;
  r.cycles = max_cycles;
  return r;
}

/// run_stream_until `expected_out` beats have come out.
template <typename Model>
RunResult<typename Model::out_type> run_stream(Model& model,
                                               std::vector<typename Model::in_type> beats,
                                               const StallPattern& pattern,
                                               std::size_t expected_out,
                                               std::int64_t max_cycles = 1'000'000) {
  return run_stream_until(
      model, std::move(beats), pattern,
      [expected_out](const std::vector<typename Model::out_type>& out) {
        return out.size() >= expected_out;
      },
      max_cycles);
}

/// run_stream for a source: `run` follows the input side of `pattern` (idle cycles drop run),
/// the sink the output side. Stops after `expected_out` beats are taken; checks the handshake
/// rules every cycle (OutputCheck). `each_cycle(c, model)`, if given, runs before the cycle's
/// evaluation (to drive the knot port mid-run). The trace records run as in_valid and "a beat
/// issues if run" as in_ready.
template <typename Model>
RunResult<typename Model::out_type> run_source(
    Model& model, const StallPattern& pattern, std::size_t expected_out,
    std::int64_t max_cycles = 1'000'000,
    const std::function<void(std::int64_t, Model&)>& each_cycle = {}) {
  using Out = typename Model::out_type;
  RunResult<Out> r;
  OutputCheck<Out> check(r);
  StallGen run_gen(pattern, StallGen::Side::kInput);
  StreamMonitor<Out> mon(pattern);
  for (std::int64_t c = 0; c < max_cycles; ++c) {
    if (r.out.size() >= expected_out) {
      r.cycles = c;
      return r;
    }
    if (each_cycle) each_cycle(c, model);
    const bool run = run_gen.next();
    const auto lo = model.eval(run, false);
    const auto hi = model.eval(run, true);
    const bool out_ready = mon.ready();
    const auto o = model.eval(run, out_ready);
    check.cycle(c, lo, hi, o, out_ready, CycleRecord{run, o.in_ready, false, false, {}});
    model.tick();
  }
  r.timed_out = true;
  r.cycles = max_cycles;
  return r;
}

/// The first cycle at which two traces differ, described; empty if they are equal.
std::string first_difference(const std::vector<CycleRecord>& a, const std::vector<CycleRecord>& b,
                             const std::string& name_a, const std::string& name_b);

}  // namespace scw::sim
