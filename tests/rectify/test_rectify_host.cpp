// SPDX-License-Identifier: Apache-2.0
// Host side of rectify: calibration loading, map quantisation, row planning, and real chessboard
// rows lining up after the fixed-point streaming model.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "hls/rectify/map_taps.hpp"
#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/run_model.hpp"
#include "tests/common/scoped_env.hpp"

namespace {
using namespace scw::rectify;
namespace fs = std::filesystem;

const std::string kData = SCW_DATA_DIR;
const std::string kCalib = kData + "/chessboard/derived_stereo_calibration_helper.yml";
constexpr int kPairs[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 12, 13, 14};

std::string image_path(const char* side, int i) {
  char name[32];
  std::snprintf(name, sizeof name, "%s%02d.jpg", side, i);
  return kData + "/chessboard/" + name;
}

cv::Mat read_grey(const std::string& path) {
  cv::Mat m = cv::imread(path, cv::IMREAD_GRAYSCALE);
  REQUIRE(!m.empty());
  return m;
}

/// The chessboard calibration rectified at the default alpha, quantised and planned once.
struct Chessboard {
  StereoCalibration calib = load_stereo_calibration(kCalib);
  StereoRectification rect = rectify_calibration(calib);
  FixedMap left = quantise_map(rect.map1_x, rect.map1_y);
  FixedMap right = quantise_map(rect.map2_x, rect.map2_y);
  RectifyPlan plan =
      plan_for_stage({row_window(left), row_window(right)}, kHostStageRows, "chessboard");
};
const Chessboard& chessboard() {
  static const Chessboard c;
  return c;
}

/// 9 x 6 inner corners refined as in OpenCV's stereo_calib sample.
bool find_corners(const cv::Mat& img, std::vector<cv::Point2f>& corners) {
  if (!cv::findChessboardCorners(img, {9, 6}, corners,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE))
    return false;
  cv::cornerSubPix(img, corners, {11, 11}, {-1, -1},
                   cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 0.01));
  return true;
}

/// Mean and max |y_left - y_right| over the corners of every pair where both boards are found.
struct RowError {
  double sum = 0, max = 0;
  int corners = 0, pairs = 0;
  void add(const cv::Mat& l, const cv::Mat& r) {
    std::vector<cv::Point2f> cl, cr;
    if (!find_corners(l, cl) || !find_corners(r, cr)) return;
    ++pairs;
    for (std::size_t i = 0; i < cl.size(); ++i) {
      const double d = std::abs(cl[i].y - cr[i].y);
      sum += d;
      max = std::max(max, d);
      ++corners;
    }
  }
  double mean() const { return corners ? sum / corners : std::numeric_limits<double>::infinity(); }
};

/// A scratch folder for broken calibration files.
fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / "scw_test_rectify_host";
  fs::create_directories(d);
  return d;
}

/// Writes a calibration with the chessboard's values, letting the test replace or drop nodes.
std::string write_calib(const std::string& name, const std::string& drop,
                        const std::string& replace_name = "", const cv::Mat& replace = {}) {
  const auto& c = chessboard().calib;
  const std::string path = (scratch() / name).string();
  cv::FileStorage out(path, cv::FileStorage::WRITE);
  out << "image_width" << c.image_size.width << "image_height" << c.image_size.height;
  const std::pair<const char*, cv::Mat> nodes[] = {{"M1", c.M1}, {"D1", c.D1}, {"M2", c.M2},
                                                   {"D2", c.D2}, {"R", c.R},   {"T", c.T}};
  for (const auto& [n, m] : nodes) {
    if (n == drop) continue;
    out << n << (n == replace_name ? replace : m);
  }
  return path;
}

