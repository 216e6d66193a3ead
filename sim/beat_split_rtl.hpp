// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_beat_split as a stream model, and the check that it has the C++ parameters.
#pragma once

#include "hls/pipeline/beat_split.hpp"
#include "sim/pack.hpp"
#include "sim/rtl_stream.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_beat_split module class (its /*verilator public*/ parameters are
/// static constexpr members), built for P pixels of T each.
template <typename VM, typename T, int P>
constexpr bool beat_split_params_match() {
  return VM::Ppc == P && VM::PixW == value_bits<T>();
}

/// The Verilated scw_beat_split (built per beat_split_params_match) as a cycle model; it has
/// in_sof_i/in_eol_i ports, so pixels travel on *_data and flags on their own ports.
template <typename VM, typename T, int P>
using BeatSplitRtl = RtlStream<VM, hls::Beat<T, P>, hls::Beat<T, 1>>;

}  // namespace scw::sim
