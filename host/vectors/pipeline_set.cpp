// SPDX-License-Identifier: Apache-2.0
#include "host/vectors/pipeline_set.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "host/pipeline/setup.hpp"
#include "host/pipeline/synthetic.hpp"
#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/map_grid.hpp"
#include "host/synth/top_params.hpp"
#include "host/vectors/labelling_set.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/builds/pipeline_small_rtl.hpp"
#include "sim/pipeline/pipeline_chain.hpp"
#include "sim/pipeline/pipeline_top.hpp"
#include "sim/words/disparity_cfg.hpp"
#include "sim/words/labelling_cfg.hpp"
#include "sim/words/pack.hpp"
#include "sim/words/road_cfg.hpp"
#include "sim/words/warning_cfg.hpp"

namespace scw::vectors {
namespace {

using json = nlohmann::json;
using sim::Bits;

// scw_pipeline's frame geometry ports in port order: cfg.hex holds one 32-bit word for each, and
// tests/pipeline/tb/tb_pipeline_replay.sv connects them in this order; each stage's configuration
// word (cfg_disparity_i, cfg_labelling_i, cfg_road_i, cfg_warning_i) is a file of its own,
// cfg_<stage>.hex. The values come from sim::drive_pipeline_cfg, the function that configures
// the Verilated top.
// clang-format off
#define SCW_PIPELINE_CFG_PORTS(X) X(cfg_width_i) X(cfg_height_i) X(cfg_lead_i)
// clang-format on

/// One port's value as drive_pipeline_cfg assigns it (its bit pattern, at most 32 bits).
struct CfgValue {
  std::uint32_t value = 0;
  bool driven = false;
  template <typename T>
  CfgValue& operator=(T v) {
    value = static_cast<std::uint32_t>(v);
    driven = true;
    return *this;
  }
};

/// A port wider than 64 bits as Verilator declares it (VlWide's storage), what Bits::to_port
/// writes.
template <int N>
struct WidePort {
  std::uint32_t m_storage[(N + 31) / 32] = {};
};

/// Stands in for the Verilated top: a member per cfg_* port.
struct CfgPorts {
#define SCW_MEMBER(port) CfgValue port;
  SCW_PIPELINE_CFG_PORTS(SCW_MEMBER)
#undef SCW_MEMBER
  WidePort<sim::disparity_cfg::kBits> cfg_disparity_i;
  WidePort<sim::labelling_cfg::kBits> cfg_labelling_i;
  WidePort<sim::warning_cfg::kBits> cfg_warning_i;
  WidePort<sim::road_cfg::kBits> cfg_road_i;
};

/// What drive_pipeline_cfg drives: the narrow ports' words in port order, and the stages'
/// configuration words.
struct CfgDrive {
  std::vector<std::pair<std::string, std::uint32_t>> ports;
  Bits disparity, labelling, warning, road;
};

template <typename Build>
CfgDrive cfg_drive(const sim::PipelineSetup& s) {
  CfgPorts p;
  sim::drive_pipeline_cfg<CfgPorts, Build>(p, s);
  CfgDrive d;
#define SCW_ENTRY(port)                                                                  \
  if (!p.port.driven) throw std::logic_error("pipeline set: " #port " is never driven"); \
  d.ports.emplace_back(#port, p.port.value);
  SCW_PIPELINE_CFG_PORTS(SCW_ENTRY)
#undef SCW_ENTRY
  d.disparity = Bits::from_port(p.cfg_disparity_i, sim::disparity_cfg::kBits);
  d.labelling = Bits::from_port(p.cfg_labelling_i, sim::labelling_cfg::kBits);
  d.warning = Bits::from_port(p.cfg_warning_i, sim::warning_cfg::kBits);
  d.road = Bits::from_port(p.cfg_road_i, sim::road_cfg::kBits);
  return d;
}

}  // namespace

void add_synthetic_frames(PipelineSetOptions& o) {
  if (!o.left.empty() || !o.right.empty()) return;
  const int dmax = sim::small_build::Build<1>::kNumDisp - 1;
  const int w = o.width, h = o.height;
  for (int f = 0; f < o.frames; ++f) {
    const int d = std::min(dmax, dmax / 2 + 2 * f);
    const int px = std::min(w / 2 + 3 * f, w - w / 6 - 1);
    const std::vector<host::pipeline::SyntheticBox> boxes = {
        {w / 8, h / 3, w / 8 + w / 4, h - h / 8, dmax / 2}, {px, h / 4, px + w / 6, h - h / 10, d}};
    const auto pair =
        host::pipeline::synthetic_pair(w, h, 2, boxes, o.seed + static_cast<std::uint32_t>(f));
    o.left.push_back(pair.left);
    o.right.push_back(pair.right);
  }
}

namespace {

/// The knot port's words as tb_pipeline_replay.sv writes them, one a clock, left camera first:
/// {right, row << col bits | col, {y, x}}.
template <typename G>
std::vector<Bits> knot_words(const sim::PipelineSetup& s) {
  constexpr int kb = G::kKnotBits, addr_bits = G::kKnotRowBits + G::kKnotColBits;
  const std::uint64_t mask = (std::uint64_t{1} << kb) - 1;
  std::vector<Bits> v;
  for (const bool right : {false, true}) {
    const auto& k = right ? s.right_knots : s.left_knots;
    for (int j = 0; j < s.knot_rows; ++j)
      for (int i = 0; i < s.knot_cols; ++i) {
        const auto& p = k[static_cast<std::size_t>(j * s.knot_cols + i)];
        Bits w(2 * kb + addr_bits + 1);
        w.set(0, kb, static_cast<std::uint64_t>(static_cast<std::int64_t>(p.x)) & mask);
        w.set(kb, kb, static_cast<std::uint64_t>(static_cast<std::int64_t>(p.y)) & mask);
        w.set(2 * kb, addr_bits,
              (static_cast<std::uint64_t>(j) << G::kKnotColBits) | static_cast<std::uint64_t>(i));
        w.set(2 * kb + addr_bits, 1, right ? 1 : 0);
        v.push_back(std::move(w));
      }
  }
  return v;
}

/// Both cameras' knots and the rectifiers' lead: the calibration's grid maps (the lead planned
/// from the expanded maps, as `scw run --engine rtl` does), or the identity map.
/// With a calibration, the warning's rig becomes its rectified cameras' (f, baseline, principal
/// point; metres as the calibration's units).
template <typename Build>
std::tuple<std::vector<hls::rectify::KnotPoint>, std::vector<hls::rectify::KnotPoint>, int>
knots_of(const std::filesystem::path& calib_file, int w, int h, host::warning::WarningSetup& rig) {
  if (calib_file.empty()) {
    const auto k = host::pipeline::identity_knots(w, h, Build::kGridLog2);
    return {k, k, 2};
  }
  const auto calib = rectify::load_stereo_calibration(calib_file.string(), cv::Size(w, h));
  if (calib.image_size != cv::Size(w, h))
    throw std::invalid_argument(
        "pipeline set: " + calib_file.string() + " calibrates " +
        std::to_string(calib.image_size.width) + "x" + std::to_string(calib.image_size.height) +
        " images, the frames are " + std::to_string(w) + "x" + std::to_string(h));
  const auto rect = rectify::rectify_calibration(calib);
  rig.focal_px = rect.focal_px();
  rig.baseline_m = rect.baseline();
  rig.cu_px = rect.principal_point().x;
  rig.cv_px = rect.principal_point().y;
  const auto k = rectify::grid_knots(calib, rect, Build::kGridLog2);
  const int lead = rectify::plan_for_stage({rectify::row_window(rectify::expand(k.left)),
                                            rectify::row_window(rectify::expand(k.right))},
                                           Build::kRectRows, "the calibration's grid maps")
                       .lead_rows;
  return {k.left.knots, k.right.knots, lead};
}

template <typename T>
void require_equal(const std::vector<T>& rtl, const std::vector<T>& cpp, const char* what) {
  const auto a = sim::pack_all(rtl), b = sim::pack_all(cpp);
  if (a.size() != b.size())
    throw std::runtime_error(std::string("pipeline set: the Verilated top's ") + what + " has " +
                             std::to_string(a.size()) + " words, the C++ chain's " +
                             std::to_string(b.size()));
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i]))
      throw std::runtime_error(std::string("pipeline set: the Verilated top's ") + what +
                               " differs from the C++ chain's at word " + std::to_string(i));
}

/// The stage settings of a build's sets: the small build's tests' own, or for the larger builds
/// `scw sim`'s (every candidate from 0, the build's tiles, objects of w h / 2000 px).
template <typename Build>
host::pipeline::StageOptions stage_options(int w, int h) {
  auto stage = host::pipeline::small_build_options();
  if constexpr (Build::kMaxWidthPx > sim::small_build::Build<1>::kMaxWidthPx) {
    stage.num_disp = Build::kNumDisp;
    stage.tiles_x = Build::kMaxTilesX;
    stage.tiles_y = Build::kMaxTilesY;
    stage.min_area = std::max(20, w * h / 2000);
    stage.warning = {};
  }
  if (w * h <= 64 * 48) stage.road_min_count = 50;  // as `scw soak`: a small frame's road
  return stage;
}

/// The set at a build: the C++ chain always, the Verilated top (`Top`, void: none) when asked.
template <typename Build, typename Top>
PipelineSetSummary write_build(const PipelineSetOptions& o, const std::filesystem::path& dir,
                               const std::function<void(const std::string&)>& say) {
  constexpr int P = Build::kPpc;
  const int w = o.left.front().cols, h = o.left.front().rows;
  if (w > Build::kMaxWidthPx || h > Build::kMaxHeight || w % P != 0)
    throw std::invalid_argument("pipeline set: " + std::to_string(w) + "x" + std::to_string(h) +
                                " frames do not fit the " + o.config + " build (up to " +
                                std::to_string(Build::kMaxWidthPx) + "x" +
                                std::to_string(Build::kMaxHeight) + ")");
  auto stage = stage_options<Build>(w, h);
  const auto [left_knots, right_knots, lead] = knots_of<Build>(o.calib, w, h, stage.warning);
  const auto setup =
      host::pipeline::make_setup(w, h, Build::kGridLog2, stage, left_knots, right_knots, lead);
  const auto left = host::pipeline::frames_beats<P>(o.left);
  const auto right = host::pipeline::frames_beats<P>(o.right);
  const auto frames = static_cast<std::size_t>(o.frames);
  const std::int64_t bound = static_cast<std::int64_t>(frames + 2) * (64LL * w * h + 50000);

  sim::PipelineChain<Build> chain(setup, sim::PipelineEngines::all(sim::Engine::cpp), left, right);
  chain.rect_left().record(true);
  chain.rect_right().record(true);
  chain.disparity().record(true);
  chain.road().record(true);
  chain.run(frames, bound);
  if (say)
    say("C++ chain: " + std::to_string(frames) + " frames in " + std::to_string(chain.cycles()) +
        " cycles");
  PipelineSetSummary sum{o.frames,       w,    h, P, left.size(), chain.object_table().size(),
                         chain.cycles(), false};
  if constexpr (!std::is_void_v<Top>) {
    if (o.rtl) {
      Top top(setup);
      const auto r = top.run(left, right, frames, bound);
      require_equal(r.results, chain.results(), "frame results");
      require_equal(r.object_table, chain.object_table(), "object table");
      sum.rtl = true;
      if (say) say("Verilated scw_pipeline: results and object table equal the C++ chain's");
    }
  } else if (o.rtl) {
    throw std::invalid_argument("pipeline set: the " + o.config +
                                " build's top is not Verilated in the CLI; give --engine cpp");
  }

  json params = json::object();
  for (const auto& [name, value] : host::synth::top_params<Build>()) params[name] = value;
  const auto cfg = cfg_drive<Build>(setup);
  json config = {{"config", o.config}, {"ppc", P},           {"width", w},
                 {"height", h},        {"frames", o.frames}, {"cfg_words", cfg.ports.size()},
                 {"params", params}};
  VectorWriter out(
      dir, "pipeline", config,
      "scw_pipeline (" + o.config + " build, P = " + std::to_string(P) +
          "): " + std::to_string(o.frames) + " frames of " + std::to_string(w) + "x" +
          std::to_string(h) + " back to back, " +
          (o.calib.empty() ? std::string("rectified (identity map)")
                           : "raw, rectified with " + o.calib.filename().string() +
                                 "'s grid maps (lead " + std::to_string(lead) + " rows)") +
          "; every stream between the stages");
  std::vector<Bits> cfg_bits;
  json lines = json::array();
  for (const auto& [port, value] : cfg.ports) {
    Bits b(32);
    b.set(0, 32, value);
    cfg_bits.push_back(b);
    lines.push_back({{"name", port}, {"value", value}});
  }
  out.add_hex("cfg.hex", "input", cfg_bits, {{"lines", lines}});
  add_config_hex<hls::disparity::DisparityConfig>(out, "cfg_disparity.hex", cfg.disparity,
                                                  sim::disparity_cfg::kConfigFields, true);
  add_config_hex<hls::labelling::LabellingConfig>(out, "cfg_labelling.hex", cfg.labelling,
                                                  sim::labelling_cfg::kConfigFields, true);
  add_config_hex<hls::warning::WarningConfig>(out, "cfg_warning.hex", cfg.warning,
                                              sim::warning_cfg::kConfigFields, true);
  add_config_hex<hls::road::RoadConfig>(out, "cfg_road.hex", cfg.road, sim::road_cfg::kConfigFields,
                                        true);
  using G = typename Build::map_grid;
  out.add_hex(
      "knots.hex", "input", knot_words<G>(setup),
      {{"fields", json::array({{{"name", "x"}, {"lsb", 0}, {"bits", G::kKnotBits}},
                               {{"name", "y"}, {"lsb", G::kKnotBits}, {"bits", G::kKnotBits}},
                               {{"name", "address"},
                                {"lsb", 2 * G::kKnotBits},
                                {"bits", G::kKnotRowBits + G::kKnotColBits}},
                               {{"name", "right"},
                                {"lsb", 2 * G::kKnotBits + G::kKnotRowBits + G::kKnotColBits},
                                {"bits", 1}}})}});
  out.add_hex("left.hex", "input", sim::pack_all(left), pixel_beat_layout(P, 8));
  out.add_hex("right.hex", "input", sim::pack_all(right), pixel_beat_layout(P, 8));
  cv::Mat strip_l, strip_r;
  cv::vconcat(o.left, strip_l);
  cv::vconcat(o.right, strip_r);
  out.add_image("left.png", "input", strip_l);
  out.add_image("right.png", "input", strip_r);
  out.add_hex("rect_left.hex", "expected", sim::pack_all(chain.rect_left().recorded()),
              pixel_beat_layout(P, 8));
  out.add_hex("rect_right.hex", "expected", sim::pack_all(chain.rect_right().recorded()),
              pixel_beat_layout(P, 8));
  out.add_hex("disparity.hex", "expected", sim::pack_all(chain.disparity().recorded()),
              pixel_beat_layout(P, 16));
  out.add_hex("road.hex", "expected", sim::pack_all(chain.road().recorded()),
              pixel_beat_layout(P, 16));
  const auto objects = sim::pack_all(chain.object_table());
  // The object words are the labelling stage's: their layout names its fields (as the labelling
  // sets' expected.hex), so a set made before a field's width changed compares field by field.
  if (objects.front().width() != labelling_word_layout().at("data_bits").get<int>() + 1)
    throw std::logic_error("pipeline set: the object words are not the labelling word");
  out.add_hex("objects.hex", "expected", objects, labelling_word_layout());
  const auto results = sim::pack_all(chain.results());
  out.add_hex("results.hex", "expected", results, stream_beat_layout(results.front().width() - 1));
  out.finish();
  return sum;
}

}  // namespace

