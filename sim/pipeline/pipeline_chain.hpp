// SPDX-License-Identifier: Apache-2.0
// The whole pipeline in the simulator: the graph of rtl_models/pipeline/scw_pipeline.sv built
// from each block's C++ model or its Verilated twin (any mix), linked by sim::Fifo.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "hls/pipeline/pipeline_params.hpp"
#include "hls/pipeline/pipeline_result.hpp"
#include "sim/core/components.hpp"
#include "sim/core/join.hpp"
#include "sim/core/side_component.hpp"
#include "sim/core/simulator.hpp"
#include "sim/models/disparity_model.hpp"
#include "sim/models/frame_check_model.hpp"
#include "sim/models/ground_model.hpp"
#include "sim/models/labelling_model.hpp"
#include "sim/models/map_grid_model.hpp"
#include "sim/models/rectify_model.hpp"
#include "sim/models/road_model.hpp"
#include "sim/models/warning_model.hpp"
#include "sim/pipeline/pipeline_setup.hpp"
#include "sim/pipeline/pipeline_timing.hpp"
#include "sim/pipeline/result_merge.hpp"
#include "sim/rtl/disparity_rtl.hpp"
#include "sim/rtl/frame_check_rtl.hpp"
#include "sim/rtl/ground_rtl.hpp"
#include "sim/rtl/labelling_rtl.hpp"
#include "sim/rtl/map_grid_rtl.hpp"
#include "sim/rtl/rectify_rtl.hpp"
#include "sim/rtl/road_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "sim/rtl/warning_rtl.hpp"

namespace scw::sim {

/// The Verilated classes of one build, one per block (`void`: not built). Whoever names them
/// static_asserts each one's parameters (the V<prefix>_<module> class) against the build's,
/// with the *_params_match functions, as every Verilated model in the project is checked.
/// `Ground` is the optional ground filter, which the scw_pipeline top does not have.
template <typename Check, typename MapGrid, typename Rectify, typename Disparity,
          typename Labelling, typename Warning, typename Merge, typename Ground = void,
          typename Road = void>
struct PipelineRtl {
  using check = Check;
  using map_grid = MapGrid;
  using rectify = Rectify;
  using disparity = Disparity;
  using labelling = Labelling;
  using warning = Warning;
  using merge = Merge;
  using ground = Ground;
  using road = Road;
};
using NoRtl = PipelineRtl<void, void, void, void, void, void, void>;

/// The pipeline on the simulator's clock. Cycle 0 is the first cycle after the knots are
/// loaded (both cameras, one knot per cycle, left first, as scw_pipeline's knot port takes
/// them), when the map expanders start and the inputs may offer their first beats.
template <typename Build, typename Rtl = NoRtl>
class PipelineChain {
 public:
  using raw_beat = typename Build::rectify::pixel_beat;
  using disp_beat = typename Build::disparity::disp_beat;
  using label_beat = typename Build::labelling::in_beat;
  using Result = hls::pipeline::PipelineResultPacket;
  static constexpr int P = Build::kPpc;

