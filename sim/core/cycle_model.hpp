// SPDX-License-Identifier: Apache-2.0
// The cycle-level interface shared by C++ twins and Verilated RTL: evaluate, then clock.
#pragma once

namespace scw::sim {

/// What a one-in, one-out stream block presents in a cycle, given its inputs.
///
/// A cycle model `M` has `in_type`, `out_type` and
///   StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready);
///   void tick();
/// `eval` settles the combinational logic for the given inputs and changes no state (it may be
/// called several times per cycle, e.g. to check that out_valid ignores out_ready); `tick` is
/// the clock edge, using the inputs of the last `eval`. C++ twins (Fifo, StreamReg, SkidBuf,
/// PipelineShell) and RtlStream (a Verilated module) all have this shape, so drivers,
/// checkers and the simulator treat them alike.
template <typename Out>
struct StreamOutputs {
  bool in_ready = false;
  bool out_valid = false;
  Out out{};
};

}  // namespace scw::sim
