// SPDX-License-Identifier: Apache-2.0
// A road model from the disparity map itself, tried on what `scw run` wrote for a synthetic
// scene before it becomes a stage (docs/scene.md, "A road model: first measurements").
//
// v-disparity, shaped for streaming hardware: while frame N streams, each row keeps a small
// histogram of its pixels' disparities around the road the previous frame found (offsets of
// -W .. +W px, a count and a code sum per bin); at the row's end its peak becomes one point
// (row, mean disparity in the peak, count). Between frames a weighted least-squares line through
// those points is the road for frame N + 1, so the model adds no latency. Frame 0 starts from
// the flat road of the nominal camera height. A pixel is road when its disparity lies within
// t_abs + t_rel * d_road(v) of the road's at its row, and leaves the labelling's input.
//
// Each frame's filtered map then goes through the stages' C++ models (labelling, warning) as
// `scw run` runs them, and what decided the frame is traced back into the scene
// (host/eval/surfaces.hpp). Printed per frame and summed: severity against the truth, and how
// many frames the road, a kerb or a pavement decided.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "host/eval/surfaces.hpp"
#include "host/labelling/picture.hpp"
#include "host/labelling/run_model.hpp"
#include "host/rectify/calibration.hpp"
#include "host/reference/road_ref.hpp"
#include "host/road/run_model.hpp"
#include "host/road/setup.hpp"
#include "host/warning/run_model.hpp"
#include "host/warning/setup.hpp"
#include "tools/jsonl.hpp"

