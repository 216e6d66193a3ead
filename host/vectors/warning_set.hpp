// SPDX-License-Identifier: Apache-2.0
// Golden vector sets of the warning stage: labelling object tables in, one collision-warning
// result word per frame out, from the C++ model (vectors/warning/README.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"
#include "host/warning/setup.hpp"

namespace scw::vectors {

/// The golden-vector build: a reciprocal table for disparities below 128 px (2048 Q11.4 codes),
/// twice the default search range, so that a set can hold objects both inside the table and
/// past it. A replay builds scw_warning with MaxDisparityPx = 128.
constexpr int kWarningVecMaxDisparityPx = 128;
using WarningVecParams = hls::warning::WarningParams<kWarningVecMaxDisparityPx>;

/// How a frame's table is sent, and so which flags its result must carry.
enum class WarningShape {
  kGood,          // the objects, then a status word with the right count and `last`
  kStatusNoLast,  // the status word without `last`: stream_error
  kLastNoStatus,  // `last` on the final object, no status word: stream_error
  kWrongCount,    // the status word counts one object fewer: stream_error
};

/// One object table and, for the hand-placed ones, the result it was placed to give.
struct WarningFrame {
  std::string name;
  std::vector<hls::labelling::Object> objects;
  WarningShape shape = WarningShape::kGood;
  // tile_overflow, object_overflow, stream_error as labelling reports them
  hls::labelling::FrameStatus flags;
  // The hand-placed frames state what they are there to show; random frames leave it open.
  bool check_severity = false;
  hls::warning::Severity severity = hls::warning::Severity::kNone;
  bool in_tunnel = false, too_close = false;
  int index = -1;  // the deciding object, -1 = none
};

/// Tables streamed back to back through one stage from reset, and the rig they were placed on.
struct WarningPreset {
  host::warning::WarningSetup setup;
  std::vector<WarningFrame> frames;
  std::string description;
  int width = 1280, height = 480;  // the image the objects lie in (for the description only)
  std::string build = "vectors";   // warning_builds()
};

/// The builds a set is made at: "vectors" (WarningVecParams; the committed sets) and the
/// pipeline's "small", "tsukuba" (a table for disparities below 32 px) and "thesis" (128 px).
const std::vector<std::string>& warning_builds();

/// The presets `scw vectors warning` writes: "thesis", "random" and "malformed".
const std::vector<std::string>& warning_presets();
/// The tables of a preset; throws std::invalid_argument naming the presets for another name.
///   thesis: 13 hand-placed tables, one per rule of eq. 5.2, incl. the thesis's worked example.
///   random: 64 seeded random tables over the whole range of the stage.
///   malformed: every way a table can break the packet rules, each followed by a good one.
WarningPreset warning_preset(const std::string& name);

/// Object tables of the user's (host/vectors/object_tables.hpp) on the user's rig.
struct UserTables {
  std::filesystem::path objects, status;  // status: optional
  host::warning::WarningSetup setup;      // cu_px = cv_px = 0: the image centre
  int width = 1280, height = 480;         // the image the objects lie in
  std::string build = "vectors";
};
/// The preset of a user's tables: every frame checked only against the plain fold of evaluate().
/// Throws std::runtime_error naming the file, line and column of a bad value.
WarningPreset warning_user_preset(const UserTables& u);

/// What write_warning_set() checked and wrote, for the CLI to print.
struct WarningSetSummary {
  std::size_t frames = 0, words_in = 0, results = 0;
  std::size_t objects = 0;  // object words in the input (rows of expected_objects.csv)
  std::int64_t cycles = 0;  // the model from reset to the last result, no stalls
};

/// Streams `p` through sim::WarningModel (no stalls; and again with idle input and backpressure,
/// which must give the same results), checks every frame's result against a plain fold of
/// evaluate() and the hand-placed frames against what they were placed for, then writes the set
/// into `dir`: in.hex, in_words.csv, expected.hex, expected.csv, expected_objects.csv and the
/// manifest. Throws std::runtime_error or std::logic_error (before writing anything) when a
/// check fails.
WarningSetSummary write_warning_set(const WarningPreset& p, const std::filesystem::path& dir);

}  // namespace scw::vectors
