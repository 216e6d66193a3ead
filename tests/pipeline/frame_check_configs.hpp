// SPDX-License-Identifier: Apache-2.0
// The builds of scw_frame_check under test: the one source frame_check.cmake must match (the
// test static_asserts the Verilated parameters against these).
#pragma once

#include "hls/pipeline/frame_check.hpp"

namespace scw::test::pipeline {

/// Frame check: small enough for exhaustive stall runs, P = 1 and 2.
using CheckP1 = hls::pipeline::FrameCheckParams<1, 16, 8>;
using CheckP2 = hls::pipeline::FrameCheckParams<2, 16, 8>;

}  // namespace scw::test::pipeline
