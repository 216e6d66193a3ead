// SPDX-License-Identifier: Apache-2.0
// The warning kernel clocked as a one-in one-out stream model: object words -> frame results.
#pragma once

#include "hls/warning/warning.hpp"
#include "sim/kernel_model.hpp"
#include "sim/labelling_pack.hpp"
#include "sim/warning_pack.hpp"

namespace scw::sim {

/// The warning stage's ready: its one pipeline enable, !out_valid || out_ready.
template <typename Params>
bool warning_ready(const hls::warning::Warning<Params>& k,
                   const typename hls::warning::Warning<Params>::in_type&, bool out_ready) {
  return k.in_ready(out_ready);
}

/// hls::warning::Warning as a cycle model: its output register is the stage's output.
template <typename Params>
using WarningModel = KernelModel<hls::warning::Warning<Params>, &warning_ready<Params>>;

}  // namespace scw::sim