  /// `left` and `right` are the raw frames' beats back to back; `in` stalls the two inputs
  /// (the right one with another seed, so they do not idle in step), `out` the result sink.
  /// Throws std::invalid_argument for a setup a stage cannot take, or an engine not built.
  /// `threads` 2 steps the disparity and road stages on a second thread (kLane): the same
  /// results and reports, clock for clock (docs/sim.md, "Two threads").
  PipelineChain(const PipelineSetup& s, const PipelineEngines& engines, std::vector<raw_beat> left,
                std::vector<raw_beat> right, const StallPattern& in = {},
                const StallPattern& out = {}, int threads = 1)
      : setup_(s), sim_(threads) {
    check_setup<Build>(s);
    const PipelineDepths& d = s.depths;
    auto& raw_l = sim_.fifo<raw_beat>("raw_left", d.raw);
    auto& raw_r = sim_.fifo<raw_beat>("raw_right", d.raw);
    raw_l_ = &raw_l;
    raw_r_ = &raw_r;
    auto& chk_l = sim_.fifo<raw_beat>("checked_left", d.raw);
    auto& chk_r = sim_.fifo<raw_beat>("checked_right", d.raw);
    auto& flag_l = sim_.fifo<hls::pipeline::FlagPacket>("flag_left", d.flag);
    auto& flag_r = sim_.fifo<hls::pipeline::FlagPacket>("flag_right", d.flag);
    auto& map_l = sim_.fifo<typename Build::rectify::map_beat>("map_left", d.map);
    auto& map_r = sim_.fifo<typename Build::rectify::map_beat>("map_right", d.map);
    rect_l_ = &sim_.fifo<raw_beat>("rect_left", d.rect);
    rect_r_ = &sim_.fifo<raw_beat>("rect_right", d.rect);
    disp_ = &sim_.fifo<disp_beat>("disparity", d.disp);
    objects_ = &sim_.fifo<hls::labelling::LabelPacket>("objects", d.obj);
    // The object words go to the warning stage and, in lockstep, out as the object table.
    warning_in_ = &sim_.fifo<hls::labelling::LabelPacket>("objects_warning", d.obj);
    table_ = &sim_.fifo<hls::labelling::LabelPacket>("object_table", d.obj);
    sim_.add<Fork<hls::labelling::LabelPacket>>("object_fork", *objects_, *warning_in_, *table_);
    auto& res = sim_.fifo<hls::warning::ResultPacket>("frame_result", d.res);
    out_ = &sim_.fifo<Result>("result", d.res);

    add_check("check_left", engines.check, raw_l, chk_l, flag_l);
    add_check("check_right", engines.check, raw_r, chk_r, flag_r);
    const auto grid_l = add_map_grid("map_grid_left", engines.map_grid, map_l);
    const auto grid_r = add_map_grid("map_grid_right", engines.map_grid, map_r);
    add_rectify("rectify_left", engines.rectify, chk_l, map_l, *rect_l_);
    add_rectify("rectify_right", engines.rectify, chk_r, map_r, *rect_r_);
    add_disparity(engines.disparity);
    // The road stage takes the disparity beats whole, and the labelling stage what it leaves,
    // a lane a pixel.
    road_ = &sim_.fifo<label_beat>("road", d.disp);
    lines_ = &sim_.fifo<hls::Packet<hls::road::Line>>("road_line", d.line);
    add_road(engines.road);
    label_in_ = road_;
    if constexpr (P == 1) {
      if (s.ground) {
        auto& filtered = sim_.fifo<label_beat>("ground", d.disp);
        add_ground(engines.ground, *label_in_, filtered);
        label_in_ = &filtered;
      }
    }
    add_labelling(engines.labelling, *label_in_);
    add_warning(engines.warning, res);
    add_merge(engines.merge, res, flag_l, flag_r);
    load_knots(grid_l, s.left_knots);
    load_knots(grid_r, s.right_knots);
    start_ = sim_.cycle();
    running_ = true;

    src_l_ = &sim_.add<Source<raw_beat>>("input_left", raw_l, std::move(left), in);
    src_r_ = &sim_.add<Source<raw_beat>>("input_right", raw_r, std::move(right),
                                         in.other_stream(kRightInputSalt));
    // The ends join after the knots are in, so their stall patterns start at cycle 0.
    sink_ = &sim_.add<Sink<Result>>("sink", *out_, out);
    table_sink_ = &sim_.add<Sink<hls::labelling::LabelPacket>>("table_sink", *table_,
                                                                out.other_stream(kObjectTableSalt));
  }

  /// Steps until `frames` results are out. Throws DeadlockError (naming the FIFOs that hold the
  /// pipeline) or std::runtime_error after `max_cycles`. `progress(cycles, results)`, if given,
  /// is called every `every` cycles.
  void run(std::size_t frames, std::int64_t max_cycles,
           const std::function<void(std::int64_t, std::size_t)>& progress = {},
           std::int64_t every = 100000) {
    sim_.run_until(
        [&] {
          if (progress && cycles() % every == 0) progress(cycles(), sink_->beats().size());
          return sink_->beats().size() >= frames;
        },
        max_cycles);
  }
  /// Offers more raw frames after the ones given so far, both cameras' beats back to back (a
  /// sequence read frame by frame through one chain).
  void feed(std::vector<raw_beat> left, std::vector<raw_beat> right) {
    src_l_->append(std::move(left));
    src_r_->append(std::move(right));
  }
  /// Frame period, latencies and busy times so far (sim/pipeline/pipeline_timing.hpp).
  PipelineTiming timing() const {
    return pipeline_timing(sim_.report(), *raw_l_, *raw_r_, *out_, start_);
  }
  /// Steps `cycles` more cycles.
  void step(std::int64_t cycles) {
    for (std::int64_t i = 0; i < cycles; ++i) sim_.step();
  }

