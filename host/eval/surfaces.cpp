// SPDX-License-Identifier: Apache-2.0
// What the deciding object is (host/eval/surfaces.hpp).
#include "host/eval/surfaces.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "host/rectify/calibration.hpp"
#include "host/scene/presets.hpp"
#include "host/scene/rays.hpp"
#include "host/scene/render.hpp"
#include "host/scene/write.hpp"

namespace scw::host::eval {

namespace fs = std::filesystem;

std::optional<SceneView> load_scene_view(const fs::path& dir) {
  const fs::path scene = dir / "scene.json";
  if (!fs::exists(scene)) return std::nullopt;
  std::ifstream in(scene);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or a number too large
    throw std::runtime_error("'" + scene.string() + "' is not JSON (" + e.what() + ")");
  }
  if (!j.is_object() || !j.contains("preset") || !j["preset"].is_string()) return std::nullopt;
  const auto names = scene::preset_names();
  const std::string preset = j["preset"].get<std::string>();
  if (std::find(names.begin(), names.end(), preset) == names.end()) return std::nullopt;
  SceneView v;
  try {
    v.seed = j.at("seed").get<std::uint32_t>();
    v.frames = scene::make_preset(preset, j.at("frames").get<int>(), v.seed).frames;
    v.rig.pitch_rad = j.at("rig").value("pitch_rad", 0.0);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("'" + scene.string() + "' lacks what scw scene writes (" +
                             e.what() + "); render the scene again");
  }
  const auto calib = rectify::load_stereo_calibration((dir / "calibration.yml").string());
  const auto rect = rectify::rectify_calibration(calib);
  v.map_x = rect.map1_x;
  v.map_y = rect.map1_y;
  return v;
}

Surface object_surface(const SceneView& view, int frame, const cv::Mat& labels, int label) {
  if (frame < 0 || frame >= static_cast<int>(view.frames.size()))
    throw std::runtime_error("frame " + std::to_string(frame) + " is not in the scene");
  if (labels.type() != CV_16UC1 || labels.size() != view.map_x.size())
    throw std::runtime_error("the label picture of frame " + std::to_string(frame) +
                             " is not a 16-bit picture of the rectified size");
  const auto& objects = view.frames[static_cast<std::size_t>(frame)].objects;
  const cv::Vec3d origin = view.rig.centre_in_vehicle(scene::Side::left);
  const double pixel_rad = 1.0 / view.rig.left.fx;
  std::map<std::string, int> count;
  int total = 0;
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x) {
      if (labels.at<std::uint16_t>(y, x) != label) continue;
      const cv::Point2d raw(view.map_x.at<float>(y, x), view.map_y.at<float>(y, x));
      const cv::Vec3d dir = scene::ray_direction(view.rig, scene::Side::left, raw);
      const scene::Hit h = scene::cast_ray(origin, dir, objects, pixel_rad, 1, view.seed);
      const std::string name =
          h.object >= 0 ? scene::kind_name(objects[static_cast<std::size_t>(h.object)].kind)
          : h.distance_m < 1e300 ? "road"
                                 : "sky";
      ++count[name];
      ++total;
    }
  if (total == 0)
    throw std::runtime_error("frame " + std::to_string(frame) + ": the label picture holds no "
                             "pixel of object " + std::to_string(label));
  Surface best;
  for (const auto& [name, n] : count)
    if (n > best.share) best = {name, static_cast<double>(n)};
  best.share /= total;
  return best;
}

bool is_street_surface(const std::string& name) {
  return name == "road" || name == "kerb" || name == "pavement";
}

void trace_deciding_surfaces(EvalReport& report, const SceneView& view,
                             const fs::path& results_dir) {
  for (auto& f : report.frames) {
    if (f.label <= 0 || f.measured_severity == Severity::kNone) continue;
    // scw run names a frame's pictures after its left image: 0007_left.png -> 0007_labels.png.
    std::string name = scene::left_name(f.frame);
    name.replace(name.find("left"), 4, "labels");
    const fs::path file = results_dir / name;
    if (!fs::exists(file))
      throw std::runtime_error("'" + file.string() + "' is missing: tracing what decided frame " +
                               std::to_string(f.frame) + " needs the label pictures scw run "
                               "writes beside results.jsonl");
    const cv::Mat labels = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
    if (labels.empty()) throw std::runtime_error("cannot read '" + file.string() + "'");
    const Surface s = object_surface(view, f.frame, labels, f.label);
    f.deciding_surface = s.name;
    f.surface_share = s.share;
  }
  report.surfaces_traced = true;
}

}  // namespace scw::host::eval
