// SPDX-License-Identifier: Apache-2.0
// Stereo test pairs for the disparity tests and the two input streams of frames back to back.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "sim/core/frame_beats.hpp"

namespace scw::test {

struct StereoPair {
  std::vector<std::uint8_t> left, right;
};

/// A right image of noise and a left image that sees it shifted by a piecewise-constant
/// disparity field inside [dmin, dmin + nd), with 10 % of the pixels replaced by noise (so
/// minima are not all unique and ties and rejections happen).
inline StereoPair random_pair(int w, int h, int dmin, int nd, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  StereoPair p{std::vector<std::uint8_t>(static_cast<std::size_t>(w * h)),
               std::vector<std::uint8_t>(static_cast<std::size_t>(w * h))};
  for (auto& v : p.right) v = static_cast<std::uint8_t>(rng() % 64 * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int s = dmin + (x / 7 + y / 5) % nd;
      auto& l = p.left[static_cast<std::size_t>(y * w + x)];
      l = x >= s ? p.right[static_cast<std::size_t>(y * w + x - s)]
                 : static_cast<std::uint8_t>(rng());
      if (rng() % 10 == 0) l = static_cast<std::uint8_t>(rng());
    }
  return p;
}

/// The left and right streams of `frames` (w x h each) sent back to back.
template <typename Beat>
struct StereoStreams {
  std::vector<Beat> left, right;
};

template <typename Beat>
StereoStreams<Beat> stereo_streams(const std::vector<StereoPair>& frames, int w, int h) {
  StereoStreams<Beat> s;
  for (const auto& f : frames) {
    const auto bl = sim::frame_beats_of<Beat>(f.left.data(), w, h);
    const auto br = sim::frame_beats_of<Beat>(f.right.data(), w, h);
    s.left.insert(s.left.end(), bl.begin(), bl.end());
    s.right.insert(s.right.end(), br.begin(), br.end());
  }
  return s;
}

}  // namespace scw::test
