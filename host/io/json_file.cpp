// SPDX-License-Identifier: Apache-2.0
// Writing a JSON document to a file (json_file.hpp).
#include "host/io/json_file.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace scw::host::io {

void write_json(const std::filesystem::path& file, const nlohmann::json& doc) {
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  std::ofstream f(file);
  if (f) f << doc.dump(2) << "\n";
  if (!f) throw std::runtime_error("cannot write '" + file.string() + "'");
}

}  // namespace scw::host::io