  const std::vector<Result>& results() const { return sink_->beats(); }
  /// The cycle each result left the chain (taken from the result FIFO), from cycle 0.
  std::vector<std::int64_t> result_cycles() const {
    std::vector<std::int64_t> v;
    for (const auto& f : out_->frames())
      if (f.first_pop >= 0) v.push_back(f.first_pop - start_);
    return v;
  }
  /// Every object word that left on the object-table output, frames back to back.
  const std::vector<hls::labelling::LabelPacket>& object_table() const {
    return table_sink_->beats();
  }

  /// Cycles since cycle 0.
  std::int64_t cycles() const { return sim_.cycle() - start_; }
  /// The first cycle of the run on the simulator's clock: subtract it from report() stamps.
  std::int64_t start_cycle() const { return start_; }
  bool inputs_done() const { return src_l_->done() && src_r_->done(); }
  SimReport report() const { return sim_.report(); }
  Simulator& simulator() { return sim_; }

  // Links worth looking at (pictures of each stage, FIFO stamps for timing).
  Fifo<raw_beat>& rect_left() { return *rect_l_; }
  Fifo<raw_beat>& rect_right() { return *rect_r_; }
  const Fifo<raw_beat>& rect_left() const { return *rect_l_; }
  const Fifo<raw_beat>& rect_right() const { return *rect_r_; }
  Fifo<disp_beat>& disparity() { return *disp_; }
  /// What the road stage leaves of the disparity.
  Fifo<label_beat>& road() { return *road_; }
  /// What the labelling stage takes: the road stage's output, filtered again when the setup has a
  /// ground filter.
  Fifo<label_beat>& labelling_input() { return *label_in_; }
  Fifo<hls::labelling::LabelPacket>& objects() { return *objects_; }
  Fifo<Result>& result_fifo() { return *out_; }

  /// What the labelling stage is doing this cycle, read from its C++ model ("" when it runs as
  /// RTL): its phase (init, frame, drain, border, resolve) and "+emit" while Emit runs beside it.
  /// Reset trials say with it which of the stage's phases each reset cut.
  std::string labelling_activity() const { return labelling_activity_ ? labelling_activity_() : ""; }

 private:
  template <typename T>
  static constexpr bool kBuilt = !std::is_void_v<T>;

  [[noreturn]] static void not_built(const std::string& block) {
    throw std::invalid_argument("the " + block +
                                " RTL is not built for this configuration: run it with the C++ "
                                "engine, or build the Verilated models (docs/performance.md)");
  }

  void add_check(const std::string& name, Engine e, Fifo<raw_beat>& in, Fifo<raw_beat>& out,
                 Fifo<hls::pipeline::FlagPacket>& flags) {
    const hls::pipeline::FrameCheckConfig cfg{setup_.width, setup_.height};
    using CppModel = FrameCheckModel<P, Build::kMaxWidthPx, Build::kMaxHeight>;
    if (e == Engine::cpp) {
      sim_.add<SideComponent<CppModel>>(name, CppModel(cfg), in, out, flags);
      return;
    }
    using VM = typename Rtl::check;
    if constexpr (kBuilt<VM>) {
      using Params = typename CppModel::params;
      sim_.add<SideComponent<FrameCheckRtl<VM, Params>>>(
          name, FrameCheckRtl<VM, Params>(name, cfg), in, out, flags);
    } else {
      not_built("frame check");
    }
  }

  /// Returns a knot writer for the expander just added.
  using KnotWriter = std::function<void(const KnotWrite&)>;
  KnotWriter add_map_grid(const std::string& name, Engine e,
                          Fifo<typename Build::rectify::map_beat>& out) {
    using Params = typename Build::map_grid;
    const hls::rectify::MapGridConfig cfg{setup_.width, setup_.height};
    auto run = [this] { return running_; };
    if (e == Engine::cpp) {
      auto& c = sim_.add<SourceModelComponent<MapGridModel<Params>>>(
          name, MapGridModel<Params>(cfg), out, run);
      return [&c](const KnotWrite& w) { c.model().drive_knot(w); };
    }
    using VM = typename Rtl::map_grid;
    if constexpr (kBuilt<VM>) {
      auto& c = sim_.add<SourceModelComponent<MapGridRtl<VM, Params>>>(
          name, MapGridRtl<VM, Params>(name, cfg), out, run);
      return [&c](const KnotWrite& w) { c.model().drive_knot(w); };
    } else {
      not_built("map grid");
    }
  }

