// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the sequence folder scanner (`scw run --sequence`: find_pairs, frame_prefix). The
// input is a list of file names, one a line; each is made, empty, in a fresh folder, which is
// then scanned, and every pair found named as its output files would be.
#include <string>

#include "fuzz/fuzz_target.hpp"
#include "host/app/pair_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  const fs::path dir = scw::fuzz::scratch() / "sequence";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string names(reinterpret_cast<const char*>(data), size), name;
  for (std::size_t i = 0, lines = 0; i <= names.size() && lines < 64; ++i) {
    if (i < names.size() && names[i] != '\n') {
      name += names[i];
      continue;
    }
    // A name the file system can hold: no separators, no NUL, not . or .., at most 200 bytes.
    if (!name.empty() && name.size() <= 200 && name != "." && name != ".." &&
        name.find_first_of(std::string("/\0", 2)) == std::string::npos) {
      std::ofstream(dir / name).put('\n');
      ++lines;
    }
    name.clear();
  }
  scw::fuzz::expect_clear_error([&] {
    for (const auto& p : scw::app::find_pairs(dir)) (void)scw::app::frame_prefix(p.first);
  });
  return 0;
}
