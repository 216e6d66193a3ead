// SPDX-License-Identifier: Apache-2.0
// cv::StereoBM, the peer implementation the opencv mode is checked against, set up once.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/disparity/disparity_params.hpp"

namespace scw::reference {

/// cv::StereoBM on a row-major 8-bit grey pair with the options of a configuration: x-Sobel
/// prefilter with cfg.prefilter_cap, cfg.dmin, cfg.texture_threshold, cfg.uniqueness_ratio,
/// an N x N window and num_disp candidates (a multiple of 16); speckle filter and left-right
/// check off. `optimized` sets cv::setUseOptimized for the call (restored after). Returns the
/// CV_16S disparities (x16) as uint16 bit patterns.
std::vector<std::uint16_t> stereo_bm(const std::uint8_t* left, const std::uint8_t* right, int width,
                                     int height, int window_n, int num_disp,
                                     const hls::disparity::DisparityConfig& cfg, bool optimized);

}  // namespace scw::reference
