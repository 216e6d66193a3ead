// SPDX-License-Identifier: Apache-2.0
// The labelling stage at the thesis size: the one source bench/CMakeLists.txt must match.
#pragma once

#include "hls/labelling/labelling_params.hpp"

namespace scw::bench {

/// The thesis camera (architecture section 2): 1280 x 480.
constexpr int kLabBenchWidth = 1280;
constexpr int kLabBenchHeight = 480;
/// 8 x 4 tiles of 160 x 120 pixels, 256 labels each, 256 objects per frame.
constexpr int kLabBenchTilesX = 8;
constexpr int kLabBenchTilesY = 4;
constexpr int kLabBenchLabels = 256;
constexpr int kLabBenchObjects = 256;
constexpr double kLabClockMhz = 125.0;

using LabellingBench =
    hls::labelling::LabellingParams<kLabBenchWidth, kLabBenchHeight, kLabBenchTilesX,
                                    kLabBenchTilesY, kLabBenchLabels, kLabBenchObjects>;

}  // namespace scw::bench
