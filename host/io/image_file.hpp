// SPDX-License-Identifier: Apache-2.0
// Writing a picture or an image file, with the one error every command gives when it cannot.
#pragma once

#include <filesystem>

#include <opencv2/core.hpp>

namespace scw::host::io {

/// cv::imwrite with the format from the extension; throws std::runtime_error naming the file
/// (and OpenCV's reason, e.g. an extension it has no writer for) when it cannot be written.
void write_image(const std::filesystem::path& file, const cv::Mat& image);

}  // namespace scw::host::io
