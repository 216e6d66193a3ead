// SPDX-License-Identifier: Apache-2.0
// The files `scw run` writes for a frame: the rectified pair, the disparity (8 and 16 bits), the
// labels, the overlay, the road picture and objects.csv (docs/warning.md, "`scw run`").
#pragma once

#include <filesystem>
#include <string>

#include "host/app/run.hpp"

namespace scw::app {

/// Each object with the warning stage's view of it and the application layer's, one row per
/// object. Throws std::runtime_error naming the file if it cannot be written.
void write_objects_csv(const std::filesystem::path& p, const FrameOutput& f);

/// Which pictures a run writes for each frame (`scw run --pictures`): none, the overlay alone, or
/// all of them (the rectified pair, the disparity in 8 and 16 bits, the labels, the overlay, the
/// road). A frame's objects.csv and results.jsonl line are written whichever is chosen.
enum class Pictures { kNone, kOverlay, kAll };
/// "none", "overlay", "all"; pictures_from_name throws std::invalid_argument for another name.
const char* pictures_name(Pictures p);
Pictures pictures_from_name(const std::string& name);

/// The files write_frame() writes for a frame under `pictures`, comma-separated, for messages.
std::string frame_file_names(Pictures pictures);

/// The chosen pictures of a frame and its objects.csv into `dir`, names prefixed with `prefix`.
void write_frame(const std::filesystem::path& dir, const std::string& prefix, const FrameOutput& f,
                 Pictures pictures = Pictures::kAll);

}  // namespace scw::app
