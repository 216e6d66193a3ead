// SPDX-License-Identifier: Apache-2.0
// The distance-error and severity plots of `scw eval` (docs/eval.md).
#include "host/eval/plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace scw::host::eval {

namespace {

// The y range always shows the bar with room beyond it: at least -6 .. +6 %.
constexpr double kMinSpanPercent = 6.0;

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f %%", 100.0 * fraction);
  return buf;
}

std::string titled(const std::string& what, const EvalReport& r) {
  return r.preset.empty() ? what : what + ": " + r.preset;
}

/// A stats line left-aligned on the legend's row.
void note(cv::Mat& img, const Axes& a, const std::string& s) {
  put_label(img, s, {a.area.x, a.area.y - 12}, 0.5, kInkBgr);
}

double level(Severity s) { return static_cast<double>(s); }

/// A step line through (i, level_i): flat across each frame's width, upright between frames.
void steps(cv::Mat& img, const Axes& a, const std::vector<double>& levels, const cv::Scalar& bgr,
           int thickness) {
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double x = static_cast<double>(i);
    solid_line(img, a.to_px(x - 0.5, levels[i]), a.to_px(x + 0.5, levels[i]), bgr, thickness);
    if (i + 1 < levels.size() && levels[i + 1] != levels[i])
      solid_line(img, a.to_px(x + 0.5, levels[i]), a.to_px(x + 0.5, levels[i + 1]), bgr,
                 thickness);
  }
}

}  // namespace

Axes distance_axes(const EvalReport& r, cv::Size size) {
  std::vector<double> ds, es;
  for (const auto& f : r.frames)
    if (f.rel_error) {
      ds.push_back(*f.true_distance_m);
      es.push_back(100.0 * *f.rel_error);
    }
  // The thesis's range when there is nothing to show, so an empty plot still has a scale.
  double dlo = 0.0, dhi = 30.0;
  double elo = -kMinSpanPercent, ehi = kMinSpanPercent;
  if (!ds.empty()) {
    const auto [dl, dh] = std::minmax_element(ds.begin(), ds.end());
    dlo = *dl;
    dhi = *dh;
    // A margin keeps the dots at the extreme errors off the frame.
    const auto [el, eh] = std::minmax_element(es.begin(), es.end());
    const double m = 0.03 * (std::max(ehi, *eh) - std::min(elo, *el));
    elo = std::min(elo, *el - m);
    ehi = std::max(ehi, *eh + m);
  }
  const auto [x0, x1] = widen_to_step(dlo, dhi, nice_step(dlo, dhi, 8));
  const auto [y0, y1] = widen_to_step(elo, ehi, nice_step(elo, ehi, 8));
  // The nearest and farthest frames may sit on the rounded range's ends: a margin again.
  const double xm = 0.03 * (x1 - x0);
  return axes_in(size, std::max(0.0, x0 - xm), x1 + xm, y0, y1);
}

cv::Mat distance_error_plot(const EvalReport& r, cv::Size size) {
  const Axes a = distance_axes(r, size);
  ChartText text{titled("Relative distance error against the truth", r),
                 "true distance from the bumper (m)", "(measured - true) / true (%)"};
  cv::Mat img = blank_chart(size, a, numeric_ticks(a.x0, a.x1, nice_step(a.x0, a.x1, 8)),
                            numeric_ticks(a.y0, a.y1, nice_step(a.y0, a.y1, 8)), text);
  auto [area, v] = plot_view(img, a);
  solid_line(area, v.to_px(v.x0, 0.0), v.to_px(v.x1, 0.0), cv::Scalar::all(150), 1);
  const double bar = 100.0 * kThesisDistanceBar;
  for (const double y : {bar, -bar}) {
    dashed_line(area, v.to_px(v.x0, y), v.to_px(v.x1, y), kBarBgr, 2);
    const std::string s = y > 0 ? "thesis bar +5 %" : "thesis bar -5 %";
    const cv::Size sz = label_size(s, 0.5);
    // Above the upper line, below the lower one: outside the band the dots should sit in.
    const int row = static_cast<int>(std::lround(v.to_px(v.x1, y).y));
    const int base = y > 0 ? row - 7 : row + 7 + sz.height;
    put_label(area, s, {v.area.width - 8 - sz.width, base}, 0.5, kBarBgr);
  }
  for (const auto& f : r.frames) {
    if (!f.rel_error) continue;
    const bool beyond = std::abs(*f.rel_error) > kThesisDistanceBar;
    dot(area, v.to_px(*f.true_distance_m, 100.0 * *f.rel_error), 5.0,
        beyond ? kBeyondBarBgr : kWithinBarBgr);
  }
  draw_box(img, a);
  if (r.max_rel_distance_error) {
    note(img, a, "max " + percent(*r.max_rel_distance_error) + ", mean " +
                     percent(*r.mean_rel_distance_error) + ", " +
                     std::to_string(r.frames_with_distance) + " of " +
                     std::to_string(r.frames.size()) + " frames");
  } else {
    const std::string s = "no frame has both a true and a measured distance";
    const cv::Size sz = label_size(s, 0.6);
    put_label(img, s, {a.area.x + (a.area.width - sz.width) / 2, a.area.y + a.area.height / 3},
              0.6, kInkBgr);
  }
  using S = LegendEntry::Sample;
  draw_legend(img, a, {{S::kDot, kWithinBarBgr, 1, "frame"},
                       {S::kDot, kBeyondBarBgr, 1, "beyond 5 %"},
                       {S::kDashed, kBarBgr, 2, "thesis bar 5 %"}});
  return img;
}