namespace {

namespace fs = std::filesystem;
namespace ev = scw::host::eval;

struct Line {  // d_road(v) = a v + b, px
  double a = 0.0, b = 0.0;
  double at(int v) const { return a * v + b; }
};

struct Settings {
  double window_px = 4.0, window_rel = 0.15;  // the histogram's half width: W = w_px + w_rel d
  int min_count = 20;                         // a row's peak needs this many pixels
  double tol_px = 1.0, tol_rel = 0.15;        // road: |d - d_road| <= tol_px + tol_rel d_road
};

struct RowPeak {
  int v;
  double d, weight;
};

/// The weighted least-squares line through the peaks within `tol` of `around` (all when tol < 0);
/// false when fewer than 10 rows take part.
bool least_squares(const std::vector<RowPeak>& peaks, const Line& around, double tol, Line& out) {
  double sw = 0, sv = 0, sd = 0, svv = 0, svd = 0;
  int rows = 0;
  for (const auto& p : peaks) {
    if (tol >= 0 && std::abs(p.d - around.at(p.v)) > tol) continue;
    const double wt = p.weight;
    sw += wt, sv += wt * p.v, sd += wt * p.d, svv += wt * p.v * p.v, svd += wt * p.v * p.d;
    ++rows;
  }
  const double det = sw * svv - sv * sv;
  if (rows < 10 || std::abs(det) < 1e-9) return false;
  out.a = (sw * svd - sv * sd) / det;
  out.b = (sd - out.a * sv) / sw;
  return true;
}

/// One frame's row peaks around `pred`, a least-squares line through them, again through the
/// peaks within 1 px of it; kept only when it is a road a car's camera can see: a height within
/// half to twice the nominal (slope b / H) and a horizon within 3 degrees of pitch of the
/// principal point. Otherwise `pred` stays.
Line fit_road(const cv::Mat& q4, const Line& pred, const Line& nominal, double focal_px,
              const Settings& s) {
  std::vector<RowPeak> peaks;
  for (int v = 0; v < q4.rows; ++v) {
    const double dp = pred.at(v);
    if (dp < 1.0) continue;
    const int w = static_cast<int>(s.window_px + s.window_rel * dp);
    std::vector<int> count(2 * w + 1, 0);
    std::vector<double> sum(2 * w + 1, 0.0);
    for (int u = 0; u < q4.cols; ++u) {
      const int code = q4.at<std::uint16_t>(v, u);
      if (code == 0) continue;
      const int o = static_cast<int>(std::lround(code / 16.0 - dp));
      if (o < -w || o > w) continue;
      ++count[o + w];
      sum[o + w] += code / 16.0;
    }
    int best = 0;
    for (int k = 1; k < 2 * w + 1; ++k)
      if (count[k] > count[best]) best = k;
    if (count[best] < s.min_count) continue;
    peaks.push_back({v, sum[best] / count[best], static_cast<double>(count[best])});
  }
  Line first, l;
  if (!least_squares(peaks, pred, -1.0, first) || !least_squares(peaks, first, 1.0, l))
    return pred;
  const double ratio = l.a / nominal.a;
  const double horizon = -l.b / l.a, nominal_horizon = -nominal.b / nominal.a;
  const double max_shift = focal_px * std::tan(3.0 * 3.141592653589793 / 180.0);
  if (!(ratio >= 0.5 && ratio <= 2.0) || std::abs(horizon - nominal_horizon) > max_shift)
    return pred;
  return l;
}

/// The v-disparity picture of a frame: a row per image row, 4 columns per disparity pixel, the
/// log of each (row, disparity) count in grey; the road the frame was filtered with in red and
/// its tolerance band in yellow.
cv::Mat vdisparity_picture(const cv::Mat& q4, const Line& road, const Settings& s) {
  constexpr int kMaxD = 128, kScale = 4;
  cv::Mat count(q4.rows, kMaxD, CV_32F, cv::Scalar(0));
  for (int v = 0; v < q4.rows; ++v)
    for (int u = 0; u < q4.cols; ++u) {
      const int d = q4.at<std::uint16_t>(v, u) / 16;
      if (d > 0 && d < kMaxD) count.at<float>(v, d) += 1.0f;
    }
  cv::Mat grey;
  cv::log(count + 1.0f, count);
  count.convertTo(grey, CV_8U, 255.0 / std::log(1.0 + q4.cols));
  cv::Mat pic;
  cv::resize(255 - grey, pic, cv::Size(kMaxD * kScale, q4.rows), 0, 0, cv::INTER_NEAREST);
  cv::cvtColor(pic, pic, cv::COLOR_GRAY2BGR);
  for (int v = 0; v + 1 < q4.rows; ++v) {
    const double d0 = road.at(v), d1 = road.at(v + 1);
    if (d0 < 1.0) continue;
    for (double sign : {-1.0, 1.0}) {
      const double t0 = d0 + sign * (s.tol_px + s.tol_rel * d0);
      const double t1 = d1 + sign * (s.tol_px + s.tol_rel * d1);
      cv::line(pic, cv::Point2d(t0 * kScale, v), cv::Point2d(t1 * kScale, v + 1),
               cv::Scalar(0, 200, 255), 1, cv::LINE_AA);
    }
    cv::line(pic, cv::Point2d(d0 * kScale, v), cv::Point2d(d1 * kScale, v + 1),
             cv::Scalar(0, 0, 255), 2, cv::LINE_AA);
  }
  cv::putText(pic, "disparity 0 .. 127 px ->", {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  return pic;
}

/// `q4` without its road pixels.
cv::Mat remove_road(const cv::Mat& q4, const Line& road, const Settings& s) {
  cv::Mat out = q4.clone();
  for (int v = 0; v < q4.rows; ++v) {
    const double dr = road.at(v);
    if (dr < 1.0) continue;
    const double tol = s.tol_px + s.tol_rel * dr;
    for (int u = 0; u < q4.cols; ++u) {
      std::uint16_t& c = out.at<std::uint16_t>(v, u);
      if (c != 0 && std::abs(c / 16.0 - dr) <= tol) c = 0;
    }
  }
  return out;
}

using scw::tools::read_jsonl;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"A v-disparity road model on a scw run of a synthetic scene (docs/scene.md)"};
  std::string scene_dir, run_dir;
  Settings s;
  bool list = false, off = false;
  std::string rule = "stage";
  scw::road::RoadSetup rs;
  double camera_height = 1.2;
  app.add_option("--scene", scene_dir, "Folder scw scene wrote")->required()->check(CLI::ExistingDirectory);
  app.add_option("--run", run_dir, "Folder scw run wrote for it (its defaults)")->required()->check(CLI::ExistingDirectory);
  app.add_option("--tol-px", s.tol_px, "Road tolerance, px")->capture_default_str();
  app.add_option("--tol-rel", s.tol_rel, "Road tolerance, share of the road's disparity")->capture_default_str();
  app.add_option("--camera-height", camera_height, "Nominal camera height for frame 0's road, m")->capture_default_str();
  app.add_option("--rule", rule,
                 "stage: the road stage (hls/road, per-pixel gate and least squares); histogram: "
                 "per-row histogram peaks, two least-squares passes")
      ->check(CLI::IsMember({"stage", "histogram"}))
      ->capture_default_str();
  app.add_option("--gate-px", rs.gate_px, "Stage rule: the fit's gate, px")->capture_default_str();
  app.add_option("--gate-rel", rs.gate_rel, "Stage rule: the fit's gate, share of d_road")->capture_default_str();
  app.add_option("--min-count", rs.min_count, "Stage rule: pixels a fit needs")->capture_default_str();
  app.add_flag("--off", off, "Remove nothing (today's chain, for comparison)");
  app.add_flag("--list", list, "Print every frame");
  int picture_frame = -1;
  std::string picture_dir;
  app.add_option("--picture-frame", picture_frame,
                 "Write this frame's v-disparity with its road, and its map before and after "
                 "removal, into --picture-dir");
  app.add_option("--picture-dir", picture_dir, "Folder for --picture-frame's pictures");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto view = ev::load_scene_view(scene_dir);
    if (!view) throw std::runtime_error("'" + scene_dir + "' holds no scene.json of a preset");
    const auto truth = read_jsonl(fs::path(scene_dir) / "truth.jsonl");
    const auto rect = scw::rectify::rectify_calibration(
        scw::rectify::load_stereo_calibration((fs::path(scene_dir) / "calibration.yml").string()));
    // The warning stage's setup as scw run makes it (defaults, d 0 .. 127).
    scw::host::warning::WarningSetup w;
    w.focal_px = rect.focal_px();
    w.baseline_m = rect.baseline();
    w.cu_px = rect.principal_point().x;
    w.cv_px = rect.principal_point().y;
    w.d_limit_px = 127;
    const auto wcfg = scw::host::warning::to_fixed(w);
    Line nominal;  // the flat road of the nominal height: d = (b / H) (v - cv)
    nominal.a = w.baseline_m / camera_height;
    nominal.b = -nominal.a * w.cv_px;
    Line road = nominal;
    rs.baseline_m = w.baseline_m;
    rs.camera_height_m = camera_height;
    rs.cv_px = w.cv_px;
    rs.focal_px = w.focal_px;
    rs.tol_px = s.tol_px;
    rs.tol_rel = s.tol_rel;
    scw::road::RoadFilter stage(scw::road::to_fixed(rs));
    int agree = 0, street = 0, frames = 0;
    std::map<std::string, int> decided;
    for (const auto& t : truth) {
      const int f = t.at("frame").get<int>();
      char name[32];
      std::snprintf(name, sizeof name, "%04d_disparity16.png", f);
      const cv::Mat q4 = cv::imread((fs::path(run_dir) / name).string(), cv::IMREAD_UNCHANGED);
      if (q4.empty() || q4.type() != CV_16UC1)
        throw std::runtime_error("'" + (fs::path(run_dir) / name).string() +
                                 "' is missing or not 16-bit: run scw run on the scene first");
      cv::Mat kept;
      if (rule == "stage") {
        kept = stage.filter(q4);
        const auto px = scw::reference::to_px(stage.road());
        road = Line{px.a, px.b};
        if (off) kept = q4;
      } else {
        kept = off ? q4 : remove_road(q4, road, s);
      }
      if (f == picture_frame && !picture_dir.empty()) {
        fs::create_directories(picture_dir);
        cv::imwrite((fs::path(picture_dir) / "vdisparity.png").string(),
                    vdisparity_picture(q4, road, s));
        cv::imwrite((fs::path(picture_dir) / "disparity.png").string(),
                    scw::labelling::disparity_picture(q4));
        cv::imwrite((fs::path(picture_dir) / "disparity_without_road.png").string(),
                    scw::labelling::disparity_picture(kept));
      }
      const Line next = rule == "stage" ? road : fit_road(q4, road, nominal, w.focal_px, s);
      const auto lcfg = scw::labelling::grid_config(kept.cols, kept.rows, 4, 4, 0, 200);
      const auto seg = scw::labelling::segment(kept, lcfg);
      const auto r =
          scw::warning::run_warning(scw::warning::table_words(seg.objects, seg.status), wcfg);
      std::string by = "-";
      if (r.index != 0xffff) {
        // The deciding object's label: objects are unique by their first pixel.
        const auto& o = seg.objects[r.index];
        const int label = seg.labels.at<std::uint16_t>(o.first_y, o.first_x);
        by = ev::object_surface(*view, f, seg.labels, label).name;
      }
      const std::string truth_sev = t.at("severity").get<std::string>();
      const bool ok = truth_sev == scw::hls::warning::severity_name(r.severity);
      agree += ok;
      street += ev::is_street_surface(by);
      ++decided[by];
      ++frames;
      if (list)
        std::printf("frame %3d road d = %.4f v %+.2f  truth %-6s %6.2f m  measured %-6s %6.2f m  "
                    "by %s%s\n",
                    f, road.a, road.b, truth_sev.c_str(),
                    t.at("distance_m").is_null() ? 0.0 : t.at("distance_m").get<double>(),
                    scw::hls::warning::severity_name(r.severity), r.distance_mm / 1000.0,
                    by.c_str(), ok ? "" : "  *");
      road = next;
    }
    std::printf("%d frames: severity agrees in %d; decided by road, kerb or pavement in %d; by:",
                frames, agree, street);
    for (const auto& [k, n] : decided) std::printf(" %s %d", k.c_str(), n);
    std::printf("\n");
  } catch (const std::exception& e) {
    std::cerr << "road_model: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
