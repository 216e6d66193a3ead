// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_rectify_map_grid as a source-shaped cycle model, interchangeable with
// sim::MapGridModel (map_grid_model.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "hls/rectify/map_grid.hpp"
#include "sim/models/map_grid_model.hpp"
#include "sim/rtl/rtl_adapter.hpp"
#include "sim/words/pack.hpp"

namespace scw::sim {

/// Drives a knot write port (scw_rectify_map_grid's, or a top's that passes it on): knot_we_i,
/// knot_addr_i = {row, col}, knot_data_i = {y, x} as KnotBits-bit two's complement.
template <typename Params, typename VM>
void drive_knot_port(VM& m, const KnotWrite& w) {
  constexpr int kb = Params::kKnotBits;
  constexpr std::uint64_t mask = (std::uint64_t{1} << kb) - 1;
  m.knot_we_i = w.we;
  m.knot_addr_i =
      static_cast<std::uint32_t>((static_cast<std::uint32_t>(w.row) << Params::kKnotColBits) |
                                 static_cast<std::uint32_t>(w.col));
  Bits d(2 * kb);
  d.set(0, kb, static_cast<std::uint64_t>(static_cast<std::int64_t>(w.knot.x)) & mask);
  d.set(kb, kb, static_cast<std::uint64_t>(static_cast<std::int64_t>(w.knot.y)) & mask);
  d.to_port(m.knot_data_i);
}

/// `VM` is a Verilated scw_rectify_map_grid built with `Params` (map_grid_params_match).
template <typename VM, typename Params>
class MapGridRtl : public RtlAdapter<VM> {
 public:
  using out_type = typename Params::map_beat;

  MapGridRtl(const std::string& name, const hls::rectify::MapGridConfig& cfg)
      : RtlAdapter<VM>(name, [&cfg](VM& m) {
          m.cfg_width_i = static_cast<unsigned>(cfg.width);
          m.cfg_height_i = static_cast<unsigned>(cfg.height);
        }) {}

  StreamOutputs<out_type> eval(bool run, bool out_ready) {
    VM& m = this->dut();
    m.run_i = run;
    m.out_ready_i = out_ready;
    auto o = settle_out<StreamOutputs<out_type>>(this->harness());
    o.in_ready = !o.out_valid || out_ready;  // the pipeline enable; a beat issues if run
    return o;
  }
  void drive_knot(const KnotWrite& w) { drive_knot_port<Params>(this->dut(), w); }
  /// The write port is idle again after the edge (drive_knot drives one cycle).
  void tick() {
    RtlAdapter<VM>::tick();
    this->dut().knot_we_i = 0;
  }
};

/// `VM` is a Verilated scw_rectify_map_grid module class; `Params` a MapGridParams.
template <typename VM, typename Params>
constexpr bool map_grid_params_match() {
  return VM::Ppc == Params::kPpc && VM::MaxWidthPx == Params::kMaxWidthPx &&
         VM::MaxHeight == Params::kMaxHeight && VM::GridLog2 == Params::kGridLog2 &&
         VM::FracBits == Params::kFracBits && VM::KnotFracBits == Params::kKnotFracBits &&
         VM::Latency == Params::kLatency && VM::MapCoordBits == Params::kCoordBits &&
         VM::KnotBits == Params::kKnotBits && VM::KnotColBits == Params::kKnotColBits &&
         VM::KnotRowBits == Params::kKnotRowBits;
}

}  // namespace scw::sim
