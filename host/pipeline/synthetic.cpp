// SPDX-License-Identifier: Apache-2.0
// Synthetic rectified pairs with known disparities (host/pipeline/synthetic.hpp).
#include "host/pipeline/synthetic.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

namespace scw::host::pipeline {

namespace {

/// A texture wide enough for any shift: blurred noise, so block matching has a clear minimum.
cv::Mat texture(int width, int height, std::mt19937& rng) {
  cv::Mat t(height, width, CV_8U);
  std::uniform_int_distribution<int> v(0, 255);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) t.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(v(rng));
  cv::GaussianBlur(t, t, cv::Size(3, 3), 0.8);
  return t;
}

}  // namespace

SyntheticPair synthetic_pair(int width, int height, int background_disparity,
                             const std::vector<SyntheticBox>& boxes, std::uint32_t seed) {
  if (width < 1 || height < 1) throw std::invalid_argument("synthetic_pair: empty image");
  int dmax = background_disparity;
  for (const auto& b : boxes) {
    if (b.x0 < 0 || b.y0 < 0 || b.x1 > width || b.y1 > height || b.x0 >= b.x1 || b.y0 >= b.y1)
      throw std::invalid_argument("synthetic_pair: a box outside the " + std::to_string(width) +
                                  " x " + std::to_string(height) + " image");
    if (b.disparity < 0) throw std::invalid_argument("synthetic_pair: a negative disparity");
    dmax = std::max(dmax, b.disparity);
  }
  if (background_disparity < 0) throw std::invalid_argument("synthetic_pair: negative disparity");
  std::mt19937 rng(seed);
  const int tw = width + dmax + 1;
  std::vector<cv::Mat> tex;
  tex.push_back(texture(tw, height, rng));  // the background
  for (std::size_t i = 0; i < boxes.size(); ++i) tex.push_back(texture(tw, height, rng));

  SyntheticPair p{cv::Mat(height, width, CV_8U), cv::Mat(height, width, CV_8U),
                  cv::Mat(height, width, CV_16S)};
  // The surface seen at left-image column xl (scene coordinate) on row y: the nearest box
  // covering it, else the background. Index 0 = background.
  const auto surface = [&](int xl, int y) {
    int best = 0, best_d = background_disparity;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto& b = boxes[i];
      if (xl >= b.x0 && xl < b.x1 && y >= b.y0 && y < b.y1 && b.disparity >= best_d) {
        best = static_cast<int>(i) + 1;
        best_d = b.disparity;
      }
    }
    return std::pair<int, int>(best, best_d);
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto [s, d] = surface(x, y);
      p.left.at<std::uint8_t>(y, x) = tex[static_cast<std::size_t>(s)].at<std::uint8_t>(y, x);
      p.truth.at<std::int16_t>(y, x) = static_cast<std::int16_t>(16 * d);
      // Right column x sees the scene point that the left sees at x + d, for the nearest
      // surface whose disparity takes it there.
      int rs = 0, rd = -1;
      for (int k = 0; k <= static_cast<int>(boxes.size()); ++k) {
        const int dk = k == 0 ? background_disparity : boxes[static_cast<std::size_t>(k - 1)].disparity;
        const int xl = x + dk;
        if (xl >= tw) continue;
        if (k > 0) {
          const auto& b = boxes[static_cast<std::size_t>(k - 1)];
          if (xl < b.x0 || xl >= b.x1 || y < b.y0 || y >= b.y1) continue;
        }
        if (dk > rd) {
          rs = k;
          rd = dk;
        }
      }
      p.right.at<std::uint8_t>(y, x) =
          tex[static_cast<std::size_t>(rs)].at<std::uint8_t>(y, std::min(x + rd, tw - 1));
    }
  return p;
}

std::vector<SyntheticBox> street_boxes(int width, int height, int dmin, int dmax) {
  const int range = dmax - dmin;
  std::vector<SyntheticBox> b;
  // a car to the left, mid-range
  b.push_back({width / 10, height * 2 / 5, width / 10 + width / 5, height * 4 / 5,
               dmin + range / 2});
  // a pedestrian ahead, near
  b.push_back({width / 2 - width / 40, height / 4, width / 2 + width / 40, height * 5 / 6,
               dmin + range * 3 / 4});
  // a post to the right, nearer still
  b.push_back({width * 3 / 4, height / 6, width * 3 / 4 + std::max(4, width / 80), height * 5 / 6,
               dmin + range * 9 / 10});
  return b;
}

}  // namespace scw::host::pipeline
