// SPDX-License-Identifier: Apache-2.0
// The one comparison of a C++ twin's run with its RTL's run, shared by every RTL test.
#pragma once

#include <catch2/catch.hpp>
#include <string>

#include "sim/core/stream_check.hpp"

namespace scw::test {

/// Both runs followed the handshake rules, finished, and have the same cycle trace (every
/// valid, ready and output word) and the same output beats.
template <typename Out>
void check_twin_runs(const sim::RunResult<Out>& cpp, const sim::RunResult<Out>& rtl) {
  CHECK(cpp.violations.empty());
  CHECK(rtl.violations.empty());
  INFO((rtl.violations.empty() ? std::string() : rtl.violations.front()));
  REQUIRE_FALSE(cpp.timed_out);
  REQUIRE_FALSE(rtl.timed_out);
  CHECK(sim::first_difference(cpp.trace, rtl.trace, "C++", "RTL") == "");
  CHECK(cpp.out == rtl.out);
}

}  // namespace scw::test
