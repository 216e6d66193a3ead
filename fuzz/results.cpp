// SPDX-License-Identifier: Apache-2.0
// Fuzz target: a run's results.jsonl as `scw eval --results` reads it (parse_results).
#include <sstream>

#include "fuzz/fuzz_target.hpp"
#include "host/eval/records.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  scw::fuzz::expect_clear_error([&] { scw::host::eval::parse_results(in, "results.jsonl"); });
  return 0;
}
