// SPDX-License-Identifier: Apache-2.0
// `scw vectors disparity`: writes a golden vector set of the disparity stage (left and right
// pixels in, Q11.4 disparities out), produced by the C++ model and checked against the direct
// reference. The RTL replay comes with the RTL.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "host/cli/commands.hpp"
#include "host/disparity/run_model.hpp"
#include "host/io/image_file.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/frame_beats.hpp"
#include "sim/pack.hpp"

namespace scw::cli {
namespace {

using hls::disparity::DisparityConfig;

// The golden-vector build of the stage: P = 2, frames up to 128 px wide, 16 candidates.
constexpr int kPpc = 2;
constexpr int kMaxWidthPx = 128;
constexpr int kNumDisp = 16;
constexpr int kMaxHeight = 64;  // the RTL's row counters (a replay builds scw_disparity so)
template <int N>
using VecParams = hls::disparity::DisparityParams<kPpc, kMaxWidthPx, N, kNumDisp, kMaxHeight>;

struct Options {
  std::string preset;
  std::string out;
  std::string data_dir = "data/tsukuba";
};

/// One pair to match and the configuration (the window is run<N>'s).
struct Frame {
  cv::Mat left, right;  // 8UC1, same size
  disparity::Mode mode = disparity::Mode::thesis;
  DisparityConfig cfg;
  std::string description;
  cv::Mat shift;  // synthetic: the true disparity of every left pixel (8UC1), else empty
};

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
Frame tsukuba(const Options& o) {
  const std::filesystem::path dir(o.data_dir);
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

template <typename Beat>
std::vector<sim::Bits> packed(const std::vector<Beat>& beats) {
  std::vector<sim::Bits> v;
  v.reserve(beats.size());
  for (const auto& b : beats) v.push_back(sim::pack(b));
  return v;
}

template <int N>
void run(const Options& o, const Frame& f) {
  using Params = VecParams<N>;
  const int w = f.left.cols, h = f.left.rows;
  if (w > kMaxWidthPx || w % kPpc != 0 || w < N || h < N || h > kMaxHeight)
    throw std::logic_error("vectors disparity: frame does not fit the vector configuration");
  const DisparityConfig& cfg = f.cfg;
  const auto l = sim::frame_beats<kPpc>(f.left.ptr<std::uint8_t>(), w, h);
  const auto r = sim::frame_beats<kPpc>(f.right.ptr<std::uint8_t>(), w, h);
  const auto ref = reference::disparity_reference(
      f.left.ptr<std::uint8_t>(), f.right.ptr<std::uint8_t>(), w, h, N, kNumDisp, cfg);
  const auto expect = sim::frame_beats_of<typename Params::disp_beat>(ref.data(), w, h);
  std::int64_t cycles = 0;
  const auto got = disparity::run_disparity_model<Params>(l, r, cfg, &cycles);
  for (std::size_t i = 0; i < expect.size(); ++i)
    if (got[i] != expect[i])
      throw std::runtime_error("vectors disparity: the C++ model's beat " + std::to_string(i) +
                               " (row " + std::to_string(i / (w / kPpc)) + ") is " +
                               sim::pack(got[i]).hex() + ", the reference gives " +
                               sim::pack(expect[i]).hex());
  std::cout << "C++ model: " << got.size() << " beats equal the direct reference (" << cycles
            << " cycles)\n";
  const std::uint16_t invalid = hls::disparity::invalid_code(cfg);
  if (!f.shift.empty()) {
    long valid = 0, right = 0;
    for (int i = 0; i < w * h; ++i) {
      if (ref[i] == invalid) continue;
      ++valid;
      right += ref[i] == f.shift.data[i] * 16 ? 1 : 0;
    }
    std::cout << "known shifts: " << right << " of " << valid
              << " computed pixels find their true disparity\n";
  }

  const nlohmann::json config = {{"width", w},
                                 {"height", h},
                                 {"ppc", kPpc},
                                 {"max_width_px", kMaxWidthPx},
                                 {"max_height", kMaxHeight},
                                 {"window", N},
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
                                 {"invalid_code", invalid}};
  auto disp_layout = vectors::pixel_beat_layout(kPpc, 16);
  disp_layout["signed"] = true;
  disp_layout["frac_bits"] = 4;
  vectors::VectorWriter vw(o.out, "disparity", config, f.description);
  vw.add_image("left.png", "input", f.left);
  vw.add_image("right.png", "input", f.right);
  vw.add_hex("left.hex", "input", packed(l), vectors::pixel_beat_layout(kPpc, 8));
  vw.add_hex("right.hex", "input", packed(r), vectors::pixel_beat_layout(kPpc, 8));
  vw.add_hex("expected.hex", "expected", packed(expect), disp_layout);
  cv::Mat out_img(h, w, CV_16UC1);
  std::memcpy(out_img.data, ref.data(), ref.size() * sizeof(std::uint16_t));
  vw.add_image("expected.png", "expected", out_img);
  vw.finish();
  std::cout << "wrote " << o.out << "/ (" << w << "x" << h << ", P = " << kPpc << ", N = " << N
            << ", d " << cfg.dmin << ".." << cfg.dmin + kNumDisp - 1 << ", "
            << disparity::mode_name(f.mode) << " mode)\n";
}

}  // namespace

void add_vectors_disparity_command(CLI::App& vectors) {
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "disparity", "Write a disparity golden vector set (left + right in, disparities out)");
  cmd->add_option("--preset", o->preset,
                  "texture (64x24 random texture with known shifts, N = 5, d 0..15, thesis "
                  "mode) or tsukuba (96x48 crop of the bundled pair, N = 9, d 0..15, opencv mode)")
      ->required()
      ->check(CLI::IsMember({"texture", "tsukuba"}));
  cmd->add_option("--out", o->out, "Vector set directory to write")->required();
  cmd->add_option("--data-dir", o->data_dir, "Folder with the Tsukuba PPMs");
  cmd->callback([o] {
    if (o->preset == "texture")
      run<5>(*o, synthetic());
    else
      run<9>(*o, tsukuba(*o));
  });
}

}  // namespace scw::cli
