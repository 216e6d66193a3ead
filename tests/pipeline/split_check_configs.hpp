// SPDX-License-Identifier: Apache-2.0
// The builds of scw_beat_split and scw_frame_check under test: the one source split_check.cmake
// must match (each test static_asserts the Verilated parameters against these).
#pragma once

#include <cstdint>

#include "hls/pipeline/frame_check.hpp"

namespace scw::test::pipeline {

/// Beat split: 16-bit pixels (disparities, the pipeline's use), 1, 2 and 4 per beat.
using split_pixel_t = std::uint16_t;

/// Frame check: small enough for exhaustive stall runs, P = 1 and 2.
using CheckP1 = hls::pipeline::FrameCheckParams<1, 16, 8>;
using CheckP2 = hls::pipeline::FrameCheckParams<2, 16, 8>;

}  // namespace scw::test::pipeline
