// SPDX-License-Identifier: Apache-2.0
// The warning tests' camera: the thesis's 1280 x 480 image seen by a Karlsruhe-like rig.
#pragma once

#include "host/warning/setup.hpp"

namespace scw::test {

inline constexpr int kImageWidth = 1280, kImageHeight = 480;

/// Karlsruhe-like: f 700 px, b 0.54 m (WarningSetup's defaults), principal point at the centre
/// of the 1280 x 480 image, thesis vehicle origin (-0.30, -1.20, 1.65) m, d_limit 64 px.
inline host::warning::WarningSetup karlsruhe_like() {
  host::warning::WarningSetup s;
  s.cu_px = kImageWidth / 2.0;
  s.cv_px = kImageHeight / 2.0;
  return s;
}

}  // namespace scw::test
