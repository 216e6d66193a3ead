// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_warning as a stream model (object words in, frame results out), and the
// compile-time check that it was built with the C++ parameters.
#pragma once

#include <memory>
#include <string>

#include "hls/warning/warning.hpp"
#include "sim/cycle_model.hpp"
#include "sim/join.hpp"
#include "sim/labelling_pack.hpp"
#include "sim/rtl_stream.hpp"
#include "sim/verilated_harness.hpp"
#include "sim/warning_pack.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_warning module class (its /*verilator public*/ parameters are static
/// constexpr members); `Params` an hls::warning::WarningParams. The pipeline depth must be the
/// model's too, or the two would fold words on different clocks.
template <typename VM, typename Params>
constexpr bool warning_params_match() {
  return VM::MaxDisparityPx == Params::kMaxDisparityPx && VM::TableSize == Params::kTableSize &&
         VM::RuleLatency == hls::warning::kRuleLatency && VM::Latency == hls::warning::kLatency;
}

/// Sets the cfg_* ports of the warning stage (scw_warning, or a top that passes them on).
template <typename VM>
void drive_warning_cfg(VM& m, const hls::warning::WarningConfig& cfg) {
  m.cfg_baseline_q8_i = cfg.baseline_q8;
  m.cfg_focal_q4_i = cfg.focal_q4;
  m.cfg_cu_q4_i = cfg.cu_q4;
  m.cfg_cv_q4_i = cfg.cv_q4;
  m.cfg_veh_x_mm_i = static_cast<std::uint16_t>(cfg.veh_x_mm);
  m.cfg_veh_y_mm_i = static_cast<std::uint16_t>(cfg.veh_y_mm);
  m.cfg_veh_z_mm_i = static_cast<std::uint16_t>(cfg.veh_z_mm);
  m.cfg_tunnel_half_w_mm_i = cfg.tunnel_half_w_mm;
  m.cfg_tunnel_h_mm_i = cfg.tunnel_h_mm;
  m.cfg_high_mm_i = cfg.high_mm;
  m.cfg_medium_mm_i = cfg.medium_mm;
  m.cfg_near_mm_i = cfg.near_mm;
  m.cfg_min_height_mm_i = cfg.min_height_mm;
  m.cfg_d_limit_q4_i = cfg.d_limit_q4;
  m.cfg_rule_i = static_cast<std::uint8_t>(cfg.rule);
  m.cfg_spread_i = cfg.spread_q4;
}

/// A Verilated scw_warning as a cycle model. RtlStream carries a packet's `last` inside *_data
/// for the opaque elastic blocks; this stage has a separate in_last_i/out_last_o beside its
/// payload ports (the labelling stage's output shape), and a road input. WarningRtl is the
/// one-input shape (sim::WarningModel's: the road port idle), WarningRoadRtl the join
/// (sim::WarningRoadModel's).
template <typename VM>
class WarningRtlBase {
 public:
  using out_type = hls::warning::ResultPacket;

  /// Checks nothing: use make_warning_rtl, which checks `cfg` as the model does.
  WarningRtlBase(const std::string& name, const hls::warning::WarningConfig& cfg)
      : h_(std::make_unique<Harness<VM>>(name)) {
    // Static inputs, set once before reset; Verilator keeps input values, so they stay stable.
    drive_warning_cfg(h_->dut(), cfg);
    h_->dut().cfg_road_height_i = cfg.road_height;
    h_->reset();
  }

  void tick() { h_->tick(); }
  Harness<VM>& harness() { return *h_; }
  VM& dut() { return h_->dut(); }

 protected:
  /// Drives every input, settles, and returns the RTL's view.
  JoinOutputs<out_type> settle(bool in_valid, const hls::labelling::LabelPacket& in,
                               bool road_valid, const hls::warning::RoadLine& road,
                               bool out_ready) {
    VM& m = h_->dut();
    m.in_valid_i = in_valid;
    m.out_ready_i = out_ready;
    BeatLayout<hls::labelling::LabelPacket>::payload(in).to_port(m.in_data_i);
    m.in_last_i = in.last;
    m.road_valid_i = road_valid;
    m.road_a_i = static_cast<std::uint32_t>(road.a) & 0x3ffffu;
    m.road_b_i = static_cast<std::uint32_t>(road.b);
    m.eval();
    JoinOutputs<out_type> o;
    o.a_ready = m.in_ready_o;
    o.b_ready = m.road_ready_o;
    o.out_valid = m.out_valid_o;
    o.out = read_stage_out<out_type>(m);
    return o;
  }

 private:
  std::unique_ptr<Harness<VM>> h_;
};

template <typename VM>
class WarningRtl : public WarningRtlBase<VM> {
 public:
  using in_type = hls::labelling::LabelPacket;
  using out_type = hls::warning::ResultPacket;
  using WarningRtlBase<VM>::WarningRtlBase;

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    const auto j = this->settle(in_valid, in, false, {}, out_ready);
    StreamOutputs<out_type> o;
    o.in_ready = j.a_ready;
    o.out_valid = j.out_valid;
    o.out = j.out;
    return o;
  }
};

template <typename VM>
class WarningRoadRtl : public WarningRtlBase<VM> {
 public:
  using a_type = hls::labelling::LabelPacket;
  using b_type = hls::Packet<hls::warning::RoadLine>;
  using out_type = hls::warning::ResultPacket;
  using WarningRtlBase<VM>::WarningRtlBase;

  JoinOutputs<out_type> eval(bool a_valid, const a_type& a, bool b_valid, const b_type& b,
                             bool out_ready) {
    return this->settle(a_valid, a, b_valid, b.data, out_ready);
  }
};

/// Checks `cfg` as the model does (std::invalid_argument) and drives the cfg_* ports from it
/// before reset. `VM` is a Verilated scw_warning built with `Params` (warning_params_match).
template <typename VM, typename Params>
WarningRtl<VM> make_warning_rtl(const std::string& name, const hls::warning::WarningConfig& cfg) {
  hls::warning::check_config<Params>(cfg);
  return WarningRtl<VM>(name, cfg);
}

/// The same for the join shape, with a road line a frame (cfg.road_height).
template <typename VM, typename Params>
WarningRoadRtl<VM> make_warning_road_rtl(const std::string& name,
                                         const hls::warning::WarningConfig& cfg) {
  hls::warning::check_config<Params>(cfg);
  return WarningRoadRtl<VM>(name, cfg);
}

}  // namespace scw::sim
