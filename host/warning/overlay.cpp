// SPDX-License-Identifier: Apache-2.0
// The Fig. 5.11 b overlay (docs/warning-reference.md).
#include "host/warning/overlay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace scw::host::warning {

using hls::warning::Severity;

namespace {

// Sub-pixel drawing: cv::line takes fixed-point coordinates with this many fraction bits, so
// projected points land where the pinhole model puts them instead of on the nearest pixel.
constexpr int kShift = 4;
constexpr double kOne = 1 << kShift;

/// Clips segment p-q to `r` (Liang-Barsky) in doubles, before the fixed-point conversion, so
/// points far outside the image cannot overflow it. False when nothing is left.
bool clip(const cv::Rect2d& r, cv::Point2d& p, cv::Point2d& q) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  double t0 = 0.0, t1 = 1.0;
  const std::array<double, 4> pk{-dx, dx, -dy, dy};
  const std::array<double, 4> qk{p.x - r.x, r.x + r.width - p.x, p.y - r.y, r.y + r.height - p.y};
  for (int i = 0; i < 4; ++i) {
    if (pk[i] == 0.0) {
      if (qk[i] < 0.0) return false;
      continue;
    }
    const double t = qk[i] / pk[i];
    if (pk[i] < 0.0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  const cv::Point2d a = p, b = q;
  p = a + t0 * (b - a);
  q = a + t1 * (b - a);
  return true;
}

void draw_segment(cv::Mat& img, cv::Point2d p, cv::Point2d q, const cv::Scalar& bgr,
                  int thickness) {
  // A margin wider than any line keeps clipped ends outside the visible image.
  const double m = 8.0 + thickness;
  if (!clip(cv::Rect2d(-m, -m, img.cols + 2 * m, img.rows + 2 * m), p, q)) return;
  const cv::Point a(static_cast<int>(std::lround(p.x * kOne)),
                    static_cast<int>(std::lround(p.y * kOne)));
  const cv::Point b(static_cast<int>(std::lround(q.x * kOne)),
                    static_cast<int>(std::lround(q.y * kOne)));
  // LINE_8, not anti-aliased: the colours stay exact, so a reader (or a test) can tell the
  // severity from the pixels.
  cv::line(img, a, b, bgr, thickness, cv::LINE_8, kShift);
}

/// A camera-frame segment, clipped to z >= near before projecting (the pinhole model folds
/// points behind the camera onto the image).
void draw_3d(cv::Mat& img, const WarningSetup& s, Eigen::Vector3d a, Eigen::Vector3d b, double near,
             const cv::Scalar& bgr, int thickness) {
  if (a.z() < near && b.z() < near) return;
  if (a.z() < near) a = a + (near - a.z()) / (b.z() - a.z()) * (b - a);
  if (b.z() < near) b = b + (near - b.z()) / (a.z() - b.z()) * (a - b);
  draw_segment(img, project(a, s), project(b, s), bgr, thickness);
}

std::string metres(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f m", m);
  return buf;
}

}  // namespace

cv::Scalar severity_bgr(Severity s) {
  switch (s) {
    case Severity::kLow:
      return {0, 200, 0};
    case Severity::kMedium:
      return {0, 255, 255};
    case Severity::kHigh:
      return {0, 0, 255};
    case Severity::kNone:
      break;
  }
  return {255, 255, 255};
}

std::string overlay_caption(const OverlayObject* o) {
  if (o == nullptr || o->severity == Severity::kNone) return "no obstacle";
  // Too close: the stage only knows the object is nearer than the end of its search range.
  return (o->too_close ? "< " : "") + metres(o->distance_m) + " " +
         hls::warning::severity_name(o->severity);
}

cv::Point2d project(const Eigen::Vector3d& p, const WarningSetup& s) {
  return {s.cu_px + s.focal_px * p.x() / p.z(), s.cv_px - s.focal_px * p.y() / p.z()};
}

std::optional<OverlayObject> overlay_object(const hls::warning::FrameResult& r,
                                            const WarningSetup& s) {
  if (r.index == 0xffff || r.severity == Severity::kNone || r.d_max < 16) return std::nullopt;
  OverlayObject o;
  o.u0 = r.x_min;
  o.v0 = r.y_min;
  o.u1 = r.x_max;
  o.v1 = r.y_max;
  o.z_m = s.baseline_m * s.focal_px / (r.d_max / 16.0);
  o.distance_m = r.distance_mm / 1000.0;
  o.severity = r.severity;
  o.too_close = r.too_close;
  return o;
}

cv::Mat draw_overlay(const cv::Mat& rectified_left, const WarningSetup& s,
                     const OverlayObject* deciding, const OverlayStyle& style) {
  if (rectified_left.empty()) throw std::invalid_argument("overlay: the image is empty");
  cv::Mat img;
  if (rectified_left.type() == CV_8UC1)
    cv::cvtColor(rectified_left, img, cv::COLOR_GRAY2BGR);
  else if (rectified_left.type() == CV_8UC3)
    img = rectified_left.clone();
  else
    throw std::invalid_argument("overlay: the image must be 8-bit grey or BGR");

  // The tunnel in vehicle coordinates (origin on the road below the bumper's centre, axes as
  // the camera's, Fig. 5.4), moved into the camera frame by the vehicle origin.
  const double hw = s.tunnel_half_width_m(), th = s.tunnel_height_m();
  const double near = std::max(style.near_clip_m, 1e-3);
  // The return type is spelled out: deduced, it would be an Eigen expression holding a
  // reference to the temporary vector.
  auto cam = [&](double xv, double yv, double zv) -> Eigen::Vector3d {
    return Eigen::Vector3d(xv, yv, zv) + s.vehicle_origin;
  };
  const std::array<std::array<double, 2>, 4> corners{{{-hw, 0.0}, {hw, 0.0}, {-hw, th}, {hw, th}}};
  for (const auto& c : corners)
    draw_3d(img, s, cam(c[0], c[1], 0.0), cam(c[0], c[1], style.tunnel_length_m), near,
            style.tunnel_bgr, style.tunnel_thickness_px);

  // Cross-section rectangles every mark_step_m, labelled at the floor's right corner.
  for (int k = 1; style.mark_step_m > 0.0 && k * style.mark_step_m <= style.tunnel_length_m + 1e-9;
       ++k) {
    const double zv = k * style.mark_step_m;
    if (cam(0, 0, zv).z() < near) continue;
    const Eigen::Vector3d fl = cam(-hw, 0, zv), fr = cam(hw, 0, zv);
    const Eigen::Vector3d rl = cam(-hw, th, zv), rr = cam(hw, th, zv);
    draw_3d(img, s, fl, fr, near, style.tunnel_bgr, style.tunnel_thickness_px);
    draw_3d(img, s, rl, rr, near, style.tunnel_bgr, style.tunnel_thickness_px);
    draw_3d(img, s, fl, rl, near, style.tunnel_bgr, style.tunnel_thickness_px);
    draw_3d(img, s, fr, rr, near, style.tunnel_bgr, style.tunnel_thickness_px);
    char label[16];
    std::snprintf(label, sizeof label, "%g m", zv);
    const cv::Point2d at = project(fr, s);
    if (std::abs(at.x) < 1e5 && std::abs(at.y) < 1e5)
      cv::putText(img, label, cv::Point(static_cast<int>(at.x) + 4, static_cast<int>(at.y)),
                  cv::FONT_HERSHEY_SIMPLEX, 0.8 * style.font_scale, style.tunnel_bgr, 1,
                  cv::LINE_AA);
  }

  // The deciding object's cuboid: the front face is its bounding box (pixel edges) at the
  // closest point's depth, so it projects back onto the box exactly.
  if (deciding != nullptr && deciding->severity != Severity::kNone && deciding->z_m > 0.0) {
    const OverlayObject& o = *deciding;
    const cv::Scalar bgr = severity_bgr(o.severity);
    const double z0 = o.z_m, z1 = o.z_m + style.cuboid_depth_m;
    auto at = [&](double u, double v, double z) -> Eigen::Vector3d {
      return Eigen::Vector3d((u - s.cu_px) * z / s.focal_px, (s.cv_px - v) * z / s.focal_px, z);
    };
    const std::array<std::array<double, 2>, 4> box{{{o.u0 - 0.5, o.v0 - 0.5},
                                                    {o.u1 + 0.5, o.v0 - 0.5},
                                                    {o.u1 + 0.5, o.v1 + 0.5},
                                                    {o.u0 - 0.5, o.v1 + 0.5}}};
    // Back edges first, so the front face stays on top where they cross.
    for (int i = 0; i < 4; ++i) {
      const auto& p = box[i];
      const auto& q = box[(i + 1) % 4];
      // The same metric box further away (not the same rays, which would project onto the
      // front face).
      const Eigen::Vector3d pf = at(p[0], p[1], z0), qf = at(q[0], q[1], z0);
      const Eigen::Vector3d pb(pf.x(), pf.y(), z1), qb(qf.x(), qf.y(), z1);
      draw_3d(img, s, pb, qb, near, bgr, style.cuboid_thickness_px);
      draw_3d(img, s, pf, pb, near, bgr, style.cuboid_thickness_px);
    }
    for (int i = 0; i < 4; ++i) {
      const auto& p = box[i];
      const auto& q = box[(i + 1) % 4];
      draw_segment(img, {p[0], p[1]}, {q[0], q[1]}, bgr, style.cuboid_thickness_px);
    }
  }

  // The caption in the upper left corner, on a dark box so it reads on any scene.
  const std::string caption = overlay_caption(deciding);
  const Severity sev = deciding != nullptr ? deciding->severity : Severity::kNone;
  int baseline = 0;
  const cv::Size ts =
      cv::getTextSize(caption, cv::FONT_HERSHEY_SIMPLEX, style.font_scale, 1, &baseline);
  const cv::Rect bg(4, 4, ts.width + 8, ts.height + baseline + 8);
  cv::rectangle(img, bg & cv::Rect(0, 0, img.cols, img.rows), cv::Scalar(0, 0, 0), cv::FILLED);
  cv::putText(img, caption, cv::Point(8, 8 + ts.height), cv::FONT_HERSHEY_SIMPLEX, style.font_scale,
              severity_bgr(sev), 1, cv::LINE_AA);
  return img;
}

}  // namespace scw::host::warning
