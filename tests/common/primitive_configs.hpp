// SPDX-License-Identifier: Apache-2.0
// Parameters of the primitives under test: the one source tests/CMakeLists.txt must match.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "hls/common/beat.hpp"
#include "hls/common/line_buffer.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/words/pack.hpp"

namespace scw::test {

// Elastic blocks carry a whole packed beat: Width = P * 8 + 2.
using Beat2 = hls::Beat<std::uint8_t, 2>;  // 18-bit words (IData ports)
using Beat4 = hls::Beat<std::uint8_t, 4>;  // 34-bit words (QData ports)

template <typename B, int Depth>
struct FifoCfg {
  using beat_t = B;
  static constexpr int kWidth = sim::BeatLayout<B>::kBits;
  static constexpr int kDepth = Depth;
};
using FifoD1 = FifoCfg<Beat2, 1>;
using FifoD2 = FifoCfg<Beat2, 2>;
using FifoD5 = FifoCfg<Beat4, 5>;
constexpr int kElasticWidth = sim::BeatLayout<Beat4>::kBits;  // stream register, skid buffer

using LineBufP1 = hls::LineBufferParams<1, 32, 3>;
using LineBufP2 = hls::LineBufferParams<2, 32, 2>;
using LineBufP4 = hls::LineBufferParams<4, 32, 3>;

/// Random beats with random flags (elastic blocks must not interpret them).
template <typename B>
std::vector<B> random_beats(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<B> v(n);
  for (auto& b : v) {
    for (auto& p : b.px) p = static_cast<typename B::value_type>(rng());
    b.sof = (rng() % 7) == 0;
    b.eol = (rng() % 5) == 0;
  }
  return v;
}

inline std::vector<std::uint8_t> random_image(int width, int height, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> img(static_cast<std::size_t>(width * height));
  for (auto& p : img) p = static_cast<std::uint8_t>(rng());
  return img;
}

}  // namespace scw::test
