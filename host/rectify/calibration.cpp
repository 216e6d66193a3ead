// SPDX-License-Identifier: Apache-2.0
// Loading a stereo calibration with messages that say what is wrong, and rectifying with OpenCV.
#include "host/rectify/calibration.hpp"

#include <cmath>
#include <filesystem>
#include <opencv2/calib3d.hpp>
#include <stdexcept>
#include <string>

#include "host/io/file_storage.hpp"

namespace scw::rectify {
namespace {

const char* const kFormatHint =
    "write it with cv::FileStorage as OpenCV's stereo_calib sample does "
    "(fs << \"M1\" << M1 << \"D1\" << D1 << ... after cv::stereoCalibrate); see "
    "data/chessboard/derived_stereo_calibration_helper.yml for an example";

/// The largest side of any calibration matrix (D: 1 x 14).
constexpr int kMaxSide = 16;

std::string shape(const cv::Mat& m) {
  return std::to_string(m.rows) + "x" + std::to_string(m.cols) +
         (m.channels() > 1 ? " with " + std::to_string(m.channels()) + " channels" : "");
}

[[noreturn]] void fail(const std::string& path, const std::string& msg) {
  throw std::runtime_error("calibration '" + path + "': " + msg);
}

/// Reads one !!opencv-matrix node as CV_64F, checking presence, shape class and finiteness.
cv::Mat read_matrix(const cv::FileStorage& fs, const std::string& path, const std::string& name,
                    const std::string& expected) {
  const cv::FileNode node = fs[name];
  if (node.empty() || node.isNone())
    fail(path, "node '" + name + "' is missing; expected " + expected + "; " + kFormatHint);
  // cv::FileStorage allocates the size a matrix node declares before it reads the data, so a
  // damaged rows or cols would ask for gigabytes: a calibration's matrices are small.
  if (node.isMap()) {
    const cv::FileNode rows = node["rows"], cols = node["cols"];
    const auto small = [](const cv::FileNode& n) {
      return n.isInt() && static_cast<int>(n) >= 1 && static_cast<int>(n) <= kMaxSide;
    };
    if (!small(rows) || !small(cols))
      fail(path, "node '" + name + "' does not declare rows and cols from 1 to " +
                     std::to_string(kMaxSide) + "; expected " + expected +
                     " written as !!opencv-matrix");
  }
  cv::Mat m;
  try {
    node >> m;
  } catch (const cv::Exception& e) {
    fail(path, "node '" + name + "' is not a matrix (" + e.err + "); expected " + expected +
                   " written as !!opencv-matrix");
  }
  if (m.empty() || m.channels() != 1)
    fail(path, "node '" + name + "' is not a single-channel matrix; expected " + expected +
                   " written as !!opencv-matrix");
  cv::Mat d;
  m.convertTo(d, CV_64F);
  for (int r = 0; r < d.rows; ++r)
    for (int c = 0; c < d.cols; ++c)
      if (!std::isfinite(d.at<double>(r, c)))
        fail(path, "node '" + name + "' has a non-finite value (" +
                       std::to_string(d.at<double>(r, c)) + ") at row " + std::to_string(r) +
                       ", column " + std::to_string(c) +
                       "; the calibration failed or the file was edited: recalibrate");
  return d;
}

cv::Mat read_camera_matrix(const cv::FileStorage& fs, const std::string& path,
                           const std::string& name) {
  const std::string expected = "a 3x3 camera matrix [fx 0 cx; 0 fy cy; 0 0 1]";
  cv::Mat m = read_matrix(fs, path, name, expected);
  if (m.rows != 3 || m.cols != 3)
    fail(path, "node '" + name + "' is " + shape(m) + "; expected " + expected);
  if (!(m.at<double>(0, 0) > 0 && m.at<double>(1, 1) > 0) || m.at<double>(2, 2) != 1.0)
    fail(path, "node '" + name + "' is not a camera matrix (needs fx > 0, fy > 0 and a 1 at " +
                   "(2, 2)); expected " + expected);
  return m;
}

cv::Mat read_distortion(const cv::FileStorage& fs, const std::string& path,
                        const std::string& name) {
  const std::string expected =
      "a 1xN distortion vector with N = 4, 5, 8, 12 or 14 (k1 k2 p1 p2 [k3 [k4 k5 k6 [s1 s2 s3 "
      "s4 [tx ty]]]])";
  cv::Mat d = read_matrix(fs, path, name, expected);
  const int n = static_cast<int>(d.total());
  if ((d.rows != 1 && d.cols != 1) || !(n == 4 || n == 5 || n == 8 || n == 12 || n == 14))
    fail(path, "node '" + name + "' is " + shape(d) + "; expected " + expected);
  return d.reshape(1, 1).clone();
}

int read_size_node(const cv::FileStorage& fs, const std::string& path, const std::string& name) {
  const cv::FileNode node = fs[name];
  if (!node.isInt() || static_cast<int>(node) <= 0)
    fail(path, "node '" + name + "' must be a positive integer (pixels)");
  return static_cast<int>(node);
}

StereoCalibration read_stereo_calibration(const std::string& path, cv::Size fallback_size) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    fail(path,
         "no such file; pass the YAML/XML file with M1 D1 M2 D2 R T that "
         "cv::stereoCalibrate's results were saved to (for example "
         "data/chessboard/derived_stereo_calibration_helper.yml)");
  if (std::filesystem::file_size(path, ec) == 0)
    fail(path, std::string("the file is empty; ") + kFormatHint);
  cv::FileStorage fs;
  try {
    fs = host::io::open_file_storage(path, "calibration '" + path + "'");
  } catch (const cv::Exception& e) {
    fail(path, "not an OpenCV FileStorage file (YAML starting with %YAML:1.0, XML or JSON): " +
                   e.err + "; " + kFormatHint);
  }
  if (!fs.isOpened())
    fail(path, "not an OpenCV FileStorage file (YAML starting with %YAML:1.0, XML or JSON); " +
                   std::string(kFormatHint));

