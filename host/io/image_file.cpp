// SPDX-License-Identifier: Apache-2.0
// Reading and writing image files (host/io/image_file.hpp).
#include "host/io/image_file.hpp"

#include <stdexcept>
#include <string>

#include <opencv2/imgcodecs.hpp>

namespace scw::host::io {

cv::Mat read_grey_image(const std::filesystem::path& file) {
  // IMREAD_ANYDEPTH keeps a 16-bit or float file's depth so it can be refused below; for 8-bit
  // files the grey levels are IMREAD_GRAYSCALE's (the flag only skips the conversion to 8 bits).
  cv::Mat img;
  std::string why;
  try {
    img = cv::imread(file.string(), cv::IMREAD_GRAYSCALE | cv::IMREAD_ANYDEPTH);
  } catch (const cv::Exception& e) {
    why = " (" + e.err + ")";
  }
  if (img.empty())
    throw std::runtime_error("cannot read '" + file.string() + "' as an image" + why +
                             "; give a PNG, JPEG, PGM, PPM, ... file");
  if (img.depth() != CV_8U)
    throw std::runtime_error("'" + file.string() + "' has " + std::to_string(img.elemSize1() * 8) +
                             "-bit samples; scw takes 8-bit images (convert it to 8 bits first)");
  return img;
}

cv::Mat read_disparity_q4(const std::filesystem::path& file) {
  cv::Mat img;
  try {
    img = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    img.release();  // reported below with the rest
  }
  if (img.empty() || img.channels() != 1 || img.depth() != CV_16U)
    throw std::runtime_error("'" + file.string() +
                             "' is not a 16-bit one-channel image; give the Q11.4 map "
                             "`scw disparity --out16` writes");
  return img;
}

void write_image(const std::filesystem::path& file, const cv::Mat& image) {
  bool ok = false;
  std::string why;
  try {
    ok = cv::imwrite(file.string(), image);
  } catch (const cv::Exception& e) {
    why = ": " + e.err;
  }
  if (!ok) throw std::runtime_error("cannot write '" + file.string() + "'" + why);
}

}  // namespace scw::host::io
