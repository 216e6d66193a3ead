// SPDX-License-Identifier: Apache-2.0
// What the soak and the reset trials run: the small build at one pixel a beat, its C++ chain and
// its Verilated top, and each one's output in the form compare_runs takes.
#pragma once

#include <utility>

#include "host/soak/soak.hpp"
#include "sim/builds/pipeline_small_rtl.hpp"

namespace scw::host::soak::small {

constexpr int P = 1;
using Build = sim::small_build::Build<P>;
using Chain = sim::small_build::Chain<P>;
using Top = sim::small_build::Top<P>;

/// The chain's results, the cycles they left (from its cycle 0) and its object words.
inline RunOutput output_of(const Chain& c) {
  return {c.results(), c.result_cycles(), c.object_table()};
}

inline RunOutput output_of(sim::TopRun&& r) {
  return {std::move(r.results), std::move(r.result_cycles), std::move(r.object_table)};
}

}  // namespace scw::host::soak::small
