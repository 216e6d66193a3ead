// SPDX-License-Identifier: Apache-2.0
// Compile-time checks that a Verilated model was built with the C++ parameters.
#pragma once

namespace scw::sim {

/// `VM` is the Verilated scw_line_buffer module class (its /*verilator public*/ parameters are
/// static constexpr members); `Params` is an hls::LineBufferParams.
template <typename VM, typename Params>
constexpr bool line_buffer_params_match() {
  return VM::Ppc == Params::kPpc && VM::MaxWidthPx == Params::kMaxWidthPx &&
         VM::Rows == Params::kRows && VM::Latency == Params::kLatency;
}

}  // namespace scw::sim
