// SPDX-License-Identifier: Apache-2.0
// `scw disparity`: SAD block-matching disparity of a rectified stereo pair through the streaming
// C++ model of the disparity stage; writes an 8-bit map and optionally the 16-bit x16 values and
// a colour picture.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "hls/disparity/disparity_params.hpp"
#include "host/cli/commands.hpp"
#include "host/io/image_file.hpp"
#include "host/disparity/run_model.hpp"

namespace scw::cli {
namespace {

struct Options {
  std::string left, right;
  int window = 0;
  int min_disp = 0, max_disp = 0;
  std::string mode = disparity::mode_name(disparity::kDefaultMode);
  int prefilter_cap = -1, texture = -1, uniqueness = -1, sad_limit = -1;  // -1: the mode's
  std::string out, out16, color;
};

/// 0 = invalid, else the integer disparity value >> 4 saturated to 0 .. 255 (a valid d < 1
/// also reads 0: docs/disparity.md).
cv::Mat to_8bit(const cv::Mat& d16, std::int16_t invalid) {
  cv::Mat out(d16.size(), CV_8UC1);
  for (int y = 0; y < d16.rows; ++y)
    for (int x = 0; x < d16.cols; ++x) {
      const std::int16_t v = d16.at<std::int16_t>(y, x);
      out.at<std::uint8_t>(y, x) =
          v == invalid ? 0 : static_cast<std::uint8_t>(std::clamp(v >> 4, 0, 255));
    }
  return out;
}

/// cv::COLORMAP_JET over dmin .. dmax (x16 values, so sub-pixel steps show), invalid black.
cv::Mat to_colour(const cv::Mat& d16, std::int16_t invalid, int dmin, int dmax) {
  cv::Mat grey(d16.size(), CV_8UC1), mask(d16.size(), CV_8UC1);
  const int lo = dmin * 16, span = std::max(1, (dmax - dmin) * 16);
  for (int y = 0; y < d16.rows; ++y)
    for (int x = 0; x < d16.cols; ++x) {
      const int v = d16.at<std::int16_t>(y, x);
      mask.at<std::uint8_t>(y, x) = v == invalid ? 255 : 0;
      grey.at<std::uint8_t>(y, x) =
          static_cast<std::uint8_t>(std::clamp((v - lo) * 255 / span, 0, 255));
    }
  cv::Mat colour;
  cv::applyColorMap(grey, colour, cv::COLORMAP_JET);
  colour.setTo(cv::Scalar(0, 0, 0), mask);
  return colour;
}

void write(const std::string& path, const cv::Mat& m) {
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  host::io::write_image(p, m);
}

void run(const Options& o) {
  const cv::Mat left = host::io::read_grey_image(o.left);
  const cv::Mat right = host::io::read_grey_image(o.right);
  if (left.size() != right.size())
    throw std::runtime_error("the left image '" + o.left + "' is " + std::to_string(left.cols) +
                             " x " + std::to_string(left.rows) + " px but the right image '" +
                             o.right + "' is " + std::to_string(right.cols) + " x " +
                             std::to_string(right.rows) + " px; give a rectified pair of one size");
  const auto mode = disparity::mode_from_name(o.mode);
  auto cfg = disparity::mode_config(mode, left.cols, left.rows, o.min_disp);
  if (o.prefilter_cap >= 0) cfg.prefilter_cap = o.prefilter_cap;
  if (o.texture >= 0) cfg.texture_threshold = o.texture;
  if (o.uniqueness >= 0) cfg.uniqueness_ratio = o.uniqueness;
  if (o.sad_limit >= 0) cfg.sad_limit = o.sad_limit;

  std::cerr << "disparity: " << left.cols << " x " << left.rows << " px, window " << o.window
            << ", d " << o.min_disp << " .. " << o.max_disp << ", " << o.mode << " mode (prefilter "
            << (cfg.prefilter ? "cap " + std::to_string(cfg.prefilter_cap) : std::string("off"))
            << ", texture " << cfg.texture_threshold << ", uniqueness " << cfg.uniqueness_ratio
            << ", SAD limit " << cfg.sad_limit << ", sub-pixel " << (cfg.subpixel ? "on" : "off")
            << ")\n";
  const cv::Mat d16 =
      disparity::disparity_image(left, right, o.window, o.min_disp, o.max_disp, cfg);
  const auto invalid = static_cast<std::int16_t>(hls::disparity::invalid_code(cfg));
  long held = 0;  // pixels holding the invalid code (in thesis mode with min 0 also d = 0)
  for (int y = 0; y < d16.rows; ++y)
    for (int x = 0; x < d16.cols; ++x) held += d16.at<std::int16_t>(y, x) == invalid;

  write(o.out, to_8bit(d16, invalid));
  std::string wrote = o.out;
  if (!o.out16.empty()) {
    // The int16 bit patterns as uint16 (convertTo would saturate negatives to 0).
    cv::Mat u16(d16.size(), CV_16UC1);
    std::memcpy(u16.data, d16.data, d16.total() * d16.elemSize());
    write(o.out16, u16);
    wrote += ", " + o.out16;
  }
  if (!o.color.empty()) {
    write(o.color, to_colour(d16, invalid, o.min_disp, o.max_disp));
    wrote += ", " + o.color;
  }
  std::cout << "pixels holding the invalid code " << invalid << ": " << held << " of "
            << d16.total() << "\n"
            << "wrote " << wrote << "\n";
}

}  // namespace

void add_disparity_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "disparity",
      "SAD block-matching disparity of a rectified pair with the disparity stage's streaming "
      "model (P = 1)");
  std::string windows;
  for (const int n : disparity::kHostWindows)
    windows += (windows.empty() ? "" : ", ") + std::to_string(n);
  cmd->add_option("--left", o->left, "Rectified left image (colour is converted to grey)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--right", o->right, "Rectified right image")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--window", o->window, "SAD window N (N x N), built: " + windows)->required();
  cmd->add_option("--min-disp", o->min_disp, "Smallest candidate disparity (>= 0)")->required();
  cmd->add_option("--max-disp", o->max_disp,
                  "Largest candidate; at most " + std::to_string(disparity::kHostMaxNumDisp) +
                      " candidates (max - min + 1)")
      ->required();
  cmd->add_option("--mode", o->mode,
                  "thesis: plain SAD on raw pixels, nothing rejected, integer d, invalid 0; "
                  "opencv: cv::StereoBM's defaults (x-Sobel prefilter cap 31, texture 10, "
                  "uniqueness 15, sub-pixel, invalid (min-1)*16). scw run and scw sim share the "
                  "default; docs/disparity.md has the measurements that chose it")
      ->capture_default_str()
      ->check(CLI::IsMember({"thesis", "opencv"}));
  cmd->add_option("--prefilter-cap", o->prefilter_cap,
                  "x-Sobel cap (opencv mode's prefilter; also the texture measure's offset)")
      ->check(CLI::Range(1, 63));
  cmd->add_option("--texture", o->texture, "Texture threshold, 0 = off (overrides the mode)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--uniqueness", o->uniqueness,
                  "Uniqueness ratio in %, 0 = off (overrides the mode)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--sad-limit", o->sad_limit, "Reject a minimum SAD above this, 0 = off")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--out", o->out,
                  "8-bit PNG: 0 = invalid, else the integer disparity (x16 value >> 4, at most "
                  "255); with --min-disp 0 a valid d below 1 also reads 0")
      ->required();
  cmd->add_option("--out16", o->out16,
                  "16-bit PNG of the stage's values, disparity x 16 as int16 bit patterns "
                  "(cv::StereoBM's CV_16S output in opencv mode; invalid 0 in thesis mode)");
  cmd->add_option("--color", o->color,
                  "Colour picture (COLORMAP_JET over min .. max disparity, invalid black)");
  cmd->callback([o] { run(*o); });
}

}  // namespace scw::cli
