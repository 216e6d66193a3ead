// SPDX-License-Identifier: Apache-2.0
// Disparity RTL configurations under test: the one source tests/CMakeLists.txt must match.
#pragma once

#include "hls/disparity/disparity_params.hpp"

namespace scw::test {

// Small stages, 32 pixels wide and up to 16 rows. P = 2 with N = 7 puts the results of a beat
// across two output beats (R = 3 is not a multiple of P), as P = 4 with N = 5 does.
using DisparityP1 = hls::disparity::DisparityParams<1, 32, 5, 6, 16>;
using DisparityP2 = hls::disparity::DisparityParams<2, 32, 7, 6, 16>;
using DisparityP4 = hls::disparity::DisparityParams<4, 32, 5, 5, 16>;

}  // namespace scw::test
