// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_pipeline driven as PipelineChain drives its graph: same knot loading, same
// input and output stall generators, so the two can be compared clock for clock.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/pipeline/pipeline_result.hpp"
#include "sim/core/stall.hpp"
#include "sim/pipeline/pipeline_setup.hpp"
#include "sim/pipeline/pipeline_timing.hpp"
#include "sim/rtl/disparity_rtl.hpp"
#include "sim/rtl/labelling_rtl.hpp"
#include "sim/rtl/map_grid_rtl.hpp"
#include "sim/rtl/road_rtl.hpp"
#include "sim/rtl/rtl_adapter.hpp"
#include "sim/rtl/warning_rtl.hpp"
#include "sim/words/bits.hpp"
#include "sim/words/labelling_pack.hpp"
#include "sim/words/pack.hpp"
#include "sim/words/pipeline_pack.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_pipeline module class; `Build` an hls::pipeline::PipelineParams.
template <typename VM, typename Build>
constexpr bool pipeline_params_match() {
  return VM::Ppc == Build::kPpc && VM::MaxWidthPx == Build::kMaxWidthPx &&
         VM::MaxHeight == Build::kMaxHeight && VM::RectRows == Build::kRectRows &&
         VM::GridLog2 == Build::kGridLog2 && VM::Window == Build::kWindow &&
         VM::NumDisp == Build::kNumDisp && VM::MaxTilesX == Build::kMaxTilesX &&
         VM::MaxTilesY == Build::kMaxTilesY && VM::LabelsPerTile == Build::kLabelsPerTile &&
         VM::MaxObjects == Build::kMaxObjects && VM::MaxDisparityPx == Build::kMaxDisparityPx;
}

/// What a run of the top gives: the results and, per frame, the cycles of the input and
/// output transfers (cycle 0 = the first cycle after the knots are loaded).
struct TopRun {
  std::vector<hls::pipeline::PipelineResultPacket> results;
  std::vector<std::int64_t> result_cycles;
  std::vector<hls::labelling::LabelPacket> object_table;  // every word of the obj_* output
  std::vector<std::int64_t> first_in_cycles;        // left input beats with sof
  std::vector<std::int64_t> first_in_right_cycles;  // right input beats with sof
  std::vector<std::int64_t> last_in_cycles;         // each frame's last beat, either camera
  std::int64_t cycles = 0;
  std::uint64_t harness_start = 0;  // the harness's cycle count at this run's cycle 0 (traces)
};

/// Optional controls of a run: stop at a cycle (a reset is about to cut the frames short) and
/// report progress.
struct TopRunControl {
  std::int64_t stop_at = -1;  // >= 0: return before driving this cycle, whatever is out
  std::function<void(std::int64_t cycle, std::size_t results)> progress;
  std::int64_t every = 100000;  // cycles between progress calls
};

/// Every cfg_* port of scw_pipeline from `s`, checked as the chain checks it
/// (std::invalid_argument). `VM` is the Verilated top, or anything with members named as the ports
/// (the pipeline vector set records them so: host/vectors/pipeline_set.cpp).
template <typename VM, typename Build>
void drive_pipeline_cfg(VM& m, const PipelineSetup& s) {
  check_setup<Build>(s);
  const auto l = s.labelling_config();
  hls::labelling::check_config<typename Build::labelling>(l);
  hls::warning::check_config<typename Build::warning>(s.warning);
  m.cfg_lead_i = static_cast<unsigned>(s.lead_rows < 0 ? 0 : s.lead_rows);
  drive_disparity_cfg<VM, typename Build::disparity>(m, s.disparity_config());
  drive_labelling_cfg(m, l);  // the top's width and height ports: the same frame
  drive_warning_cfg(m, s.warning);
  drive_road_cfg(m, s.road);
}

template <typename VM, typename Build>
class PipelineTop : private RtlAdapter<VM> {
 public:
  using raw_beat = typename Build::rectify::pixel_beat;

  /// Sets the cfg_* ports from `s` (checked as the chain checks it), resets, and loads both
  /// cameras' knots, left first, one per cycle. The top's FIFO depths are its parameters'.
  explicit PipelineTop(const PipelineSetup& s)
      : RtlAdapter<VM>("pipeline", [&s](VM& m) { configure(m, s); }) {
    VM& m = this->dut();
    load(false, s, s.left_knots);
    load(true, s, s.right_knots);
    knot_cycles_ = 2 * s.knot_rows * s.knot_cols;
    m.knot_we_i = 0;
    m.run_i = 1;
  }

