// SPDX-License-Identifier: Apache-2.0
// The files `scw run` writes for a frame: the rectified pair, the disparity (8 and 16 bits), the
// labels, the overlay, the road picture and objects.csv (docs/run.md).
#pragma once

#include <filesystem>
#include <string>

#include "host/app/run.hpp"

namespace scw::app {

/// Each object with the warning stage's view of it and the application layer's, one row per
/// object. Throws std::runtime_error naming the file if it cannot be written.
void write_objects_csv(const std::filesystem::path& p, const FrameOutput& f);

/// Every picture of a frame and its objects.csv into `dir`, names prefixed with `prefix`.
void write_frame(const std::filesystem::path& dir, const std::string& prefix, const FrameOutput& f);

}  // namespace scw::app
