// SPDX-License-Identifier: Apache-2.0
// Feature rows as CSV: the training and test sets `scw train` reads and writes.
#pragma once

#include <string>
#include <vector>

#include "host/app/object_features.hpp"

namespace scw::app {

/// Reads feature rows from CSV: the header `class,hu1,hu2,hu3,width_m,height_m`, then one row
/// per object (class name as to_string(ObjectClass), five non-negative finite numbers). Blank
/// lines are skipped; spaces around fields and CRLF line ends are allowed. std::runtime_error
/// naming the file, the line and the column for a malformed header or row, an unknown class,
/// or a file without rows.
std::vector<LabelledFeatures> read_feature_csv(const std::string& path);
/// Writes rows in read_feature_csv's format, every value with 17 significant digits so it
/// reads back bit for bit. std::runtime_error naming the path when it cannot be written.
void write_feature_csv(const std::string& path, const std::vector<LabelledFeatures>& rows);

}  // namespace scw::app
