// SPDX-License-Identifier: Apache-2.0
// The grid map expander clocked as its RTL pipeline (a source: run level in, map stream out),
// a checked run for source-shaped models, and their simulator component.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include "hls/rectify/map_grid.hpp"
#include "sim/core/components.hpp"
#include "sim/core/cycle_model.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/pipeline_shell.hpp"

namespace scw::sim {

/// One cycle of a knot write port (knot_we_i, knot_addr_i = {row, col}, knot_data_i = {y, x}).
struct KnotWrite {
  bool we = false;
  int col = 0, row = 0;
  hls::rectify::KnotPoint knot{};
};

/// A source-shaped cycle model `M` has `out_type` and
///   StreamOutputs<out_type> eval(bool run, bool out_ready);   // in_ready: a beat issues if run
///   void drive_knot(const KnotWrite&);                         // this cycle's write port
///   void tick();
/// with the meaning of the one-in one-out models (cycle_model.hpp): eval settles and changes
/// nothing, tick is the clock edge using the inputs of the last eval and drive_knot (the write
/// port is idle again after the edge).
///
/// hls::rectify::MapGrid behind Latency register stages under one enable (adv = !out_valid ||
/// out_ready), as scw_rectify_map_grid: a beat issues when run && adv, the knot RAMs sample its
/// address at that edge (before a write at the same edge lands, as block RAM reads old data),
/// and it is presented Latency cycles later.
template <typename Params>
class MapGridModel {
 public:
  using Kernel = hls::rectify::MapGrid<Params>;
  using out_type = typename Kernel::out_type;
  static constexpr int kLatency = Params::kLatency;

  explicit MapGridModel(const hls::rectify::MapGridConfig& cfg) : k_(cfg) {}

  StreamOutputs<out_type> eval(bool run, bool out_ready) {
    StreamOutputs<out_type> o;
    slots_.present(o);
    advance_ = slots_.enable(out_ready);
    o.in_ready = advance_;
    issue_ = run && advance_;
    return o;
  }
  void drive_knot(const KnotWrite& w) { write_ = w; }
  void tick() {
    // The step reads the knots before this edge's write.
    if (advance_) slots_.advance(issue_, [this] { return k_.step(); });
    if (write_.we) k_.write_knot(write_.col, write_.row, write_.knot);
    write_ = KnotWrite{};
  }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  SlotRegister<out_type, kLatency> slots_;
  bool advance_ = false, issue_ = false;
  KnotWrite write_{};
};

/// Writes every knot of a cols x rows grid (`knot(col, row)`), one per cycle with run low.
template <typename Model, typename KnotAt>
void load_knots(Model& m, int cols, int rows, KnotAt knot) {
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      m.drive_knot(KnotWrite{true, i, j, knot(i, j)});
      m.eval(false, true);
      m.tick();
    }
}

}  // namespace scw::sim
