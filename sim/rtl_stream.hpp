// SPDX-License-Identifier: Apache-2.0
// A Verilated one-in one-out stream module as a cycle model, interchangeable with its C++ twin.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

#include "sim/cycle_model.hpp"
#include "sim/pack.hpp"
#include "sim/verilated_harness.hpp"

namespace scw::sim {

namespace detail {
template <typename M, typename = void>
struct has_flag_ports : std::false_type {};
template <typename M>
struct has_flag_ports<M, std::void_t<decltype(std::declval<M&>().in_sof_i)>> : std::true_type {};
}  // namespace detail

/// Reads a stage's out_data_o/out_sof_o/out_eol_o as a beat, or out_data_o/out_last_o as a
/// packet.
template <typename Out, typename VM>
Out read_stage_out(const VM& m) {
  const Bits data = Bits::from_port(m.out_data_o, BeatLayout<Out>::kPayloadBits);
  if constexpr (hls::detail::has_last<Out>::value) {
    return BeatLayout<Out>::from_payload(data, m.out_last_o);
  } else {
    return BeatLayout<Out>::from_payload(data, m.out_sof_o, m.out_eol_o);
  }
}

/// Drives a stage's input beat (in_valid_i, in_data_i with the pixels, in_sof_i, in_eol_i) and
/// its out_ready_i.
template <typename In, typename VM>
void drive_stage_in(VM& m, bool in_valid, const In& in, bool out_ready) {
  m.in_valid_i = in_valid;
  BeatLayout<In>::payload(in).to_port(m.in_data_i);
  m.in_sof_i = BeatLayout<In>::sof(in);
  m.in_eol_i = BeatLayout<In>::eol(in);
  m.out_ready_i = out_ready;
}

/// Binds the common port shape (in_valid_i/in_ready_o/in_data_i, out_valid_o/out_ready_i/
/// out_data_o). Modules with in_sof_i/in_eol_i ports (stages) carry the flags on them and the
/// pixels in *_data; opaque elastic blocks (FIFO, stream register, skid buffer) carry the whole
/// packed beat {eol, sof, payload} in *_data.
template <typename VM, typename In, typename Out>
class RtlStream {
 public:
  using in_type = In;
  using out_type = Out;

  explicit RtlStream(const std::string& name) : h_(std::make_unique<Harness<VM>>(name)) {
    h_->reset();
  }
  /// `configure` sets the module's static cfg_* inputs once, before reset; Verilator keeps
  /// input values, so they stay stable throughout.
  RtlStream(const std::string& name, const std::function<void(VM&)>& configure)
      : h_(std::make_unique<Harness<VM>>(name)) {
    configure(h_->dut());
    h_->reset();
  }

  StreamOutputs<Out> eval(bool in_valid, const In& in, bool out_ready) {
    VM& m = h_->dut();
    if constexpr (detail::has_flag_ports<VM>::value) {
      drive_stage_in(m, in_valid, in, out_ready);
    } else {
      m.in_valid_i = in_valid;
      m.out_ready_i = out_ready;
      pack(in).to_port(m.in_data_i);
    }
    m.eval();
    StreamOutputs<Out> o;
    o.in_ready = m.in_ready_o;
    o.out_valid = m.out_valid_o;
    if constexpr (detail::has_flag_ports<VM>::value) {
      o.out = read_stage_out<Out>(m);
    } else {
      o.out = unpack<Out>(Bits::from_port(m.out_data_o, BeatLayout<Out>::kBits));
    }
    return o;
  }
  void tick() { h_->tick(); }

  Harness<VM>& harness() { return *h_; }
  VM& dut() { return h_->dut(); }

 private:
  std::unique_ptr<Harness<VM>> h_;
};

}  // namespace scw::sim
