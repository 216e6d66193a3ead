// SPDX-License-Identifier: Apache-2.0
// Chart scaffolding for the eval plots (docs/eval.md).
#include "host/eval/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "host/io/number_text.hpp"

namespace scw::host::eval {

namespace {

// Margins around the plot area, px: the title and legend above, tick labels and the x name
// below, tick labels and the upright y name to the left.
constexpr int kLeft = 96, kRight = 28, kTop = 66, kBottom = 62;

// cv::line and cv::circle take fixed-point coordinates with this many fraction bits, so points
// land where the data puts them rather than on the nearest pixel.
constexpr int kShift = 4;
constexpr double kOne = 1 << kShift;

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
const cv::Scalar kGrid{228, 228, 228};
constexpr double kTickScale = 0.5, kNameScale = 0.55, kTitleScale = 0.65;

cv::Point fixed(cv::Point2d p) {
  return {static_cast<int>(std::lround(p.x * kOne)), static_cast<int>(std::lround(p.y * kOne))};
}

/// Decimals that tell ticks `step` apart: 0 for 1, 2, 5, 10; 1 for 0.5; 2 for 0.02.
int decimals(double step) {
  return std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
}

/// Text turned upright (read bottom to top) with its middle at `centre`.
void put_upright(cv::Mat& img, const std::string& s, cv::Point centre, double scale) {
  int base = 0;
  const cv::Size sz = cv::getTextSize(s, kFont, scale, 1, &base);
  cv::Mat strip(sz.height + base + 4, sz.width + 4, img.type(), cv::Scalar::all(255));
  cv::putText(strip, s, {2, sz.height + 2}, kFont, scale, kInkBgr, 1, cv::LINE_AA);
  cv::Mat upright;
  cv::rotate(strip, upright, cv::ROTATE_90_COUNTERCLOCKWISE);
  cv::Rect to(centre.x - upright.cols / 2, centre.y - upright.rows / 2, upright.cols, upright.rows);
  const cv::Rect clipped = to & cv::Rect(0, 0, img.cols, img.rows);
  upright(cv::Rect(clipped.tl() - to.tl(), clipped.size())).copyTo(img(clipped));
}

}  // namespace

cv::Point2d Axes::to_px(double x, double y) const {
  return {area.x + (x - x0) / (x1 - x0) * area.width,
          area.y + area.height - (y - y0) / (y1 - y0) * area.height};
}

Axes axes_in(cv::Size size, double x0, double x1, double y0, double y1) {
  Axes a;
  a.area = cv::Rect(kLeft, kTop, std::max(1, size.width - kLeft - kRight),
                    std::max(1, size.height - kTop - kBottom));
  // An empty range would divide by zero in to_px: give it a unit width around its value.
  a.x0 = x1 > x0 ? x0 : x0 - 0.5;
  a.x1 = x1 > x0 ? x1 : x0 + 0.5;
  a.y0 = y1 > y0 ? y0 : y0 - 0.5;
  a.y1 = y1 > y0 ? y1 : y0 + 0.5;
  return a;
}

double nice_step(double lo, double hi, int count) {
  const double raw = (hi > lo ? hi - lo : 1.0) / std::max(1, count);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double n = raw / mag;
  return (n < 1.5 ? 1.0 : n < 3.0 ? 2.0 : n < 7.0 ? 5.0 : 10.0) * mag;
}

std::pair<double, double> widen_to_step(double lo, double hi, double step) {
  // The tolerance keeps a bound already on a multiple (6.000000001) from growing a step.
  return {std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step};
}

std::vector<Tick> numeric_ticks(double lo, double hi, double step) {
  std::vector<Tick> ticks;
  const int dec = decimals(step);
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1.0) {
    const double v = k == 0.0 ? 0.0 : k * step;  // no "-0"
    ticks.push_back({v, io::fixed(v, dec)});
  }
  return ticks;
}

