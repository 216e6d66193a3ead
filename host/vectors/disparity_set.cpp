// SPDX-License-Identifier: Apache-2.0
// Disparity stage golden vectors: the presets, the model run and its check against the direct
// reference, the files.
#include "host/vectors/disparity_set.hpp"

#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "host/io/image_file.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/words/pack.hpp"

namespace scw::vectors {
namespace {

using hls::disparity::DisparityConfig;
using Frame = DisparityFrame;

constexpr int kPpc = DisparityVecParams<5>::kPpc;
constexpr int kMaxWidthPx = DisparityVecParams<5>::kMaxWidthPx;
constexpr int kNumDisp = DisparityVecParams<5>::kNumDisp;
constexpr int kMaxHeight = DisparityVecParams<5>::kMaxHeight;

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
Frame synthetic() {
  constexpr int w = 64, h = 24;
  Frame f;
  f.right = cv::Mat(h, w, CV_8UC1);
  f.left = cv::Mat(h, w, CV_8UC1);
  f.shift = cv::Mat(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) f.right.at<std::uint8_t>(y, x) = hash_pixel(x, y);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int s = x < 24 ? 3 : (x < 44 ? 8 : 14);
      if (x >= 28 && x < 40 && y >= 6 && y < 18) s = 11;
      f.shift.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(s);
      f.left.at<std::uint8_t>(y, x) =
          x >= s ? f.right.at<std::uint8_t>(y, x - s) : hash_pixel(x + 1000, y + 1000);
    }
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
Frame tsukuba(const std::filesystem::path& dir) {
  const auto read = [&](const char* name) {
    const auto p = dir / name;
    if (!std::filesystem::exists(p))
      throw std::runtime_error("vectors disparity: no '" + p.string() +
                               "'; the tsukuba set needs data/tsukuba (give --data-dir)");
    return host::io::read_grey_image(p.string());
  };
  const cv::Rect roi(144, 112, 96, 48);
  Frame f;
  f.left = read("scene1.row3.col3.ppm")(roi).clone();
  f.right = read("scene1.row3.col4.ppm")(roi).clone();
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
Frame tsukuba_edge(const std::filesystem::path& dir) {
  Frame f = tsukuba(dir);
  f.cfg.edge_candidates = 4;
  f.description += "; the left edge band decided from 4 candidates (edge_candidates 4)";
  return f;
}

/// How many of the computed pixels find the frame's true disparity.
void count_known_shifts(const Frame& f, const std::vector<std::uint16_t>& ref,
                        std::uint16_t invalid, DisparitySetSummary& sum) {
  sum.known_shifts = true;
  for (int i = 0; i < f.left.cols * f.left.rows; ++i) {
    if (ref[i] == invalid) continue;
    ++sum.shifts_valid;
    sum.shifts_right += ref[i] == f.shift.data[i] * 16 ? 1 : 0;
  }
}

nlohmann::json config_json(const Frame& f, int window, std::uint16_t invalid) {
  const DisparityConfig& cfg = f.cfg;
  return {{"width", f.left.cols},
          {"height", f.left.rows},
          {"ppc", kPpc},
          {"max_width_px", kMaxWidthPx},
          {"max_height", kMaxHeight},
          {"window", window},
          {"num_disp", kNumDisp},
          {"mode", disparity::mode_name(f.mode)},
          {"dmin", cfg.dmin},
          {"dmax", cfg.dmin + kNumDisp - 1},
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

template <typename In, typename Out>
void write_files(const std::filesystem::path& dir, const Frame& f, const nlohmann::json& config,
                 const std::vector<In>& l, const std::vector<In>& r, const std::vector<Out>& expect,
                 const std::vector<std::uint16_t>& ref) {
  auto disp_layout = pixel_beat_layout(kPpc, 16);
  disp_layout["signed"] = true;
  disp_layout["frac_bits"] = 4;
  VectorWriter vw(dir, "disparity", config, f.description);
  vw.add_image("left.png", "input", f.left);
  vw.add_image("right.png", "input", f.right);
  vw.add_hex("left.hex", "input", sim::pack_all(l), pixel_beat_layout(kPpc, 8));
  vw.add_hex("right.hex", "input", sim::pack_all(r), pixel_beat_layout(kPpc, 8));
  vw.add_hex("expected.hex", "expected", sim::pack_all(expect), disp_layout);
  cv::Mat out_img(f.left.rows, f.left.cols, CV_16UC1);
  std::memcpy(out_img.data, ref.data(), ref.size() * sizeof(std::uint16_t));
  vw.add_image("expected.png", "expected", out_img);
  vw.finish();
}

template <int N>
DisparitySetSummary run(const Frame& f, const std::filesystem::path& dir) {
  using Params = DisparityVecParams<N>;
  const int w = f.left.cols, h = f.left.rows;
  if (w > kMaxWidthPx || w % kPpc != 0 || w < N || h < N || h > kMaxHeight)
    throw std::logic_error("vectors disparity: frame does not fit the vector configuration");
  const DisparityConfig& cfg = f.cfg;
  const auto l = sim::frame_beats<kPpc>(f.left.ptr<std::uint8_t>(), w, h);
  const auto r = sim::frame_beats<kPpc>(f.right.ptr<std::uint8_t>(), w, h);
  const auto ref = reference::disparity_reference(
      f.left.ptr<std::uint8_t>(), f.right.ptr<std::uint8_t>(), w, h, N, kNumDisp, cfg);
  const auto expect = sim::frame_beats_of<typename Params::disp_beat>(ref.data(), w, h);
  DisparitySetSummary sum;
  const auto got = disparity::run_disparity_model<Params>(l, r, cfg, &sum.cycles);
  for (std::size_t i = 0; i < expect.size(); ++i)
    if (got[i] != expect[i])
      throw std::runtime_error("vectors disparity: the C++ model's beat " + std::to_string(i) +
                               " (row " + std::to_string(i / (w / kPpc)) + ") is " +
                               sim::pack(got[i]).hex() + ", the reference gives " +
                               sim::pack(expect[i]).hex());
  const std::uint16_t invalid = hls::disparity::invalid_code(cfg);
  if (!f.shift.empty()) count_known_shifts(f, ref, invalid, sum);
  write_files(dir, f, config_json(f, N, invalid), l, r, expect, ref);
  sum.width = w;
  sum.height = h;
  sum.ppc = kPpc;
  sum.window = N;
  sum.dmin = cfg.dmin;
  sum.dmax = cfg.dmin + kNumDisp - 1;
  sum.mode = disparity::mode_name(f.mode);
  sum.beats = got.size();
  return sum;
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

DisparityFrame disparity_frame(const UserPair& u) {
  const cv::Mat l = host::io::read_grey_image(u.left), r = host::io::read_grey_image(u.right);
  if (l.size() != r.size())
    throw std::invalid_argument("vectors disparity: " + u.left.string() + " is " +
                                std::to_string(l.cols) + "x" + std::to_string(l.rows) + ", " +
                                u.right.string() + " " + std::to_string(r.cols) + "x" +
                                std::to_string(r.rows) + ": a pair has one size");
  const cv::Rect roi = u.roi.area() > 0 ? u.roi : cv::Rect(0, 0, l.cols, l.rows);
  if ((roi & cv::Rect(0, 0, l.cols, l.rows)) != roi)
    throw std::invalid_argument("vectors disparity: --roi " + std::to_string(roi.x) + " " +
                                std::to_string(roi.y) + " " + std::to_string(roi.width) + " " +
                                std::to_string(roi.height) + " is not inside the " +
                                std::to_string(l.cols) + "x" + std::to_string(l.rows) + " pair");
  if (roi.width > kMaxWidthPx || roi.height > kMaxHeight || roi.width % kPpc != 0)
    throw std::invalid_argument(
        "vectors disparity: a " + std::to_string(roi.width) + "x" + std::to_string(roi.height) +
        " frame does not fit the vector build (up to " + std::to_string(kMaxWidthPx) + "x" +
        std::to_string(kMaxHeight) + ", width a multiple of " + std::to_string(kPpc) +
        "): give --roi X Y W H");
  if (u.dmin < 0 || u.dmin + kNumDisp > roi.width)
    throw std::invalid_argument("vectors disparity: --dmin " + std::to_string(u.dmin) +
                                " leaves no column with all 16 candidates in a " +
                                std::to_string(roi.width) + "-px frame");
  Frame f;
  f.left = l(roi).clone();
  f.right = r(roi).clone();
  f.window = u.window;
  f.mode = u.mode;
  f.cfg = disparity::mode_config(f.mode, roi.width, roi.height, u.dmin);
  f.cfg.edge_candidates = u.edge_candidates;
  std::ostringstream d;
  d << "scw disparity stage, " << disparity::mode_name(f.mode) << " mode, N = " << f.window
    << ", d " << u.dmin << ".." << u.dmin + kNumDisp - 1 << ", edge_candidates "
    << u.edge_candidates << ": " << u.left.filename().string() << " (left) and "
    << u.right.filename().string() << " (right), grey by cv::imread IMREAD_GRAYSCALE, crop x "
    << roi.x << " y " << roi.y << " " << roi.width << "x" << roi.height;
  f.description = d.str();
  return f;
}

DisparitySetSummary write_disparity_set(const DisparityFrame& f, const std::filesystem::path& dir) {
  if (f.window == 5) return run<5>(f, dir);
  if (f.window == 9) return run<9>(f, dir);
  throw std::invalid_argument("vectors disparity: window " + std::to_string(f.window) +
                              "; the sets are built for N = 5 or 9");
}

}  // namespace scw::vectors
