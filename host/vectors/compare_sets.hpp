// SPDX-License-Identifier: Apache-2.0
// Two golden vector sets of one preset compared (`scw vectors compare`): byte for byte where
// their packing is the same, and field by field where a word's layout differs. A set committed
// before a field of scw_pkg.sv changed width holds the same values at another packing; the
// regeneration test tells that apart from a change of values (docs/vectors.md, "When a width
// changes").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace scw::vectors {

/// What compare_sets() found.
struct SetComparison {
  std::vector<std::string> same;      // files equal byte for byte
  std::vector<std::string> repacked;  // hex files of another layout whose every field is equal
  std::vector<std::string> problems;  // what differs; empty when the sets agree
};

/// Compares set `b` with set `a`. Both are opened as VectorSet::open() does: a valid manifest,
/// every file verified (its SHA-256 and shape), or std::runtime_error naming the first problem.
/// Their manifests must agree in stage, description, config and file list (names, roles,
/// kinds); each file must be equal byte for byte, except a hex file whose layout (word width, or
/// a field's place or width) differs, which must have as many beats and, beat by beat, every
/// field of the same name equal in value (nested word tables, such as a labelling word's object
/// and status fields, decoded by its discriminating bit). A file whose bytes differ at the same
/// layout is a problem, as is a layout without fields.
SetComparison compare_sets(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace scw::vectors