  StereoCalibration c;
  c.source = path;
  c.M1 = read_camera_matrix(fs, path, "M1");
  c.D1 = read_distortion(fs, path, "D1");
  c.M2 = read_camera_matrix(fs, path, "M2");
  c.D2 = read_distortion(fs, path, "D2");

  const std::string r_expected = "a 3x3 rotation matrix (or a 3x1 Rodrigues vector)";
  cv::Mat r = read_matrix(fs, path, "R", r_expected);
  if (r.total() == 3 && (r.rows == 1 || r.cols == 1)) {
    cv::Mat rm;
    cv::Rodrigues(r.reshape(1, 3), rm);
    r = rm;
  }
  if (r.rows != 3 || r.cols != 3)
    fail(path, "node 'R' is " + shape(r) + "; expected " + r_expected);
  if (cv::norm(r * r.t(), cv::Mat::eye(3, 3, CV_64F), cv::NORM_INF) > 1e-3 ||
      cv::determinant(r) < 0)
    fail(path, "node 'R' is not a rotation (R * R^T must be the identity, det R = 1); expected " +
                   r_expected);
  c.R = r;

  const std::string t_expected = "a 3x1 translation vector from the left to the right camera";
  cv::Mat t = read_matrix(fs, path, "T", t_expected);
  if (t.total() != 3 || (t.rows != 1 && t.cols != 1))
    fail(path, "node 'T' is " + shape(t) + "; expected " + t_expected);
  c.T = t.reshape(1, 3).clone();
  if (cv::norm(c.T) == 0) fail(path, "node 'T' is zero; the two cameras need a baseline");

  const bool has_w = !fs["image_width"].empty(), has_h = !fs["image_height"].empty();
  if (has_w || has_h) {
    c.image_size = {read_size_node(fs, path, "image_width"),
                    read_size_node(fs, path, "image_height")};
  } else if (fallback_size.area() > 0) {
    c.image_size = fallback_size;
  } else {
    fail(path,
         "nodes 'image_width' and 'image_height' are missing and no image size was given; "
         "add them (the calibration images' size in pixels) or pass the images");
  }
  return c;
}

}  // namespace

StereoCalibration load_stereo_calibration(const std::string& path, cv::Size fallback_size) {
  // cv::FileStorage throws from a read the file's structure does not allow (a key looked up in
  // a list: cv::Exception; a garbled string: std::length_error); the checks in
  // read_stereo_calibration name the common faults and throw runtime_error, this the rest.
  try {
    return read_stereo_calibration(path, fallback_size);
  } catch (const std::runtime_error&) {
    throw;
  } catch (const cv::Exception& e) {
    fail(path, "the file is damaged: OpenCV cannot read it (" + e.err + "); " + kFormatHint);
  } catch (const std::exception& e) {
    fail(path, std::string("the file is damaged: OpenCV cannot read it (") + e.what() + "); " +
                   kFormatHint);
  }
}

double StereoRectification::focal_px() const { return P1.at<double>(0, 0); }

double StereoRectification::baseline() const {
  return std::abs(P2.at<double>(0, 3) / P2.at<double>(0, 0));
}

cv::Point2d StereoRectification::principal_point() const {
  return {P1.at<double>(0, 2), P1.at<double>(1, 2)};
}

StereoRectification rectify_calibration(const StereoCalibration& c, double alpha) {
  StereoRectification r;
  r.image_size = c.image_size;
  r.alpha = alpha;
  cv::stereoRectify(c.M1, c.D1, c.M2, c.D2, c.image_size, c.R, c.T, r.R1, r.R2, r.P1, r.P2, r.Q,
                    cv::CALIB_ZERO_DISPARITY, alpha, c.image_size, &r.roi1, &r.roi2);
  cv::initUndistortRectifyMap(c.M1, c.D1, r.R1, r.P1, c.image_size, CV_32FC1, r.map1_x, r.map1_y);
  cv::initUndistortRectifyMap(c.M2, c.D2, r.R2, r.P2, c.image_size, CV_32FC1, r.map2_x, r.map2_y);
  return r;
}

}  // namespace scw::rectify
