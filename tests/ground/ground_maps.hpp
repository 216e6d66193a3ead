// SPDX-License-Identifier: Apache-2.0
// Disparity maps for the ground-removal tests: a road ramp with objects standing on it, noisy
// random scenes and uniform noise; their beats and the reference's expected beats.
#pragma once

#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

#include "hls/ground/ground_params.hpp"
#include "host/reference/ground_ref.hpp"
#include "sim/core/frame_beats.hpp"

namespace scw::test::ground {

using hls::ground::GroundConfig;
using GroundBeat = hls::Beat<std::uint16_t, 1>;

/// A flat road under a rectified camera: disparity 0 (invalid, sky) down to row `horizon`,
/// then round(16 * px_per_row * (v - horizon)) in Q11.4 (thesis 6.2: the ground brightens
/// steadily downwards).
struct Road {
  int horizon = 0;
  double px_per_row = 0.45;  // b / h of the default rig (0.54 m / 1.20 m)

  int q4(int v) const {
    return v <= horizon ? 0 : static_cast<int>(std::lround(16.0 * px_per_row * (v - horizon)));
  }
};

/// An object standing on the road: a face of constant disparity, the road's at its foot row,
/// over columns x0 .. x1 and rows top .. foot (inclusive).
struct Box {
  int x0, x1, top, foot;
};

inline cv::Mat road_scene(int w, int h, const Road& road, const std::vector<Box>& boxes) {
  cv::Mat m(h, w, CV_16SC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at<std::int16_t>(y, x) = static_cast<std::int16_t>(road.q4(y));
  for (const Box& b : boxes)
    for (int y = b.top; y <= b.foot; ++y)
      for (int x = b.x0; x <= b.x1; ++x)
        m.at<std::int16_t>(y, x) = static_cast<std::int16_t>(road.q4(b.foot));
  return m;
}

/// A road of random slope and horizon with measurement noise, holes (0 and negative codes, as
/// the disparity stage's two invalid encodings) and random boxes: enough ground that both
/// outcomes of the rule occur, and every way of failing it.
inline cv::Mat noisy_scene(int w, int h, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uni = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  Road road;
  road.horizon = uni(-4, h / 3);
  road.px_per_row = std::uniform_real_distribution<double>(0.1, 1.5)(rng);
  std::vector<Box> boxes;
  for (int n = uni(0, 4); n > 0; --n) {
    const int x0 = uni(0, w - 1), foot = uni(0, h - 1);
    boxes.push_back({x0, std::min(w - 1, x0 + uni(0, w / 3)), std::max(0, foot - uni(0, h)), foot});
  }
  cv::Mat m = road_scene(w, h, road, boxes);
  const int noise = uni(0, 6), holes = uni(0, 8);  // Q11.4 amplitude, percent
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto& d = m.at<std::int16_t>(y, x);
      int v = d + uni(-noise, noise);
      if (uni(0, 99) < holes) v = uni(0, 1) ? 0 : -16;
      d = static_cast<std::int16_t>(v);
    }
  return m;
}

/// Every 16-bit pattern equally likely: almost never ground, exercises the validity checks.
inline cv::Mat uniform_map(int w, int h, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  cv::Mat m(h, w, CV_16UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at<std::uint16_t>(y, x) = static_cast<std::uint16_t>(rng());
  return m;
}

/// A configuration drawn around the defaults, enable mostly on.
inline GroundConfig random_config(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uni = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  GroundConfig c;
  c.enable = uni(0, 7) != 0;
  c.step_tol_q4 = uni(0, 12);
  c.min_rise_q4 = uni(0, 120);
  c.max_rise_q4 = c.min_rise_q4 + uni(-10, 200);
  if (c.max_rise_q4 < 0) c.max_rise_q4 = 0;
  return c;
}

inline std::vector<GroundBeat> map_beats(const std::vector<cv::Mat>& maps) {
  std::vector<GroundBeat> beats;
  for (const auto& m : maps) {
    const cv::Mat c = m.clone();  // continuous
    const auto b = sim::frame_beats_of<GroundBeat>(c.ptr<std::uint16_t>(), c.cols, c.rows);
    beats.insert(beats.end(), b.begin(), b.end());
  }
  return beats;
}

/// The reference's output of each map, as the beats the stage must emit.
inline std::vector<GroundBeat> expected_beats(const std::vector<cv::Mat>& maps,
                                              const GroundConfig& cfg) {
  std::vector<cv::Mat> ref;
  for (const auto& m : maps) ref.push_back(reference::ground_reference(m, cfg));
  return map_beats(ref);
}

/// The pixels where `a` and `b` (CV_16S or CV_16U, same size) hold different bit patterns.
inline int differences(const cv::Mat& a, const cv::Mat& b) {
  const cv::Mat ua(a.rows, a.cols, CV_16UC1, a.data, a.step);
  const cv::Mat ub(b.rows, b.cols, CV_16UC1, b.data, b.step);
  return cv::countNonZero(ua != ub);
}

}  // namespace scw::test::ground
