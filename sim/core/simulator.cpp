// SPDX-License-Identifier: Apache-2.0
// The clock loop, deadlock detection and reports.
#include "sim/core/simulator.hpp"

#include <algorithm>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace scw::sim {

void check_threads(int threads, const std::string& what) {
  if (threads != 1 && threads != 2)
    throw std::invalid_argument(what + " " + std::to_string(threads) +
                                ": use 1 or 2 (the simulator steps its components on 1 or 2 "
                                "threads, docs/sim.md)");
}

Simulator::Simulator(int threads) {
  check_threads(threads, "threads");
  if (threads == 2) {
    lane_ = std::make_unique<LaneThread>();
    lane_step_ = [this] { lane_cycle(); };
  }
}

Simulator::~Simulator() {
  if (!lane_) return;
  try {
    settle_lane();
  } catch (...) {  // already reported to whoever stepped it
  }
  // Lane 1's components are unmade by the thread that made them, then the thread stops.
  lane_->call([this] {
    for (auto& c : components_)
      if (std::find(lanes_[1].begin(), lanes_[1].end(), c.get()) != lanes_[1].end()) c.reset();
  });
  lane_.reset();
}

bool Simulator::step_lane(int lane, std::int64_t cycle) {
  for (auto* c : lanes_[lane]) c->eval();
  for (auto* c : lanes_[lane]) c->tick();
  bool moved = false;
  for (auto* ch : own_fifos_[lane]) {
    ch->commit(cycle);
    moved = moved || ch->moved();
  }
  for (auto* ch : push_ends_[lane]) moved = ch->commit_push(cycle) || moved;
  for (auto* ch : pop_ends_[lane]) moved = ch->commit_pop(cycle) || moved;
  return moved;
}

void Simulator::see_lane(int lane, std::int64_t cycle) {
  for (auto* ch : push_ends_[lane]) ch->see_pops(cycle);
  for (auto* ch : pop_ends_[lane]) ch->see_pushes(cycle);
}

void Simulator::lane_cycle() {
  const std::int64_t c = lane_next_++;
  if (lane_error_) return;  // a cycle started before lane 0 saw the error: lane 0 lets it pass
  try {
    lane_moved_[c & 1] = step_lane(1, c);
  } catch (...) {
    lane_error_ = std::current_exception();
  }
  done_[1].cycles.store(c + 1, std::memory_order_release);
  await_count(done_[0].cycles, c + 1);
  if (!lane_error_) see_lane(1, c);
}

void Simulator::assign_fifos() {
  settle_lane();
  std::map<const ChannelBase*, unsigned> feeds, drains;  // bit k: a component of lane k
  for (int k = 0; k < 2; ++k)
    for (const auto* c : lanes_[k]) {
      for (const auto* ch : c->inputs()) drains[ch] |= 1u << k;
      for (const auto* ch : c->outputs()) feeds[ch] |= 1u << k;
    }
  for (int k = 0; k < 2; ++k) {
    own_fifos_[k].clear();
    push_ends_[k].clear();
    pop_ends_[k].clear();
  }
  for (auto& ch : channels_) {
    const unsigned f = feeds[ch.get()], d = drains[ch.get()];
    const bool split = (f | d) == 3u && (f == 1u || f == 2u) && (d == 1u || d == 2u);
    ch->split(split);
    if (split) {
      push_ends_[f == 2u ? 1 : 0].push_back(ch.get());
      pop_ends_[d == 2u ? 1 : 0].push_back(ch.get());
    } else {
      own_fifos_[(f | d) == 2u ? 1 : 0].push_back(ch.get());
    }
  }
  assigned_ = components_.size();
  assigned_fifos_ = channels_.size();
}

void Simulator::reassign_if_added() {
  if (assigned_ != components_.size() || assigned_fifos_ != channels_.size()) assign_fifos();
}

void Simulator::settle_lane() {
  if (lane_) lane_->wait();
}

void Simulator::step() {
  step_once();
  settle_lane();
}

