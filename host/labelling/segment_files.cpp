// SPDX-License-Identifier: Apache-2.0
// read_disparity_map(), the object and region CSVs (host/labelling/segment_files.hpp).
#include "host/labelling/segment_files.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <opencv2/imgcodecs.hpp>

#include "host/labelling/hu_moments.hpp"

namespace scw::labelling {
namespace {

const char* const kSupported =
    "scw segment reads a single-channel disparity map: a 16-bit PNG of disparity x 16 (Q11.4, "
    "what `scw disparity --out16` writes) or an 8-bit image of disparity x S (--scale S, "
    "default 16 as Middlebury's ground truth)";

}  // namespace

DisparityInput read_disparity_map(const std::string& path, double scale, bool scale_given) {
  const cv::Mat img = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (img.empty())
    throw std::runtime_error("cannot read '" + path + "' as an image; " + kSupported);
  DisparityInput in;
  if (img.type() == CV_16UC1 || img.type() == CV_16SC1) {
    if (scale_given)
      throw std::runtime_error("'" + path +
                               "' is 16-bit, already disparity x 16 (Q11.4); --scale applies to "
                               "8-bit maps only, drop it");
    // `scw disparity --out16` stores int16 bit patterns: a negative invalid code (opencv mode)
    // reads as >= 0x8000 in a 16-bit PNG; both are no data.
    img.convertTo(in.q4, CV_16UC1);  // a no-op copy for 16U; CV_16S negatives saturate to 0
    if (img.type() == CV_16SC1) in.negatives = cv::countNonZero(img < 0);
    for (int y = 0; y < in.q4.rows; ++y)
      for (int x = 0; x < in.q4.cols; ++x) {
        auto& d = in.q4.at<std::uint16_t>(y, x);
        if (d >= 0x8000) d = 0, ++in.negatives;
      }
    in.kind = "16-bit Q11.4";
    return in;
  }
  if (img.type() == CV_8UC1) {
    if (!(scale > 0) || 255.0 * 16.0 / scale > 32767.0)
      throw std::runtime_error("--scale " + std::to_string(scale) +
                               " cannot be used: 8-bit values are disparity x S with S > 0 and "
                               "255 / S at most 2047 px (the stage's Q11.4 range)");
    in.q4.create(img.size(), CV_16UC1);
    for (int y = 0; y < img.rows; ++y)
      for (int x = 0; x < img.cols; ++x)
        in.q4.at<std::uint16_t>(y, x) =
            static_cast<std::uint16_t>(std::lround(img.at<std::uint8_t>(y, x) * 16.0 / scale));
    std::ostringstream kind;
    kind << "8-bit, disparity = value / " << scale;
    in.kind = kind.str();
    return in;
  }
  throw std::runtime_error("'" + path + "' has " + std::to_string(img.channels()) +
                           " channel(s) of " + std::to_string(8 * img.elemSize1()) +
                           "-bit values; " + kSupported);
}

std::string px_text(int q4) {
  std::string s = std::to_string(q4 / 16);
  if (const int frac = q4 % 16; frac != 0) {
    std::string digits = std::to_string(10000 + frac * 625).substr(1);
    while (digits.back() == '0') digits.pop_back();
    s += "." + digits;
  }
  return s;
}

namespace {

std::ofstream open_csv(const std::filesystem::path& p) {
  std::ofstream f(p);
  if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
  f.precision(12);  // Hu invariants span many decades: significant digits, not decimals
  return f;
}

}  // namespace

void write_objects_csv(const std::filesystem::path& p, const std::vector<Object>& objects) {
  std::ofstream f = open_csv(p);
  f << "label,area,x_min,x_max,y_min,y_max,d_min,d_max,d_min_q4,d_max_q4,closest_x,closest_y,"
       "first_x,first_y,m10,m01,m20,m11,m02,m30,m21,m12,m03,hu1,hu2,hu3,hu4,hu5,hu6,hu7\n";
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const Object& o = objects[k];
    f << k + 1 << ',' << o.area << ',' << o.x_min << ',' << o.x_max << ',' << o.y_min << ','
      << o.y_max << ',' << px_text(o.d_min) << ',' << px_text(o.d_max) << ',' << o.d_min << ','
      << o.d_max << ',' << o.closest_x << ',' << o.closest_y << ',' << o.first_x << ',' << o.first_y << ','
      << o.m10 << ',' << o.m01 << ',' << o.m20 << ',' << o.m11 << ',' << o.m02 << ',' << o.m30
      << ',' << o.m21 << ',' << o.m12 << ',' << o.m03;
    for (const double h : hu_moments(o)) f << ',' << h;
    f << '\n';
  }
  if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
}

void write_regions_csv(const std::filesystem::path& p, const std::vector<Region>& regions) {
  std::ofstream f = open_csv(p);
  f << "region,labels,area,x_min,x_max,y_min,y_max,d_min,d_max,d_median,closest_x,closest_y,"
       "hull_px,visible_px,hull\n";
  for (std::size_t g = 0; g < regions.size(); ++g) {
    const auto& r = regions[g];
    const Object& o = r.object;
    std::string labels, hull;
    for (const int k : r.labels) labels += (labels.empty() ? "" : " ") + std::to_string(k);
    for (const auto& q : r.hull.polygon)
      hull += (hull.empty() ? "" : " ") + std::to_string(q.x) + ":" + std::to_string(q.y);
    f << g + 1 << ',' << labels << ',' << o.area << ',' << o.x_min << ',' << o.x_max << ','
      << o.y_min << ',' << o.y_max << ',' << px_text(o.d_min) << ',' << px_text(o.d_max) << ','
      << px_text(r.d_median) << ',' << o.closest_x << ',' << o.closest_y << ','
      << cv::countNonZero(r.hull.mask) << ',' << cv::countNonZero(r.visible) << ',' << hull << '\n';
  }
  if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
}

std::string status_flags(const FrameStatus& s) {
  std::string t;
  for (const auto& [flag, name] :
       {std::pair{s.tile_overflow, "tile_overflow"},
        std::pair{s.object_overflow, "object_overflow"}, std::pair{s.stream_error, "stream_error"}})
    if (flag) t += (t.empty() ? "" : " ") + std::string(name);
  return t.empty() ? "ok" : t;
}

}  // namespace scw::labelling
