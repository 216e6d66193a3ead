// SPDX-License-Identifier: Apache-2.0
// Whole images through the fixed-point rectify stage, one clock an iteration, no stalls.
#include "host/rectify/run_model.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include "hls/rectify/rectify.hpp"
#include "sim/core/frame_beats.hpp"

namespace scw::rectify {

namespace {
using HostParams = hls::rectify::RectifyParams<1, 2048, 2048, kHostStageRows>;

// The stage's top loop (rectify_frame: one clock of the kernel an iteration, the output never
// stalled), the loop its C-simulation test holds equal to the clocked model, without a vector of
// beats in or out: the sequence runner's share of time is this loop.
using Kernel = hls::rectify::Rectify<HostParams>;

void check_image(const cv::Mat& raw, int width, int height) {
  if (raw.type() != CV_8UC1)
    throw std::invalid_argument("rectify_image: the raw image must be 8-bit grey (CV_8UC1)");
  if (raw.cols != width || raw.rows != height)
    throw std::invalid_argument("rectify_image: raw image is " + std::to_string(raw.cols) + "x" +
                                std::to_string(raw.rows) + " but the map is " +
                                std::to_string(width) + "x" + std::to_string(height) +
                                "; rectify images of the calibration's size");
}
}  // namespace

struct Rectifier::Stage {
  int width = 0, height = 0;
  hls::rectify::RectifyConfig cfg{};
  std::unique_ptr<Kernel> kernel;  // line buffers: keep them off the stack
  std::vector<Kernel::map_type> points;
  // A frame that fails leaves the kernel mid-frame: the next frame starts on a fresh one, as
  // the disparity runner's does.
  void restart() { kernel = std::make_unique<Kernel>(cfg); }
};

Rectifier::Rectifier(const FixedMap& map, int lead_rows) : stage_(std::make_unique<Stage>()) {
  if (map.frac_bits != HostParams::kFracBits)
    throw std::invalid_argument("rectify_image: the map has " + std::to_string(map.frac_bits) +
                                " fractional bits, the stage " +
                                std::to_string(HostParams::kFracBits));
  if (map.width > HostParams::kMaxWidthPx || map.height > HostParams::kMaxHeight || map.width < 4)
    throw std::invalid_argument("rectify_image: images must be 4 .. 2048 pixels wide and at most "
                                "2048 rows high");
  plan_for_stage({row_window(map)}, HostParams::kRows, "rectify_image");
  if (lead_rows < 1 || lead_rows > HostParams::kRows - 1)
    throw std::invalid_argument("rectify_image: lead_rows must be 1 .. " +
                                std::to_string(HostParams::kRows - 1));
  stage_->width = map.width;
  stage_->height = map.height;
  stage_->cfg = hls::rectify::RectifyConfig{map.width, map.height, lead_rows};
  stage_->restart();
  stage_->points = sim::frame_beats_of<Kernel::map_type>(map.points.data(), map.width, map.height);
}

Rectifier::~Rectifier() = default;
Rectifier::Rectifier(Rectifier&&) noexcept = default;
Rectifier& Rectifier::operator=(Rectifier&&) noexcept = default;

cv::Mat Rectifier::operator()(const cv::Mat& raw) {
  Stage& s = *stage_;
  check_image(raw, s.width, s.height);
  const cv::Mat img = raw.isContinuous() ? raw : raw.clone();
  const int n = static_cast<int>(s.points.size());
  sim::FrameBeatsIn<Kernel::raw_type> pixels(img.ptr<std::uint8_t>(), img.cols, img.rows);
  hls::ArrayIn<Kernel::map_type> points(s.points.data(), n);
  cv::Mat out(raw.rows, raw.cols, CV_8UC1);
  sim::FrameBeatsOut<Kernel::out_type> beats(out.ptr<std::uint8_t>());
  if (hls::rectify::rectify_frame(*s.kernel, pixels, points, beats, n, sim::frame_clock_limit(n)) !=
      n) {
    s.restart();
    throw std::logic_error("rectify_image: the stage stopped producing output");
  }
  if (const auto bits = s.kernel->error(); bits != 0) {
    s.restart();
    throw std::logic_error("rectify_image: the stage flagged error bits " + std::to_string(bits));
  }
  return out;
}

cv::Mat rectify_image(const cv::Mat& raw, const FixedMap& map, int lead_rows) {
  check_image(raw, map.width, map.height);  // a wrong image is named before the map
  return Rectifier(map, lead_rows)(raw);
}

}  // namespace scw::rectify