void Simulator::step_once() {
  reassign_if_added();
  const std::int64_t c = cycle_;
  if (!lane_) {
    const bool moved = step_lane(0, c);
    quiet_ = moved ? 0 : quiet_ + 1;
    ++cycle_;
    return;
  }
  settle_lane();
  lane_next_ = c;
  lane_->start(lane_step_);
  meet(c, lane0_part());
}

bool Simulator::lane0_part() {
  const std::int64_t c = cycle_;
  bool moved = false;
  try {
    moved = step_lane(0, c);
  } catch (...) {
    done_[0].cycles.store(c + 1, std::memory_order_release);  // lane 1 finishes its cycle first
    try {
      settle_lane();
    } catch (...) {
    }
    lane_error_ = nullptr;  // lane 0's error is the one reported
    throw;
  }
  done_[0].cycles.store(c + 1, std::memory_order_release);
  ++cycle_;
  return moved;
}

void Simulator::meet(std::int64_t c, bool moved) {
  await_count(done_[1].cycles, c + 1);
  if (lane_error_) {
    // Lane 1 may have started the next cycle already; let it through, then report.
    done_[0].cycles.store(c + 2, std::memory_order_release);
    try {
      settle_lane();
    } catch (...) {
    }
    std::exception_ptr e = lane_error_;
    lane_error_ = nullptr;
    std::rethrow_exception(e);
  }
  moved = lane_moved_[c & 1] || moved;
  see_lane(0, c);
  quiet_ = moved ? 0 : quiet_ + 1;
}

void Simulator::check_progress(std::int64_t limit, std::int64_t max_cycles) {
  if (quiet_ >= deadlock_window_) {
    settle_lane();
    std::vector<std::string> stuck;
    const std::string text = deadlock_report(&stuck);
    throw DeadlockError(text, stuck);
  }
  if (cycle_ >= limit)
    throw std::runtime_error("simulation did not finish within " + std::to_string(max_cycles) +
                             " cycles (cycle " + std::to_string(cycle_) + ")");
}

void Simulator::run_until(const std::function<bool()>& done, std::int64_t max_cycles) {
  const std::int64_t limit = cycle_ + max_cycles;
  if (lane_) return run_two(done, limit, max_cycles);
  while (!done()) {
    check_progress(limit, max_cycles);
    step_once();
  }
}

void Simulator::run_two(const std::function<bool()>& done, std::int64_t limit,
                        std::int64_t max_cycles) {
  reassign_if_added();
  settle_lane();
  lane_next_ = cycle_;
  if (done()) return;
  for (bool started = false;;) {
    if (!started) {  // lane 0 could not start this cycle ahead (below)
      check_progress(limit, max_cycles);
      lane_->start(lane_step_);
    }
    const std::int64_t c = cycle_;
    const bool moved = lane0_part();
    // Lane 0's part of cycle c is all done() may read: ask it now, and start lane 1's next
    // cycle before meeting it, unless a deadlock could be declared after this cycle (it is
    // decided on both lanes' moves) or the limit is reached.
    bool go_on = false;
    try {
      go_on = !done();
    } catch (...) {
      try {
        meet(c, moved);
        settle_lane();
      } catch (...) {
      }
      lane_error_ = nullptr;
      throw;
    }
    started = go_on && quiet_ + 1 < deadlock_window_ && cycle_ < limit;
    if (started) lane_->start(lane_step_);
    meet(c, moved);
    if (!started) settle_lane();
    if (!go_on) return;
  }
}

