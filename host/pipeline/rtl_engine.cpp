// SPDX-License-Identifier: Apache-2.0
// The Verilated pipeline behind `scw run --engine rtl` (host/pipeline/rtl_engine.hpp).
#include "host/pipeline/rtl_engine.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/pipeline/setup.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/reference/ground_ref.hpp"
#include "host/road/run_model.hpp"
#include "sim/builds/pipeline_small_rtl.hpp"
#include "sim/core/simulator.hpp"
#include "sim/pipeline/pipeline_chain.hpp"
#if SCW_THESIS_RTL
#include "sim/builds/pipeline_thesis_rtl.hpp"
#endif

namespace scw::host::pipeline {
namespace {

template <typename Beat>
cv::Mat picture(const std::vector<Beat>& beats, int width, int height, int type) {
  cv::Mat m(height, width, type);
  constexpr int P = Beat::kPixels;
  std::size_t i = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; x += P, ++i)
      for (int k = 0; k < P; ++k) {
        if (type == CV_8U)
          m.at<std::uint8_t>(y, x + k) = static_cast<std::uint8_t>(beats.at(i).px[k]);
        else
          m.at<std::int16_t>(y, x + k) = static_cast<std::int16_t>(beats.at(i).px[k]);
      }
  return m;
}

/// Calls `f` on each link whose beats make a frame's outputs (the labelling's input is the
/// road stage's output when there is no ground filter: it is called twice then).
template <typename Chain, typename F>
void for_each_recorded_link(Chain& c, F&& f) {
  f(c.rect_left());
  f(c.rect_right());
  f(c.disparity());
  f(c.road());
  f(c.labelling_input());
  f(c.objects());
}

template <typename Build, typename Rtl>
app::StageEngine engine_for(const app::RunOptions& o, int width, int height,
                            const KnotSource& knot_source, int threads) {
  StageOptions so;
  so.mode = o.mode;
  so.edge_candidates = o.edge_candidates;
  so.dmin = o.min_disp;
  so.num_disp = o.max_disp - o.min_disp + 1;
  so.tiles_x = o.tiles_x;
  so.tiles_y = o.tiles_y;
  so.min_area = o.min_area;
  so.warning = o.warning;
  so.road = o.road;
  so.camera_height_m = o.camera_height_m;
  so.camera_pitch_deg = o.camera_pitch_deg;
  std::vector<hls::rectify::KnotPoint> left, right;
  int lead = 1;
  if (knot_source) {
    const auto k = knot_source(Build::kGridLog2);
    left = k.left.knots;
    right = k.right.knots;
    lead = rectify::plan_for_stage({rectify::row_window(rectify::expand(k.left)),
                                    rectify::row_window(rectify::expand(k.right))},
                                   Build::kRectRows, "the calibration's grid maps")
               .lead_rows;
  } else {
    left = right = identity_knots(width, height, Build::kGridLog2);
  }
  auto setup = make_setup(width, height, Build::kGridLog2, so, left, right, lead);
  // The host's chain filters with the same rule and settings (app::Runner).
  if (o.ground)
    setup.ground = scw::ground::default_ground_config(o.warning.baseline_m, o.camera_height_m);
  sim::check_setup<Build>(setup);
  // One chain for the whole sequence, built at the first pair: each pair is fed after the last
  // one's result is out, so the road stage goes from frame to frame as it does on the board (each
  // frame gated with the road fitted on the one before), and the C++ road model beside it, kept
  // as long, checks it.
  using Chain = sim::PipelineChain<Build, Rtl>;
  struct State {
    std::unique_ptr<Chain> chain;
    std::unique_ptr<road::RoadFilter> road;
    std::size_t frames = 0;
  };
  auto state = std::make_shared<State>();
  return [setup, width, height, state, threads](const cv::Mat& l, const cv::Mat& r) {
    constexpr int P = Build::kPpc;
    State& st = *state;
    if (!st.chain) {
      st.chain = std::make_unique<Chain>(setup, sim::PipelineEngines::all(sim::Engine::rtl),
                                         frames_beats<P>({l}), frames_beats<P>({r}),
                                         sim::StallPattern{}, sim::StallPattern{}, threads);
      for_each_recorded_link(*st.chain, [](auto& f) { f.record(true); });
      st.road = std::make_unique<road::RoadFilter>(setup.road);
    } else {
      st.chain->feed(frames_beats<P>({l}), frames_beats<P>({r}));
    }
    Chain& chain = *st.chain;
    chain.run(st.frames + 1, 64 * static_cast<std::int64_t>(width) * height + 1000000);
    app::StageOutputs s;
    s.left = picture(chain.rect_left().recorded(), width, height, CV_8U);
    s.right = picture(chain.rect_right().recorded(), width, height, CV_8U);
    s.disparity = picture(chain.labelling_input().recorded(), width, height, CV_16S);
    const cv::Mat before = picture(chain.disparity().recorded(), width, height, CV_16S);
    const cv::Mat filtered = st.road->filter(before);
    const cv::Mat road_out = picture(chain.road().recorded(), width, height, CV_16S);
    if (cv::countNonZero(filtered != road_out) != 0)
      throw std::logic_error("the engine's road stage differs from the C++ road model");
    s.road_mask = road::removed_mask(before, road_out);
    s.road = st.road->road();  // the road this frame was gated with
    for (const auto& w : chain.objects().recorded()) {
      if (w.data.is_status)
        s.status = w.data.status;
      else
        s.objects.push_back(w.data.object);
    }
    const auto& res = chain.results().at(st.frames).data;
    s.result = res.frame;
    s.input_error = res.input_error_left || res.input_error_right;
    for_each_recorded_link(chain, [](auto& f) { f.clear_recorded(); });
    ++st.frames;
    return s;
  };
}

/// The build's limits in words, for the error that lists them.
template <typename Build>
std::string describe(const char* name) {
  return std::string(name) + ": up to " + std::to_string(Build::kMaxWidthPx) + " x " +
         std::to_string(Build::kMaxHeight) + ", window " + std::to_string(Build::kWindow) +
         ", up to " + std::to_string(Build::kNumDisp) + " disparities, up to " +
         std::to_string(Build::kMaxTilesX) + " x " + std::to_string(Build::kMaxTilesY) + " tiles";
}

template <typename Build>
bool takes(const app::RunOptions& o, int width, int height) {
  return width <= Build::kMaxWidthPx && height <= Build::kMaxHeight &&
         o.window == Build::kWindow && o.max_disp - o.min_disp + 1 <= Build::kNumDisp &&
         o.tiles_x <= Build::kMaxTilesX && o.tiles_y <= Build::kMaxTilesY;
}

}  // namespace

