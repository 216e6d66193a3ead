// SPDX-License-Identifier: Apache-2.0
// Chart scaffolding on a cv::Mat for the eval plots: data-to-pixel axes, round ticks, grid, axis
// names, title, dashed lines and a legend, with OpenCV drawing only.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace scw::host::eval {

/// The colour of text and axes (BGR): near black, softer than pure black beside the data.
inline const cv::Scalar kInkBgr{40, 40, 40};

/// A tick on an axis: where it is (data units) and what is written there.
struct Tick {
  double value = 0.0;
  std::string label;
};

/// The data rectangle [x0, x1] x [y0, y1] drawn into the pixel rectangle `area`, y up.
struct Axes {
  cv::Rect area;
  double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
  /// Where a data point lands, in pixels (sub-pixel; x0 at area.x, y0 at the area's bottom).
  cv::Point2d to_px(double x, double y) const;
};

/// Axes filling an image of `size` less the margins that hold the title, the legend, the tick
/// labels and the axis names.
Axes axes_in(cv::Size size, double x0, double x1, double y0, double y1);

/// A round step (1, 2 or 5 times a power of ten) cutting [lo, hi] into about `count` intervals.
double nice_step(double lo, double hi, int count);

/// [lo, hi] widened outwards to multiples of `step`.
std::pair<double, double> widen_to_step(double lo, double hi, double step);

/// Ticks at the multiples of `step` within [lo, hi], written with the decimals `step` needs.
std::vector<Tick> numeric_ticks(double lo, double hi, double step);

/// The words of a chart. Units go in the axis names: "true distance (m)".
struct ChartText {
  std::string title, x_label, y_label;
};

/// A white image of `size` with a light grid at the ticks, the axes' box, the tick labels, the
/// axis names (the y name turned upright) and the title.
cv::Mat blank_chart(cv::Size size, const Axes& a, const std::vector<Tick>& x_ticks,
                    const std::vector<Tick>& y_ticks, const ChartText& text);

/// The plot area of `img` as a view, with axes that draw into it. OpenCV clips at a Mat's edge,
/// so data drawn through the view (thick lines' caps, shading) cannot spill onto the labels.
struct PlotView {
  cv::Mat area;
  Axes axes;
};
PlotView plot_view(cv::Mat& img, const Axes& a);

/// Draws the axes' box again, over data that covered it.
void draw_box(cv::Mat& img, const Axes& a);

/// Drawing in sub-pixel coordinates. Anti-aliased, so shapes look smooth; the inside of a dot
/// or a thick line still has exactly its colour, which is what tests look for.
void solid_line(cv::Mat& img, cv::Point2d a, cv::Point2d b, const cv::Scalar& bgr, int thickness);
void dashed_line(cv::Mat& img, cv::Point2d a, cv::Point2d b, const cv::Scalar& bgr, int thickness,
                 double dash_px = 10.0, double gap_px = 6.0);
void dot(cv::Mat& img, cv::Point2d centre, double radius_px, const cv::Scalar& bgr);

/// Text in the charts' font, `org` its baseline's left end; `scale` 0.5 is the tick labels'.
void put_label(cv::Mat& img, const std::string& s, cv::Point org, double scale,
               const cv::Scalar& bgr);
/// The pixels put_label takes for `s` (height without the part below the baseline).
cv::Size label_size(const std::string& s, double scale);

/// One entry of a legend: a sample of what the chart draws, then its words.
struct LegendEntry {
  enum class Sample { kLine, kLineDot, kDot, kDashed, kSwatch };
  Sample sample = Sample::kLine;
  cv::Scalar bgr;
  int thickness = 2;
  std::string label;
};

/// The entries in one row, right-aligned in the top margin just above the plot area, where they
/// cannot hide data.
void draw_legend(cv::Mat& img, const Axes& a, const std::vector<LegendEntry>& entries);

}  // namespace scw::host::eval