cv::Mat blank_chart(cv::Size size, const Axes& a, const std::vector<Tick>& x_ticks,
                    const std::vector<Tick>& y_ticks, const ChartText& text) {
  cv::Mat img(size, CV_8UC3, cv::Scalar::all(255));
  const int bottom = a.area.y + a.area.height, right = a.area.x + a.area.width;
  for (const auto& t : x_ticks) {
    const double x = a.to_px(t.value, a.y0).x;
    solid_line(img, {x, static_cast<double>(a.area.y)}, {x, static_cast<double>(bottom)}, kGrid, 1);
    solid_line(img, {x, static_cast<double>(bottom)}, {x, bottom + 5.0}, kInkBgr, 1);
    const cv::Size s = label_size(t.label, kTickScale);
    put_label(img, t.label, {static_cast<int>(std::lround(x)) - s.width / 2, bottom + 8 + s.height},
              kTickScale, kInkBgr);
  }
  for (const auto& t : y_ticks) {
    const double y = a.to_px(a.x0, t.value).y;
    solid_line(img, {static_cast<double>(a.area.x), y}, {static_cast<double>(right), y}, kGrid, 1);
    solid_line(img, {a.area.x - 5.0, y}, {static_cast<double>(a.area.x), y}, kInkBgr, 1);
    const cv::Size s = label_size(t.label, kTickScale);
    const int base = static_cast<int>(std::lround(y)) + s.height / 2;
    put_label(img, t.label, {a.area.x - 9 - s.width, base}, kTickScale, kInkBgr);
  }
  draw_box(img, a);
  const cv::Size xs = label_size(text.x_label, kNameScale);
  put_label(img, text.x_label, {a.area.x + a.area.width / 2 - xs.width / 2, size.height - 14},
            kNameScale, kInkBgr);
  put_upright(img, text.y_label, {18, a.area.y + a.area.height / 2}, kNameScale);
  put_label(img, text.title, {a.area.x, 26}, kTitleScale, kInkBgr);
  return img;
}

PlotView plot_view(cv::Mat& img, const Axes& a) {
  PlotView v{img(a.area), a};
  v.axes.area.x = 0;
  v.axes.area.y = 0;
  return v;
}

void draw_box(cv::Mat& img, const Axes& a) { cv::rectangle(img, a.area, kInkBgr, 1); }

void solid_line(cv::Mat& img, cv::Point2d a, cv::Point2d b, const cv::Scalar& bgr, int thickness) {
  cv::line(img, fixed(a), fixed(b), bgr, thickness, cv::LINE_AA, kShift);
}

void dashed_line(cv::Mat& img, cv::Point2d a, cv::Point2d b, const cv::Scalar& bgr, int thickness,
                 double dash_px, double gap_px) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  if (len <= 0.0) return;
  const cv::Point2d u = (b - a) / len;
  for (double s = 0.0; s < len; s += dash_px + gap_px)
    solid_line(img, a + u * s, a + u * std::min(len, s + dash_px), bgr, thickness);
}

void dot(cv::Mat& img, cv::Point2d centre, double radius_px, const cv::Scalar& bgr) {
  cv::circle(img, fixed(centre), static_cast<int>(std::lround(radius_px * kOne)), bgr, cv::FILLED,
             cv::LINE_AA, kShift);
}

void put_label(cv::Mat& img, const std::string& s, cv::Point org, double scale,
               const cv::Scalar& bgr) {
  cv::putText(img, s, org, kFont, scale, bgr, 1, cv::LINE_AA);
}

cv::Size label_size(const std::string& s, double scale) {
  int base = 0;
  return cv::getTextSize(s, kFont, scale, 1, &base);
}

void draw_legend(cv::Mat& img, const Axes& a, const std::vector<LegendEntry>& entries) {
  constexpr int kSample = 28, kPad = 6, kSpace = 18;
  int width = 0;
  for (const auto& e : entries)
    width += kSample + kPad + label_size(e.label, kTickScale).width + kSpace;
  int x = a.area.x + a.area.width - (width - kSpace);
  const int base = a.area.y - 12;
  const double mid = base - 5.0;
  for (const auto& e : entries) {
    const cv::Point2d l(x, mid), r(x + kSample, mid), c(x + kSample / 2.0, mid);
    using S = LegendEntry::Sample;
    if (e.sample == S::kLine || e.sample == S::kLineDot) solid_line(img, l, r, e.bgr, e.thickness);
    if (e.sample == S::kDashed) dashed_line(img, l, r, e.bgr, e.thickness, 8.0, 4.0);
    if (e.sample == S::kLineDot || e.sample == S::kDot) dot(img, c, 4.0, e.bgr);
    if (e.sample == S::kSwatch)
      cv::rectangle(img, cv::Rect(x + 4, base - 12, kSample - 8, 14), e.bgr, cv::FILLED);
    x += kSample + kPad;
    put_label(img, e.label, {x, base}, kTickScale, kInkBgr);
    x += label_size(e.label, kTickScale).width + kSpace;
  }
}

}  // namespace scw::host::eval
