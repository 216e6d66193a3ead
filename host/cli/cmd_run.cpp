// SPDX-License-Identifier: Apache-2.0
// `scw run`: the whole chain on a stereo pair or a folder of numbered pairs; writes the
// rectified pair, disparity, labels, the warning overlay and results.jsonl (docs/run.md).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "host/app/run.hpp"
#include "host/io/image_file.hpp"
#include "host/cli/commands.hpp"
#include "host/cli/progress.hpp"
#include "host/pipeline/rtl_engine.hpp"
#include "host/labelling/picture.hpp"
#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/map_grid.hpp"
#include "host/rectify/run_model.hpp"

namespace scw::cli {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string calib, left, right, sequence, out_dir;
  bool rectified = false;
  double focal = 0, baseline = 0, cx = -1, cy = -1;
  double calib_unit_m = 1.0;
  std::string engine = "cpp";
  std::string maps = "full";  // raw pairs: full quantised maps, or expanded grid knots
  int grid_log2 = 4;          // knot spacing of --maps grid (the thesis build's)
  std::string mode = disparity::mode_name(disparity::kDefaultMode);
  std::string tiles;
  app::RunOptions run;
};

/// Pairs in a folder: every file whose name holds "left" and has a twin with "right" in its
/// place, in name order (000_left.png / 000_right.png, left_0001.pgm / right_0001.pgm, ...).
std::vector<std::pair<fs::path, fs::path>> find_pairs(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw std::runtime_error("--sequence '" + dir.string() + "' is not a folder");
  std::vector<fs::path> lefts;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename().string().find("left") != std::string::npos)
      lefts.push_back(e.path());
  std::sort(lefts.begin(), lefts.end());
  std::vector<std::pair<fs::path, fs::path>> pairs;
  for (const auto& l : lefts) {
    std::string name = l.filename().string();
    name.replace(name.find("left"), 4, "right");
    const fs::path r = l.parent_path() / name;
    if (fs::exists(r)) pairs.emplace_back(l, r);
  }
  if (pairs.empty())
    throw std::runtime_error("--sequence '" + dir.string() +
                             "' holds no pairs: name them like 0001_left.png and 0001_right.png");
  return pairs;
}

/// "0001_left.png" -> "0001_": what a frame's output files start with in a sequence.
std::string frame_prefix(const fs::path& left) {
  std::string stem = left.stem().string();
  stem.erase(stem.find("left"), 4);
  const auto first = stem.find_first_not_of("_-.");
  const auto last = stem.find_last_not_of("_-.");
  return first == std::string::npos ? "frame_" : stem.substr(first, last - first + 1) + "_";
}

using host::io::write_image;

/// How the pairs are rectified: the host's fixed-point maps for the C++ models, and the grid
/// knots for the Verilated rectifiers (at the spacing of the build that takes the frame). Both
/// empty for pairs already rectified.
struct Rectification {
  std::optional<app::RectifyMaps> maps;
  host::pipeline::KnotSource knots;
};

/// Reads the camera from the calibration (rectified f, principal point, baseline) once and builds
/// the fixed-point maps and the knot source from it, or takes --focal/--baseline/--cx/--cy for
/// rectified pairs.
Rectification set_up_camera(Options& o, cv::Size size) {
  auto& w = o.run.warning;
  if (o.rectified) {
    // Zero is the options' "not given"; any other value must be a positive length.
    const auto need_positive = [](double v, const std::string& opt, const std::string& what,
                                  const std::string& unit, const std::string& eg) {
      if (v == 0)
        throw std::runtime_error("--rectified needs " + opt + " (" + what + ", " + unit +
                                 "), e.g. " + opt + " " + eg);
      if (!(v > 0)) {
        std::ostringstream m;
        m << opt << " " << v << ": the " << what << " must be a positive number of " << unit
          << ", e.g. " << opt << " " << eg;
        throw std::runtime_error(m.str());
      }
    };
    need_positive(o.focal, "--focal", "focal length", "px", "615");
    need_positive(o.baseline, "--baseline", "baseline", "m", "0.1");
    w.focal_px = o.focal;
    w.baseline_m = o.baseline;
    w.cu_px = o.cx >= 0 ? o.cx : (size.width - 1) / 2.0;
    w.cv_px = o.cy >= 0 ? o.cy : (size.height - 1) / 2.0;
    return {};
  }
  if (o.calib.empty())
    throw std::runtime_error("give --calib CALIB for raw pairs, or --rectified with --focal, "
                             "--baseline (and --cx, --cy) for pairs already rectified");
  const auto calib = rectify::load_stereo_calibration(o.calib, size);
  if (calib.image_size != size)
    throw std::runtime_error("the images are " + std::to_string(size.width) + " x " +
                             std::to_string(size.height) + " px but the calibration '" + o.calib +
                             "' is for " + std::to_string(calib.image_size.width) + " x " +
                             std::to_string(calib.image_size.height) + " px");
  const auto rect = rectify::rectify_calibration(calib);
  w.focal_px = rect.focal_px();
  w.baseline_m = rect.baseline() * o.calib_unit_m;
  w.cu_px = rect.principal_point().x;
  w.cv_px = rect.principal_point().y;
  app::RectifyMaps maps;
  if (o.maps == "grid") {  // what the RTL's map-grid expanders stream (docs/rectify.md)
    const auto knots = rectify::grid_knots(calib, rect, o.grid_log2);
    maps.left = rectify::expand(knots.left);
    maps.right = rectify::expand(knots.right);
  } else {
    maps.left = rectify::quantise_map(rect.map1_x, rect.map1_y);
    maps.right = rectify::quantise_map(rect.map2_x, rect.map2_y);
  }
  const auto plan = rectify::plan_for_stage(
      {rectify::row_window(maps.left), rectify::row_window(maps.right)}, rectify::kHostStageRows,
      o.calib);
  maps.lead_rows = plan.lead_rows;
  return {maps,
          [calib, rect](int grid_log2) { return rectify::grid_knots(calib, rect, grid_log2); }};
}

