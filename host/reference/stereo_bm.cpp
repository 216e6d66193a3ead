// SPDX-License-Identifier: Apache-2.0
// cv::StereoBM with the options of a disparity configuration.
#include "host/reference/stereo_bm.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

namespace scw::reference {

std::vector<std::uint16_t> stereo_bm(const std::uint8_t* left, const std::uint8_t* right, int width,
                                     int height, int window_n, int num_disp,
                                     const hls::disparity::DisparityConfig& cfg, bool optimized) {
  const bool was = cv::useOptimized();
  cv::setUseOptimized(optimized);
  auto bm = cv::StereoBM::create(num_disp, window_n);
  bm->setPreFilterType(cv::StereoBM::PREFILTER_XSOBEL);
  bm->setPreFilterCap(cfg.prefilter_cap);
  bm->setMinDisparity(cfg.dmin);
  bm->setTextureThreshold(cfg.texture_threshold);
  bm->setUniquenessRatio(cfg.uniqueness_ratio);
  bm->setSpeckleWindowSize(0);
  bm->setSpeckleRange(0);
  bm->setDisp12MaxDiff(-1);
  const cv::Mat lm(height, width, CV_8UC1, const_cast<std::uint8_t*>(left));
  const cv::Mat rm(height, width, CV_8UC1, const_cast<std::uint8_t*>(right));
  cv::Mat disp;
  bm->compute(lm, rm, disp);
  cv::setUseOptimized(was);
  std::vector<std::uint16_t> out(disp.total());
  for (int y = 0; y < disp.rows; ++y)
    for (int x = 0; x < disp.cols; ++x)
      out[static_cast<std::size_t>(y) * disp.cols + x] =
          static_cast<std::uint16_t>(disp.at<std::int16_t>(y, x));
  return out;
}

}  // namespace scw::reference
