// SPDX-License-Identifier: Apache-2.0
// Golden vector sets of the labelling stage: Q11.4 disparities in, object descriptors and frame
// status words out, from the C++ model (docs/vectors.md, "Labelling sets").
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hls/labelling/labelling_params.hpp"

namespace scw::vectors {

/// The golden-vector build of the stage: frames up to 64 x 48, up to 4 x 4 tiles, 16 labels a
/// tile (256 a frame), 64 objects a frame. Small tables, so that the overflow preset can exhaust
/// them with a readable frame; a replay builds scw_labelling with these parameters.
using LabellingVecParams = hls::labelling::LabellingParams<64, 48, 4, 4, 16, 64>;

/// What the stage must report for a frame.
enum class LabellingExpect {
  kClean,           // exactly the reference's objects, no flag
  kTileOverflow,    // a tile runs out of labels: tile_overflow only
  kObjectOverflow,  // more than MaxObjects objects: object_overflow only, MaxObjects emitted
};

struct LabellingFrame {
  std::string name;
  cv::Mat d;  // CV_16UC1, the config's width x height (the presets: 64 x 48), Q11.4
  LabellingExpect expect = LabellingExpect::kClean;
};

/// Frames streamed back to back through one stage from reset, and its configuration.
struct LabellingPreset {
  std::vector<LabellingFrame> frames;
  hls::labelling::LabellingConfig cfg;
  int tiles_x = 1, tiles_y = 1;
  std::string description;
  std::string build = "vectors";  // labelling_builds()
};

/// The builds a set is made at: "vectors" (LabellingVecParams; the committed sets) and the
/// pipeline's "small", "tsukuba" and "thesis" (hls/pipeline/pipeline_configs.def), each at one
/// disparity a beat.
const std::vector<std::string>& labelling_builds();

/// The presets `scw vectors labelling` writes: "shapes", "tsukuba" and "overflow".
const std::vector<std::string>& labelling_presets();
/// The frames of a preset; throws std::invalid_argument naming the presets for another name.
///   shapes: five adversarial shapes (host/vectors/labelling_maps.hpp) on 3 x 4 uneven tiles.
///   tsukuba: a 64 x 48 crop of `data_dir`/truedisp.row3.col3.pgm, 2 x 2 tiles, min area 4
///     (throws std::runtime_error when the file is missing or not the 8-bit ground truth).
///   overflow: a tile overflow and an object overflow, then a normal frame.
LabellingPreset labelling_preset(const std::string& name, const std::filesystem::path& data_dir);

/// Disparity maps of the user's, one a frame, sent back to back: 16-bit PNGs of Q11.4 values (as
/// `scw disparity --out16` writes), the one crop of them all (empty: the first map's whole size)
/// and the stage's settings.
struct UserMap {
  std::vector<std::filesystem::path> disparity;
  cv::Rect roi;
  int tiles_x = 2, tiles_y = 2;
  int floor = 0, min_area = 4;
  std::string build = "vectors";
};

/// The frames of a user's maps; every object must come out (a frame that overflows the build's
/// tables fails the check). Throws std::invalid_argument naming what does not fit and
/// std::runtime_error for a file that is not a 16-bit map.
LabellingPreset labelling_frames(const UserMap& map);

/// What write_labelling_set() checked and wrote, for the CLI to print.
struct LabellingSetSummary {
  std::size_t frames = 0, words = 0;
  std::size_t objects = 0;  // object words out (rows of expected_objects.csv)
  int width = 0, height = 0, tiles_x = 0, tiles_y = 0;
  std::int64_t cycles = 0;  // the model from reset to the last word, no stalls
};

/// Streams `p` through sim::LabellingModel (no stalls; and again with idle input and
/// backpressure, which must give the same words), checks every frame against the flood-fill
/// reference (and a clean frame against the host's segment() too), then writes the set into
/// `dir`: in.hex, in.png, expected.hex, expected_objects.csv, expected_status.csv, labels.png and
/// the manifest. Throws std::runtime_error or std::logic_error (before writing anything) when a
/// check fails.
LabellingSetSummary write_labelling_set(const LabellingPreset& p, const std::filesystem::path& dir);

/// The layout of the labelling stage's output word (sim/words/labelling_pack.hpp) for add_hex(): the
/// generic {last, data}, plus the two shapes of data, told apart by bit 0. The warning stage's
/// input is the same word.
nlohmann::json labelling_word_layout();

}  // namespace scw::vectors
