// SPDX-License-Identifier: Apache-2.0
// The bundled Tsukuba pair (data/tsukuba: Middlebury's scene1, row 3, columns 3 and 4) and its
// ground truth, by name in one place for the tests, tools, benches and vector presets that use it.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>

namespace scw::host::io {

struct TsukubaPair {
  cv::Mat left, right;  // 384 x 288, CV_8UC1, read as read_grey_image() reads
};

/// scene1.row3.col3.ppm (left) and scene1.row3.col4.ppm (right) from `dir`. Throws
/// std::runtime_error naming the file that cannot be read.
TsukubaPair read_tsukuba_pair(const std::filesystem::path& dir);

/// truedisp.row3.col3.pgm from `dir`, converted to `type` (CV_8UC1 as stored, CV_16UC1 for the
/// labelling stage, CV_16SC1 for the disparity maps): Middlebury stores disparity x 16 in 8 bits,
/// which is already the stages' Q11.4; 0 marks the unknown border. Throws std::runtime_error
/// naming the file when it cannot be read or is not the 8-bit one-channel 384 x 288 truth.
cv::Mat read_tsukuba_truth(const std::filesystem::path& dir, int type = CV_8UC1);

}  // namespace scw::host::io
