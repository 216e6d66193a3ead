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
  RunOutput o{c.results(), {}, c.object_table()};
  for (const auto& f : const_cast<Chain&>(c).result_fifo().frames())
    if (f.first_pop >= 0) o.result_cycles.push_back(f.first_pop - c.start_cycle());
  return o;
}

inline RunOutput output_of(sim::TopRun&& r) {
  return {std::move(r.results), std::move(r.result_cycles), std::move(r.object_table)};
}

}  // namespace scw::host::soak::small
