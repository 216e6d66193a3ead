// SPDX-License-Identifier: Apache-2.0
// Pictures of the labelling stage's output: coloured label images and object overlays.
#include "host/labelling/picture.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace scw::labelling {

namespace {

/// Colours of objects first .. last, converted from HSV by OpenCV in one call (hue in degrees,
/// saturation and value in 0 .. 1 for float pixels).
std::vector<cv::Vec3b> label_colours(int first, int last) {
  cv::Mat3f px(1, std::max(0, last - first + 1));
  for (int k = first; k <= last; ++k) {
    // Hue steps of 1/phi of the circle never repeat and keep consecutive numbers far apart;
    // saturation and value alternate as well so numbers whose hues come close still differ.
    const double golden = 0.6180339887498949;
    const double h = std::fmod(static_cast<double>(k) * golden, 1.0) * 360.0;
    px(0, k - first) =
        cv::Vec3f(static_cast<float>(h), (k & 1) != 0 ? 0.9f : 0.6f, (k & 2) != 0 ? 1.0f : 0.8f);
  }
  std::vector<cv::Vec3b> out;
  if (px.empty()) return out;
  cv::cvtColor(px, px, cv::COLOR_HSV2BGR);
  const auto byte = [](float x) { return cv::saturate_cast<uchar>(std::lround(x * 255.0f)); };
  for (const cv::Vec3f& c : cv::Mat_<cv::Vec3f>(px))
    out.emplace_back(byte(c[0]), byte(c[1]), byte(c[2]));
  return out;
}

}  // namespace

cv::Vec3b label_colour(int k) { return label_colours(k, k).front(); }

cv::Mat colour_labels(const cv::Mat& labels16) {
  if (labels16.type() != CV_16UC1)
    throw std::invalid_argument("colour_labels needs a CV_16UC1 label image (0 = none)");
  double mx = 0;
  if (!labels16.empty()) cv::minMaxLoc(labels16, nullptr, &mx);
  // Every label's colour converted at once; 0 (no object) black.
  std::vector<cv::Vec3b> lut{cv::Vec3b(0, 0, 0)};
  const auto colours = label_colours(1, static_cast<int>(mx));
  lut.insert(lut.end(), colours.begin(), colours.end());
  cv::Mat out(labels16.size(), CV_8UC3);
  for (int y = 0; y < labels16.rows; ++y) {
    const auto* lab = labels16.ptr<std::uint16_t>(y);
    auto* o = out.ptr<cv::Vec3b>(y);
    for (int x = 0; x < labels16.cols; ++x) o[x] = lut[lab[x]];
  }
  return out;
}

cv::Mat disparity_picture(const cv::Mat& disp_q4) {
  if (disp_q4.type() != CV_16UC1)
    throw std::invalid_argument("disparity_picture needs a CV_16UC1 Q11.4 disparity map");
  int lo = 0x7fff, hi = 1;
  for (int y = 0; y < disp_q4.rows; ++y)
    for (int x = 0; x < disp_q4.cols; ++x) {
      const int d = disp_q4.at<std::uint16_t>(y, x);
      if (d == 0 || d >= 0x8000) continue;
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  cv::Mat grey(disp_q4.size(), CV_8UC1);
  const int span = std::max(1, hi - lo);
  for (int y = 0; y < disp_q4.rows; ++y)
    for (int x = 0; x < disp_q4.cols; ++x) {
      const int d = disp_q4.at<std::uint16_t>(y, x);
      grey.at<uchar>(y, x) =
          d == 0 || d >= 0x8000 ? 0
                                : static_cast<uchar>(64 + std::clamp(d - lo, 0, span) * 191 / span);
    }
  cv::Mat out;
  cv::cvtColor(grey, out, cv::COLOR_GRAY2BGR);
  return out;
}

cv::Rect box_of(const hls::labelling::Object& o) {
  return {o.x_min, o.y_min, o.x_max - o.x_min + 1, o.y_max - o.y_min + 1};
}

cv::Mat draw_overlay(const cv::Mat& picture, const std::vector<OverlayItem>& items) {
  cv::Mat out;
  if (picture.type() == CV_8UC1)
    cv::cvtColor(picture, out, cv::COLOR_GRAY2BGR);
  else if (picture.type() == CV_8UC3)
    out = picture.clone();
  else
    throw std::invalid_argument("draw_overlay draws on an 8-bit grey or BGR picture");
  const cv::Rect whole(0, 0, out.cols, out.rows);
  // Tints first, then lines and numbers, so no tint covers another item's outline or number.
  for (const auto& it : items) {
    if (it.mask.empty()) continue;
    if (it.mask.size() != it.box.size() || it.mask.type() != CV_8UC1)
      throw std::invalid_argument("an overlay mask must be CV_8UC1 of its box's size");
    const cv::Rect r = it.box & whole;
    if (r.empty()) continue;
    cv::Mat roi = out(r), blend;
    cv::addWeighted(roi, 0.5, cv::Mat(r.size(), CV_8UC3, cv::Scalar(label_colour(it.number))), 0.5,
                    0.0, blend);
    blend.copyTo(roi, it.mask(r - it.box.tl()));
  }
  for (const auto& it : items) {
    const cv::Scalar colour(label_colour(it.number));
    cv::rectangle(out, it.box, cv::Scalar(255, 255, 255), 1);
    if (!it.outline.empty())
      cv::polylines(out, std::vector<std::vector<cv::Point>>{it.outline}, true, colour, 1);
    const std::string text = std::to_string(it.number);
    const cv::Point at(it.box.x + 2, it.box.y + 11);
    cv::putText(out, text, at, cv::FONT_HERSHEY_PLAIN, 0.8, cv::Scalar(0, 0, 0), 2);
    cv::putText(out, text, at, cv::FONT_HERSHEY_PLAIN, 0.8, colour, 1);
  }
  return out;
}

}  // namespace scw::labelling
