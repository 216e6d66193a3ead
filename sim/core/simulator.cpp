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

Simulator::Simulator(int threads) {
  if (threads != 1 && threads != 2)
    throw std::invalid_argument("the simulator steps its components on 1 or 2 threads, not " +
                                std::to_string(threads));
  if (threads == 2) {
    lane_ = std::make_unique<LaneThread>();
    lane_step_ = [this] { lane_moved_ = step_lane(1); };
  }
}

Simulator::~Simulator() {
  if (!lane_) return;
  // Lane 1's components are unmade by the thread that made them, then the thread stops.
  lane_->call([this] {
    for (auto& c : components_)
      if (std::find(lanes_[1].begin(), lanes_[1].end(), c.get()) != lanes_[1].end()) c.reset();
  });
  lane_.reset();
}

bool Simulator::step_lane(int lane) {
  for (auto* c : lanes_[lane]) c->eval();
  for (auto* c : lanes_[lane]) c->tick();
  bool moved = false;
  for (auto* ch : own_fifos_[lane]) {
    ch->commit(cycle_);
    moved = moved || ch->moved();
  }
  return moved;
}

void Simulator::assign_fifos() {
  std::map<const ChannelBase*, unsigned> users;  // bit k: a component of lane k
  for (int k = 0; k < 2; ++k)
    for (const auto* c : lanes_[k]) {
      for (const auto* ch : c->inputs()) users[ch] |= 1u << k;
      for (const auto* ch : c->outputs()) users[ch] |= 1u << k;
    }
  for (auto& v : own_fifos_) v.clear();
  shared_fifos_.clear();
  for (auto& ch : channels_) {
    const unsigned u = users[ch.get()];
    if (u == 3u)
      shared_fifos_.push_back(ch.get());
    else
      own_fifos_[u == 2u ? 1 : 0].push_back(ch.get());
  }
  assigned_ = components_.size();
}

void Simulator::step() {
  if (assigned_ != components_.size() ||
      channels_.size() != own_fifos_[0].size() + own_fifos_[1].size() + shared_fifos_.size())
    assign_fifos();
  bool moved = false;
  if (lane_) {
    lane_->start(lane_step_);
    try {
      moved = step_lane(0);
    } catch (...) {
      try {
        lane_->wait();  // the other thread finishes its part before this one's error leaves
      } catch (...) {
      }
      throw;
    }
    lane_->wait();
    moved = moved || lane_moved_;
    for (auto* ch : shared_fifos_) {
      ch->commit(cycle_);
      moved = moved || ch->moved();
    }
  } else {
    moved = step_lane(0);
  }
  quiet_ = moved ? 0 : quiet_ + 1;
  ++cycle_;
}

void Simulator::run_until(const std::function<bool()>& done, std::int64_t max_cycles) {
  const std::int64_t limit = cycle_ + max_cycles;
  while (!done()) {
    if (quiet_ >= deadlock_window_) {
      std::vector<std::string> stuck;
      const std::string text = deadlock_report(&stuck);
      throw DeadlockError(text, stuck);
    }
    if (cycle_ >= limit)
      throw std::runtime_error("simulation did not finish within " + std::to_string(max_cycles) +
                               " cycles (cycle " + std::to_string(cycle_) + ")");
    step();
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
    for (const auto* in : c->inputs()) {
      for (std::size_t i = 0; i < in->frames().size(); ++i) {
        earliest(frame(i).first_in, in->frames()[i].first_pop);
        latest(frame(i).last_in, in->frames()[i].last_pop);
      }
    }
    for (const auto* out : c->outputs()) {
      for (std::size_t i = 0; i < out->frames().size(); ++i) {
        earliest(frame(i).first_out, out->frames()[i].first_push);
        latest(frame(i).last_out, out->frames()[i].last_push);
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
