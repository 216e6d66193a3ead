// SPDX-License-Identifier: Apache-2.0
// `scw sim`'s work: the whole pipeline clocked in sim/ on one pair repeated (C++ models,
// Verilated blocks or a mix), its timing, its results, the floating-point chain beside it, and
// the JSON report (docs/performance.md).
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hls/pipeline/pipeline_result.hpp"
#include "host/disparity/run_model.hpp"
#include "host/synth/builds.hpp"
#include "sim/core/simulator.hpp"
#include "sim/pipeline/pipeline_timing.hpp"

namespace scw::host::pipeline {

/// What a run is asked for (the `scw sim` options).
struct SimOptions {
  std::string config = "thesis";  // thesis or small
  int ppc = 1;
  int frames = 3;
  std::string engine = "cpp";  // cpp or rtl
  std::vector<std::string> rtl_stages;  // these blocks Verilated, the rest C++
  std::string left, right;     // empty: a synthetic street
  std::string mode = disparity::mode_name(disparity::kDefaultMode);
  int edge_candidates = 0;      // DisparityConfig::edge_candidates (0: cv::StereoBM's band)
  int dmin = -1, num_disp = 0;  // -1 / 0: the configuration's
  std::string stalls = "none";  // sim::StallPattern::parse
  std::string synth_json;       // a `scw synth --json` report of the same build: ms at its Fmax
  bool reference = false;       // also run the floating-point chain and compare
  int threads = 1;              // 2: the chain's disparity and road stages on a second thread
};

/// The floating-point chain's frame result on the same pair, and whether the pipeline's last
/// result agrees with it (severity, object count, the deciding object's closest point and box,
/// its distance within host::warning::distance_tolerance_m).
struct ReferenceCheck {
  hls::warning::Severity severity = hls::warning::Severity::kNone;
  int objects = 0;
  int index = -1;
  double distance_m = 0.0;
  bool agrees = false;
  /// The line `scw sim --reference` prints: the chain's result and whether it agrees.
  std::string text() const;
};

/// What a run measured.
struct SimRun {
  SimOptions options;
  std::string engine;  // "cpp", "rtl" or "mixed (rtl: ...)"
  int width = 0, height = 0, window = 0, ppc = 1;
  int dmin = 0, num_disp = 0;
  disparity::Mode mode = disparity::kDefaultMode;
  std::int64_t cycles = 0;
  sim::PipelineTiming timing;
  sim::SimReport report;
  std::vector<hls::pipeline::PipelineResult> results;
  std::optional<ReferenceCheck> reference;
  std::optional<host::synth::SlowestModule> slowest;  // from options.synth_json
};

/// Runs the pipeline. Notes and progress go to `log`. Throws std::invalid_argument naming a bad
/// option (frames, ppc, config, engine, stalls, images, a synth report for another build).
SimRun run_sim(const SimOptions& o, std::ostream& log);

/// The run as `scw sim --json` writes it, with the thesis's Table 5.7 figures beside it.
nlohmann::json sim_json(const SimRun& r);

}  // namespace scw::host::pipeline
