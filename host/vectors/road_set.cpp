// SPDX-License-Identifier: Apache-2.0
// Road stage golden vectors: the presets, the model run and its checks, the files.
#include "host/vectors/road_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "hls/pipeline/pipeline_params.hpp"
#include "hls/road/road.hpp"
#include "host/io/image_file.hpp"
#include "host/io/number_text.hpp"
#include "host/reference/road_ref.hpp"
#include "host/road/setup.hpp"
#include "host/vectors/road_maps.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/stall.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/road_model.hpp"
#include "sim/words/pack.hpp"
#include "sim/words/road_cfg.hpp"

namespace scw::vectors {
namespace {

using hls::road::FitSums;
using hls::road::Line;
using hls::road::RoadConfig;

constexpr int kMinFrames = 4;
constexpr double kUnit = hls::road::kPxUnit;
// How far the model's road may lie from the reference's, over the frame's rows, before the set
// is refused: tests/road's 1/100 px over a 64 x 48 frame, plus what truncating the slope to its
// register (one unit, 2^-16 px a row, in fit_line's division) moves the line over `height` rows.
// That term is 0.0007 px at 48 rows and 0.0073 px at the thesis's 480.
double road_tolerance_px(int height) { return 0.01 + height / kUnit; }

reference::RoadLinePx px(const Line& l) { return reference::to_px(l); }

/// The largest distance between two lines over rows 0 .. height - 1, in px.
double distance_px(const reference::RoadLinePx& x, const reference::RoadLinePx& y, int height) {
  const double db = x.b - y.b, da = x.a - y.a;
  return std::max(std::abs(db), std::abs(db + da * (height - 1)));
}

using host::io::fixed;

std::string line_text(const Line& l) {
  std::ostringstream s;
  s << "(a " << l.a << ", b " << l.b << ": " << fixed(l.a / kUnit, 4) << " px a row from row "
    << (l.a > 0 ? fixed(-double(l.b) / l.a, 2) : std::string("-")) << ")";
  return s.str();
}

// ---- presets ------------------------------------------------------------------------------

/// fixtures::road_map's default scene (64 x 48, 0.45 px a row from row 12, two objects).
fixtures::RoadScene street_scene() { return fixtures::RoadScene{}; }

RoadSequence street() {
  const fixtures::RoadScene scene = street_scene();
  RoadSequence s;
  s.preset = "street";
  // The nominal road 1.3 times too steep and its horizon 4 rows low: frame 0 is filtered with a
  // wrong road, and every later frame with the one fitted on the frame before.
  s.cfg = fixtures::road_config(scene, 1.3, 4.0);
  // The camera pitches: the true horizon moves by a row between some frames, so the fitted road
  // follows it a frame late.
  const double horizons[] = {12, 12, 13, 14, 13, 12};
  for (int f = 0; f < 6; ++f) {
    fixtures::RoadScene sc = scene;
    sc.horizon = horizons[f];
    s.frames.push_back({"street horizon " + fixed(sc.horizon, 0),
                        fixtures::road_map(sc, 10 + static_cast<std::uint32_t>(f)),
                        RoadFit::kFitted});
  }
  s.description =
      "scw road stage, P = 2, 64x48: six fixtures::road_map frames (road 0.45 px a row, true "
      "horizon at rows 12, 12, 13, 14, 13, 12, two objects standing on it, +-0.2 px noise, 1 "
      "pixel in 9 a hole, seeds 10..15) back to back from reset; nominal road 0.585 px a row "
      "from row 16 (1.3 times too steep, 4 rows low); every frame's fit is plausible, so each "
      "frame after the first is filtered with the road fitted on the frame before";
  return s;
}

RoadSequence implausible() {
  const fixtures::RoadScene scene = street_scene();
  RoadSequence s;
  s.preset = "implausible";
  // The nominal road is the true one of the default scene; plausible are slopes 0.225 .. 0.9 px
  // a row and horizons at rows 4 .. 20.
  s.cfg = fixtures::road_config(scene, 1.0, 0.0);
  auto frame = [&](const char* name, double slope, double horizon, std::uint32_t seed,
                   RoadFit expect) {
    fixtures::RoadScene sc = scene;
    sc.slope = slope;
    sc.horizon = horizon;
    s.frames.push_back({name, fixtures::road_map(sc, seed), expect});
  };
  frame("road 3 times too steep", scene.slope * 3, scene.horizon, 20, RoadFit::kSlope);
  frame("road 4 times too flat", scene.slope / 4, scene.horizon, 21, RoadFit::kSlope);
  frame("horizon at row 24, below h_max", 0.65, 24, 22, RoadFit::kHorizon);
  frame("horizon at row 0, above h_min", scene.slope, 0, 23, RoadFit::kHorizon);
  frame("horizon at row -4, above the image", 0.35, -4, 25, RoadFit::kHorizon);
  {
    // Holes: the road with all but 1 pixel in 64 invalid, as the disparity stage's opencv mode
    // codes it (-16, 0xfff0), so the gate holds fewer than min_count pixels.
    cv::Mat m = fixtures::road_map(scene, 24);
    for (int v = 0; v < m.rows; ++v)
      for (int u = 0; u < m.cols; ++u)
        if ((7 * u + 3 * v) % 64 != 0) m.at<std::uint16_t>(v, u) = 0xfff0;
    s.frames.push_back({"1 pixel in 64 valid, the rest -16", m, RoadFit::kFewPixels});
  }
  s.description =
      "scw road stage, P = 2, 64x48: six fixtures::road_map frames whose fits the plausibility "
      "rules refuse, back to back from reset (seeds 20..25): a road 3 times too steep (slope "
      "above a_max), one 4 times too flat (below a_min), 0.65 px a row from row 24 (horizon "
      "below h_max = 20), 0.45 from row 0 (above h_min = 4), 0.35 from row -4 (above the "
      "image), and the road with all but 1 pixel in 64 set to -16 (fewer than min_count = 50 "
      "pixels); every frame is filtered with the nominal road, 0.45 px a row from row 12";
  return s;
}

// ---- the run ------------------------------------------------------------------------------

struct FrameRun {
  Line road;     // the road the frame was filtered with
  FitSums sums;  // its gate's sums, fitted at the next sof
  RoadFit verdict = RoadFit::kFitted;
  long removed = 0;
};

template <typename Params>
void check_sequence(const RoadSequence& seq) {
  if (static_cast<int>(seq.frames.size()) < kMinFrames)
    throw std::invalid_argument(
        "vectors road: preset '" + seq.preset + "' has " + std::to_string(seq.frames.size()) +
        " frames; a road set needs at least " + std::to_string(kMinFrames) +
        " back to back, so that fits happen between them and a replay sees their effect");
  const cv::Mat& first = seq.frames.front().d;
  for (const RoadFrame& f : seq.frames) {
    const cv::Mat& d = f.d;
    if (d.type() != CV_16UC1 || d.size() != first.size() || !d.isContinuous())
      throw std::invalid_argument("vectors road: frame '" + f.name +
                                  "' is not a continuous 16-bit map of the first frame's size");
  }
  const int w = first.cols, h = first.rows;
  if (w < Params::kPpc || w > Params::kMaxWidthPx || w % Params::kPpc != 0 || h < 2 ||
      h > Params::kMaxHeight)
    throw std::invalid_argument("vectors road: frames of " + std::to_string(w) + " x " +
                                std::to_string(h) + " do not fit the vector build (rows of " +
                                "2 .. 64 px in beats of 2, 2 .. 48 rows)");
  hls::road::check_config(seq.cfg);
}

/// The kernel through road_frame(), one frame at a time, so each frame's road and sums can be
/// read between frames.
template <typename Params>
std::vector<FrameRun> run_kernel(const RoadSequence& seq,
                                 const std::vector<typename Params::in_beat>& in,
                                 std::vector<typename Params::out_beat>& out) {
  using Kernel = hls::road::Road<Params>;
  using OutBeat = typename Params::out_beat;
  const std::size_t per_frame = in.size() / seq.frames.size();
  Kernel k(seq.cfg);
  std::vector<FrameRun> runs(seq.frames.size());
  out.assign(in.size(), OutBeat{});
  for (std::size_t f = 0; f < seq.frames.size(); ++f) {
    const std::size_t at = f * per_frame;
    hls::road::road_frame(k, in.data() + at, out.data() + at, static_cast<int>(per_frame));
    FrameRun& r = runs[f];
    r.road = k.line();
    r.sums = k.sums();
    r.verdict = road_fit_verdict(r.sums, seq.cfg);
    for (std::size_t i = at; i < at + per_frame; ++i)
      for (int p = 0; p < Params::kPpc; ++p) r.removed += in[i].px[p] != out[i].px[p];
  }
  return runs;
}

/// The fits the sequence expects happened, and each changed the road.
void check_fits(const RoadSequence& seq, const std::vector<FrameRun>& runs) {
  const std::string at = "vectors road: preset '" + seq.preset + "', ";
  if (runs.front().road != seq.cfg.nominal)
    throw std::logic_error(at + "frame 0 was not filtered with the nominal road");
  for (std::size_t f = 0; f < runs.size(); ++f) {
    const RoadFrame& in = seq.frames[f];
    const FrameRun& r = runs[f];
    // The verdict is ours; the road is what fit_line made.
    const Line sentinel{-1, 1};  // no fit returns it: a fitted slope is at least a_min >= 0
    const bool fitted = hls::road::fit_line(r.sums, seq.cfg, sentinel) != sentinel;
    if (fitted != (r.verdict == RoadFit::kFitted))
      throw std::logic_error(at + "road_fit_verdict disagrees with hls::road::fit_line");
    if (in.check_fit && r.verdict != in.expect)
      throw std::runtime_error(at + "frame " + std::to_string(f) + " ('" + in.name + "'): its " +
                               std::to_string(r.sums.n) + " gate pixels give the fit '" +
                               road_fit_name(r.verdict) + "', the preset expects '" +
                               road_fit_name(in.expect) + "'");
    if (f + 1 == runs.size()) break;  // the last frame's fit would serve a frame not in the set
    const Line& next = runs[f + 1].road;
    if (in.check_fit && fitted && next == r.road)
      throw std::runtime_error(at + "the fit after frame " + std::to_string(f) +
                               " gave the same road " + line_text(next) +
                               "; the set would not show the road moving");
    if (!fitted && next != r.road) throw std::logic_error(at + "a refused fit changed the road");
  }
}

/// One frame against the reference given the model's road: the pixels removed, the gate's count,
/// the verdict and the next road (its distance from the reference's goes to `road_error`).
/// Returns how many pixels the two decide differently, each within the kernel's rounding of a
/// band's edge (any other difference throws).
long check_frame_against_reference(const RoadSequence& seq, std::size_t f, const FrameRun& r,
                                   const cv::Mat& out_frame, double& road_error) {
  const cv::Mat& q4 = seq.frames[f].d;
  const RoadConfig& cfg = seq.cfg;
  const std::string at = "vectors road: preset '" + seq.preset + "', frame " + std::to_string(f) +
                         " ('" + seq.frames[f].name + "'): ";
  const reference::RoadLinePx road = px(r.road);
  const auto ref = reference::road_reference(q4, road, cfg);
  // The kernel forms each band's edges from the line by arithmetic shifts (floor) and steps them
  // a row at a time, so an edge lies up to (v + 1) line units (2^-16 px) inside the exact one.
  const auto near_edge = [&](double d, double dr, double abs_px, double rel, int v) {
    return std::abs(std::abs(d - dr) - (abs_px + rel * dr)) <= (v + 1) / kUnit + 1e-9;
  };
  long edge = 0, gate_edge = 0;
  for (int v = 0; v < q4.rows; ++v) {
    const double dr = road.a * v + road.b;  // exact in doubles: the kernel's row register
    for (int u = 0; u < q4.cols; ++u) {
      const std::uint16_t c = q4.at<std::uint16_t>(v, u);
      const bool got = out_frame.at<std::uint16_t>(v, u) != c;
      const bool want = ref.kept.at<std::uint16_t>(v, u) != c;
      if (!hls::road::is_valid(c) || dr < 1.0) {
        if (got || want)
          throw std::runtime_error(at + "a pixel off the active rows or invalid was removed");
        continue;
      }
      const bool near = near_edge(c / 16.0, dr, cfg.tol_q4 / 16.0, cfg.tol_rel_q8 / 256.0, v);
      gate_edge += near_edge(c / 16.0, dr, cfg.gate_q4 / 16.0, cfg.gate_rel_q8 / 256.0, v);
      edge += near && got != want;
      if (got != want && !near)
        throw std::runtime_error(at + "row " + std::to_string(v) + " column " + std::to_string(u) +
                                 " (code " + std::to_string(c) + "): the model " +
                                 (got ? "removes" : "keeps") + " it, the reference " +
                                 (want ? "removes" : "keeps") + " it (road " + fixed(dr, 4) +
                                 " px)");
    }
  }
  const double n = static_cast<double>(r.sums.n);
  if (std::abs(ref.pixels - n) > static_cast<double>(gate_edge))
    throw std::runtime_error(at + "the model's gate holds " + std::to_string(r.sums.n) +
                             " pixels, the reference's " + fixed(ref.pixels, 0));
  if (ref.fitted != (r.verdict == RoadFit::kFitted))
    throw std::runtime_error(at + "the model's fit is '" + road_fit_name(r.verdict) +
                             "', the reference " + (ref.fitted ? "fits" : "keeps") + " the road");
  const Line next = hls::road::fit_line(r.sums, cfg, r.road);
  const double e = distance_px(px(next), ref.next, q4.rows);
  if (e > road_tolerance_px(q4.rows))
    throw std::runtime_error(at + "the next road " + line_text(next) + " is " + fixed(e, 4) +
                             " px from the reference's least-squares line");
  road_error = std::max(road_error, e);
  return edge;
}

nlohmann::json disparity_layout(int ppc) {
  nlohmann::json l = pixel_beat_layout(ppc, 16);
  l["signed"] = true;
  l["frac_bits"] = 4;
  return l;
}

}  // namespace

const char* road_fit_name(RoadFit f) {
  switch (f) {
    case RoadFit::kFitted:
      return "fitted";
    case RoadFit::kFewPixels:
      return "few_pixels";
    case RoadFit::kNoSlope:
      return "no_slope";
    case RoadFit::kSlope:
      return "slope";
    case RoadFit::kHorizon:
      return "horizon";
  }
  return "?";
}

RoadFit road_fit_verdict(const FitSums& s, const RoadConfig& cfg) {
  __extension__ typedef __int128 i128;
  if (s.n < cfg.min_count) return RoadFit::kFewPixels;
  const i128 den = i128(s.n) * s.svv - i128(s.sv) * s.sv;
  const i128 num = i128(s.n) * s.svd - i128(s.sv) * s.sd;
  if (den <= 0 || num <= 0) return RoadFit::kNoSlope;
  if (num >= (den << (hls::road::kSlopeBits - hls::road::kFracBits))) return RoadFit::kSlope;
  const i128 a = (num << hls::road::kFracBits) / den;
  if (a < cfg.a_min || a > cfg.a_max) return RoadFit::kSlope;
  const i128 c = a * i128(s.sv) - (i128(s.sd) << hls::road::kFracBits);
  if (c < 0) return RoadFit::kHorizon;
  const i128 nb = c / i128(s.n);
  if (nb < a * cfg.h_min || nb > a * cfg.h_max) return RoadFit::kHorizon;
  return RoadFit::kFitted;
}

const std::vector<std::string>& road_presets() {
  static const std::vector<std::string> kNames = {"street", "implausible"};
  return kNames;
}

RoadSequence road_preset(const std::string& name) {
  if (name == "street") return street();
  if (name == "implausible") return implausible();
  throw std::invalid_argument("vectors road: no preset '" + name +
                              "' (there are: street, implausible)");
}

RoadSequence road_frames(const UserRoadMaps& u) {
  RoadSequence s;
  s.preset = "user";
  s.build = u.build;
  s.ppc = u.ppc;
  if (u.disparity.empty()) throw std::invalid_argument("vectors road: give the maps");
  cv::Rect roi = u.roi;
  const auto maps = crop_maps(u.disparity, roi, "vectors road");
  // The principal row defaults to the whole map's centre; the stage sees it from the crop's top.
  const double cy =
      u.cy_px >= 0 ? u.cy_px : 0.5 * (host::io::read_disparity_q4(u.disparity[0]).rows - 1);
  for (std::size_t i = 0; i < maps.size(); ++i) {
    RoadFrame f;
    f.name = u.disparity[i].filename().string();
    f.d = maps[i];
    f.check_fit = false;
    s.frames.push_back(std::move(f));
  }
  auto rig =
      road::rig_setup(u.baseline_m, u.focal_px, cy - roi.y, u.camera_height_m, u.camera_pitch_deg);
  // The rig's default count is for a thesis-size frame (1280 x 480); a crop needs fewer.
  rig.min_count = u.min_count > 0 ? u.min_count
                                  : std::max(50, static_cast<int>(static_cast<long>(rig.min_count) *
                                                                  roi.area() / (1280L * 480L)));
  s.cfg = road::to_fixed(rig);
  std::ostringstream d;
  d << "scw road stage (" << u.build << " build): " << s.frames.size()
    << " maps back to back, the crop " << crop_text(roi) << " of";
  for (const auto& path : u.disparity) d << " " << path.filename().string();
  d << " (Q11.4); nominal road from f " << u.focal_px << " px, b " << u.baseline_m
    << " m, principal row " << cy << ", camera " << u.camera_height_m << " m high, pitched "
    << u.camera_pitch_deg << " deg down; fits need " << rig.min_count << " pixels";
  s.description = d.str();
  return s;
}

namespace {

template <typename Params>
RoadSetSummary write_set(const RoadSequence& seq, const std::filesystem::path& dir) {
  using InBeat = typename Params::in_beat;
  using OutBeat = typename Params::out_beat;
  using Model = sim::RoadModel<Params>;
  check_sequence<Params>(seq);
  const int w = seq.frames.front().d.cols, h = seq.frames.front().d.rows;
  const int frames = static_cast<int>(seq.frames.size());
  std::vector<InBeat> in;
  for (const RoadFrame& f : seq.frames) {
    const auto b = sim::frame_beats_of<InBeat>(f.d.ptr<std::uint16_t>(), w, h);
    in.insert(in.end(), b.begin(), b.end());
  }

  // The frame function, frame by frame: the expected beats, every frame's road and sums.
  std::vector<OutBeat> want;
  const std::vector<FrameRun> runs = run_kernel<Params>(seq, in, want);
  check_fits(seq, runs);

  // The cycle model from reset, as a replay runs the RTL: the same beats, with and without
  // stalls (a replay stalls both sides; what it must see cannot depend on that).
  const std::int64_t limit =
      8 * static_cast<std::int64_t>(in.size()) + 4 * frames * (hls::road::kFitClocks + 8) + 1000;
  RoadSetSummary sum;
  {
    Model m(seq.cfg);
    const auto r = sim::run_stream(m, in, sim::StallPattern{}, in.size(), limit);
    if (r.timed_out || !r.violations.empty() || r.out != want)
      throw std::logic_error("vectors road: the cycle model's beats differ from road_frame's");
    sum.cycles = r.cycles;
    Model ms(seq.cfg);
    const auto s =
        sim::run_stream(ms, in, sim::StallPattern{sim::StallKind::kBoth, 0}, in.size(), limit);
    if (s.timed_out || !s.violations.empty() || s.out != want)
      throw std::logic_error("vectors road: the cycle model's beats change under stalls");
  }

  // Frame by frame against the floating-point reference: the removed pixels given the model's
  // road, and a road chained through the reference's own fits from the nominal one.
  std::vector<cv::Mat> in_images, out_images;
  reference::RoadLinePx chained = px(seq.cfg.nominal);
  const std::size_t per_frame = in.size() / seq.frames.size();
  for (int f = 0; f < frames; ++f) {
    const cv::Mat& q4 = seq.frames[static_cast<std::size_t>(f)].d;
    cv::Mat out(h, w, CV_16UC1);
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u) {
        const OutBeat& b = want[static_cast<std::size_t>(f) * per_frame +
                                static_cast<std::size_t>(v * w + u) / Params::kPpc];
        out.at<std::uint16_t>(v, u) = b.px[static_cast<std::size_t>(u % Params::kPpc)];
      }
    const FrameRun& r = runs[static_cast<std::size_t>(f)];
    sum.band_edge +=
        check_frame_against_reference(seq, static_cast<std::size_t>(f), r, out, sum.road_error_px);
    const double drift = distance_px(px(r.road), chained, h);
    if (drift > road_tolerance_px(h))
      throw std::runtime_error("vectors road: preset '" + seq.preset + "', frame " +
                               std::to_string(f) + ": the model's road " + line_text(r.road) +
                               " is " + fixed(drift, 4) +
                               " px from the road the reference reaches on its own");
    sum.road_error_px = std::max(sum.road_error_px, drift);
    chained = reference::road_reference(q4, chained, seq.cfg).next;
    in_images.push_back(q4);
    out_images.push_back(out);
    sum.removed += r.removed;
    sum.roads.push_back(r.road);
    sum.verdicts.push_back(r.verdict);
    if (f > 0 && r.road != runs[static_cast<std::size_t>(f) - 1].road) ++sum.fits;
  }

