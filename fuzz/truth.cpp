// SPDX-License-Identifier: Apache-2.0
// Fuzz target: a scene's truth.jsonl as `scw eval --truth` reads it (parse_truth).
#include <sstream>

#include "fuzz/fuzz_target.hpp"
#include "host/eval/records.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  scw::fuzz::expect_clear_error([&] { scw::host::eval::parse_truth(in, "truth.jsonl"); });
  return 0;
}
