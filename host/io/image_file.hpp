// SPDX-License-Identifier: Apache-2.0
// Reading and writing image files, with the one error every command gives when it cannot.
#pragma once

#include <filesystem>

#include <opencv2/core.hpp>

namespace scw::host::io {

/// Reads an 8-bit image as grey exactly as `cv::imread(file, cv::IMREAD_GRAYSCALE)` does (the
/// codec converts colour), so a pair given to scw and to cv::StereoBM holds the same grey levels.
/// The one reader of every command's input images. Throws std::runtime_error naming the file when
/// it cannot be read as an image, and when its samples are not 8-bit (a 16-bit or float file,
/// which IMREAD_GRAYSCALE would silently scale to 8 bits).
cv::Mat read_grey_image(const std::filesystem::path& file);

/// Reads a 16-bit one-channel map of Q11.4 disparities (disparity x 16, what `scw disparity
/// --out16` writes) bit for bit, as the labelling stage receives it. Throws std::runtime_error
/// naming the file when it cannot be read or is not 16-bit one-channel (an 8-bit picture).
cv::Mat read_disparity_q4(const std::filesystem::path& file);

/// cv::imwrite with the format from the extension; throws std::runtime_error naming the file
/// (and OpenCV's reason, e.g. an extension it has no writer for) when it cannot be written.
void write_image(const std::filesystem::path& file, const cv::Mat& image);

}  // namespace scw::host::io
