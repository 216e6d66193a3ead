// SPDX-License-Identifier: Apache-2.0
// Disparity stage golden vectors: the presets, the model run and its check against the direct
// reference, the files.
#include "host/vectors/disparity_set.hpp"

#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "hls/pipeline/pipeline_params.hpp"
#include "host/io/image_file.hpp"
#include "host/io/tsukuba.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/words/disparity_cfg.hpp"
#include "sim/words/pack.hpp"

namespace scw::vectors {
namespace {

using hls::disparity::DisparityConfig;

/// A fixed integer hash: reproducible texture on every platform and library version.
std::uint8_t hash_pixel(int x, int y) {
  std::uint32_t n =
      static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u;
  n = (n ^ (n >> 13)) * 0x5bd1e995u;
  n ^= n >> 15;
  return static_cast<std::uint8_t>(n >> 8);
}

/// 64 x 24: a random right image; the left sees it shifted by 3 px (x < 24), 8 px (24 .. 43)
/// and 14 px (x >= 44), with a 12 x 12 block at 11 px in front (x 28 .. 39, y 6 .. 17);
/// left pixels whose source falls off the right image are fresh noise.
DisparityFrame synthetic() {
  constexpr int w = 64, h = 24;
  DisparityFrame f;
  cv::Mat right(h, w, CV_8UC1), left(h, w, CV_8UC1);
  f.shift = cv::Mat(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) right.at<std::uint8_t>(y, x) = hash_pixel(x, y);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int s = x < 24 ? 3 : (x < 44 ? 8 : 14);
      if (x >= 28 && x < 40 && y >= 6 && y < 18) s = 11;
      f.shift.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(s);
      left.at<std::uint8_t>(y, x) =
          x >= s ? right.at<std::uint8_t>(y, x - s) : hash_pixel(x + 1000, y + 1000);
    }
  f.left = {left};
  f.right = {right};
  f.window = 5;
  f.mode = disparity::Mode::thesis;
  f.cfg = disparity::mode_config(f.mode, w, h, 0);
  f.description =
      "scw disparity stage, thesis mode (plain SAD, no rejection, integer d, invalid 0), "
      "N = 5, d 0..15: 64x24 hashed random right image; the left sees it shifted by 3 px "
      "(x < 24), 8 px (24..43), 14 px (x >= 44) and a 12x12 block at 11 px (x 28..39, "
      "y 6..17); left pixels whose source is off the image are fresh noise";
  return f;
}

/// A 96 x 48 crop of the bundled Tsukuba pair (read as every command reads it), opencv mode.
DisparityFrame tsukuba(const std::filesystem::path& dir) {
  const auto pair = host::io::read_tsukuba_pair(dir);
  const cv::Rect roi(144, 112, 96, 48);
  DisparityFrame f;
  f.left = {pair.left(roi).clone()};
  f.right = {pair.right(roi).clone()};
  f.window = 9;
  f.mode = disparity::Mode::opencv;
  f.cfg = disparity::mode_config(f.mode, roi.width, roi.height, 0);
  std::ostringstream d;
  d << "scw disparity stage, opencv mode (x-Sobel prefilter cap 31, texture 10, uniqueness 15, "
       "sub-pixel, invalid -16), N = 9, d 0..15: data/tsukuba scene1.row3.col3.ppm (left) and "
       "scene1.row3.col4.ppm (right), grey by cv::imread IMREAD_GRAYSCALE, crop x "
    << roi.x << " y " << roi.y << " " << roi.width << "x" << roi.height;
  f.description = d.str();
  return f;
}

/// The Tsukuba crop with the left edge band: its columns 7 .. 18 decided among the candidates
/// whose window fits the right image, from 4 of them on (DisparityConfig::edge_candidates).
DisparityFrame tsukuba_edge(const std::filesystem::path& dir) {
  DisparityFrame f = tsukuba(dir);
  f.cfg.edge_candidates = 4;
  f.description += "; the left edge band decided from 4 candidates (edge_candidates 4)";
  return f;
}

/// How many of the computed pixels find the frame's true disparity.
void count_known_shifts(const DisparityFrame& f, const std::vector<std::uint16_t>& ref,
                        std::uint16_t invalid, DisparitySetSummary& sum) {
  sum.known_shifts = true;
  for (int i = 0; i < f.shift.cols * f.shift.rows; ++i) {
    if (ref[i] == invalid) continue;
    ++sum.shifts_valid;
    sum.shifts_right += ref[i] == f.shift.data[i] * 16 ? 1 : 0;
  }
}

template <typename Params>
nlohmann::json config_json(const DisparityFrame& f, std::uint16_t invalid) {
  const DisparityConfig& cfg = f.cfg;
  return {{"width", f.left[0].cols},
          {"height", f.left[0].rows},
          {"frames", f.left.size()},
          {"build", f.build},
          {"ppc", Params::kPpc},
          {"max_width_px", Params::kMaxWidthPx},
          {"max_height", Params::kMaxHeight},
          {"window", Params::kWindow},
          {"num_disp", Params::kNumDisp},
          {"mode", disparity::mode_name(f.mode)},
          {"dmin", cfg.dmin},
          {"dmax", cfg.dmin + Params::kNumDisp - 1},
          {"prefilter", cfg.prefilter},
          {"prefilter_cap", cfg.prefilter_cap},
          {"sad_limit", cfg.sad_limit},
          {"texture_threshold", cfg.texture_threshold},
          {"uniqueness_ratio", cfg.uniqueness_ratio},
          {"subpixel", cfg.subpixel},
          {"opencv_invalid", cfg.opencv_invalid},
          {"edge_candidates", cfg.edge_candidates},
          {"invalid_code", invalid}};
}

template <int P, typename In, typename Out>
void write_files(const std::filesystem::path& dir, const DisparityFrame& f,
                 const nlohmann::json& config, const sim::Bits& cfg_word, const std::vector<In>& l,
                 const std::vector<In>& r, const std::vector<Out>& expect,
                 const std::vector<std::uint16_t>& ref) {
  constexpr int kPpc = P;
  auto disp_layout = pixel_beat_layout(kPpc, 16);
  disp_layout["signed"] = true;
  disp_layout["frac_bits"] = 4;
  VectorWriter vw(dir, "disparity", config, f.description);
  // The configuration word the testbench puts on cfg_disparity_i: what the build reads of the
  // config (disparity_cfg::port_config), its fields in the layout.
  add_config_hex<DisparityConfig>(vw, "cfg.hex", cfg_word, sim::disparity_cfg::kConfigFields,
                                  false);
  vw.add_image("left.png", "input", stacked_frames(f.left));
  vw.add_image("right.png", "input", stacked_frames(f.right));
  vw.add_hex("left.hex", "input", sim::pack_all(l), pixel_beat_layout(kPpc, 8));
  vw.add_hex("right.hex", "input", sim::pack_all(r), pixel_beat_layout(kPpc, 8));
  vw.add_hex("expected.hex", "expected", sim::pack_all(expect), disp_layout);
  cv::Mat out_img(f.left[0].rows * static_cast<int>(f.left.size()), f.left[0].cols, CV_16UC1);
  std::memcpy(out_img.data, ref.data(), ref.size() * sizeof(std::uint16_t));
  vw.add_image("expected.png", "expected", out_img);
  vw.finish();
}

/// Throws std::invalid_argument unless `f`'s frames fit Params (and its crop its dmin).
template <typename Params>
void check_fits(const DisparityFrame& f) {
  const int w = f.left[0].cols, h = f.left[0].rows, n = Params::kNumDisp;
  const std::string size = std::to_string(w) + "x" + std::to_string(h);
  if (w > Params::kMaxWidthPx || h > Params::kMaxHeight || w % Params::kPpc != 0 ||
      w < Params::kWindow || h < Params::kWindow)
    throw std::invalid_argument("vectors disparity: a " + size + " frame does not fit the " +
                                f.build + " build (up to " + std::to_string(Params::kMaxWidthPx) +
                                "x" + std::to_string(Params::kMaxHeight) +
                                ", at least the window, width a multiple of " +
                                std::to_string(Params::kPpc) + "): give --roi X Y W H");
  if (f.cfg.dmin < 0 || f.cfg.dmin + n > w)
    throw std::invalid_argument("vectors disparity: --dmin " + std::to_string(f.cfg.dmin) +
                                " leaves no column with all " + std::to_string(n) +
                                " candidates in a " + std::to_string(w) + "-px frame");
}

template <typename Params>
DisparitySetSummary run(const DisparityFrame& f, const std::filesystem::path& dir) {
  constexpr int kPpc = Params::kPpc, N = Params::kWindow;
  check_fits<Params>(f);
  const int w = f.left[0].cols, h = f.left[0].rows;
  const DisparityConfig& cfg = f.cfg;
  std::vector<typename Params::pixel_beat> l, r;
  std::vector<typename Params::disp_beat> expect;
  std::vector<std::uint16_t> ref;
  for (std::size_t i = 0; i < f.left.size(); ++i) {
    const cv::Mat& lm = f.left[i];
    const cv::Mat& rm = f.right[i];
    if (lm.size() != f.left[0].size() || rm.size() != lm.size() || !lm.isContinuous() ||
        !rm.isContinuous())
      throw std::logic_error("vectors disparity: the frames are not one continuous size");
    const auto lb = sim::frame_beats<kPpc>(lm.ptr<std::uint8_t>(), w, h);
    const auto rb = sim::frame_beats<kPpc>(rm.ptr<std::uint8_t>(), w, h);
    l.insert(l.end(), lb.begin(), lb.end());
    r.insert(r.end(), rb.begin(), rb.end());
    const auto fr = reference::disparity_reference(lm.ptr<std::uint8_t>(), rm.ptr<std::uint8_t>(),
                                                   w, h, N, Params::kNumDisp, cfg);
    const auto fe = sim::frame_beats_of<typename Params::disp_beat>(fr.data(), w, h);
    ref.insert(ref.end(), fr.begin(), fr.end());
    expect.insert(expect.end(), fe.begin(), fe.end());
  }
  DisparitySetSummary sum;
  const auto got = disparity::run_disparity_model<Params>(l, r, cfg, &sum.cycles);
  const std::size_t per_frame = expect.size() / f.left.size(), per_row = w / kPpc;
  for (std::size_t i = 0; i < expect.size(); ++i)
    if (got[i] != expect[i])
      throw std::runtime_error("vectors disparity: the C++ model's beat " + std::to_string(i) +
                               " (frame " + std::to_string(i / per_frame) + ", row " +
                               std::to_string(i % per_frame / per_row) + ") is " +
                               sim::pack(got[i]).hex() + ", the reference gives " +
                               sim::pack(expect[i]).hex());
  const std::uint16_t invalid = hls::disparity::invalid_code(cfg);
  if (!f.shift.empty()) count_known_shifts(f, ref, invalid, sum);
  const sim::Bits cfg_word = sim::words::pack_word(
      sim::disparity_cfg::port_config<Params::kNumDisp>(cfg), sim::disparity_cfg::kConfigFields);
  write_files<kPpc>(dir, f, config_json<Params>(f, invalid), cfg_word, l, r, expect, ref);
  sum.width = w;
  sum.height = h;
  sum.frames = static_cast<int>(f.left.size());
  sum.build = f.build;
  sum.ppc = kPpc;
  sum.window = N;
  sum.dmin = cfg.dmin;
  sum.dmax = cfg.dmin + Params::kNumDisp - 1;
  sum.mode = disparity::mode_name(f.mode);
  sum.beats = got.size();
  return sum;
}

/// Runs `f` at its P on a pipeline build.
template <template <int> class Build>
DisparitySetSummary run_build(const DisparityFrame& f, const std::filesystem::path& dir) {
  switch (f.ppc) {
    case 1:
      return run<typename Build<1>::disparity>(f, dir);
    case 2:
      return run<typename Build<2>::disparity>(f, dir);
    case 4:
      return run<typename Build<4>::disparity>(f, dir);
    default:
      throw std::invalid_argument("vectors disparity: P = " + std::to_string(f.ppc) +
                                  "; the builds take 1, 2 or 4 pixels a beat");
  }
}

/// The window a build is made with (0: the vectors build's 5 or 9).
int build_window(const std::string& build) {
  if (build == "small") return hls::pipeline::SmallPipeline<1>::kWindow;
  if (build == "tsukuba") return hls::pipeline::TsukubaPipeline<1>::kWindow;
  if (build == "thesis") return hls::pipeline::ThesisPipeline<1>::kWindow;
  return 0;
}

}  // namespace

