// SPDX-License-Identifier: Apache-2.0
// Writing image files (host/io/image_file.hpp).
#include "host/io/image_file.hpp"

#include <stdexcept>
#include <string>

#include <opencv2/imgcodecs.hpp>

namespace scw::host::io {

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