  /// One knot per cycle on the whole pipeline's clock (the other blocks idle, as in the top).
  void load_knots(const KnotWriter& write, const std::vector<hls::rectify::KnotPoint>& knots) {
    for (int j = 0; j < setup_.knot_rows; ++j)
      for (int i = 0; i < setup_.knot_cols; ++i) {
        write(KnotWrite{true, i, j, knots[static_cast<std::size_t>(j * setup_.knot_cols + i)]});
        sim_.step();
      }
  }

  void add_rectify(const std::string& name, Engine e, Fifo<raw_beat>& raw,
                   Fifo<typename Build::rectify::map_beat>& map, Fifo<raw_beat>& out) {
    using Params = typename Build::rectify;
    const hls::rectify::RectifyConfig cfg{setup_.width, setup_.height, setup_.lead_rows};
    if (e == Engine::cpp) {
      sim_.add<JoinComponent<RectifyModel<Params>>>(name, RectifyModel<Params>(cfg), raw, map,
                                                    out);
      return;
    }
    using VM = typename Rtl::rectify;
    if constexpr (kBuilt<VM>) {
      sim_.add<JoinComponent<RectifyRtl<VM, Params>>>(name, make_rectify_rtl<VM, Params>(name, cfg),
                                                      raw, map, out);
    } else {
      not_built("rectify");
    }
  }

  /// The second thread's share of a cycle, with two: the disparity stage, the most costly block
  /// (45 % of a thesis-size run at P = 4, all RTL), and the road stage it feeds. Each thread
  /// then has about half the work and four FIFOs cross between them; with the right camera's
  /// blocks on it too, it had more than half (docs/sim.md, "Two threads").
  static constexpr int kLane = 1;

  void add_disparity(Engine e) {
    using Params = typename Build::disparity;
    const auto cfg = setup_.disparity_config();
    if (e == Engine::cpp) {
      sim_.add_to(kLane, [&] {
        return std::make_unique<JoinComponent<DisparityModel<Params>>>(
            "disparity", DisparityModel<Params>(cfg), *rect_l_, *rect_r_, *disp_);
      });
      return;
    }
    using VM = typename Rtl::disparity;
    if constexpr (kBuilt<VM>) {
      sim_.add_to(kLane, [&] {
        return std::make_unique<JoinComponent<DisparityRtl<VM, Params>>>(
            "disparity", make_disparity_rtl<VM, Params>("disparity", cfg), *rect_l_, *rect_r_,
            *disp_);
      });
    } else {
      not_built("disparity");
    }
  }

  void add_road(Engine e) {
    using Params = typename Build::road;
    static_assert(std::is_same_v<typename Params::in_beat, disp_beat> &&
                      std::is_same_v<typename Params::out_beat, label_beat>,
                  "the road stage sits between the disparity and labelling stages");
    if (e == Engine::cpp) {
      sim_.add_to(kLane, [&] {
        return std::make_unique<SideComponent<RoadModel<Params>>>(
            "road", RoadModel<Params>(setup_.road), *disp_, *road_, *lines_);
      });
      return;
    }
    using VM = typename Rtl::road;
    if constexpr (kBuilt<VM>) {
      sim_.add_to(kLane, [&] {
        return std::make_unique<SideComponent<RoadSideRtl<VM, Params>>>(
            "road", RoadSideRtl<VM, Params>("road", setup_.road), *disp_, *road_, *lines_);
      });
    } else {
      not_built("road");
    }
  }

  void add_ground(Engine e, Fifo<label_beat>& in, Fifo<label_beat>& out) {
    using Params = typename Build::ground;
    static_assert(std::is_same_v<typename Params::in_beat, label_beat>,
                  "the ground filter takes what the labelling stage takes");
    const hls::ground::GroundConfig cfg = *setup_.ground;
    if (e == Engine::cpp) {
      sim_.add<StreamComponent<GroundModel<Params>>>("ground", GroundModel<Params>(cfg), in, out);
      return;
    }
    using VM = typename Rtl::ground;
    if constexpr (kBuilt<VM>) {
      sim_.add<StreamComponent<GroundRtl<VM, Params>>>(
          "ground", make_ground_rtl<VM, Params>("ground", cfg), in, out);
    } else {
      not_built("ground");
    }
  }

