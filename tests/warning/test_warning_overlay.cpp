// SPDX-License-Identifier: Apache-2.0
// The Fig. 5.11 b overlay: tunnel marks where the pinhole model puts them, the cuboid in its
// severity colour, captions, and the image's size and type.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "hls/warning/warning_params.hpp"
#include "host/warning/overlay.hpp"
#include "host/warning/setup.hpp"
#include "tests/warning/karlsruhe_like.hpp"

namespace {

using scw::test::karlsruhe_like;
using scw::test::kImageHeight;
using scw::test::kImageWidth;

using scw::hls::warning::FrameResult;
using scw::hls::warning::Severity;
using scw::host::warning::draw_overlay;
using scw::host::warning::overlay_caption;
using scw::host::warning::overlay_object;
using scw::host::warning::OverlayObject;
using scw::host::warning::OverlayStyle;
using scw::host::warning::severity_bgr;
using scw::host::warning::WarningSetup;

/// The worked example's bike (tests/warning/test_warning_ref.cpp): d = 805 / 16 px.
OverlayObject bike(Severity sev) {
  OverlayObject o;
  o.u0 = 785;
  o.v0 = 185;
  o.u1 = 952;
  o.v1 = 351;
  o.z_m = 0.54 * 700.0 / (805 / 16.0);
  o.distance_m = 6.2400098;
  o.severity = sev;
  return o;
}

cv::Vec3b bgr(const cv::Scalar& s) {
  return cv::Vec3b(static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2]));
}

/// Pixels of exactly `colour` below the caption box (the caption is anti-aliased text).
int count_colour(const cv::Mat& img, const cv::Vec3b& colour) {
  int n = 0;
  for (int y = 40; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) n += img.at<cv::Vec3b>(y, x) == colour;
  return n;
}

/// Whether `colour` occurs within `r` pixels of (x, y).
bool colour_near(const cv::Mat& img, double x, double y, const cv::Vec3b& colour, int r = 1) {
  const int cx = static_cast<int>(std::lround(x)), cy = static_cast<int>(std::lround(y));
  for (int yy = cy - r; yy <= cy + r; ++yy)
    for (int xx = cx - r; xx <= cx + r; ++xx)
      if (xx >= 0 && yy >= 0 && xx < img.cols && yy < img.rows &&
          img.at<cv::Vec3b>(yy, xx) == colour)
        return true;
  return false;
}

void maybe_save(const cv::Mat& img, const char* name) {
  // For looking at the overlay by eye: SCW_OVERLAY_DIR=<dir> writes the test images there.
  if (const char* dir = std::getenv("SCW_OVERLAY_DIR"))
    cv::imwrite(std::string(dir) + "/" + name + ".png", img);
}

}  // namespace

TEST_CASE("overlay keeps the image size and takes grey or BGR", "[ref][warning][overlay]") {
  const WarningSetup s = karlsruhe_like();
  const cv::Mat grey(kImageHeight, kImageWidth, CV_8UC1, cv::Scalar(90));
  const cv::Mat colour(kImageHeight, kImageWidth, CV_8UC3, cv::Scalar(90, 90, 90));
  const OverlayObject o = bike(Severity::kMedium);
  for (const cv::Mat* in : {&grey, &colour}) {
    const cv::Mat out = draw_overlay(*in, s, &o);
    CHECK(out.size() == in->size());
    CHECK(out.type() == CV_8UC3);
  }
  const cv::Mat small(100, 160, CV_8UC1, cv::Scalar(0));
  CHECK(draw_overlay(small, s, nullptr).size() == small.size());  // everything clipped, no throw
  CHECK_THROWS_AS(draw_overlay(cv::Mat(), s, nullptr), std::invalid_argument);
  CHECK_THROWS_AS(draw_overlay(cv::Mat(10, 10, CV_16UC1), s, nullptr), std::invalid_argument);
  // The input is not drawn on.
  CHECK(cv::countNonZero(grey != 90) == 0);
}

