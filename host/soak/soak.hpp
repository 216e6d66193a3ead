// SPDX-License-Identifier: Apache-2.0
// `scw soak`: the small build's Verilated scw_pipeline against the C++ chain over many frames of
// varied content, under random input gaps and output backpressure, with a broken frame every K;
// every result checked against the C++ chain, every good frame's against the floating-point
// reference chain.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hls/labelling/labelling_params.hpp"
#include "hls/pipeline/pipeline_result.hpp"
#include "host/pipeline/setup.hpp"
#include "host/soak/soak_frames.hpp"

namespace scw::host::soak {

/// A line of progress for the terminal.
using Progress = std::function<void(const std::string&)>;

struct SoakOptions {
  int frames = 1000;          // content frames (a sof mid-frame makes two results of one)
  int malformed_every = 50;   // a broken frame every K frames (0: none)
  std::uint64_t seed = 1;     // content, faults, and the stall patterns
  int width = 64, height = 32;
  bool stalls = true;         // random input gaps and output backpressure
  RealPair real;              // the real crops' source
  std::string fst_dir;        // "": no trace; else the first divergence's FST window goes here
  std::int64_t fst_window = 2000;  // cycles either side of the divergence
  int inject_divergence = -1;  // >= 0: flip a bit of the RTL's result of this frame, to see the
                               // checker fire and the trace written
  Progress progress;
  /// The settings a summary records beside its counts: seed, malformed_every and size.
  nlohmann::json to_json() const;
};

/// Where the RTL first differs from the C++ chain: the result's index, the cycle of the first of
/// the two results (or of the result of the frame whose object words differ), and what differs.
struct Divergence {
  int frame = -1;
  std::int64_t cycle = -1;
  std::string what;
  std::string fst;  // the trace written around it, if any
};

struct SoakSummary {
  int frames = 0, results = 0, malformed = 0;
  int divergences = 0;           // results (with their object words and cycles) RTL != C++
  int deadlocks = 0;             // runs that stopped short of their results
  int reference_checked = 0;     // good frames compared with the floating-point chain
  int reference_mismatches = 0;  // of those, results not the reference's
  int reference_boundary = 0;    // of those, results that differ only by an object at a decision
                                 // boundary (pipeline::decision_boundary): not mismatches
  int flag_mismatches = 0;       // broken frames not flagged on their camera, good ones flagged
  std::map<std::string, int> content, faults;
  std::int64_t cycles = 0;
  double cpp_seconds = 0, rtl_seconds = 0, reference_seconds = 0;
  std::optional<Divergence> first_divergence;
  std::string first_reference_mismatch, first_reference_boundary, first_flag_mismatch, deadlock;
  /// frames, malformed, divergences, deadlocks, reference_mismatches and the rest.
  nlohmann::json to_json() const;
  /// The lines `scw soak` prints: counts, then the first of each kind of failure.
  std::string text() const;
  bool passed() const {
    return divergences == 0 && deadlocks == 0 && reference_mismatches == 0 && flag_mismatches == 0;
  }
};

/// The settings a soak runs with: opencv mode, disparities 0 .. 15, 2 x 2 tiles, objects of 20
/// px, f 100 px, b 0.2 m, the road stage fitting from 50 pixels, identity maps (the content is
/// rectified).
pipeline::StageOptions soak_stage_options();

/// Runs the soak. Throws std::invalid_argument for options the small build cannot take.
SoakSummary run_soak(const SoakOptions& o);

/// One side's output of a run, for comparing two.
struct RunOutput {
  std::vector<hls::pipeline::PipelineResultPacket> results;
  std::vector<std::int64_t> result_cycles;
  std::vector<hls::labelling::LabelPacket> object_table;
};

/// The object words of each frame (status words left out), frames back to back.
std::vector<std::vector<hls::labelling::Object>> objects_per_frame(
    const std::vector<hls::labelling::LabelPacket>& table);

/// Counts the results where `rtl` differs from `cpp` (value, cycle, or that frame's object
/// words; a missing result counts) and returns the first, or nothing when they agree.
std::pair<int, std::optional<Divergence>> compare_runs(const RunOutput& cpp, const RunOutput& rtl);

}  // namespace scw::host::soak
