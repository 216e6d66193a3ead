// SPDX-License-Identifier: Apache-2.0
// Compile-time checks that a Verilated model was built with the C++ parameters.
#pragma once

#include <type_traits>

namespace scw::sim {

/// `VM` is the Verilated scw_line_buffer module class (its /*verilator public*/ parameters are
/// static constexpr members); `Params` is an hls::LineBufferParams.
template <typename VM, typename Params>
constexpr bool line_buffer_params_match() {
  return VM::Ppc == Params::kPpc && VM::MaxWidthPx == Params::kMaxWidthPx &&
         VM::Rows == Params::kRows && VM::Latency == Params::kLatency;
}

}  // namespace scw::sim

namespace scw::sim {

/// `VM` is a Verilated scw_rectify module class; `Params` an hls::rectify::RectifyParams.
template <typename VM, typename Params>
constexpr bool rectify_params_match() {
  return VM::Ppc == Params::kPpc && VM::MaxWidthPx == Params::kMaxWidthPx &&
         VM::MaxHeight == Params::kMaxHeight && VM::Rows == Params::kRows &&
         VM::FracBits == Params::kFracBits && VM::Latency == Params::kLatency &&
         VM::MapCoordBits == Params::kCoordBits;
}

}  // namespace scw::sim

namespace scw::sim {

/// `VM` is a Verilated scw_disparity module class; `Kernel` the hls::disparity::Disparity it
/// twins: the structure, the latency from issue to result and the result queue must agree.
template <typename VM, typename Kernel>
constexpr bool disparity_params_match() {
  using Params = typename Kernel::params;
  return VM::Ppc == Params::kPpc && VM::MaxWidthPx == Params::kMaxWidthPx &&
         VM::MaxHeight == Params::kMaxHeight && VM::Window == Params::kWindow &&
         VM::NumDisp == Params::kNumDisp && VM::ResultLatency == Kernel::kLatency &&
         VM::QueueWords * Params::kPpc == Kernel::kQueue;
}

}  // namespace scw::sim

namespace scw::sim {

/// Picks the Verilated model built for P pixels per beat: ByPpc<P, Vx_p1, Vx_p2, Vx_p4>.
template <int P, typename V1, typename V2, typename V4>
using ByPpc = std::conditional_t<P == 1, V1, std::conditional_t<P == 2, V2, V4>>;

}  // namespace scw::sim
