// SPDX-License-Identifier: Apache-2.0
// What every Verilated adapter shares: the harness it owns, configured then reset, its clock
// edge, and the copy between beats and the standard port groups.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

#include "hls/common/beat.hpp"
#include "sim/rtl/verilated_harness.hpp"
#include "sim/words/pack.hpp"

namespace scw::sim {

namespace detail {
/// Stage modules carry a beat's flags on ports of their own (in_sof_i/in_eol_i or in_last_i);
/// the opaque elastic blocks (FIFO, stream register, skid buffer) carry the whole packed beat
/// {flags, payload} in *_data.
template <typename M, typename = void>
struct has_in_sof : std::false_type {};
template <typename M>
struct has_in_sof<M, std::void_t<decltype(std::declval<M&>().in_sof_i)>> : std::true_type {};
template <typename M, typename = void>
struct has_in_last : std::false_type {};
template <typename M>
struct has_in_last<M, std::void_t<decltype(std::declval<M&>().in_last_i)>> : std::true_type {};
template <typename M, typename = void>
struct has_out_sof : std::false_type {};
template <typename M>
struct has_out_sof<M, std::void_t<decltype(std::declval<M&>().out_sof_o)>> : std::true_type {};
template <typename M, typename = void>
struct has_out_last : std::false_type {};
template <typename M>
struct has_out_last<M, std::void_t<decltype(std::declval<M&>().out_last_o)>> : std::true_type {};
template <typename M>
inline constexpr bool has_in_flags = has_in_sof<M>::value || has_in_last<M>::value;
template <typename M>
inline constexpr bool has_out_flags = has_out_sof<M>::value || has_out_last<M>::value;
}  // namespace detail

/// Binds an input port group P_valid_i/P_ready_o/P_data_i with the beat's flags on P_sof_i and
/// P_eol_i (a pixel beat) or on P_last_i (a packet): SCW_IN_PORTS(MapPorts, map). The data is
/// packed only with valid (without it the RTL must not look at it, and the port keeps the last
/// beat, as a register would): packing the idle labelling word cost a heap allocation a clock.
#define SCW_IN_PORTS(NAME, P)                                    \
  struct NAME {                                                  \
    template <typename VM, typename Beat>                        \
    static void drive(VM& m, bool valid, const Beat& beat) {     \
      using Layout = ::scw::sim::BeatLayout<Beat>;               \
      m.P##_valid_i = valid;                                     \
      if (valid) Layout::payload(beat).to_port(m.P##_data_i);    \
      if constexpr (::scw::hls::detail::has_last<Beat>::value) { \
        m.P##_last_i = beat.last;                                \
      } else {                                                   \
        m.P##_sof_i = Layout::sof(beat);                         \
        m.P##_eol_i = Layout::eol(beat);                         \
      }                                                          \
    }                                                            \
    template <typename VM>                                       \
    static bool ready(const VM& m) {                             \
      return m.P##_ready_o;                                      \
    }                                                            \
  }

SCW_IN_PORTS(StageInPorts, in);

/// Reads a module's out_data_o as a beat: with out_sof_o/out_eol_o or out_last_o beside it (a
/// stage), or the whole packed beat (an opaque elastic block).
template <typename Out, typename VM>
Out read_stage_out(const VM& m) {
  if constexpr (!detail::has_out_flags<VM>) {
    return unpack<Out>(Bits::from_port(m.out_data_o, BeatLayout<Out>::kBits));
  } else {
    const Bits data = Bits::from_port(m.out_data_o, BeatLayout<Out>::kPayloadBits);
    if constexpr (hls::detail::has_last<Out>::value) {
      return BeatLayout<Out>::from_payload(data, m.out_last_o);
    } else {
      return BeatLayout<Out>::from_payload(data, m.out_sof_o, m.out_eol_o);
    }
  }
}

/// Drives a module's in_* group (StageInPorts for a stage, the packed beat in in_data_i for an
/// opaque block) and its out_ready_i.
template <typename In, typename VM>
void drive_stage_in(VM& m, bool in_valid, const In& in, bool out_ready) {
  if constexpr (detail::has_in_flags<VM>) {
    StageInPorts::drive(m, in_valid, in);
  } else {
    m.in_valid_i = in_valid;
    if (in_valid) pack(in).to_port(m.in_data_i);  // as StageInPorts: no packing without valid
  }
  m.out_ready_i = out_ready;
}

/// Settles `m` after its inputs were driven and reads its out_* group into a fresh `Outputs`
/// (StreamOutputs, JoinOutputs, SideOutputs...); the caller adds the ready outputs. The beat is
/// read only while out_valid, as the C++ models leave it default otherwise. `key` and `out(m)`
/// say what was driven and read (QuietKey): Harness::settle skips the cycles that change nothing.
template <typename Outputs, typename VM, typename Out>
Outputs settle_out(Harness<VM>& h, std::uint32_t key, Out&& out) {
  h.settle(key, std::forward<Out>(out));
  const VM& m = h.dut();
  Outputs o;
  o.out_valid = m.out_valid_o != 0;
  if (o.out_valid) o.out = read_stage_out<decltype(o.out)>(m);
  return o;
}
/// settle_out for an adapter that does not say what it drove: every cycle is evaluated.
template <typename Outputs, typename VM>
Outputs settle_out(Harness<VM>& h) {
  return settle_out<Outputs>(h, 0, [](const VM&) { return QuietKey::kBusy; });
}

/// The base of every Verilated adapter (RtlStream, RtlJoin, FrameCheckRtl, ...): it owns the
/// harness, sets the module's static inputs once before reset and is clocked by tick(). The
/// harness is held by pointer so that adapters move (the make_*_rtl functions return them).
template <typename VM>
class RtlAdapter {
 public:
  void tick() { h_->tick(); }
  Harness<VM>& harness() { return *h_; }
  VM& dut() { return h_->dut(); }

 protected:
  /// `configure` sets the module's static cfg_* inputs (and may check the config first);
  /// Verilator keeps input values, so they stay stable throughout.
  template <typename Configure>
  RtlAdapter(const std::string& name, Configure&& configure)
      : h_(std::make_unique<Harness<VM>>(name)) {
    std::forward<Configure>(configure)(h_->dut());
    h_->reset();
  }
  explicit RtlAdapter(const std::string& name) : RtlAdapter(name, [](VM&) {}) {}

 private:
  std::unique_ptr<Harness<VM>> h_;
};

}  // namespace scw::sim
