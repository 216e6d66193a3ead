// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the golden vector set's manifest reader (read_manifest: format, fields, file
// names) behind `scw vectors verify` and `scw vectors show`.
#include "fuzz/fuzz_target.hpp"
#include "host/vectors/vector_set.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scw::fuzz::write_scratch("manifest.json", data, size);
  scw::fuzz::expect_clear_error([] { scw::vectors::read_manifest(scw::fuzz::scratch()); });
  return 0;
}
