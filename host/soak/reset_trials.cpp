// SPDX-License-Identifier: Apache-2.0
// Reset trials (host/soak/reset_trials.hpp).
#include "host/soak/reset_trials.hpp"

#include <algorithm>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "host/pipeline/reference_chain.hpp"
#include "host/soak/small_top.hpp"

namespace scw::host::soak {

namespace {

using namespace small;

/// The blocks that took or sent a beat in the last 8 cycles: those a reset now cuts in mid-work.
std::vector<std::string> active_blocks(const Chain& c) {
  std::vector<std::string> v;
  const std::int64_t recent = c.start_cycle() + c.cycles() - 8;
  for (const auto& st : c.report().stages)
    for (const auto& f : st.frames)
      if (std::max(f.last_in, f.last_out) >= recent) {
        v.push_back(st.name);
        break;
      }
  return v;
}

class Trial {
 public:
  Trial(const ResetOptions& o, int t, const sim::PipelineSetup& setup)
      : o_(o), setup_(setup), t_(t), seed_(o.seed * 1000003u + static_cast<std::uint64_t>(t)),
        rng_(seed_) {}

  /// "" when the trial passed, else what failed.
  std::string run(ResetSummary& s) {
    const auto stalls = pattern(0);
    const SoakStream all = frames(0, 8);
    const std::int64_t bound = 40LL * (64LL * o_.width * o_.height + 50000);
    // The reset falls in the span of the first three results, at a cycle drawn among those where
    // the labelling stage does what trial t aims at (its phases in turn, Emit beside them), so
    // that the rare phases (Resolve, Border, Emit) are cut as often as the long ones.
    Chain calm(setup_, sim::PipelineEngines::all(sim::Engine::cpp), all.left, all.right, stalls,
               stalls);
    std::map<std::string, std::vector<std::int64_t>> by_activity;
    while (calm.results().size() < 3) {
      if (calm.cycles() >= bound) throw std::runtime_error("the C++ chain gave no 3 results");
      calm.step(1);
      by_activity[calm.labelling_activity()].push_back(calm.cycles());
    }
    auto aim = by_activity.begin();
    std::advance(aim, static_cast<long>(static_cast<std::size_t>(t_) % by_activity.size()));
    const auto& cycles = aim->second;
    const std::int64_t at = cycles[std::uniform_int_distribution<std::size_t>(0, cycles.size() - 1)(rng_)];
    // rst_ni held 1 .. 8 clocks: one edge must reset everything that must be reset.
    const int hold = std::uniform_int_distribution<int>(kMinResetHold, 8)(rng_);
    Chain before(setup_, sim::PipelineEngines::all(sim::Engine::cpp), all.left, all.right,
                 stalls, stalls);
    before.step(at);
    for (const auto& b : active_blocks(before)) ++s.busy[b];
    ++s.labelling[before.labelling_activity()];
    where_ = "reset at cycle " + std::to_string(at) + " for " + std::to_string(hold) +
             " cycles, labelling " + before.labelling_activity();

    Top top(setup_);
    sim::TopRunControl ctl;
    ctl.stop_at = at;
    auto cut = top.run(all.left, all.right, 1000, at + 1, stalls, stalls, ctl);
    const int next = static_cast<int>(
        std::max(cut.first_in_cycles.size(), cut.first_in_right_cycles.size()));
    const auto pre = output_of(before);
    const auto got_pre = output_of(std::move(cut));
    if (compare_runs(pre, got_pre).second || pre.object_table != got_pre.object_table) {
      ++s.before_mismatches;
      return "before the reset: the top != the C++ chain";
    }
    top.reset(hold);

    // After the reset: the next whole frame and one more, as a fresh chain takes them.
    const auto after_stalls = pattern(1);
    const SoakStream again = frames(next, 2);
    Chain fresh(setup_, sim::PipelineEngines::all(sim::Engine::cpp), again.left, again.right,
                after_stalls, after_stalls);
    fresh.run(2, bound);
    const auto want = output_of(fresh);
    const auto got = output_of(top.run(again.left, again.right, 2, bound, after_stalls, after_stalls));
    if (const auto d = compare_runs(want, got).second) {
      ++s.after_mismatches;
      return "after the reset, result " + std::to_string(d->frame) + ": " + d->what;
    }
    pipeline::ReferenceChain ref(Build::kWindow, soak_stage_options());
    for (int k = 0; k < 2; ++k) {
      const auto f = ref.next(content_[static_cast<std::size_t>(next + k)].left,
                              content_[static_cast<std::size_t>(next + k)].right);
      const auto& result = want.results[static_cast<std::size_t>(k)].data.frame;
      auto why = pipeline::object_mismatch(
          objects_per_frame(want.object_table)[static_cast<std::size_t>(k)], f);
      if (why.empty()) {
        why = pipeline::reference_mismatch(result, f, o_.width, o_.height, soak_stage_options());
        // A decision the doubles may take the other way is not a failure (the soak counts it).
        if (!why.empty() &&
            !pipeline::decision_boundary(f, o_.width, o_.height, soak_stage_options()).empty()) {
          ++s.reference_boundary;
          why.clear();
        }
      }
      if (!why.empty()) {
        ++s.reference_mismatches;
        return "frame " + std::to_string(k) + " after the reset against the reference: " + why;
      }
    }
    return "";
  }
  const std::string& where() const { return where_; }

