// SPDX-License-Identifier: Apache-2.0
// Writing a rendered scene (host/scene/write.hpp).
#include "host/scene/write.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "host/io/image_file.hpp"
#include "host/warning/setup.hpp"

namespace scw::host::scene {
namespace {

namespace fs = std::filesystem;

std::string frame_name(int frame, const char* side) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%04d_%s.png", frame, side);
  return buf;
}

nlohmann::json vec(const cv::Vec3d& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

nlohmann::json camera_json(const CameraModel& c) {
  return {{"fx", c.fx}, {"fy", c.fy}, {"cx", c.cx}, {"cy", c.cy},
          {"dist", {c.dist[0], c.dist[1], c.dist[2], c.dist[3], c.dist[4]}}};
}

/// Quoted for a POSIX shell when it holds anything but plain path characters.
std::string shell_word(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789_-./+=:,@") == std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string number(double v) {
  std::ostringstream os;
  os.precision(12);
  os << v;
  return os.str();
}

/// The highest frame index of earlier NNNN_left.png / NNNN_right.png files in `dir`, or -1.
int last_existing_frame(const fs::path& dir) {
  static const std::regex name(R"((\d{4})_(left|right)\.png)");
  int last = -1;
  for (const auto& e : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string n = e.path().filename().string();
    if (std::regex_match(n, m, name)) last = std::max(last, std::stoi(m[1].str()));
  }
  return last;
}

}  // namespace

std::string left_name(int frame) { return frame_name(frame, "left"); }
std::string right_name(int frame) { return frame_name(frame, "right"); }

void write_calibration(const std::string& path, const StereoRig& rig) {
  const cv::Mat m1(rig.left.matrix()), m2(rig.right.matrix());
  const cv::Mat d1 = cv::Mat(rig.left.dist).reshape(1, 1);
  const cv::Mat d2 = cv::Mat(rig.right.dist).reshape(1, 1);
  const cv::Mat r(rig.rotation()), t(rig.translation_m);
  try {
    cv::FileStorage fs(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
    if (!fs.isOpened()) throw std::runtime_error("cannot write '" + path + "'");
    fs.writeComment("scw scene: the synthetic rig (docs/scene.md); units: metres");
    fs << "image_width" << rig.image_size.width << "image_height" << rig.image_size.height;
    fs << "M1" << m1 << "D1" << d1 << "M2" << m2 << "D2" << d2 << "R" << r << "T" << t;
  } catch (const cv::Exception& e) {
    throw std::runtime_error("cannot write '" + path + "': " + e.err);
  }
}

nlohmann::json truth_json(const FrameTruth& t) {
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& o : t.objects)
    objects.push_back({{"id", o.id},
                       {"kind", kind_name(o.kind)},
                       {"box_min_m", vec(o.box_min)},
                       {"box_max_m", vec(o.box_max)},
                       {"closest_m", vec(o.closest)},
                       {"distance_m", o.distance_m},
                       {"disparity_px", o.disparity_px},
                       {"in_tunnel", o.in_tunnel},
                       {"gap_m", o.gap_m},
                       {"obstacle", o.obstacle},
                       {"in_view", o.in_view},
                       {"severity", severity_name(o.severity)}});
  const bool any = t.deciding >= 0;
  return {{"frame", t.frame},
          {"left", left_name(t.frame)},
          {"right", right_name(t.frame)},
          {"time_s", t.time_s},
          {"severity", severity_name(t.severity)},
          {"deciding", any ? nlohmann::json(t.deciding) : nlohmann::json(nullptr)},
          {"distance_m", any ? nlohmann::json(t.distance_m) : nlohmann::json(nullptr)},
          {"objects", objects}};
}

nlohmann::json rig_json(const StereoRig& rig, int subsamples, const RenderOptions& options) {
  const cv::Matx33d r = rig.rotation();
  const host::warning::WarningSetup w;
  return {{"image_size", {rig.image_size.width, rig.image_size.height}},
          {"frame_rate_hz", rig.frame_rate_hz},
          {"left", camera_json(rig.left)},
          {"right", camera_json(rig.right)},
          {"rotation_rodrigues_rad", vec(rig.rotation_rodrigues)},
          {"R",
           {{r(0, 0), r(0, 1), r(0, 2)}, {r(1, 0), r(1, 1), r(1, 2)}, {r(2, 0), r(2, 1), r(2, 2)}}},
          {"T_m", vec(rig.translation_m)},
          {"baseline_m", rig.baseline_m()},
          {"camera_in_vehicle_m", vec(rig.camera_in_vehicle_m)},
          {"vehicle_origin_m", {w.vehicle_origin.x(), w.vehicle_origin.y(), w.vehicle_origin.z()}},
          {"subsamples", subsamples},
          {"noise_sigma", options.noise_sigma},
          {"pitch_rad", rig.pitch_rad},
          {"markings", options.ground.markings},
          {"grain_contrast", options.ground.grain_contrast}};
}

std::string run_command(const std::string& dir, const std::string& out_dir,
                        const RunSettings& run, double frame_period_s) {
  std::ostringstream os;
  os << "scw run --calib " << shell_word((fs::path(dir) / "calibration.yml").string())
     << " --sequence " << shell_word(dir) << " --min-disp " << run.min_disp << " --max-disp "
     << run.max_disp << " --window " << run.window << " --tiles " << run.tiles_x << "x"
     << run.tiles_y << (run.ground ? " --ground" : "") << " --camera-height "
     << number(run.camera_height_m);
  if (run.camera_pitch_deg != 0.0) os << " --camera-pitch " << number(run.camera_pitch_deg);
  os << " --frame-period " << number(frame_period_s)
     << " --out-dir " << shell_word(out_dir);
  return os.str();
}

std::string eval_command(const std::string& dir, const std::string& out_dir) {
  return "scw eval --truth " + shell_word(dir) + " --results " +
         shell_word((fs::path(out_dir) / "results.jsonl").string());
}

nlohmann::json scene_json(const Sequence& s, const StereoRig& rig, int subsamples,
                          const RenderOptions& options, const RunSettings& run,
                          const std::string& dir, const std::string& out_dir) {
  const host::warning::WarningSetup w;
  return {{"preset", s.preset},
          {"frames", s.frames.size()},
          {"frame_period_s", s.frame_period_s},
          {"seed", s.seed},
          {"image_size", {rig.image_size.width, rig.image_size.height}},
          {"rig", rig_json(rig, subsamples, options)},
          {"warning",
           {{"tunnel_half_width_m", w.tunnel_half_width_m()},
            {"tunnel_height_m", w.tunnel_height_m()},
            {"high_m", w.high_m},
            {"medium_m", w.medium_m},
            {"near_m", w.near_m},
            {"min_height_m", w.min_height_m}}},
          {"run",
           {{"min_disp", run.min_disp},
            {"max_disp", run.max_disp},
            {"window", run.window},
            {"tiles", std::to_string(run.tiles_x) + "x" + std::to_string(run.tiles_y)},
            {"ground", run.ground},
            {"camera_height_m", run.camera_height_m},
            {"camera_pitch_deg", run.camera_pitch_deg}}},
          {"command", run_command(dir, out_dir, run, s.frame_period_s)},
          {"eval_command", eval_command(dir, out_dir)}};
}

void prepare_output_dir(const std::string& dir, int n) {
  const fs::path d(dir);
  if (n > 10000)
    throw std::runtime_error("scene: " + std::to_string(n) +
                             " frames do not fit the 4-digit names; give at most 10000");
  std::error_code ec;
  fs::create_directories(d, ec);
  if (ec || !fs::is_directory(d))
    throw std::runtime_error("cannot create the output folder '" + dir + "'" +
                             (ec ? ": " + ec.message() : ": a file of that name is in the way"));
  const int stale = last_existing_frame(d);
  if (stale >= n)
    throw std::runtime_error("'" + dir + "' already holds frames up to " + left_name(stale) +
                             " from a longer scene; `scw run --sequence` would take them too: "
                             "use an empty folder or remove them");
  // Probe: a folder can exist and still refuse files (permissions, a read-only mount).
  const fs::path probe = d / ".scw_scene_probe";
  if (!std::ofstream(probe))
    throw std::runtime_error("cannot write into the output folder '" + dir + "'");
  fs::remove(probe, ec);
}

WrittenScene write_scene(const Sequence& s, const Renderer& renderer, const std::string& dir,
                         const RenderOptions& options,
                         const std::function<void(int, int)>& progress) {
  const fs::path d(dir);
  const int n = static_cast<int>(s.frames.size());
  prepare_output_dir(dir, n);

  WrittenScene w;
  w.frames = n;
  w.dir = dir;
  w.run_out_dir = (d / "run").string();
  const StereoRig& rig = renderer.rig();
  RunSettings run;
  run.camera_height_m = rig.camera_in_vehicle_m[1];
  run.camera_pitch_deg = rig.pitch_rad * 180.0 / 3.14159265358979323846;

  std::ofstream truth(d / "truth.jsonl");
  if (!truth) throw std::runtime_error("cannot write '" + (d / "truth.jsonl").string() + "'");
  write_calibration((d / "calibration.yml").string(), rig);
  int done = 0;
  for (const auto& f : s.frames) {
    const StereoImages img = renderer.render_pair(f, options);
    for (const auto& [name, m] : {std::pair{left_name(f.index), img.left},
                                  std::pair{right_name(f.index), img.right}}) {
      io::write_image(d / name, m);
    }
    truth << truth_json(frame_truth(f, rig)).dump() << "\n";
    if (!truth) throw std::runtime_error("cannot write '" + (d / "truth.jsonl").string() + "'");
    if (progress) progress(++done, n);
  }
  std::ofstream scene(d / "scene.json");
  scene << scene_json(s, rig, renderer.rays(Side::left).subsamples(), options, run, dir,
                      w.run_out_dir)
               .dump(2)
        << "\n";
  if (!scene) throw std::runtime_error("cannot write '" + (d / "scene.json").string() + "'");
  w.run_command = run_command(dir, w.run_out_dir, run, s.frame_period_s);
  w.eval_command = eval_command(dir, w.run_out_dir);
  return w;
}

}  // namespace scw::host::scene