app::StageEngine make_rtl_engine(const app::RunOptions& o, int width, int height,
                                 const KnotSource& knots, int threads) {
  sim::check_threads(threads, "--threads");
  using Small = hls::pipeline::SmallPipeline<1>;
  if (takes<Small>(o, width, height))
    return engine_for<Small, sim::small_build::Rtl<1>::type>(o, width, height, knots, threads);
  using Thesis = hls::pipeline::ThesisPipeline<1>;
#if SCW_THESIS_RTL
  if (takes<Thesis>(o, width, height))
    return engine_for<Thesis, sim::thesis_build::Rtl<1>::type>(o, width, height, knots, threads);
  const std::string thesis = describe<Thesis>("thesis");
#else
  const std::string thesis =
      describe<Thesis>("thesis") + " (not built into this scw: configure with -DSCW_THESIS_RTL=ON)";
#endif
  throw std::invalid_argument(
      "--engine rtl: no Verilated build takes a " + std::to_string(width) + " x " +
      std::to_string(height) + " frame with window " + std::to_string(o.window) +
      ", disparities " + std::to_string(o.min_disp) + " .. " + std::to_string(o.max_disp) +
      " and " + std::to_string(o.tiles_x) + " x " + std::to_string(o.tiles_y) +
      " tiles. Builds: " + describe<Small>("small") + "; " + thesis +
      ". Set --window, --min-disp/--max-disp and --tiles to one of them, or use --engine cpp.");
}

}  // namespace scw::host::pipeline
