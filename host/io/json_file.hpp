// SPDX-License-Identifier: Apache-2.0
// Writing a JSON document to a file, with the one error every command gives when it cannot.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace scw::host::io {

/// Writes `doc` indented by 2 and a newline, making the file's folder first if it is missing.
/// Throws std::runtime_error naming the file when it cannot be written.
void write_json(const std::filesystem::path& file, const nlohmann::json& doc);

}  // namespace scw::host::io