  void add_labelling(Engine e, Fifo<label_beat>& in) {
    using Params = typename Build::labelling;
    const auto cfg = setup_.labelling_config();
    if (e == Engine::cpp) {
      hls::labelling::check_config<Params>(cfg);
      auto& c = sim_.add<StreamComponent<LabellingModel<Params>>>(
          "labelling", LabellingModel<Params>(cfg), in, *objects_);
      labelling_activity_ = [&c] {
        using K = hls::labelling::Labelling<Params>;
        static const char* const kNames[] = {"init", "frame", "drain", "border", "resolve"};
        const K& k = c.model().kernel();
        return std::string(kNames[k.phase()]) + (k.emitting() ? "+emit" : "");
      };
      return;
    }
    using VM = typename Rtl::labelling;
    if constexpr (kBuilt<VM>) {
      sim_.add<StreamComponent<LabellingRtl<VM, Params>>>(
          "labelling", make_labelling_rtl<VM, Params>("labelling", cfg), in, *objects_);
    } else {
      not_built("labelling");
    }
  }

  void add_warning(Engine e, Fifo<hls::warning::ResultPacket>& res) {
    using Params = typename Build::warning;
    static_assert(Build::labelling::kWidths.area <= hls::warning::kRuleAreaBits,
                  "the warning stage's distance rule reads kRuleAreaBits of an object's area: a "
                  "labelling build of at most 2^20 - 1 pixels");
    // The top's warning stage always measures heights above the road stage's lines.
    const hls::warning::WarningConfig cfg = setup_.warning_config();
    if (e == Engine::cpp) {
      hls::warning::check_config<Params>(cfg);
      sim_.add<JoinComponent<WarningRoadModel<Params>>>("warning", WarningRoadModel<Params>(cfg),
                                                        *warning_in_, *lines_, res);
      return;
    }
    using VM = typename Rtl::warning;
    if constexpr (kBuilt<VM>) {
      sim_.add<JoinComponent<WarningRoadRtl<VM>>>(
          "warning", make_warning_road_rtl<VM, Params>("warning", cfg), *warning_in_, *lines_, res);
    } else {
      not_built("warning");
    }
  }

  void add_merge(Engine e, Fifo<hls::warning::ResultPacket>& res,
                 Fifo<hls::pipeline::FlagPacket>& l, Fifo<hls::pipeline::FlagPacket>& r) {
    if (e == Engine::cpp) {
      sim_.add<MergeComponent<hls::pipeline::ResultMerge>>("merge", hls::pipeline::ResultMerge(),
                                                           res, l, r, *out_);
      return;
    }
    using VM = typename Rtl::merge;
    if constexpr (kBuilt<VM>) {
      sim_.add<MergeComponent<ResultMergeRtl<VM>>>("merge", ResultMergeRtl<VM>("merge"), res, l,
                                                   r, *out_);
    } else {
      not_built("result merge");
    }
  }

  PipelineSetup setup_;
  Simulator sim_;
  Fifo<raw_beat>* raw_l_ = nullptr;
  Fifo<raw_beat>* raw_r_ = nullptr;
  Fifo<raw_beat>* rect_l_ = nullptr;
  Fifo<raw_beat>* rect_r_ = nullptr;
  Fifo<disp_beat>* disp_ = nullptr;
  Fifo<label_beat>* road_ = nullptr;
  Fifo<hls::Packet<hls::road::Line>>* lines_ = nullptr;
  Fifo<label_beat>* label_in_ = nullptr;
  Fifo<hls::labelling::LabelPacket>* objects_ = nullptr;
  Fifo<hls::labelling::LabelPacket>* warning_in_ = nullptr;
  Fifo<hls::labelling::LabelPacket>* table_ = nullptr;
  Fifo<Result>* out_ = nullptr;
  Sink<Result>* sink_ = nullptr;
  Sink<hls::labelling::LabelPacket>* table_sink_ = nullptr;
  Source<raw_beat>* src_l_ = nullptr;
  Source<raw_beat>* src_r_ = nullptr;
  std::function<std::string()> labelling_activity_;
  std::int64_t start_ = 0;
  bool running_ = false;
};

}  // namespace scw::sim