 private:
  sim::StallPattern pattern(int salt) const {
    return o_.stalls ? sim::StallPattern::parse("random:" + std::to_string(seed_ * 2 + static_cast<std::uint64_t>(salt)))
                     : sim::StallPattern{};
  }
  /// Content frames first .. first + count - 1 as beats.
  SoakStream frames(int first, int count) {
    const int dmax = soak_stage_options().num_disp - 1;
    while (static_cast<int>(content_.size()) < first + count)
      content_.push_back(content_frame(o_.width, o_.height, dmax, seed_,
                                       static_cast<int>(content_.size()), o_.real));
    SoakStream s;
    for (int k = first; k < first + count; ++k)
      append_frame(s, content_[static_cast<std::size_t>(k)], k, Fault::none, true, seed_);
    return s;
  }

  const ResetOptions& o_;
  const sim::PipelineSetup& setup_;
  int t_;
  std::uint64_t seed_;
  std::mt19937_64 rng_;
  std::vector<ContentFrame> content_;
  std::string where_;
};

}  // namespace

nlohmann::json ResetSummary::to_json() const {
  nlohmann::json j;
  j["trials"] = trials;
  j["failures"] = failures;
  j["before_mismatches"] = before_mismatches;
  j["after_mismatches"] = after_mismatches;
  j["reference_mismatches"] = reference_mismatches;
  j["reference_boundary"] = reference_boundary;
  j["busy"] = busy;
  j["labelling"] = labelling;
  if (!first_failure.empty()) j["first_failure"] = first_failure;
  return j;
}

ResetSummary run_reset_trials(const ResetOptions& o) {
  if (o.trials < 0) throw std::invalid_argument("soak: --resets must be 0 or more");
  const auto knots = pipeline::identity_knots(o.width, o.height, Build::kGridLog2);
  const auto setup = pipeline::make_setup(o.width, o.height, Build::kGridLog2,
                                          soak_stage_options(), knots, knots, 2);
  ResetSummary s;
  for (int t = 0; t < o.trials; ++t) {
    Trial trial(o, t, setup);
    std::string why;
    try {
      why = trial.run(s);
    } catch (const std::exception& e) {
      why = std::string("stuck: ") + e.what();
    }
    ++s.trials;
    if (!why.empty()) {
      ++s.failures;
      if (s.first_failure.empty())
        s.first_failure = "trial " + std::to_string(t) + " (" + trial.where() + "): " + why;
    }
    if (o.progress && (t + 1) % 10 == 0)
      o.progress("soak: " + std::to_string(t + 1) + " of " + std::to_string(o.trials) +
                 " resets, " + std::to_string(s.failures) + " failed");
  }
  return s;
}

}  // namespace scw::host::soak
