// SPDX-License-Identifier: Apache-2.0
// The two plots of `scw eval`: relative distance error against true distance with the thesis's
// 5 % bar (like Fig. 5.5), and warning severity per frame, truth beside measurement (like
// Figs. 5.12 and 5.13).
#pragma once

#include <filesystem>

#include <opencv2/core.hpp>

#include "host/eval/chart.hpp"
#include "host/eval/compare.hpp"

namespace scw::host::eval {

/// The plots' default size: readable on a screen and in the docs.
inline const cv::Size kPlotSize{900, 500};

// Colours (BGR), public so that tests can find the marks.
inline const cv::Scalar kWithinBarBgr{170, 80, 10};   // a frame's error, |e| <= 5 %: blue
inline const cv::Scalar kBeyondBarBgr{20, 20, 200};   // |e| > 5 %: red
inline const cv::Scalar kBarBgr{0, 140, 255};         // the dashed +-5 % lines: orange
inline const cv::Scalar kTruthBgr{225, 185, 130};     // the truth's severity: wide light blue
inline const cv::Scalar kMeasuredBgr{40, 40, 40};     // the measured severity: thin, near black
inline const cv::Scalar kDisagreeBgr{190, 235, 255};  // frames whose severities differ: pale

/// The distance plot's axes: x the true distances (m) with a margin, y the errors (%) and at
/// least -6 .. +6 %, both widened to round ticks.
Axes distance_axes(const EvalReport& r, cv::Size size = kPlotSize);

/// One dot per frame with a rel_error at (true distance m, error %), red beyond the bar; dashed
/// lines at +-5 % labelled as the thesis's bar. CV_8UC3 of `size`, white background.
cv::Mat distance_error_plot(const EvalReport& r, cv::Size size = kPlotSize);

/// The severity plot's axes: x frames -0.5 .. n - 0.5, y the levels none (0) .. high (3) with
/// half a level to spare.
Axes severity_axes(const EvalReport& r, cv::Size size = kPlotSize);

/// Per frame the true severity (a wide light step line) and the measured one (a thin dark step
/// line with a dot per frame when frames are at least 5 px apart), frames where they differ
/// shaded, a legend. CV_8UC3 of `size`, white background.
cv::Mat severity_plot(const EvalReport& r, cv::Size size = kPlotSize);

}  // namespace scw::host::eval