const std::vector<std::string>& pipeline_set_configs() {
  static const std::vector<std::string> v = {"small", "thesis"};
  return v;
}

PipelineSetSummary write_pipeline_set(const PipelineSetOptions& opt,
                                      const std::filesystem::path& dir,
                                      const std::function<void(const std::string&)>& progress) {
  PipelineSetOptions o = opt;
  if (std::find(pipeline_set_configs().begin(), pipeline_set_configs().end(), o.config) ==
      pipeline_set_configs().end())
    throw std::invalid_argument("pipeline set: no build '" + o.config +
                                "'; builds: small (its top Verilated here), thesis (C++ chain)");
  if (o.frames < 1) throw std::invalid_argument("pipeline set: --frames must be at least 1");
  if (o.left.size() != o.right.size())
    throw std::invalid_argument("pipeline set: " + std::to_string(o.left.size()) + " left and " +
                                std::to_string(o.right.size()) + " right frames");
  if (o.left.empty()) {
    add_synthetic_frames(o);
  } else {
    o.frames = static_cast<int>(o.left.size());
    for (std::size_t i = 0; i < o.left.size(); ++i)
      if (o.left[i].type() != CV_8UC1 || o.right[i].type() != CV_8UC1 ||
          o.left[i].size() != o.left[0].size() || o.right[i].size() != o.left[0].size())
        throw std::invalid_argument("pipeline set: frame " + std::to_string(i) +
                                    ": every frame must be 8-bit grey and of one size");
  }
  namespace small = sim::small_build;
  using hls::pipeline::ThesisPipeline;
  if (o.config == "thesis") {
    if (o.ppc == 1) return write_build<ThesisPipeline<1>, void>(o, dir, progress);
    if (o.ppc == 2) return write_build<ThesisPipeline<2>, void>(o, dir, progress);
  } else {
    if (o.ppc == 1) return write_build<small::Build<1>, small::Top<1>>(o, dir, progress);
    if (o.ppc == 2) return write_build<small::Build<2>, small::Top<2>>(o, dir, progress);
  }
  throw std::invalid_argument("pipeline set: --ppc is 1 or 2");
}

}  // namespace scw::vectors