TEST_CASE("overlay: the tunnel's distance marks sit where the pinhole model puts them",
          "[ref][warning][overlay]") {
  const WarningSetup s = karlsruhe_like();
  const OverlayStyle style;
  const cv::Mat img =
      draw_overlay(cv::Mat(kImageHeight, kImageWidth, CV_8UC1, cv::Scalar(0)), s, nullptr);
  maybe_save(img, "overlay_empty");
  const cv::Vec3b tunnel = bgr(style.tunnel_bgr);
  const double f = s.focal_px, cu = s.cu_px, cv_ = s.cv_px;
  const double tx = s.vehicle_origin.x(), ty = s.vehicle_origin.y(), tz = s.vehicle_origin.z();
  const double hw = s.tunnel_half_width_m(), th = s.tunnel_height_m();

  // The 10 m floor mark: the road (y = Ty) 10 m past the bumper (z = Tz + 10), from the left
  // wall to the right one. Every column between its ends holds its colour on the row
  // v = cv - f y / z = 240 + 700 * 1.2 / 11.65 = 312.10.
  const double z10 = tz + 10.0;
  const double v10 = cv_ - f * ty / z10;
  const double u_left = cu + f * (tx - hw) / z10, u_right = cu + f * (tx + hw) / z10;
  CHECK(v10 == Approx(312.10).margin(0.01));
  // The walls' lines reach the mark's corners at a slope of about 0.7 rows per column, so
  // within 4 rows of the mark they occupy up to 6 columns beside each corner: start 8 px in.
  int columns = 0;
  for (int u = static_cast<int>(std::ceil(u_left)) + 8; u <= static_cast<int>(u_right) - 8; ++u) {
    std::vector<int> rows;
    for (int v = static_cast<int>(v10) - 4; v <= static_cast<int>(v10) + 4; ++v)
      if (img.at<cv::Vec3b>(v, u) == tunnel) rows.push_back(v);
    INFO("column " << u << ", pinhole row " << v10);
    REQUIRE(rows.size() == 1);  // one-pixel line
    CHECK(std::abs(rows[0] - v10) <= 0.5 + 1e-9);
    ++columns;
  }
  CHECK(columns > 100);
  // The mark ends at the walls: nothing drawn on that row just beyond them (the walls' own
  // lines run steeply, so sample 6 px out).
  const int row10 = static_cast<int>(std::lround(v10));
  CHECK(img.at<cv::Vec3b>(row10, static_cast<int>(u_left) - 6) != tunnel);
  CHECK(img.at<cv::Vec3b>(row10, static_cast<int>(u_right) + 8) != tunnel);

  // On the car's centre line only the cross marks are drawn: floor and roof at 5, 10, 15, 20 m.
  const double zc = tz + 10.0;
  const int uc = static_cast<int>(std::lround(cu + f * tx / zc));
  std::vector<double> expected;
  for (double zv : {5.0, 10.0, 15.0, 20.0})
    for (double yv : {0.0, th}) expected.push_back(cv_ - f * (ty + yv) / (tz + zv));
  for (int v = 40; v < kImageHeight; ++v) {
    if (img.at<cv::Vec3b>(v, uc) != tunnel) continue;
    bool explained = false;
    for (double e : expected) explained = explained || std::abs(v - e) <= 1.0;
    INFO("row " << v << " in column " << uc);
    CHECK(explained);
  }
  for (double e : expected) CHECK(colour_near(img, uc, e, tunnel));
  // No severity colour without a deciding object.
  for (Severity sev : {Severity::kLow, Severity::kMedium, Severity::kHigh})
    CHECK(count_colour(img, bgr(severity_bgr(sev))) == 0);
}