  /// Streams the frames until `frames` results are out, the sources and the sink stalling as
  /// PipelineChain's do under the same patterns. Throws std::runtime_error after `max_cycles`.
  /// Each run starts at its own cycle 0 with fresh sources and sinks; the top keeps its state.
  TopRun run(const std::vector<raw_beat>& left, const std::vector<raw_beat>& right,
             std::size_t frames, std::int64_t max_cycles, const StallPattern& in = {},
             const StallPattern& out = {}, const TopRunControl& ctl = {}) {
    Driver dl(left, in), dr(right, in.other_stream(kRightInputSalt));
    StallGen sink(out, StallGen::Side::kOutput);
    StallGen table_sink(out.other_stream(kObjectTableSalt), StallGen::Side::kOutput);
    VM& m = this->dut();
    TopRun r;
    r.harness_start = this->harness().cycles();
    using O = BeatLayout<hls::labelling::LabelPacket>;
    for (std::int64_t c = 0; r.results.size() < frames && c != ctl.stop_at; ++c) {
      if (ctl.progress && c % ctl.every == 0) ctl.progress(c, r.results.size());
      if (c >= max_cycles)
        throw std::runtime_error("scw_pipeline: " + std::to_string(r.results.size()) + " of " +
                                 std::to_string(frames) + " results after " +
                                 std::to_string(max_cycles) + " cycles");
      const bool lv = dl.offer(), rv = dr.offer();
      const bool out_ready = sink.next();
      const bool obj_ready = table_sink.next();
      DisparityPorts::a::drive(m, lv, dl.beat());  // the top's l_*/r_* are the disparity's
      DisparityPorts::b::drive(m, rv, dr.beat());
      m.out_ready_i = out_ready;
      m.obj_ready_i = obj_ready;
      m.eval();
      const bool l_take = lv && m.l_ready_o, r_take = rv && m.r_ready_o;
      if (l_take && dl.beat().sof) r.first_in_cycles.push_back(c);
      if (r_take && dr.beat().sof) r.first_in_right_cycles.push_back(c);
      if (l_take) note_last_in(r, r.first_in_cycles.size(), c);
      if (r_take) note_last_in(r, r.first_in_right_cycles.size(), c);
      if (out_ready && m.out_valid_o) {
        r.results.push_back(read_stage_out<hls::pipeline::PipelineResultPacket>(m));
        r.result_cycles.push_back(c);
      }
      if (obj_ready && m.obj_valid_o) {
        r.object_table.push_back(
            O::from_payload(Bits::from_port(m.obj_data_o, O::kPayloadBits), m.obj_last_o));
      }
      this->tick();
      dl.taken(l_take);
      dr.taken(r_take);
      r.cycles = c + 1;
    }
    return r;
  }

  /// Holds rst_ni low for `cycles` clocks, every input stream idle, as a board does when its
  /// camera link drops: the blocks' registers return to their reset values, the RAMs (the
  /// knots among them) keep what they hold. Then run_i stays low for as many clocks as loading
  /// the knots took, without loading them: a top built afresh and this one are then on the
  /// same clock from the next run()'s cycle 0, and that run is right only if the knot RAM kept
  /// the knots and every register that must be reset was.
  void reset(int cycles) {
    VM& m = this->dut();
    m.l_valid_i = 0;
    m.r_valid_i = 0;
    m.out_ready_i = 0;
    m.obj_ready_i = 0;
    m.run_i = 0;
    this->harness().reset(cycles);
    for (int i = 0; i < knot_cycles_; ++i) this->tick();
    m.run_i = 1;
  }

  /// The sticky error bits: {labelling, disparity, rectify right [2:0], rectify left [2:0]}.
  unsigned errors() { return this->dut().err_o; }

 private:
  /// Checks `s` and drives the static inputs, every stream idle, before reset.
  static void configure(VM& m, const PipelineSetup& s) {
    const PipelineDepths defaults;
    if (s.depths.raw != defaults.raw || s.depths.map != defaults.map ||
        s.depths.rect != defaults.rect || s.depths.disp != defaults.disp ||
        s.depths.obj != defaults.obj || s.depths.res != defaults.res ||
        s.depths.flag != defaults.flag)
      throw std::invalid_argument("the Verilated scw_pipeline is built with the default depths");
    drive_pipeline_cfg<VM, Build>(m, s);
    m.run_i = 0;
    m.l_valid_i = 0;
    m.r_valid_i = 0;
    m.out_ready_i = 0;
    m.obj_ready_i = 0;
  }

  /// Source's offer rule (sim/core/components.hpp): once offered, a beat is held until taken.
  struct Driver {
    Driver(const std::vector<raw_beat>& b, const StallPattern& p)
        : beats(b), gen(p, StallGen::Side::kInput) {}
    bool offer() {
      if (next >= beats.size()) return false;
      if (!offering) offering = gen.next();
      return offering;
    }
    const raw_beat& beat() const { return next < beats.size() ? beats[next] : idle; }
    void taken(bool t) {
      if (!t) return;
      ++next;
      offering = false;
    }
    const std::vector<raw_beat>& beats;
    StallGen gen;
    std::size_t next = 0;
    bool offering = false;
    raw_beat idle{};
  };

  int knot_cycles_ = 0;

  /// A beat of frame `frames` - 1 (the frames begun on its camera) was taken in cycle `c`.
  static void note_last_in(TopRun& r, std::size_t frames, std::int64_t c) {
    if (frames == 0) return;  // beats before the first frame start, as the chain's FIFOs
    if (r.last_in_cycles.size() < frames) r.last_in_cycles.resize(frames, -1);
    r.last_in_cycles[frames - 1] = c;  // cycles only increase
  }

  void load(bool right, const PipelineSetup& s, const std::vector<hls::rectify::KnotPoint>& k) {
    VM& m = this->dut();
    for (int j = 0; j < s.knot_rows; ++j)
      for (int i = 0; i < s.knot_cols; ++i) {
        drive_knot_port<typename Build::map_grid>(
            m, KnotWrite{true, i, j, k[static_cast<std::size_t>(j * s.knot_cols + i)]});
        m.knot_right_i = right;
        this->tick();
      }
  }
};

/// The frames' timing as pipeline_timing() gives it for a chain, from what the top's ports show:
/// first and last input beat (either camera) and result cycle per frame, the period and the
/// latencies. The blocks inside the top are not seen: `stages` stays empty.
inline PipelineTiming top_timing(const TopRun& r) {
  PipelineTiming t;
  const std::size_t n = std::min({r.first_in_cycles.size(), r.first_in_right_cycles.size(),
                                  r.last_in_cycles.size(), r.result_cycles.size()});
  for (std::size_t k = 0; k < n; ++k) {
    FrameTiming f;
    f.first_in = std::min(r.first_in_cycles[k], r.first_in_right_cycles[k]);
    f.last_in = r.last_in_cycles[k];
    f.result = r.result_cycles[k];
    add_frame(t, f);
  }
  return t;
}

}  // namespace scw::sim