std::string load_error(const std::string& path) {
  try {
    load_stereo_calibration(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  FAIL("no exception for " << path);
  return {};
}

/// The chessboard calibration with the right camera turned by `deg` about its optical axis:
/// rectification must then rotate both images by deg / 2, so output rows cut across many raw
/// rows.
StereoCalibration rotated_calibration(double deg) {
  StereoCalibration c = chessboard().calib;
  const double a = deg * CV_PI / 180, ca = std::cos(a), sa = std::sin(a);
  const cv::Mat rz = (cv::Mat_<double>(3, 3) << ca, -sa, 0, sa, ca, 0, 0, 0, 1);
  c.R = rz * c.R;
  return c;
}

}  // namespace

TEST_CASE("the chessboard calibration loads and rectifies as OpenCV does", "[rectify][host]") {
  const auto& cb = chessboard();
  CHECK(cb.calib.image_size == cv::Size(640, 480));
  CHECK(cb.calib.D1.total() == 14);
  CHECK(cb.calib.T.rows == 3);
  // The helper stored stereoRectify's output (alpha -1, CALIB_ZERO_DISPARITY) in the same file.
  cv::FileStorage f(kCalib, cv::FileStorage::READ);
  cv::Mat p1, p2, q;
  f["P1"] >> p1;
  f["P2"] >> p2;
  f["Q"] >> q;
  CHECK(cv::norm(p1, cb.rect.P1, cv::NORM_INF) < 1e-6);
  CHECK(cv::norm(p2, cb.rect.P2, cv::NORM_INF) < 1e-6);
  CHECK(cv::norm(q, cb.rect.Q, cv::NORM_INF) < 1e-6);
  CHECK(cb.rect.focal_px() == Approx(528.71).epsilon(1e-4));
  CHECK(cb.rect.baseline() == Approx(0.0836).epsilon(1e-2));
  CHECK(cb.rect.map1_x.type() == CV_32FC1);
  CHECK(cb.rect.map2_y.size() == cv::Size(640, 480));
}

TEST_CASE("chessboard rows line up after the fixed-point streaming model", "[rectify][host]") {
  const auto& cb = chessboard();
  RowError raw, opencv_float, ours;
  for (int i : kPairs) {
    const cv::Mat l = read_grey(image_path("left", i)), r = read_grey(image_path("right", i));
    raw.add(l, r);
    cv::Mat lf, rf;
    cv::remap(l, lf, cb.rect.map1_x, cb.rect.map1_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
    cv::remap(r, rf, cb.rect.map2_x, cb.rect.map2_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
    opencv_float.add(lf, rf);
    ours.add(rectify_image(l, cb.left, cb.plan.lead_rows),
             rectify_image(r, cb.right, cb.plan.lead_rows));
  }
  const auto line = [](const char* what, const RowError& e) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%-22s mean |dy| %.4f px, max %.3f px (%d corners, %d pairs)",
                  what, e.mean(), e.max, e.corners, e.pairs);
    return std::string(buf);
  };
  WARN("chessboard rows, 13 pairs, lead " << cb.plan.lead_rows << ", rows needed "
                                          << cb.plan.rows_needed << "\n"
                                          << line("raw", raw) << "\n"
                                          << line("OpenCV float remap", opencv_float) << "\n"
                                          << line("ours (fixed point)", ours));
  CHECK(raw.pairs >= 12);
  CHECK(ours.pairs >= 12);
  CHECK(opencv_float.pairs >= 12);
  CHECK(raw.mean() > 5.0);
  CHECK(opencv_float.mean() < 0.3);
  CHECK(ours.mean() <= 0.3);
}

TEST_CASE("the planned lead keeps every needed raw row inside the stage's window",
          "[rectify][host]") {
  const auto& cb = chessboard();
  INFO("lead " << cb.plan.lead_rows << ", rows needed " << cb.plan.rows_needed);
  CHECK(cb.plan.rows_needed <= kHostStageRows);
  CHECK(cb.plan.lead_rows >= 1);
  CHECK(cb.plan.lead_rows < cb.plan.rows_needed);
  for (const FixedMap* m : {&cb.left, &cb.right}) {
    long outside = 0;
    for (int v = 0; v < m->height; ++v)
      for (int u = 0; u < m->width; ++u) {
        const auto t = scw::hls::rectify::decode_taps<5>(m->at(u, v), m->width, m->height);
        using scw::hls::rectify::in_row_window;
        if (t.row0 && !in_row_window(t.y0 - v, cb.plan.lead_rows, cb.plan.rows_needed)) ++outside;
        if (t.row1 && !in_row_window(t.y0 + 1 - v, cb.plan.lead_rows, cb.plan.rows_needed))
          ++outside;
      }
    CHECK(outside == 0);
  }
  // One row fewer is not enough: the plan is tight.
  CHECK_THROWS_AS(plan_for_stage({row_window(cb.left), row_window(cb.right)},
                                 cb.plan.rows_needed - 1, "chessboard"),
                  MapNotServable);
}

TEST_CASE("row window, lead and rows needed on small maps", "[rectify][host]") {
  constexpr int W = 8, H = 6, S = 32;
  FixedMap m;
  m.width = W;
  m.height = H;
  m.points.resize(W * H);
  const auto fill = [&](double dx, double dy) {
    for (int v = 0; v < H; ++v)
      for (int u = 0; u < W; ++u)
        m.points[v * W + u] = {static_cast<std::int32_t>(std::lround((u + dx) * S)),
                               static_cast<std::int32_t>(std::lround((v + dy) * S))};
  };
  fill(0, 0);  // identity: only row v itself (fy = 0, so row v + 1 carries no weight)
  auto w = row_window(m);
  CHECK((w.any && w.dy_min == 0 && w.dy_max == 0));
  auto p = plan_rows({w});
  CHECK((p.lead_rows == 1 && p.rows_needed == 3));

  fill(0.25, 2.5);  // rows v + 2 and v + 3 (inside the image only)
  w = row_window(m);
  CHECK((w.dy_min == 2 && w.dy_max == 3));
  p = plan_rows({w});
  CHECK((p.lead_rows == 4 && p.rows_needed == 6));

  fill(0, -3.5);  // rows v - 4 and v - 3
  w = row_window(m);
  CHECK((w.dy_min == -4 && w.dy_max == -3));
  p = plan_rows({w});
  CHECK((p.lead_rows == 1 && p.rows_needed == 7));

  fill(0, 0);
  m.points[2 * W + 3].y = (2 + 1) * S + 8;  // one pixel of row 2 reads rows 3 and 4
  m.points[5 * W + 0].y = 1 * S;            // one pixel of row 5 reads row 1
  w = row_window(m);
  CHECK((w.dy_min == -4 && w.dy_max == 2));
  p = plan_rows({w, RowWindow{}});  // a window that touches nothing does not count
  CHECK((p.lead_rows == 3 && p.rows_needed == 9));

  // Entirely outside: no rows, the smallest plan.
  m.points = quantise_map(cv::Mat(H, W, CV_32FC1, cv::Scalar(500.f)),
                          cv::Mat(H, W, CV_32FC1, cv::Scalar(2.f)))
                 .points;
  w = row_window(m);
  CHECK(!w.any);
  p = plan_rows({w});
  CHECK((p.lead_rows == 1 && p.rows_needed == 3));
}

TEST_CASE("a map needing more rows than the stage holds is refused with both numbers",
          "[rectify][host]") {
  SECTION("the chessboard maps on a 4-row stage") {
    const auto& cb = chessboard();
    REQUIRE(cb.plan.rows_needed > 4);
    try {
      plan_for_stage({row_window(cb.left), row_window(cb.right)}, 4, "chessboard.yml");
      FAIL("no MapNotServable");
    } catch (const MapNotServable& e) {
      const std::string msg = e.what();
      INFO(msg);
      CHECK(e.rows_needed() == cb.plan.rows_needed);
      CHECK(e.stage_rows() == 4);
      CHECK_THAT(msg, Catch::Contains("chessboard.yml"));
      CHECK_THAT(msg, Catch::Contains("need " + std::to_string(cb.plan.rows_needed) + " raw rows"));
      CHECK_THAT(msg, Catch::Contains("built with 4 rows"));
      CHECK_THAT(msg, Catch::Contains("RectifyRows >="));
    }
  }
  SECTION("a calibration whose cameras are turned 30 degrees about the optical axis") {
    const auto rect = rectify_calibration(rotated_calibration(30));
    const auto l = quantise_map(rect.map1_x, rect.map1_y);
    const auto r = quantise_map(rect.map2_x, rect.map2_y);
    try {
      plan_for_stage({row_window(l), row_window(r)}, kHostStageRows, "rotated.yml");
      FAIL("no MapNotServable");
    } catch (const MapNotServable& e) {
      const std::string msg = e.what();
      WARN(msg);
      CHECK(e.rows_needed() > kHostStageRows);
      CHECK_THAT(msg, Catch::Contains("need " + std::to_string(e.rows_needed()) + " raw rows"));
      CHECK_THAT(msg, Catch::Contains("built with " + std::to_string(kHostStageRows) + " rows"));
    }
  }
}

TEST_CASE("broken calibration files give messages naming the file and the node",
          "[rectify][host]") {
  SECTION("missing file") {
    const std::string msg = load_error(kData + "/chessboard/no_such_calibration.yml");
    CHECK_THAT(msg, Catch::Contains("no_such_calibration.yml"));
    CHECK_THAT(msg, Catch::Contains("no such file"));
  }
  SECTION("garbage text") {
    const std::string path = (scratch() / "garbage.yml").string();
    std::ofstream(path) << "this is { not [ a calibration\n\tat all: : :\n";
    const std::string msg = load_error(path);
    CHECK_THAT(msg, Catch::Contains("garbage.yml"));
    CHECK_THAT(msg, Catch::Contains("not an OpenCV FileStorage file"));
  }
  SECTION("missing T") {
    const std::string msg = load_error(write_calib("no_t.yml", "T"));
    CHECK_THAT(msg, Catch::Contains("no_t.yml"));
    CHECK_THAT(msg, Catch::Contains("'T' is missing"));
    CHECK_THAT(msg, Catch::Contains("3x1"));
  }
  SECTION("2x2 M1") {
    const std::string msg =
        load_error(write_calib("m1_2x2.yml", "", "M1", cv::Mat::eye(2, 2, CV_64F)));
    CHECK_THAT(msg, Catch::Contains("'M1' is 2x2"));
    CHECK_THAT(msg, Catch::Contains("3x3"));
  }
  SECTION("NaN in D2") {
    cv::Mat d = chessboard().calib.D2.clone();
    d.at<double>(0, 1) = std::numeric_limits<double>::quiet_NaN();
    const std::string msg = load_error(write_calib("nan.yml", "", "D2", d));
    CHECK_THAT(msg, Catch::Contains("'D2'"));
    CHECK_THAT(msg, Catch::Contains("non-finite"));
  }
  SECTION("distortion vector of 3") {
    const std::string msg =
        load_error(write_calib("d3.yml", "", "D1", cv::Mat::zeros(1, 3, CV_64F)));
    CHECK_THAT(msg, Catch::Contains("'D1' is 1x3"));
    CHECK_THAT(msg, Catch::Contains("4, 5, 8, 12 or 14"));
  }
  SECTION("R that is not a rotation") {
    const std::string msg =
        load_error(write_calib("r_scaled.yml", "", "R", 2 * cv::Mat::eye(3, 3, CV_64F)));
    CHECK_THAT(msg, Catch::Contains("'R' is not a rotation"));
  }
  SECTION("no image size in the file and none given") {
    const std::string path = (scratch() / "no_size.yml").string();
    {
      const auto& c = chessboard().calib;
      cv::FileStorage out(path, cv::FileStorage::WRITE);
      out << "M1" << c.M1 << "D1" << c.D1 << "M2" << c.M2 << "D2" << c.D2 << "R" << c.R << "T"
          << c.T;
    }
    CHECK_THAT(load_error(path), Catch::Contains("'image_width'"));
    CHECK(load_stereo_calibration(path, {640, 480}).image_size == cv::Size(640, 480));
  }
  SECTION("a file OpenCV's reader loops on, within the time SCW_READER_SECONDS gives") {
    // The minimised input fuzzing found (fuzz/regressions/calibration/opencv_yaml_loop.yml).
    const std::string path = (scratch() / "loops.yml").string();
    std::ofstream(path) << "%YAML:1.\n   -u\n:\n";
    scw::test::ScopedEnv limit("SCW_READER_SECONDS", "0.5");
    const std::string msg = load_error(path);
    CHECK_THAT(msg, Catch::Contains("loops.yml"));
    CHECK_THAT(msg, Catch::Contains("did not finish it within 0.5 s"));
    limit.set("soon");
    CHECK_THAT(load_error(path), Catch::Contains("SCW_READER_SECONDS='soon' is not a number"));
  }
}

TEST_CASE("quantised maps give the same positions as cv::convertMaps", "[rectify][host]") {
  const auto& cb = chessboard();
  const std::pair<const cv::Mat*, const cv::Mat*> float_maps[] = {
      {&cb.rect.map1_x, &cb.rect.map1_y}, {&cb.rect.map2_x, &cb.rect.map2_y}};
  const FixedMap* fixed[] = {&cb.left, &cb.right};
  for (int cam = 0; cam < 2; ++cam) {
    const cv::Mat& mx = *float_maps[cam].first;
    const cv::Mat& my = *float_maps[cam].second;
    cv::Mat cv_xy, cv_frac, our_xy, our_frac;
    cv::convertMaps(mx, my, cv_xy, cv_frac, CV_16SC2);
    to_cv_maps(*fixed[cam], our_xy, our_frac);
    REQUIRE(our_xy.type() == CV_16SC2);
    REQUIRE(our_frac.type() == CV_16UC1);
    long same = 0, clamped = 0, differ = 0;
    for (int v = 0; v < mx.rows; ++v)
      for (int u = 0; u < mx.cols; ++u) {
        const float x = mx.at<float>(v, u), y = my.at<float>(v, u);
        if (x < -1 || x > mx.cols || y < -1 || y > mx.rows) {
          ++clamped;
          continue;
        }
        if (cv_xy.at<cv::Vec2s>(v, u) == our_xy.at<cv::Vec2s>(v, u) &&
            cv_frac.at<std::uint16_t>(v, u) == our_frac.at<std::uint16_t>(v, u))
          ++same;
        else
          ++differ;
      }
    INFO("camera " << cam << ": " << same << " equal, " << clamped << " clamped");
    CHECK(differ == 0);
    CHECK(same > static_cast<long>(mx.total() / 2));
  }
  FixedMap f3;
  f3.frac_bits = 3;
  cv::Mat a, b;
  CHECK_THROWS_AS(to_cv_maps(f3, a, b), std::invalid_argument);
  CHECK_THROWS_AS(quantise_map(cv::Mat(2, 2, CV_32FC1), cv::Mat(2, 3, CV_32FC1)),
                  std::invalid_argument);
  CHECK_THROWS_AS(quantise_map(cv::Mat(2, 2, CV_16SC2), cv::Mat(2, 2, CV_16UC1)),
                  std::invalid_argument);
}

TEST_CASE("quantisation clamps positions outside the image", "[rectify][host]") {
  cv::Mat mx = (cv::Mat_<float>(1, 4) << -5.f, 3.f, 1.5f, NAN);
  cv::Mat my = (cv::Mat_<float>(1, 4) << 0.f, 1e9f, -0.999f, 0.f);
  const auto m = quantise_map(mx, my);
  CHECK(m.at(0, 0) == MapPoint{-32, 0});
  CHECK(m.at(1, 0) == MapPoint{3 * 32, 1 * 32});  // 1 x 4 image: y clamps at H * S
  CHECK(m.at(2, 0) == MapPoint{48, -32});         // cvRound(-31.97) = -32
  CHECK(m.at(3, 0).x == -32);
}

TEST_CASE("a Rectifier over a sequence equals rectify_image frame by frame", "[rectify][host]") {
  // `scw run` keeps one stage per camera for a whole sequence: each frame must come out as a
  // fresh stage makes it, whatever the rows the frame before left in the line buffer.
  const auto& cb = chessboard();
  Rectifier left(cb.left, cb.plan.lead_rows);
  int frames = 0;
  for (int i : {1, 5, 9, 1}) {
    const cv::Mat l = read_grey(image_path("left", i));
    const cv::Mat fresh = rectify_image(l, cb.left, cb.plan.lead_rows);
    CHECK(cv::countNonZero(left(l) != fresh) == 0);
    ++frames;
  }
  CHECK(frames == 4);
  CHECK_THROWS_WITH(left(cv::Mat(10, 10, CV_8UC1)),
                    Catch::Contains("rectify images of the calibration's size"));
}
