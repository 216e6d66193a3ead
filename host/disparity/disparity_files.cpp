// SPDX-License-Identifier: Apache-2.0
// run_disparity_files() and the pictures of a disparity map (host/disparity/disparity_files.hpp).
#include "host/disparity/disparity_files.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "hls/disparity/disparity_params.hpp"
#include "host/io/image_file.hpp"

namespace scw::disparity {
namespace {

void write(const std::string& path, const cv::Mat& m) {
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  host::io::write_image(p, m);
}

}  // namespace

cv::Mat disparity_8bit(const cv::Mat& d16, std::int16_t invalid) {
  cv::Mat out(d16.size(), CV_8UC1);
  for (int y = 0; y < d16.rows; ++y)
    for (int x = 0; x < d16.cols; ++x) {
      const std::int16_t v = d16.at<std::int16_t>(y, x);
      out.at<std::uint8_t>(y, x) =
          v == invalid ? 0 : static_cast<std::uint8_t>(std::clamp(v >> 4, 0, 255));
    }
  return out;
}

cv::Mat disparity_colour(const cv::Mat& d16, std::int16_t invalid, int dmin, int dmax) {
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

FilesRun run_disparity_files(const FilesOptions& o, std::ostream& log) {
  const cv::Mat left = host::io::read_grey_image(o.left);
  const cv::Mat right = host::io::read_grey_image(o.right);
  if (left.size() != right.size())
    throw std::runtime_error("the left image '" + o.left + "' is " + std::to_string(left.cols) +
                             " x " + std::to_string(left.rows) + " px but the right image '" +
                             o.right + "' is " + std::to_string(right.cols) + " x " +
                             std::to_string(right.rows) + " px; give a rectified pair of one size");
  const auto mode = mode_from_name(o.mode);
  auto cfg = mode_config(mode, left.cols, left.rows, o.min_disp);
  if (o.prefilter_cap >= 0) cfg.prefilter_cap = o.prefilter_cap;
  if (o.texture >= 0) cfg.texture_threshold = o.texture;
  if (o.uniqueness >= 0) cfg.uniqueness_ratio = o.uniqueness;
  if (o.sad_limit >= 0) cfg.sad_limit = o.sad_limit;
  cfg.edge_candidates = o.edge_candidates;

  log << "disparity: " << left.cols << " x " << left.rows << " px, window " << o.window << ", d "
      << o.min_disp << " .. " << o.max_disp << ", " << o.mode << " mode (prefilter "
      << (cfg.prefilter ? "cap " + std::to_string(cfg.prefilter_cap) : std::string("off"))
      << ", texture " << cfg.texture_threshold << ", uniqueness " << cfg.uniqueness_ratio
      << ", SAD limit " << cfg.sad_limit << ", sub-pixel " << (cfg.subpixel ? "on" : "off")
      << (cfg.edge_candidates > 0
              ? ", left edge from " + std::to_string(cfg.edge_candidates) + " candidates"
              : std::string())
      << ")\n";
  FilesRun r;
  r.d16 = disparity_image(left, right, o.window, o.min_disp, o.max_disp, cfg);
  r.invalid = static_cast<std::int16_t>(hls::disparity::invalid_code(cfg));
  for (int y = 0; y < r.d16.rows; ++y)
    for (int x = 0; x < r.d16.cols; ++x)
      r.invalid_pixels += r.d16.at<std::int16_t>(y, x) == r.invalid;

  write(o.out, disparity_8bit(r.d16, r.invalid));
  r.written.push_back(o.out);
  if (!o.out16.empty()) {
    // The int16 bit patterns as uint16 (convertTo would saturate negatives to 0).
    cv::Mat u16(r.d16.size(), CV_16UC1);
    std::memcpy(u16.data, r.d16.data, r.d16.total() * r.d16.elemSize());
    write(o.out16, u16);
    r.written.push_back(o.out16);
  }
  if (!o.color.empty()) {
    write(o.color, disparity_colour(r.d16, r.invalid, o.min_disp, o.max_disp));
    r.written.push_back(o.color);
  }
  return r;
}

}  // namespace scw::disparity