/// Each object with the warning stage's view of it and the application layer's.
void write_objects_csv(const fs::path& p, const app::FrameOutput& f) {
  std::ofstream csv(p);
  // disparity: what placed the object (the distance rule's); d_max: its largest.
  csv << "label,area,u0,v0,u1,v1,closest_u,closest_v,disparity,d_max,x_m,y_m,z_m,width_m,height_m,"
         "distance_m,gap_m,in_tunnel,obstacle,too_close,severity,hu1,hu2,hu3,class,track,"
         "deciding\n";
  for (const auto& r : f.objects) {
    const auto& o = r.object;
    const auto& e = r.eval;
    csv << r.label << ',' << o.area << ',' << o.x_min << ',' << o.y_min << ',' << o.x_max << ','
        << o.y_max << ',' << o.closest_x << ',' << o.closest_y << ',' << e.d_q4 / 16.0 << ','
        << o.d_max / 16.0 << ','
        << e.x_mm / 1000.0 << ',' << e.y_mm / 1000.0 << ',' << e.z_mm / 1000.0 << ','
        << e.width_mm / 1000.0 << ',' << e.height_mm / 1000.0 << ',' << e.distance_mm / 1000.0
        << ',' << e.gap_mm / 1000.0 << ',' << e.in_tunnel << ',' << e.obstacle << ','
        << e.too_close << ',' << app::severity_name(e.severity) << ',' << r.hu[0] << ','
        << r.hu[1] << ',' << r.hu[2] << ',' << r.cls << ',' << r.track << ','
        << (r.label == f.deciding_label) << "\n";
  }
  if (!csv) throw std::runtime_error("cannot write '" + p.string() + "'");
}

void write_frame(const fs::path& dir, const std::string& prefix, const app::FrameOutput& f) {
  write_image(dir / (prefix + "left_rect.png"), f.left);
  write_image(dir / (prefix + "right_rect.png"), f.right);
  // PNG has no signed 16-bit format (imwrite would write 8 bits): the Q11.4 codes go out as
  // CV_16U, invalid (negative) codes saturated to 0.
  cv::Mat q4;
  f.disparity.convertTo(q4, CV_16UC1);
  write_image(dir / (prefix + "disparity16.png"), q4);
  write_image(dir / (prefix + "disparity.png"), labelling::disparity_picture(q4));
  write_image(dir / (prefix + "labels.png"), f.segmentation.labels);
  write_image(dir / (prefix + "labels_color.png"), labelling::colour_labels(f.segmentation.labels));
  write_image(dir / (prefix + "overlay.png"), f.overlay);
  write_image(dir / (prefix + "road.png"), road::road_picture(f.left, f.road_mask));
  write_objects_csv(dir / (prefix + "objects.csv"), f);
}

