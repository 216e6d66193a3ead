// SPDX-License-Identifier: Apache-2.0
// The disparity stage at the thesis size: the one source bench/CMakeLists.txt must match.
#pragma once

#include "hls/disparity/disparity_params.hpp"

namespace scw::bench {

// Names carry "Disp" so that this header and rectify_bench_configs.hpp (kBenchWidth, ...) can
// be included together, as a whole-pipeline bench would.

/// The thesis camera (architecture section 2): 1280 x 480, 8-bit grey.
constexpr int kDispBenchWidth = 1280;
constexpr int kDispBenchHeight = 480;
/// The thesis's window and range (Leu, Table 5.7): N = 21, candidates d = 20 .. 64, all 45 of
/// them evaluated in parallel.
constexpr int kDispBenchWindow = 21;
constexpr int kDispBenchDMin = 20;
constexpr int kDispBenchNumDisp = 45;

template <int P>
using DisparityBench = hls::disparity::DisparityParams<P, kDispBenchWidth, kDispBenchWindow,
                                                       kDispBenchNumDisp, kDispBenchHeight>;

}  // namespace scw::bench
