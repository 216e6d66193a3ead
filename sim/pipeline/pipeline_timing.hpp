// SPDX-License-Identifier: Apache-2.0
// Frame period, latency and per-stage busy time of a pipeline run, from the cycle stamps the
// simulator keeps on every link (architecture section 5).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/core/simulator.hpp"

namespace scw::sim {

/// One frame at the pipeline's ports: cycles relative to the run's cycle 0.
struct FrameTiming {
  std::int64_t first_in = -1;  // the first input beat (either camera) is taken
  std::int64_t last_in = -1;   // the last input beat (both cameras) is taken
  std::int64_t result = -1;    // the frame's result word leaves
};

/// One block's busy time in one frame: from its first beat in to its last beat out.
struct StageTiming {
  std::string name;
  std::int64_t first_in = -1, last_out = -1;
  std::int64_t busy() const { return first_in < 0 || last_out < 0 ? 0 : last_out - first_in + 1; }
};

struct PipelineTiming {
  std::vector<FrameTiming> frames;
  /// T_P: between the last two frames' results (steady state when frames enter back to back);
  /// 0 with fewer than two frames.
  std::int64_t period = 0;
  /// T_L of the last frame, from its first and from its last input beat to its result.
  std::int64_t latency_first = 0, latency_last = 0;
  /// The largest over all frames (the first frame meets an empty pipeline, later ones may wait).
  std::int64_t max_latency_first = 0;
  std::vector<StageTiming> stages;  // of the last frame, blocks with inputs, in graph order
};

/// Adds one frame's stamps to `t` and brings T_P, T_L and the largest T_L up to date: the
/// frames come in order, so the last one added is the last frame.
inline void add_frame(PipelineTiming& t, const FrameTiming& f) {
  t.frames.push_back(f);
  t.max_latency_first = std::max(t.max_latency_first, f.result - f.first_in);
  t.latency_first = f.result - f.first_in;
  t.latency_last = f.result - f.last_in;
  if (t.frames.size() >= 2) t.period = f.result - t.frames[t.frames.size() - 2].result;
}

/// `left_in`, `right_in`: the input links; `out`: the result link (its pops are the results);
/// `start`: the run's cycle 0 on the simulator's clock.
inline PipelineTiming pipeline_timing(const SimReport& report, const ChannelBase& left_in,
                                      const ChannelBase& right_in, const ChannelBase& out,
                                      std::int64_t start) {
  PipelineTiming t;
  const auto& l = left_in.frames();
  const auto& r = right_in.frames();
  const auto& o = out.frames();
  const std::size_t n = std::min({l.size(), r.size(), o.size()});
  for (std::size_t k = 0; k < n; ++k) {
    if (o[k].first_pop < 0) break;
    FrameTiming f;
    f.first_in = std::min(l[k].first_push, r[k].first_push) - start;
    f.last_in = std::max(l[k].last_push, r[k].last_push) - start;
    f.result = o[k].first_pop - start;
    add_frame(t, f);
  }
  if (t.frames.empty()) return t;
  const std::size_t k = t.frames.size() - 1;
  for (const StageReport& s : report.stages) {
    if (s.frames.size() <= k) continue;
    const StageFrame& f = s.frames[k];
    if (f.first_in < 0 || f.last_out < 0) continue;  // sources and the sink
    t.stages.push_back({s.name, f.first_in - start, f.last_out - start});
  }
  return t;
}

}  // namespace scw::sim
