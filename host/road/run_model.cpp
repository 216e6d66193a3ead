// SPDX-License-Identifier: Apache-2.0
// RoadFilter: whole maps through the road kernel.
#include "host/road/run_model.hpp"

#include <stdexcept>

#include <opencv2/imgproc.hpp>
#include <string>

namespace scw::road {

cv::Mat RoadFilter::filter(const cv::Mat& q4) {
  if (q4.empty() || (q4.type() != CV_16UC1 && q4.type() != CV_16SC1))
    throw std::invalid_argument(
        "road: the disparity map must be one 16-bit channel of disparity x 16 (CV_16U or "
        "CV_16S)");
  if (q4.cols > HostParams::kMaxWidthPx || q4.rows > HostParams::kMaxHeight)
    throw std::invalid_argument("road: the map is " + std::to_string(q4.cols) + " x " +
                                std::to_string(q4.rows) + "; the host's build takes up to " +
                                std::to_string(HostParams::kMaxWidthPx) + " x " +
                                std::to_string(HostParams::kMaxHeight));
  cv::Mat out(q4.size(), q4.type());
  HostParams::in_beat in;
  for (int v = 0; v < q4.rows; ++v) {
    const auto* src = q4.ptr<std::uint16_t>(v);
    auto* dst = out.ptr<std::uint16_t>(v);
    for (int u = 0; u < q4.cols; ++u) {
      in.px[0] = src[u];
      in.sof = v == 0 && u == 0;
      in.eol = u + 1 == q4.cols;
      if (k_.needs_fit(in)) k_.fit();
      if (in.sof) used_ = k_.line();
      dst[u] = k_.step(in).px[0];
    }
  }
  return out;
}

cv::Mat removed_mask(const cv::Mat& before, const cv::Mat& after) {
  if (before.size() != after.size() || before.depth() != after.depth() ||
      (before.type() != CV_16UC1 && before.type() != CV_16SC1))
    throw std::invalid_argument("road: removed_mask needs two 16-bit maps of one size");
  // The bit patterns as int16: invalid codes are 0 or negative.
  const cv::Mat b(before.size(), CV_16SC1, before.data, before.step);
  const cv::Mat a(after.size(), CV_16SC1, after.data, after.step);
  return (b > 0) & (a == 0);
}

cv::Mat road_picture(const cv::Mat& left_grey, const cv::Mat& mask) {
  cv::Mat bgr;
  cv::cvtColor(left_grey, bgr, cv::COLOR_GRAY2BGR);
  cv::Mat tint(bgr.size(), bgr.type(), cv::Scalar(0, 200, 0));
  cv::Mat mixed;
  cv::addWeighted(bgr, 0.5, tint, 0.5, 0.0, mixed);
  mixed.copyTo(bgr, mask);
  return bgr;
}

hls::road::Line RoadFilter::next_road() const {
  auto copy = k_;  // the fit the next sof will run
  copy.fit();
  return copy.line();
}

}  // namespace scw::road