TEST_CASE("overlay: the deciding object's cuboid is drawn in its severity colour",
          "[ref][warning][overlay]") {
  const WarningSetup s = karlsruhe_like();
  const OverlayStyle style;
  const cv::Mat black(kImageHeight, kImageWidth, CV_8UC3, cv::Scalar(0, 0, 0));
  for (Severity sev : {Severity::kLow, Severity::kMedium, Severity::kHigh}) {
    const OverlayObject o = bike(sev);
    const cv::Mat img = draw_overlay(black, s, &o);
    if (sev == Severity::kMedium) maybe_save(img, "overlay_medium");
    const cv::Vec3b c = bgr(severity_bgr(sev));
    INFO("severity " << static_cast<int>(sev));
    // The front face: the bounding box's pixel edges, sampled at each edge's middle.
    const double um = 0.5 * (o.u0 + o.u1), vm = 0.5 * (o.v0 + o.v1);
    CHECK(colour_near(img, um, o.v0 - 0.5, c));
    CHECK(colour_near(img, um, o.v1 + 0.5, c));
    CHECK(colour_near(img, o.u0 - 0.5, vm, c));
    CHECK(colour_near(img, o.u1 + 0.5, vm, c));
    // The back face: the same box cuboid_depth_m further, scaled toward the principal point.
    const double k = o.z_m / (o.z_m + style.cuboid_depth_m);
    const double bu0 = s.cu_px + (o.u0 - 0.5 - s.cu_px) * k;
    const double bv0 = s.cv_px + (o.v0 - 0.5 - s.cv_px) * k;
    const double bu1 = s.cu_px + (o.u1 + 0.5 - s.cu_px) * k;
    CHECK(colour_near(img, 0.5 * (bu0 + bu1), bv0, c));
    // Inside the box it stays black, and no other severity colour appears.
    CHECK(img.at<cv::Vec3b>(static_cast<int>(vm), static_cast<int>(um)) == cv::Vec3b(0, 0, 0));
    for (Severity other : {Severity::kLow, Severity::kMedium, Severity::kHigh})
      if (other != sev) CHECK(count_colour(img, bgr(severity_bgr(other))) == 0);
    CHECK(count_colour(img, c) > 4 * (o.u1 - o.u0 + o.v1 - o.v0));
  }
  // Severity none: no cuboid.
  OverlayObject none = bike(Severity::kNone);
  const cv::Mat img = draw_overlay(black, s, &none);
  for (Severity sev : {Severity::kLow, Severity::kMedium, Severity::kHigh})
    CHECK(count_colour(img, bgr(severity_bgr(sev))) == 0);
}

TEST_CASE("overlay captions and the frame result's deciding object", "[ref][warning][overlay]") {
  const OverlayObject medium = bike(Severity::kMedium);
  CHECK(overlay_caption(&medium) == "6.24 m medium");
  OverlayObject close = bike(Severity::kHigh);
  close.too_close = true;
  close.distance_m = 2.3749;
  CHECK(overlay_caption(&close) == "< 2.37 m high");
  CHECK(overlay_caption(nullptr) == "no obstacle");
  const OverlayObject none = bike(Severity::kNone);
  CHECK(overlay_caption(&none) == "no obstacle");

  // The caption is drawn in the upper left corner.
  const WarningSetup s = karlsruhe_like();
  const cv::Mat img =
      draw_overlay(cv::Mat(kImageHeight, kImageWidth, CV_8UC1, cv::Scalar(0)), s, &close);
  maybe_save(img, "overlay_too_close");
  cv::Mat grey;
  cv::extractChannel(img(cv::Rect(0, 0, 200, 40)), grey, 2);  // red channel: the high colour
  CHECK(cv::countNonZero(grey) > 50);

  FrameResult r;
  CHECK_FALSE(overlay_object(r, s).has_value());  // index 0xffff: no obstacle
  r.index = 0;
  r.severity = Severity::kMedium;
  r.distance_mm = 6240;
  r.d_max = 805;
  r.x_min = 785;
  r.x_max = 952;
  r.y_min = 185;
  r.y_max = 351;
  const auto o = overlay_object(r, s);
  REQUIRE(o.has_value());
  CHECK(o->u0 == 785);
  CHECK(o->v1 == 351);
  CHECK(o->z_m == Approx(0.54 * 700 * 16 / 805.0));
  CHECK(o->distance_m == Approx(6.24));
  CHECK(overlay_caption(&*o) == "6.24 m medium");
}
