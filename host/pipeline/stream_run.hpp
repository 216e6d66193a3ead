// SPDX-License-Identifier: Apache-2.0
// `scw stream`'s work around the run (stream_line_buffer.hpp): the image, the report and the
// files.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "sim/core/simulator.hpp"
#include "sim/words/pack.hpp"

namespace scw::host::pipeline {

/// What a run is asked for (the `scw stream` options).
struct StreamOptions {
  std::string image;
  int ppc = 1;
  std::string engine = "rtl";  // cpp (the C++ twin) or rtl (Verilated)
  int frames = 2;
  std::string stalls = "none";  // sim::StallPattern::parse
  std::string out_dir = "out/stream";
  std::vector<int> roi;  // x y w h, empty = whole image
};

/// Reads o.image as grey, cut to o.roi, after checking o.stalls. Throws std::runtime_error when
/// the rectangle is not inside the image, or when the image is wider than `max_width_px` or not
/// in whole beats of o.ppc (at least two), saying what the line buffer holds.
cv::Mat read_stream_image(const StreamOptions& o, int max_width_px);

/// What a run measured, the line buffer it ran, and one frame's beats packed as the golden
/// vectors hold them.
struct StreamRun {
  sim::SimReport report;
  int ppc = 1, max_width_px = 0, rows = 0, latency = 0;
  std::size_t frame_beats = 0;  // beats of one frame
  std::size_t beats = 0;        // of all frames, every one equal to the reference
  std::vector<sim::Bits> input, expected;
};

/// The report as report.json holds it: cycles, every FIFO, every stage's frame timestamps.
nlohmann::json stream_report_json(const sim::SimReport& r);

/// Writes o.out_dir/report.json (the report, the engine, P and the thesis's clock) and the
/// golden vector set of one frame of `grey` in o.out_dir/vectors (vectors::write_line_buffer_set).
void write_stream_files(const StreamOptions& o, const StreamRun& r, const cv::Mat& grey);

}  // namespace scw::host::pipeline
