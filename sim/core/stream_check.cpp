// SPDX-License-Identifier: Apache-2.0
// Trace comparison for model-against-model (C++ twin against RTL) runs.
#include "sim/core/stream_check.hpp"

#include <algorithm>

namespace scw::sim {

namespace {
std::string describe(const CycleRecord& r) {
  std::ostringstream s;
  s << "in_valid=" << r.in_valid << " in_ready=" << r.in_ready << " out_valid=" << r.out_valid
    << " out_ready=" << r.out_ready << " b_valid=" << r.b_valid << " b_ready=" << r.b_ready;
  if (r.out_valid) s << " out=0x" << r.out.hex();
  return s.str();
}
}  // namespace

std::string first_difference(const std::vector<CycleRecord>& a, const std::vector<CycleRecord>& b,
                             const std::string& name_a, const std::string& name_b) {
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!(a[i] == b[i]))
      return "cycle " + std::to_string(i) + ": " + name_a + " {" + describe(a[i]) + "} vs " +
             name_b + " {" + describe(b[i]) + "}";
  }
  if (a.size() != b.size())
    return name_a + " ran " + std::to_string(a.size()) + " cycles, " + name_b + " " +
           std::to_string(b.size());
  return {};
}

}  // namespace scw::sim