std::string Simulator::deadlock_report(std::vector<std::string>* stuck) const {
  std::vector<const ChannelBase*> full, empty, partial;
  for (const auto& ch : channels_) {
    if (ch->size() == ch->depth()) full.push_back(ch.get());
    else if (ch->size() == 0) empty.push_back(ch.get());
    else partial.push_back(ch.get());
  }
  auto list = [](const std::vector<const ChannelBase*>& v) {
    std::ostringstream s;
    for (const auto* ch : v)
      s << "\n    " << ch->name() << " (" << ch->size() << "/" << ch->depth() << ", "
        << ch->producer << " -> " << ch->consumer << ")";
    return s.str();
  };
  // The root of a fork-and-join deadlock is a full FIFO whose consumer waits on another,
  // empty input; full FIFOs further upstream are only backed up behind it.
  std::vector<const ChannelBase*> roots;
  for (const auto& c : components_) {
    bool starved = false;
    for (const auto* in : c->inputs()) starved = starved || in->size() == 0;
    if (!starved) continue;
    for (const auto* in : c->inputs())
      if (in->size() == in->depth()) roots.push_back(in);
  }
  const auto& culprits = !roots.empty() ? roots : !full.empty() ? full : partial;
  std::vector<std::string> names;
  for (const auto* ch : culprits) names.push_back(ch->name());

  std::ostringstream s;
  s << "deadlock at cycle " << cycle_ << ": no beat moved on any FIFO for " << quiet_
    << " cycles";
  s << "\n  stuck FIFOs:";
  for (const auto& n : names) s << " " << n;
  if (!full.empty()) s << "\n  full (their producers wait):" << list(full);
  if (!partial.empty()) s << "\n  partly filled:" << list(partial);
  if (!empty.empty()) s << "\n  empty (their consumers wait):" << list(empty);
  if (!roots.empty())
    s << "\n  a full FIFO whose consumer waits on another, empty input: in a fork-and-join "
         "it must be as deep as the latency difference between the branches; make it deeper";
  if (stuck) *stuck = std::move(names);
  return s.str();
}

SimReport Simulator::report() const {
  SimReport r;
  r.cycles = cycle_;
  for (const auto& ch : channels_)
    r.fifos.push_back({ch->name(), ch->producer, ch->consumer, ch->depth(), ch->max_occupancy(),
                       ch->pushes()});
  for (const auto& c : components_) {
    StageReport st{c->name(), {}};
    auto frame = [&st](std::size_t i) -> StageFrame& {
      if (st.frames.size() <= i) st.frames.resize(i + 1);
      return st.frames[i];
    };
    auto earliest = [](std::int64_t& dst, std::int64_t v) {
      if (v >= 0 && (dst < 0 || v < dst)) dst = v;
    };
    auto latest = [](std::int64_t& dst, std::int64_t v) { dst = std::max(dst, v); };
    // A frame seen at either end of a link has a row, as when the two ends shared one table.
    auto rows_for = [&frame](const ChannelBase* ch) {
      const std::size_t n = std::max(ch->push_frames().size(), ch->pop_frames().size());
      if (n > 0) frame(n - 1);
    };
    for (const auto* in : c->inputs()) {
      rows_for(in);
      const auto& popped = in->pop_frames();
      for (std::size_t i = 0; i < popped.size(); ++i) {
        earliest(frame(i).first_in, popped[i].first_pop);
        latest(frame(i).last_in, popped[i].last_pop);
      }
    }
    for (const auto* out : c->outputs()) {
      rows_for(out);
      const auto& pushed = out->push_frames();
      for (std::size_t i = 0; i < pushed.size(); ++i) {
        earliest(frame(i).first_out, pushed[i].first_push);
        latest(frame(i).last_out, pushed[i].last_push);
      }
    }
    r.stages.push_back(std::move(st));
  }
  return r;
}

std::string SimReport::text() const {
  std::ostringstream s;
  s << "cycles: " << cycles << "\n\nFIFO                         depth  max occ   beats  from -> to\n";
  for (const auto& f : fifos)
    s << std::left << std::setw(28) << f.name << std::right << std::setw(6) << f.depth
      << std::setw(9) << f.max_occupancy << std::setw(8) << f.beats << "  " << f.producer
      << " -> " << f.consumer << "\n";
  s << "\nstage              frame  first in   last in  first out  last out\n";
  for (const auto& st : stages)
    for (std::size_t i = 0; i < st.frames.size(); ++i) {
      const auto& f = st.frames[i];
      s << std::left << std::setw(18) << st.name << std::right << std::setw(6) << i
        << std::setw(10) << f.first_in << std::setw(10) << f.last_in << std::setw(11)
        << f.first_out << std::setw(10) << f.last_out << "\n";
    }
  return s.str();
}

}  // namespace scw::sim