Axes severity_axes(const EvalReport& r, cv::Size size) {
  const double n = static_cast<double>(std::max<std::size_t>(r.frames.size(), 1));
  return axes_in(size, -0.5, n - 0.5, -0.5, 3.5);
}

cv::Mat severity_plot(const EvalReport& r, cv::Size size) {
  const Axes a = severity_axes(r, size);
  const double last = static_cast<double>(std::max<std::size_t>(r.frames.size(), 1) - 1);
  // Frames are whole numbers: no tick between two of them.
  const double step = std::max(1.0, nice_step(0.0, last, 10));
  std::vector<Tick> y_ticks;
  for (int s = 0; s < 4; ++s)
    y_ticks.push_back({static_cast<double>(s), severity_name(static_cast<Severity>(s))});
  ChartText text{titled("Warning severity per frame", r), "frame", "severity"};
  cv::Mat img = blank_chart(size, a, numeric_ticks(0.0, last, step), y_ticks, text);

  auto [area, v] = plot_view(img, a);
  std::vector<double> truth, measured;
  for (std::size_t i = 0; i < r.frames.size(); ++i) {
    const auto& f = r.frames[i];
    truth.push_back(level(f.true_severity));
    measured.push_back(level(f.measured_severity));
    if (f.agree) continue;
    // The shade first, so that the lines stay on top.
    const double x = static_cast<double>(i);
    const auto u0 = static_cast<int>(std::lround(v.to_px(x - 0.5, 0.0).x));
    const auto u1 = static_cast<int>(std::lround(v.to_px(x + 0.5, 0.0).x));
    cv::rectangle(area, cv::Rect(u0, 0, std::max(1, u1 - u0), area.rows), kDisagreeBgr,
                  cv::FILLED);
  }
  steps(area, v, truth, kTruthBgr, 7);
  steps(area, v, measured, kMeasuredBgr, 2);
  const double spacing = v.area.width / static_cast<double>(std::max<std::size_t>(truth.size(), 1));
  if (spacing >= 5.0)
    for (std::size_t i = 0; i < measured.size(); ++i)
      dot(area, v.to_px(static_cast<double>(i), measured[i]), std::min(4.0, 0.3 * spacing),
          kMeasuredBgr);
  draw_box(img, a);

  const auto agree = r.frames.size() - static_cast<std::size_t>(r.severity_disagreements);
  char buf[96];
  std::snprintf(buf, sizeof buf, "agreement %zu of %zu frames (%.1f %%)", agree, r.frames.size(),
                100.0 * r.severity_agreement);
  note(img, a, buf);
  using S = LegendEntry::Sample;
  draw_legend(img, a, {{S::kLine, kTruthBgr, 7, "truth"},
                       {S::kLineDot, kMeasuredBgr, 2, "measured"},
                       {S::kSwatch, kDisagreeBgr, 1, "differ"}});
  return img;
}

}  // namespace scw::host::eval