  const RoadConfig& c = seq.cfg;
  nlohmann::json config = {// The build (scw_road's parameters) and its constants.
                           {"build", seq.build},
                           {"ppc", Params::kPpc},
                           {"max_width_px", Params::kMaxWidthPx},
                           {"max_height", Params::kMaxHeight},
                           {"latency", hls::road::kLatency},
                           {"fit_clocks", hls::road::kFitClocks},
                           {"frac_bits", hls::road::kFracBits},
                           // The stream.
                           {"width", w},
                           {"height", h},
                           {"frames", frames},
                           {"beats", in.size()},
                           {"fits", sum.fits}};
  // Every RoadConfig field, as the C++ holds it: the fields of the word cfg.hex holds.
  config.update(field_values(sim::road_cfg::kConfigFields, c));

  const auto in_words = sim::pack_all(in);
  const auto out_words = sim::pack_all(want);
  std::vector<std::vector<std::string>> rows;
  for (int f = 0; f < frames; ++f) {
    const FrameRun& r = runs[static_cast<std::size_t>(f)];
    rows.push_back({std::to_string(f), std::to_string(static_cast<std::size_t>(f) * per_frame),
                    std::to_string(r.road.a), std::to_string(r.road.b), fixed(r.road.a / kUnit, 6),
                    r.road.a > 0 ? fixed(-double(r.road.b) / r.road.a, 3) : std::string("none"),
                    std::to_string(r.removed), std::to_string(r.sums.n), road_fit_name(r.verdict)});
  }