const std::vector<std::string>& disparity_presets() {
  static const std::vector<std::string> kNames = {"texture", "tsukuba", "tsukuba_edge"};
  return kNames;
}

DisparityFrame disparity_preset(const std::string& name, const std::filesystem::path& data_dir) {
  if (name == "texture") return synthetic();
  if (name == "tsukuba") return tsukuba(data_dir);
  if (name == "tsukuba_edge") return tsukuba_edge(data_dir);
  throw std::invalid_argument("vectors disparity: no preset '" + name +
                              "' (there are: texture, tsukuba, tsukuba_edge)");
}

const std::vector<std::string>& disparity_builds() {
  static const std::vector<std::string> kNames = {"vectors", "small", "tsukuba", "thesis"};
  return kNames;
}

DisparityFrame disparity_frames(const UserPair& u) {
  if (u.left.empty() || u.left.size() != u.right.size())
    throw std::invalid_argument("vectors disparity: give as many --right images as --left (" +
                                std::to_string(u.left.size()) + " and " +
                                std::to_string(u.right.size()) + ")");
  DisparityFrame f;
  cv::Rect roi;
  cv::Size first;
  for (std::size_t i = 0; i < u.left.size(); ++i) {
    const cv::Mat l = host::io::read_grey_image(u.left[i]);
    const cv::Mat r = host::io::read_grey_image(u.right[i]);
    const auto size_of = [](const cv::Mat& m) {
      return std::to_string(m.cols) + "x" + std::to_string(m.rows);
    };
    if (i == 0) first = l.size();
    // With a crop, each pair needs only to hold it; without, the pairs are the frame.
    if (l.size() != r.size() || (u.roi.area() == 0 && l.size() != first))
      throw std::invalid_argument(
          "vectors disparity: " + u.left[i].string() + " is " + size_of(l) + ", " +
          u.right[i].string() + " " + size_of(r) +
          (i > 0 ? ", the first pair " + size_of(cv::Mat(first, CV_8UC1)) : std::string()) +
          ": the pairs have one size (or give --roi X Y W H)");
    if (i == 0) roi = u.roi.area() > 0 ? u.roi : cv::Rect(0, 0, l.cols, l.rows);
    if ((roi & cv::Rect(0, 0, l.cols, l.rows)) != roi)
      throw std::invalid_argument("vectors disparity: --roi " + std::to_string(roi.x) + " " +
                                  std::to_string(roi.y) + " " + std::to_string(roi.width) + " " +
                                  std::to_string(roi.height) + " is not inside the " + size_of(l) +
                                  " pair " + u.left[i].filename().string());
    f.left.push_back(l(roi).clone());
    f.right.push_back(r(roi).clone());
  }
  const int built = build_window(u.build);
  if (built != 0 && u.window != built)
    throw std::invalid_argument("vectors disparity: the " + u.build + " build matches with N = " +
                                std::to_string(built) + "; give --window " + std::to_string(built));
  f.window = u.window;
  f.mode = u.mode;
  f.build = u.build;
  f.ppc = u.ppc;
  f.cfg = disparity::mode_config(f.mode, roi.width, roi.height, u.dmin);
  f.cfg.edge_candidates = u.edge_candidates;
  std::ostringstream d;
  d << "scw disparity stage (" << u.build << " build, P = " << u.ppc << "), "
    << disparity::mode_name(f.mode) << " mode, N = " << f.window << ", dmin " << u.dmin
    << ", edge_candidates " << u.edge_candidates << ": " << f.left.size()
    << " pair(s) back to back,";
  for (std::size_t i = 0; i < u.left.size(); ++i)
    d << " " << u.left[i].filename().string() << " / " << u.right[i].filename().string();
  d << " (left / right), grey by cv::imread IMREAD_GRAYSCALE, crop x " << roi.x << " y " << roi.y
    << " " << roi.width << "x" << roi.height;
  f.description = d.str();
  return f;
}

DisparitySetSummary write_disparity_set(const DisparityFrame& f, const std::filesystem::path& dir) {
  if (f.left.empty() || f.left.size() != f.right.size())
    throw std::invalid_argument("vectors disparity: no frame, or unpaired frames");
  if (f.build == "small") return run_build<hls::pipeline::SmallPipeline>(f, dir);
  if (f.build == "tsukuba") return run_build<hls::pipeline::TsukubaPipeline>(f, dir);
  if (f.build == "thesis") return run_build<hls::pipeline::ThesisPipeline>(f, dir);
  if (f.build != "vectors")
    throw std::invalid_argument("vectors disparity: no build '" + f.build +
                                "' (vectors, small, tsukuba, thesis)");
  if (f.ppc != DisparityVecParams<5>::kPpc)
    throw std::invalid_argument(
        "vectors disparity: the vectors build is P = 2; give --ppc 2 or "
        "another --config");
  if (f.window == 5) return run<DisparityVecParams<5>>(f, dir);
  if (f.window == 9) return run<DisparityVecParams<9>>(f, dir);
  throw std::invalid_argument("vectors disparity: window " + std::to_string(f.window) +
                              "; the vectors build is made for N = 5 or 9");
}

}  // namespace scw::vectors
