// SPDX-License-Identifier: Apache-2.0
// Rectify configurations under test: the one source tests/CMakeLists.txt must match.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/rectify/rectify_params.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/models/rectify_model.hpp"

namespace scw::test {

// Small RTL configurations: 32 pixels wide, up to 16 rows, a window of 8 raw rows.
using RectifyP1 = hls::rectify::RectifyParams<1, 32, 16, 8>;
using RectifyP2 = hls::rectify::RectifyParams<2, 32, 16, 8>;
using RectifyP4 = hls::rectify::RectifyParams<4, 32, 16, 8>;

/// One frame for a rectify stage: the raw image and the map (width x height each).
struct RectifyFrame {
  std::vector<std::uint8_t> raw;
  std::vector<hls::rectify::MapPoint> map;
};

/// The two input streams of frames sent back to back.
template <typename Params>
struct RectifyStreams {
  std::vector<typename Params::pixel_beat> raw;
  std::vector<typename Params::map_beat> map;
};

template <typename Params>
RectifyStreams<Params> rectify_streams(const std::vector<RectifyFrame>& frames, int width,
                                       int height) {
  RectifyStreams<Params> s;
  for (const auto& f : frames) {
    const auto r = sim::frame_beats_of<typename Params::pixel_beat>(f.raw.data(), width, height);
    const auto m = sim::frame_beats_of<typename Params::map_beat>(f.map.data(), width, height);
    s.raw.insert(s.raw.end(), r.begin(), r.end());
    s.map.insert(s.map.end(), m.begin(), m.end());
  }
  return s;
}

}  // namespace scw::test