  VectorWriter vw(dir, "road", config, seq.description);
  // The configuration word the testbench puts on cfg_road_i.
  add_config_hex<RoadConfig>(vw, "cfg.hex", sim::words::pack_word(c, sim::road_cfg::kConfigFields),
                             sim::road_cfg::kConfigFields, false);
  vw.add_hex("in.hex", "input", in_words, disparity_layout(Params::kPpc));
  vw.add_image("in.png", "input", stacked_frames(in_images));
  vw.add_hex("expected.hex", "expected", out_words, disparity_layout(Params::kPpc));
  vw.add_image("expected.png", "expected", stacked_frames(out_images));
  vw.add_csv("expected_roads.csv", "expected",
             {"frame", "first_beat", "road_a", "road_b", "slope_px", "horizon_row", "removed",
              "gate_pixels", "next_fit"},
             rows);
  vw.finish();

  sum.frames = frames;
  sum.width = w;
  sum.height = h;
  sum.beats = in.size();
  sum.ppc = Params::kPpc;
  return sum;
}

}  // namespace

const std::vector<std::string>& road_builds() {
  static const std::vector<std::string> kNames = {"vectors", "small", "tsukuba", "thesis"};
  return kNames;
}

RoadSetSummary write_road_set(const RoadSequence& seq, const std::filesystem::path& dir) {
  using hls::pipeline::SmallPipeline;
  using hls::pipeline::ThesisPipeline;
  using hls::pipeline::TsukubaPipeline;
  if (seq.build == "vectors") return write_set<RoadVecParams>(seq, dir);
  const auto on = [&](auto p1, auto p2, auto p4) -> RoadSetSummary {
    switch (seq.ppc) {
      case 1:
        return write_set<typename decltype(p1)::road>(seq, dir);
      case 2:
        return write_set<typename decltype(p2)::road>(seq, dir);
      case 4:
        return write_set<typename decltype(p4)::road>(seq, dir);
      default:
        throw std::invalid_argument("vectors road: P = " + std::to_string(seq.ppc) +
                                    "; the builds take 1, 2 or 4 pixels a beat");
    }
  };
  if (seq.build == "small") return on(SmallPipeline<1>{}, SmallPipeline<2>{}, SmallPipeline<4>{});
  if (seq.build == "tsukuba")
    return on(TsukubaPipeline<1>{}, TsukubaPipeline<2>{}, TsukubaPipeline<4>{});
  if (seq.build == "thesis")
    return on(ThesisPipeline<1>{}, ThesisPipeline<2>{}, ThesisPipeline<4>{});
  throw std::invalid_argument("vectors road: no build '" + seq.build +
                              "' (vectors, small, tsukuba, thesis)");
}

}  // namespace scw::vectors
