// SPDX-License-Identifier: Apache-2.0
// The labelling kernel clocked as a one-in one-out stream model: disparities -> object words.
#pragma once

#include "hls/labelling/labelling.hpp"
#include "sim/models/kernel_model.hpp"
#include "sim/words/labelling_pack.hpp"

namespace scw::sim {

/// The labelling stage's ready: room in the lane it feeds, in its frame phase, and not a sof in
/// mid-frame.
template <typename Params>
bool labelling_ready(const hls::labelling::Labelling<Params>& k,
                     const typename hls::labelling::Labelling<Params>::in_type& in, bool) {
  return k.in_ready(in.sof);
}

/// hls::labelling::Labelling as a cycle model: its output register is the stage's output.
template <typename Params>
using LabellingModel = KernelModel<hls::labelling::Labelling<Params>, &labelling_ready<Params>>;

}  // namespace scw::sim
