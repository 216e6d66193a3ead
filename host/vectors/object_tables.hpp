// SPDX-License-Identifier: Apache-2.0
// Object tables of the user's, read from CSV: what a labelling stage of their own sent, frame by
// frame, for a warning vector set (docs/vectors.md, "Warning sets from your object tables").
#pragma once

#include <filesystem>
#include <vector>

#include "hls/labelling/labelling_params.hpp"

namespace scw::vectors {

/// One frame's table as the labelling stage sends it: its objects, then its status word's flags
/// (the status word's count is always the number of objects).
struct ObjectTable {
  std::vector<hls::labelling::Object> objects;
  hls::labelling::FrameStatus flags;
};

/// Reads the tables of frames 0 .. K-1, K one more than the largest `frame` in either file.
///   objects: a `frame` column and one column per field of the object word (area, x_min, ..,
///     sum_dd: the names of a labelling set's expected_objects.csv, whose `word` and `label`
///     columns, like any other extra column, are ignored); rows in the order they are sent.
///   status (optional, empty path: no flags): `frame` and tile_overflow, object_overflow,
///     stream_error (0 or 1), at most one row a frame; a labelling set's expected_status.csv.
/// Throws std::runtime_error naming the file, line and column of the first value that is missing,
/// not a whole number or wider than its field.
std::vector<ObjectTable> read_object_tables(const std::filesystem::path& objects,
                                            const std::filesystem::path& status = {});

}  // namespace scw::vectors