void run(Options& o) {
  if (!o.tiles.empty()) {
    const auto x = o.tiles.find('x');
    try {
      if (x == std::string::npos) throw std::invalid_argument("no x");
      o.run.tiles_x = std::stoi(o.tiles.substr(0, x));
      o.run.tiles_y = std::stoi(o.tiles.substr(x + 1));
    } catch (const std::exception&) {
      throw std::runtime_error("--tiles " + o.tiles + ": give columns x rows, e.g. 4x4");
    }
  }
  o.run.mode = disparity::mode_from_name(o.mode);
  std::vector<std::pair<fs::path, fs::path>> pairs;
  if (!o.sequence.empty()) {
    if (!o.left.empty() || !o.right.empty())
      throw std::runtime_error("give either --left/--right or --sequence, not both");
    pairs = find_pairs(o.sequence);
  } else {
    if (o.left.empty() || o.right.empty())
      throw std::runtime_error("give --left and --right (or --sequence DIR)");
    pairs.emplace_back(o.left, o.right);
  }
  const cv::Mat first = host::io::read_grey_image(pairs.front().first.string());
  auto camera = set_up_camera(o, first.size());
  std::cerr << "run: " << pairs.size() << (pairs.size() == 1 ? " pair" : " pairs") << ", "
            << first.cols << " x " << first.rows << " px, f " << o.run.warning.focal_px
            << " px, baseline " << o.run.warning.baseline_m << " m, principal point ("
            << o.run.warning.cu_px << ", " << o.run.warning.cv_px << "), window " << o.run.window
            << ", d " << o.run.min_disp << " .. " << o.run.max_disp << ", " << o.mode << " mode"
            << (o.run.ground ? ", ground removal" : "") << "\n";
  app::StageEngine engine;
  if (o.engine == "rtl") {
    engine = host::pipeline::make_rtl_engine(o.run, first.cols, first.rows, camera.knots);
    std::cerr << "run: the stages run as Verilated RTL; the C++ models check every object and "
                 "frame result\n";
  }
  app::Runner runner(o.run, std::move(camera.maps), std::move(engine));

  const fs::path dir(o.out_dir);
  fs::create_directories(dir);
  std::ofstream jsonl(dir / "results.jsonl");
  if (!jsonl) throw std::runtime_error("cannot write '" + (dir / "results.jsonl").string() + "'");
  Progress progress(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const cv::Mat l = host::io::read_grey_image(pairs[i].first.string());
    const cv::Mat r = host::io::read_grey_image(pairs[i].second.string());
    if (l.size() != r.size())
      throw std::runtime_error("'" + pairs[i].first.string() + "' (" + std::to_string(l.cols) +
                               " x " + std::to_string(l.rows) + ") and '" +
                               pairs[i].second.string() + "' (" + std::to_string(r.cols) + " x " +
                               std::to_string(r.rows) + ") differ in size: a stereo pair has "
                               "one size");
    if (l.size() != first.size())
      throw std::runtime_error("pair '" + pairs[i].first.string() + "' differs in size from the "
                               "first pair: every pair of a sequence must have one size");
    const app::FrameOutput f = runner.process(l, r);
    const std::string prefix = pairs.size() == 1 ? "" : frame_prefix(pairs[i].first);
    write_frame(dir, prefix, f);
    const auto j = app::frame_json(static_cast<int>(i), f);
    jsonl << j.dump() << "\n";
    std::string note = std::string(app::severity_name(f.result.severity));
    if (f.deciding_label > 0) note += " at " + std::to_string(f.result.distance_mm / 1000.0).substr(0, 5) + " m";
    if (pairs.size() > 1) progress.show(i + 1, note);
    else std::cout << j.dump() << "\n";
  }
  std::cout << "wrote " << pairs.size() << (pairs.size() == 1 ? " frame" : " frames") << " in "
            << dir.string() << " (overlay.png, disparity.png, labels_color.png, results.jsonl)\n";
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "run", "The whole chain (rectify, disparity, labelling, warning) on the stages' C++ models, "
             "then classification, tracking and the warning overlay");
  cmd->add_option("--calib", o->calib, "OpenCV FileStorage calibration (M1 D1 M2 D2 R T) of raw pairs");
  cmd->add_option("--left", o->left, "Left image")->check(CLI::ExistingFile);
  cmd->add_option("--right", o->right, "Right image")->check(CLI::ExistingFile);
  cmd->add_option("--sequence", o->sequence, "Folder of numbered pairs (NNNN_left.png, NNNN_right.png)");
  cmd->add_option("--out-dir", o->out_dir, "Where the pictures and results.jsonl go")->required();
  cmd->add_flag("--rectified", o->rectified, "The pairs are already rectified: skip rectification");
  cmd->add_option("--focal", o->focal, "With --rectified: focal length, px");
  cmd->add_option("--baseline", o->baseline, "With --rectified: baseline, m");
  cmd->add_option("--cx", o->cx, "With --rectified: principal point u, px (default: image centre)");
  cmd->add_option("--cy", o->cy, "With --rectified: principal point v, px (default: image centre)");
  cmd->add_option("--calib-unit-m", o->calib_unit_m,
                  "Metres per calibration unit (e.g. the chessboard square), default 1")->capture_default_str();
  cmd->add_option("--engine", o->engine,
                  "cpp: the stages' C++ models; rtl: every block Verilated (rectified pairs, a "
                  "built size: small up to 128 x 96, window 9, 16 disparities, 2x2 tiles)")
      ->capture_default_str()
      ->check(CLI::IsMember({"cpp", "rtl"}));
  cmd->add_option("--maps", o->maps,
                  "Raw pairs on --engine cpp: full (the calibration's maps, quantised) or grid "
                  "(knots every 2^--grid-log2 px, expanded as the RTL's map-grid stage does; "
                  "--engine rtl always runs grid knots at its build's spacing)")
      ->capture_default_str()
      ->check(CLI::IsMember({"full", "grid"}));
  cmd->add_option("--grid-log2", o->grid_log2,
                  "Knot spacing of --maps grid, log2 px (4: the thesis build's 16 px)")
      ->capture_default_str()
      ->check(CLI::Range(2, 7));
  cmd->add_option("--tiles", o->tiles, "Labelling tile grid, columns x rows (default 4x4)");
  cmd->add_option("--window", o->run.window, "SAD window N")->capture_default_str();
  cmd->add_option("--min-disp", o->run.min_disp, "Smallest candidate disparity")->capture_default_str();
  cmd->add_option("--max-disp", o->run.max_disp,
                  "Largest candidate; objects reaching it are flagged too_close")->capture_default_str();
  cmd->add_option("--mode", o->mode, "Disparity mode (scw disparity --help)")->capture_default_str()
      ->check(CLI::IsMember({"thesis", "opencv"}));
  cmd->add_option("--min-area", o->run.min_area, "Smallest object, px")->capture_default_str();
  cmd->add_flag("!--no-road", o->run.road,
                "Keep the road in the labelling's input (the road stage passes every pixel)");
  cmd->add_flag("--ground", o->run.ground, "Ground-plane removal (thesis 6.2) before labelling");
  cmd->add_option("--camera-height", o->run.camera_height_m,
                  "Camera height above the road, m (the road stage's first road, ground removal's slope)")->capture_default_str();
  cmd->add_option("--camera-pitch", o->run.camera_pitch_deg,
                  "Camera's downward pitch, degrees (the road stage's first horizon; the road "
                  "it fits replaces it)")->capture_default_str();
  cmd->add_option("--min-height", o->run.warning.min_height_m,
                  "Lower objects are not obstacles (road markings), m")->capture_default_str();
  cmd->add_option_function<std::string>(
         "--distance-rule",
         [o](const std::string& rule) {
           o->run.warning.distance_rule = rule == "closest" ? hls::warning::DistanceRule::kClosest
                                                            : hls::warning::DistanceRule::kSpread;
         },
         "Which disparity places an object: spread, min(d_max, mean + k sd) of its disparities "
         "(default), or closest, its largest (the thesis's)")
      ->check(CLI::IsMember({"spread", "closest"}));
  cmd->add_option("--spread-k", o->run.warning.spread_k,
                  "k of the spread rule, 0 .. 15.9375 (steps of 1/16)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 15.9375));
  cmd->add_option("--near", o->run.warning.near_m,
                  "Outside the tunnel: medium when this close to it, m")->capture_default_str();
  cmd->add_option("--car-width", o->run.warning.car_width_m, "Car width, m (tunnel: 1.5x)")->capture_default_str();
  cmd->add_option("--car-height", o->run.warning.car_height_m, "Car height, m (tunnel: 1.5x)")->capture_default_str();
  cmd->add_option("--classifier", o->run.classifier,
                  "Model from scw train (SVM or neural network); default: the parallelepiped "
                  "classifier of Table 5.4")
      ->check(CLI::ExistingFile);
  cmd->add_option("--classifier-s", o->run.classifier_s,
                  "The parallelepiped classifier's interval m +- s sigma (Table 5.5)")
      ->capture_default_str();
  cmd->add_flag("--kalman", o->run.kalman, "Track with a cv::KalmanFilter (constant velocity)");
  cmd->add_option("--frame-period", o->run.frame_period_s, "Seconds between frames (speed)")
      ->capture_default_str();
  cmd->add_flag("--overlay-on-labels", o->run.overlay_on_labels,
                "Draw the overlay on the label picture instead of the left image");
  cmd->callback([o] { run(*o); });
}

}  // namespace scw::cli
