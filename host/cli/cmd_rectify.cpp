// SPDX-License-Identifier: Apache-2.0
// `scw rectify`: rectifies a raw stereo pair with the fixed-point streaming model of the rectify
// stage, from an OpenCV stereo calibration, and writes both images and a side-by-side check.
#include <filesystem>
#include <iostream>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "host/cli/commands.hpp"
#include "host/io/image_file.hpp"
#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/run_model.hpp"

namespace scw::cli {
namespace {

struct RectifyOptions {
  std::string calib;
  std::string left;
  std::string right;
  std::string out_dir = "out/rectify";
  double alpha = rectify::kDefaultAlpha;
};

std::string size_text(cv::Size s) {
  return std::to_string(s.width) + " x " + std::to_string(s.height);
}

std::string rows_text(const rectify::RowWindow& w) {
  if (!w.any) return "no raw rows";
  const auto off = [](int d) { return d < 0 ? std::to_string(d) : "+" + std::to_string(d); };
  return "raw rows v" + off(w.dy_min) + " .. v" + off(w.dy_max);
}

/// Left | right in colour with a thin line every 32 rows across both, so corresponding rows
/// can be checked by eye.
cv::Mat side_by_side(const cv::Mat& left, const cv::Mat& right) {
  cv::Mat grey, out;
  cv::hconcat(left, right, grey);
  cv::cvtColor(grey, out, cv::COLOR_GRAY2BGR);
  for (int y = 16; y < out.rows; y += 32)
    cv::line(out, {0, y}, {out.cols - 1, y}, cv::Scalar(0, 200, 0), 1);
  cv::line(out, {left.cols, 0}, {left.cols, out.rows - 1}, cv::Scalar(0, 0, 255), 1);
  return out;
}

void run_rectify(const RectifyOptions& o) {
  const cv::Mat left = host::io::read_grey_image(o.left);
  const cv::Mat right = host::io::read_grey_image(o.right);
  const auto calib = rectify::load_stereo_calibration(o.calib, left.size());
  for (const auto& [path, img] : {std::pair{o.left, left}, std::pair{o.right, right}})
    if (img.size() != calib.image_size)
      throw std::runtime_error("image '" + path + "' is " + size_text(img.size()) +
                               " px, but the calibration '" + o.calib + "' is for " +
                               size_text(calib.image_size) +
                               " px images; rectify images from the calibrated cameras at "
                               "their calibrated size (or recalibrate)");

  std::cerr << "calibration " << o.calib << ": " << size_text(calib.image_size)
            << " px, stereoRectify alpha " << o.alpha << "\n";
  const auto rect = rectify::rectify_calibration(calib, o.alpha);
  std::cerr << "  rectified f = " << rect.focal_px() << " px, baseline = " << rect.baseline()
            << " (calibration units), principal point (" << rect.principal_point().x << ", "
            << rect.principal_point().y << ")\n";
  const auto map_l = rectify::quantise_map(rect.map1_x, rect.map1_y);
  const auto map_r = rectify::quantise_map(rect.map2_x, rect.map2_y);
  const auto win_l = rectify::row_window(map_l);
  const auto win_r = rectify::row_window(map_r);
  std::cerr << "  output row v: left map reads " << rows_text(win_l) << ", right map reads "
            << rows_text(win_r) << "\n";
  const auto plan = rectify::plan_for_stage({win_l, win_r}, rectify::kHostStageRows, o.calib);
  std::cout << "plan: lead " << plan.lead_rows << " rows, " << plan.rows_needed
            << " raw rows in flight (stage holds " << rectify::kHostStageRows << ")\n";

  std::cerr << "  rectifying left with the streaming model\n";
  const cv::Mat left_rect = rectify::rectify_image(left, map_l, plan.lead_rows);
  std::cerr << "  rectifying right with the streaming model\n";
  const cv::Mat right_rect = rectify::rectify_image(right, map_r, plan.lead_rows);

  const std::filesystem::path dir(o.out_dir);
  std::filesystem::create_directories(dir);
  const auto write = host::io::write_image;
  write(dir / "left_rect.png", left_rect);
  write(dir / "right_rect.png", right_rect);
  write(dir / "side_by_side.png", side_by_side(left_rect, right_rect));
  std::cout << "wrote " << (dir / "left_rect.png").string() << ", "
            << (dir / "right_rect.png").string() << ", " << (dir / "side_by_side.png").string()
            << "\n";
}

}  // namespace

void add_rectify_command(CLI::App& app) {
  auto o = std::make_shared<RectifyOptions>();
  auto* cmd = app.add_subcommand(
      "rectify", "Rectify a raw stereo pair with the rectify stage's fixed-point streaming model");
  cmd->add_option("--calib", o->calib,
                  "OpenCV FileStorage calibration (YAML/XML) with M1 D1 M2 D2 R T")
      ->required();
  cmd->add_option("--left", o->left, "Raw left image (colour is converted to grey)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--right", o->right, "Raw right image")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out-dir", o->out_dir,
                  "Where left_rect.png, right_rect.png and side_by_side.png go");
  cmd->add_option("--alpha", o->alpha,
                  "cv::stereoRectify alpha: -1 OpenCV default scaling, 0 valid pixels only, "
                  "1 all raw pixels")
      ->check(CLI::Range(-1.0, 1.0));
  cmd->callback([o] { run_rectify(*o); });
}

}  // namespace scw::cli
