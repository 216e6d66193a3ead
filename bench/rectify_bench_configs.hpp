// SPDX-License-Identifier: Apache-2.0
// The rectify stage at the thesis size: the one source bench/CMakeLists.txt must match.
#pragma once

#include "hls/rectify/rectify_params.hpp"

namespace scw::bench {

/// The thesis camera (architecture section 2): 1280 x 480, 8-bit grey.
constexpr int kBenchWidth = 1280;
constexpr int kBenchHeight = 480;
/// Raw rows kept on chip: enough for a real calibration's rotation and distortion (a few dozen
/// rows), and a power of two as scw_rectify needs.
constexpr int kBenchRows = 64;

template <int P>
using RectifyBench = hls::rectify::RectifyParams<P, kBenchWidth, kBenchHeight, kBenchRows>;

}  // namespace scw::bench
