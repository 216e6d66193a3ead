// SPDX-License-Identifier: Apache-2.0
#include "host/io/tsukuba.hpp"

#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "host/io/image_file.hpp"

namespace scw::host::io {
namespace {

// Checked before OpenCV is asked, which would print a warning of its own about the path.
std::filesystem::path existing(const std::filesystem::path& dir, const char* name) {
  const auto file = dir / name;
  if (!std::filesystem::exists(file))
    throw std::runtime_error("no '" + file.string() +
                             "': the Tsukuba pair and its truth are bundled in data/tsukuba (a "
                             "command that uses them takes another folder with --data-dir)");
  return file;
}

}  // namespace

TsukubaPair read_tsukuba_pair(const std::filesystem::path& dir) {
  return {read_grey_image(existing(dir, "scene1.row3.col3.ppm")),
          read_grey_image(existing(dir, "scene1.row3.col4.ppm"))};
}

cv::Mat read_tsukuba_truth(const std::filesystem::path& dir, int type) {
  const auto file = existing(dir, "truedisp.row3.col3.pgm");
  cv::Mat truth;
  try {
    truth = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    truth.release();  // reported below with the rest
  }
  if (truth.type() != CV_8UC1 || truth.cols != 384 || truth.rows != 288)
    throw std::runtime_error("'" + file.string() +
                             "' is not the 8-bit 384x288 Tsukuba ground truth");
  if (type == CV_8UC1) return truth;
  cv::Mat out;
  truth.convertTo(out, type);
  return out;
}

}  // namespace scw::host::io
