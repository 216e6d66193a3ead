// SPDX-License-Identifier: Apache-2.0
// [scene] The synthetic stereo scenes: rays against cv::projectPoints, a rendered pair's
// disparity after rectification against f b / Z, the truth's eq. 5.2, the presets, the files.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "host/rectify/calibration.hpp"
#include "host/scene/presets.hpp"
#include "host/scene/rays.hpp"
#include "host/scene/render.hpp"
#include "host/scene/truth.hpp"
#include "host/scene/write.hpp"
#include "host/warning/setup.hpp"

namespace {

namespace fs = std::filesystem;
using namespace scw::host::scene;
using scw::host::warning::WarningSetup;

/// The thesis rig's renderer, built once: its two ray tables take seconds.
const Renderer& thesis_renderer() {
  static const Renderer r{StereoRig{}};
  return r;
}

/// A small rig (160 x 60, the thesis rig's optics scaled by 1/8) for tests of everything but
/// the optics: it renders in milliseconds.
StereoRig small_rig() {
  StereoRig rig;
  rig.image_size = {160, 60};
  for (CameraModel* c : {&rig.left, &rig.right}) {
    c->fx /= 8;
    c->fy /= 8;
    c->cx = (c->cx + 0.5) / 8 - 0.5;
    c->cy = (c->cy + 0.5) / 8 - 0.5;
  }
  return rig;
}

/// A fresh, empty folder under the system's temporary folder.
fs::path scratch(const std::string& name) {
  const fs::path p =
      fs::temp_directory_path() / ("scw_test_scene_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

double angle(const cv::Vec3d& a, const cv::Vec3d& b) {
  return std::atan2(cv::norm(a.cross(b)), a.dot(b));
}

/// A vehicle point in the camera's own frame.
cv::Vec3d in_camera(const StereoRig& rig, Side s, const cv::Vec3d& p) {
  const cv::Vec3d l = rig.vehicle_to_left(p);
  return s == Side::left ? l : rig.rotation() * l + rig.translation_m;
}

cv::Point2d project(const StereoRig& rig, Side s, const cv::Vec3d& p_cam) {
  std::vector<cv::Point2d> uv;
  cv::projectPoints(std::vector<cv::Point3d>{{p_cam[0], p_cam[1], p_cam[2]}}, cv::Vec3d(0, 0, 0),
                    cv::Vec3d(0, 0, 0), rig.camera(s).matrix(), rig.camera(s).dist, uv);
  return uv.front();
}

/// A box standing on the road: x from x_min, 0.4 m deep, its front at z.
SceneObject box(int id, double x_min, double width, double front_z, double height = 1.75) {
  SceneObject o;
  o.id = id;
  o.box_min = {x_min, 0.0, front_z};
  o.box_max = {x_min + width, height, front_z + 0.4};
  o.texture_origin = o.box_min;
  return o;
}

Severity severity_of(const SceneObject& o) { return object_truth(o, StereoRig{}).severity; }

}  // namespace

TEST_CASE("rays: each camera's ray through a projected point passes through the point", "[scene]") {
  const Renderer& r = thesis_renderer();
  const StereoRig& rig = r.rig();
  const std::vector<cv::Vec3d> points{{0.3, 1.2, 20.0},  {-3.5, 0.1, 8.0}, {5.5, 2.6, 12.0},
                                      {-7.0, 3.0, 18.0}, {0.0, 0.0, 9.0},  {3.0, 0.05, 7.0}};
  for (Side s : {Side::left, Side::right}) {
    const RayTable& rays = r.rays(s);
    const int n = rays.subsamples();
    REQUIRE(cv::norm(rays.origin() - rig.centre_in_vehicle(s)) == 0.0);
    for (const cv::Vec3d& p : points) {
      const cv::Point2d uv = project(rig, s, in_camera(rig, s, p));
      INFO("camera " << (s == Side::left ? "left" : "right") << ", point " << p << " at " << uv);
      REQUIRE(uv.x > 0.0);
      REQUIRE(uv.x < rig.image_size.width - 1.0);
      REQUIRE(uv.y > 0.0);
      REQUIRE(uv.y < rig.image_size.height - 1.0);
      CHECK(angle(ray_direction(rig, s, uv), p - rays.origin()) < 1e-9);
      // The table at the sample nearest uv: the same ray as ray_direction there (float table).
      const int sx = static_cast<int>(std::lround((uv.x + 0.5) * n - 0.5));
      const int sy = static_cast<int>(std::lround((uv.y + 0.5) * n - 0.5));
      const cv::Point2d at(sx / n + subsample_offset(sx % n, n),
                           sy / n + subsample_offset(sy % n, n));
      CHECK(std::abs(at.x - uv.x) <= 0.5 / n + 1e-12);
      CHECK(std::abs(at.y - uv.y) <= 0.5 / n + 1e-12);
      CHECK(angle(rays.direction(sx, sy), ray_direction(rig, s, at)) < 1e-6);
    }
    // Round trip from the table: corners, edges and the middle, marched 10 m and projected back,
    // land on their sub-sample centres within 1e-6 rad.
    const int w = rig.image_size.width * n, h = rig.image_size.height * n;
    for (const auto& [sx, sy] : std::vector<std::pair<int, int>>{{0, 0},
                                                                 {w - 1, 0},
                                                                 {0, h - 1},
                                                                 {w - 1, h - 1},
                                                                 {w / 2, h / 2},
                                                                 {1, h / 2},
                                                                 {w / 3, 2},
                                                                 {2 * w / 3, h - 3}}) {
      const cv::Vec3d d = rays.direction(sx, sy);
      const cv::Vec3d p = rays.origin() + 10.0 / cv::norm(d) * d;
      const cv::Point2d uv = project(rig, s, in_camera(rig, s, p));
      const cv::Point2d at(sx / n + subsample_offset(sx % n, n),
                           sy / n + subsample_offset(sy % n, n));
      INFO("sample " << sx << ", " << sy);
      CHECK(cv::norm(uv - at) / rig.camera(s).fx < 1e-6);
    }
  }
}

TEST_CASE("render: a rendered, rectified pedestrian's disparity is f b / Z", "[scene]") {
  const Renderer& r = thesis_renderer();
  const StereoRig& rig = r.rig();
  // Fronto-parallel, on the left camera's axis, its front 10 m from the bumper (Z = 11.65 m).
  SceneFrame f;
  f.objects.push_back(standing_box(1, Kind::pedestrian, {0.60, 1.75, 0.40},
                                   rig.camera_in_vehicle_m[0], 10.0, SurfaceLook{7, 90.0, 40.0}));
  const StereoImages raw = r.render_pair(f, RenderOptions{});

  const fs::path dir = scratch("rectify");
  write_calibration((dir / "calibration.yml").string(), rig);
  const auto calib = scw::rectify::load_stereo_calibration((dir / "calibration.yml").string());
  const auto rect = scw::rectify::rectify_calibration(calib);
  fs::remove_all(dir);
  cv::Mat left, right;
  cv::remap(raw.left, left, rect.map1_x, rect.map1_y, cv::INTER_LINEAR);
  cv::remap(raw.right, right, rect.map2_x, rect.map2_y, cv::INTER_LINEAR);

  // The face's centre in the rectified left camera, and the disparity its depth gives.
  const cv::Vec3d centre = rig.vehicle_to_left({rig.camera_in_vehicle_m[0], 0.875, 10.0});
  const cv::Vec3d c = cv::Matx33d(rect.R1) * centre;
  const double fr = rect.focal_px();
  const double expected = fr * rect.baseline() / c[2];
  const int u0 = static_cast<int>(std::lround(fr * c[0] / c[2] + rect.principal_point().x));
  const int v0 = static_cast<int>(std::lround(fr * c[1] / c[2] + rect.principal_point().y));
  const double truth = frame_truth(f, rig).objects.front().disparity_px;
  CHECK(std::abs(truth - expected) < 0.05);  // the truth's f and b are the raw rig's

  // SAD over 13 x 13 patches spread over the face (72 x 210 px), refined by a parabola.
  std::vector<double> found;
  const int half = 6, lo = static_cast<int>(expected) - 8, hi = static_cast<int>(expected) + 8;
  for (int dv : {-80, -40, 0, 40, 80})
    for (int du : {-20, -10, 0, 10, 20}) {
      const cv::Rect patch(u0 + du - half, v0 + dv - half, 2 * half + 1, 2 * half + 1);
      std::vector<double> sad;
      for (int d = lo; d <= hi; ++d) {
        cv::Mat diff;
        cv::absdiff(left(patch), right(patch - cv::Point(d, 0)), diff);
        sad.push_back(cv::sum(diff)[0]);
      }
      const auto best = static_cast<int>(std::min_element(sad.begin(), sad.end()) - sad.begin());
      REQUIRE(best > 0);
      REQUIRE(best < static_cast<int>(sad.size()) - 1);
      const double a = sad[best - 1], b = sad[best], e = sad[best + 1];
      found.push_back(lo + best + 0.5 * (a - e) / (a - 2 * b + e));
    }
  std::sort(found.begin(), found.end());
  const double median = found[found.size() / 2];
  INFO("expected " << expected << " px, truth " << truth << " px, found " << found.front() << " .. "
                   << found.back() << ", median " << median);
  CHECK(std::abs(median - expected) < 0.5);
  CHECK(std::abs(median - truth) < 0.5);
  for (double d : found) CHECK(std::abs(d - expected) < 1.0);
}

TEST_CASE("rig: a camera pitched down sees the horizon above its principal point", "[scene]") {
  StereoRig rig;
  rig.pitch_rad = 1.0 * 3.141592653589793 / 180.0;
  // A point far ahead at the camera's height lies on the horizon: v = cy - fy tan(pitch) (the
  // lens bends it by less than 0.001 px this close to the centre).
  const cv::Vec3d far = rig.camera_in_vehicle_m + cv::Vec3d(0.0, 0.0, 1e4);
  const cv::Point2d uv = project(rig, Side::left, rig.vehicle_to_left(far));
  CHECK(uv.y == Approx(rig.left.cy - rig.left.fy * std::tan(rig.pitch_rad)).margin(0.01));
  CHECK(uv.x == Approx(rig.left.cx).margin(0.01));
  // The optical axis points down; the frames are each other's inverse.
  CHECK(rig.left_dir_to_vehicle({0, 0, 1})[1] == Approx(-std::sin(rig.pitch_rad)));
  const cv::Vec3d p(1.0, 2.0, 30.0);
  CHECK(cv::norm(rig.left_to_vehicle(rig.vehicle_to_left(p)) - p) < 1e-12);
}

TEST_CASE("truth: the severity follows eq. 5.2 with WarningSetup's tunnel", "[scene]") {
  const WarningSetup w;
  const double hw = w.tunnel_half_width_m(), th = w.tunnel_height_m();
  // Centred boxes contain the camera's x, so their distance is exactly their front's z.
  CHECK(object_truth(box(1, -0.3, 0.6, 8.0), StereoRig{}).distance_m == Approx(8.0).margin(1e-12));
  CHECK(severity_of(box(1, -0.3, 0.6, 8.0)) == Severity::kHigh);
  CHECK(severity_of(box(1, -0.3, 0.6, 10.0)) == Severity::kHigh);  // D <= high
  CHECK(severity_of(box(1, -0.3, 0.6, 15.0)) == Severity::kMedium);
  CHECK(severity_of(box(1, -0.3, 0.6, 20.0)) == Severity::kLow);  // D < medium fails
  CHECK(severity_of(box(1, -0.3, 0.6, 25.0)) == Severity::kLow);

  // Beside the tunnel, 8 m ahead: 0.5 m away is near, 3 m is not; either side.
  const ObjectTruth near = object_truth(box(1, hw + 0.5, 0.6, 8.0), StereoRig{});
  CHECK_FALSE(near.in_tunnel);
  CHECK(near.gap_m == Approx(0.5).margin(1e-12));
  CHECK(near.severity == Severity::kMedium);
  CHECK(severity_of(box(1, -hw - 0.5 - 0.6, 0.6, 8.0)) == Severity::kMedium);
  CHECK(severity_of(box(1, hw + 3.0, 0.6, 8.0)) == Severity::kLow);
  CHECK(severity_of(box(1, hw + 0.5, 0.6, 25.0)) == Severity::kLow);  // near but far ahead
  // Touching the tunnel's edge counts as inside.
  CHECK(object_truth(box(1, hw, 0.6, 8.0), StereoRig{}).in_tunnel);

  // Above the tunnel's roof: outside by the vertical gap.
  SceneObject sign = box(1, -0.3, 0.6, 8.0);
  sign.box_min[1] = th + 0.2;
  sign.box_max[1] = th + 1.0;
  const ObjectTruth above = object_truth(sign, StereoRig{});
  CHECK_FALSE(above.in_tunnel);
  CHECK(above.gap_m == Approx(0.2).margin(1e-12));

  // Lower than min_height: not an obstacle, so no severity and it never decides.
  const ObjectTruth flat = object_truth(box(1, -0.3, 0.6, 8.0, 0.3), StereoRig{});
  CHECK_FALSE(flat.obstacle);
  CHECK(flat.severity == Severity::kNone);

  // The frame: the worst severity decides, then the nearer one; nothing in view is "none".
  SceneFrame f;
  f.objects = {box(1, hw + 3.0, 0.6, 5.0), box(2, -0.3, 0.6, 15.0), box(3, -0.3, 0.6, 12.0),
               box(4, -0.3, 0.6, 6.0, 0.3)};
  const FrameTruth t = frame_truth(f, StereoRig{});
  CHECK(t.severity == Severity::kMedium);
  CHECK(t.deciding == 3);
  CHECK(t.distance_m == Approx(12.0));
  f.objects = {box(1, -0.3, 0.6, -3.0), box(2, 40.0, 0.6, 8.0)};  // behind the camera, far aside
  const FrameTruth none = frame_truth(f, StereoRig{});
  CHECK_FALSE(none.objects[0].in_view);
  CHECK_FALSE(none.objects[1].in_view);
  CHECK(none.severity == Severity::kNone);
  CHECK(none.deciding == -1);
  CHECK(std::string(severity_name(Severity::kMedium)) == "medium");
}

TEST_CASE("truth: in view means both cameras see some of the box", "[scene]") {
  const StereoRig rig;
  // A cyclist's box at the left edge, 8 m ahead (cyclist-crossing, frame 8): its near right
  // edge is inside the left image, but 0.3 m further right the right camera sees it 40 px
  // further left, past its edge. Stereo cannot measure it, so it is not in view.
  SceneObject edge = box(1, -5.9, 1.8, 8.0);
  const cv::Vec3d corner = rig.vehicle_to_left({-4.1, 1.2, 8.0});
  const double u_left = rig.left.fx * corner[0] / corner[2] + rig.left.cx;
  REQUIRE(u_left >= 0.0);  // the left camera alone sees it
  const cv::Vec3d in_right = rig.rotation() * corner + rig.translation_m;
  REQUIRE(rig.right.fx * in_right[0] / in_right[2] + rig.right.cx < -20.0);
  CHECK_FALSE(object_truth(edge, rig).in_view);
  // A metre further right both cameras see its right edge.
  edge = box(1, -4.9, 1.8, 8.0);
  CHECK(object_truth(edge, rig).in_view);
}

TEST_CASE("presets: they re-enact the thesis's experiments", "[scene]") {
  const StereoRig rig;
  CHECK(preset_names() == std::vector<std::string>{"distance-sweep", "cyclist-crossing",
                                                   "pedestrian-running", "street-crossing",
                                                   "street-driving"});
  CHECK(make_preset("distance-sweep").frames.size() == 49);
  CHECK(make_preset("cyclist-crossing").frames.size() == 57);
  CHECK(make_preset("pedestrian-running").frames.size() == 38);
  CHECK(make_preset("street-crossing").frames.size() == 41);
  CHECK(make_preset("street-driving").frames.size() == 41);
  for (const auto& p : preset_names()) {
    CHECK(make_preset(p, 2).frames.size() == 2);
    CHECK(make_preset(p, 7).frames.size() == 7);
  }

  SECTION("distance-sweep: 30, 29.5, .. 6 m from the bumper") {
    const Sequence s = make_preset("distance-sweep");
    for (const auto& f : s.frames) {
      const FrameTruth t = frame_truth(f, rig);
      REQUIRE(t.deciding == 1);
      CHECK(std::abs(t.distance_m - (30.0 - 0.5 * f.index)) < 1e-9);
      CHECK(t.objects[0].in_tunnel);
      CHECK(t.severity == (t.distance_m <= 10.0  ? Severity::kHigh
                           : t.distance_m < 20.0 ? Severity::kMedium
                                                 : Severity::kLow));
    }
    const Sequence two = make_preset("distance-sweep", 2);
    CHECK(frame_truth(two.frames[0], rig).distance_m == Approx(30.0).margin(1e-9));
    CHECK(frame_truth(two.frames[1], rig).distance_m == Approx(6.0).margin(1e-9));
  }

  SECTION("cyclist-crossing: low, medium, high, medium, low while in view") {
    const Sequence s = make_preset("cyclist-crossing");
    CHECK(s.frame_period_s == Approx(0.05));
    CHECK(s.frames.back().time_s == Approx(2.8));
    std::vector<Severity> runs;
    for (const auto& f : s.frames) {
      const Severity sev = frame_truth(f, rig).severity;
      if (runs.empty() || runs.back() != sev) runs.push_back(sev);
    }
    // It starts and ends wholly outside the left image (x = -7 and +7 m at 8 m): "none" there.
    CHECK(runs == std::vector<Severity>{Severity::kNone, Severity::kLow, Severity::kMedium,
                                        Severity::kHigh, Severity::kMedium, Severity::kLow,
                                        Severity::kNone});
    const cv::Vec3d first = s.frames.front().objects[0].box_min;
    const cv::Vec3d second = s.frames[1].objects[0].box_min;
    CHECK(second[0] - first[0] == Approx(0.25));
  }

  SECTION("pedestrian-running: 25 m to 6.5 m at 3 m/s beside a parked car") {
    const Sequence s = make_preset("pedestrian-running");
    CHECK(s.frame_period_s == Approx(0.5 / 3.0));
    CHECK(s.frames.front().objects[0].box_min[2] == 25.0);
    CHECK(s.frames.back().objects[0].box_min[2] == 6.5);
    for (const auto& f : s.frames) {
      REQUIRE(f.objects.size() == 2);
      CHECK(f.objects[1].kind == Kind::car);
      CHECK(f.objects[1].box_min == s.frames.front().objects[1].box_min);
    }
    CHECK(frame_truth(s.frames.front(), rig).severity == Severity::kLow);
    CHECK(frame_truth(s.frames.back(), rig).severity == Severity::kHigh);
    CHECK(frame_truth(s.frames.back(), rig).deciding == 1);
  }

  SECTION("street presets: kerbs, pavements and buildings on both sides, cars parked on the right") {
    for (const char* name : {"street-crossing", "street-driving"}) {
      INFO(name);
      const Sequence s = make_preset(name);
      CHECK(s.ground.markings);
      CHECK(s.ground.grain_contrast == (std::string(name) == "street-crossing" ? 25.0 : 60.0));
      CHECK(s.pitch_rad == Approx(3.141592653589793 / 180.0));
      StereoRig pitched;
      pitched.pitch_rad = s.pitch_rad;
      for (const auto& f : s.frames) {
        std::map<Kind, int> count;
        for (const auto& o : f.objects) {
          ++count[o.kind];
          const ObjectTruth t = object_truth(o, pitched);
          // Kerb and pavement stand 0.12 m high: never obstacles; they and the buildings stay
          // outside the tunnel, the buildings beyond its "near" band.
          if (o.kind == Kind::kerb || o.kind == Kind::pavement) CHECK_FALSE(t.obstacle);
          if (o.kind != Kind::pedestrian) CHECK_FALSE(t.in_tunnel);
          if (o.kind == Kind::building) CHECK(t.gap_m > 4.0);
          CHECK(o.box_min[2] >= 2.0);  // cut to the view ahead of the bumper
        }
        CHECK(count[Kind::kerb] == 2);
        CHECK(count[Kind::pavement] == 2);
        CHECK(count[Kind::building] >= 4);
        CHECK(count[Kind::car] >= 2);
      }
    }
    // Crossing: the pedestrian decides, high while in the tunnel 9 m ahead.
    const Sequence c = make_preset("street-crossing");
    StereoRig pitched;
    pitched.pitch_rad = c.pitch_rad;
    const FrameTruth mid = frame_truth(c.frames[20], pitched);
    CHECK(mid.deciding == 1);
    CHECK(mid.severity == Severity::kHigh);
    // Driving: the street slides towards the car, its texture with it; part ids stay.
    const Sequence d = make_preset("street-driving");
    const double travel = 32.0 / 40.0;
    const auto& a = d.frames[0].objects;
    const auto& b = d.frames[1].objects;
    for (const auto& o : b) {
      const auto same = std::find_if(a.begin(), a.end(), [&](const auto& p) { return p.id == o.id; });
      if (same == a.end() || same->kind != o.kind) continue;
      CHECK(o.texture_origin[2] == Approx(same->texture_origin[2] - travel));
    }
  }

  SECTION("refusals") {
    CHECK_THROWS_WITH(make_preset("crossing"), Catch::Contains("distance-sweep, cyclist-crossing, "
                                                               "pedestrian-running"));
    CHECK_THROWS_AS(make_preset("crossing"), std::invalid_argument);
    CHECK_THROWS_WITH(make_preset("distance-sweep", 1), Catch::Contains("at least 2"));
    CHECK_THROWS_AS(make_preset("distance-sweep", 0), std::invalid_argument);
    CHECK_THROWS_AS(make_preset("crossing", 5), std::invalid_argument);
  }
}

TEST_CASE("write: the calibration written loads through rectify and equals the rig", "[scene]") {
  const StereoRig rig;
  const fs::path dir = scratch("calib");
  const std::string path = (dir / "calibration.yml").string();
  write_calibration(path, rig);
  const auto c = scw::rectify::load_stereo_calibration(path);
  fs::remove_all(dir);
  CHECK(c.image_size == cv::Size(1280, 480));
  CHECK(cv::norm(c.M1, cv::Mat(rig.left.matrix()), cv::NORM_INF) == 0.0);
  CHECK(cv::norm(c.M2, cv::Mat(rig.right.matrix()), cv::NORM_INF) == 0.0);
  REQUIRE(c.D1.size() == cv::Size(5, 1));
  REQUIRE(c.D2.size() == cv::Size(5, 1));
  for (int i = 0; i < 5; ++i) {
    CHECK(c.D1.at<double>(0, i) == rig.left.dist[i]);
    CHECK(c.D2.at<double>(0, i) == rig.right.dist[i]);
  }
  CHECK(cv::norm(c.R, cv::Mat(rig.rotation()), cv::NORM_INF) == 0.0);
  cv::Vec3d rvec;
  cv::Rodrigues(c.R, rvec);
  CHECK(cv::norm(rvec - rig.rotation_rodrigues) < 1e-12);
  CHECK(cv::norm(c.T, cv::Mat(rig.translation_m), cv::NORM_INF) == 0.0);
  CHECK(rig.baseline_m() == Approx(0.30).epsilon(1e-4));
  // The mounting is the warning stage's: the camera sits at minus its vehicle origin.
  const WarningSetup w;
  CHECK(rig.camera_in_vehicle_m ==
        cv::Vec3d(-w.vehicle_origin.x(), -w.vehicle_origin.y(), -w.vehicle_origin.z()));
}

TEST_CASE("render: deterministic, with sigma-1 noise independent per frame and camera", "[scene]") {
  const Renderer r(small_rig(), 3);
  const Sequence s = make_preset("pedestrian-running", 2);
  const StereoImages a = r.render_pair(s.frames[1], RenderOptions{});
  const StereoImages b = r.render_pair(s.frames[1], RenderOptions{});
  CHECK(cv::norm(a.left, b.left, cv::NORM_INF) == 0.0);
  CHECK(cv::norm(a.right, b.right, cv::NORM_INF) == 0.0);

  const cv::Mat clean = r.render_clean(Side::left, s.frames[1].objects, 1);
  cv::Mat noise;
  cv::Mat(a.left).convertTo(noise, CV_64F);
  noise -= clean;
  cv::Scalar mean, sd;
  cv::meanStdDev(noise, mean, sd);
  CHECK(std::abs(mean[0]) < 0.05);
  CHECK(sd[0] > 0.95);  // sigma 1 plus rounding (1/12 more variance)
  CHECK(sd[0] < 1.12);

  SceneFrame other = s.frames[1];
  other.index = 5;
  const StereoImages c = r.render_pair(other, RenderOptions{});
  CHECK(cv::norm(a.left, c.left, cv::NORM_INF) > 0.0);
  CHECK(cv::norm(c.left, c.right, cv::NORM_INF) > 0.0);
}

TEST_CASE("write: write_scene writes the pairs, the calibration, truth.jsonl and scene.json",
          "[scene]") {
  const Renderer r(small_rig(), 2);
  const Sequence s = make_preset("cyclist-crossing", 3);
  const fs::path dir = scratch("write");
  int calls = 0;
  const WrittenScene w = write_scene(s, r, dir.string(), RenderOptions{}, [&](int done, int total) {
    CHECK(done == ++calls);
    CHECK(total == 3);
  });
  CHECK(calls == 3);
  for (int i = 0; i < 3; ++i) {
    const cv::Mat l = cv::imread((dir / left_name(i)).string(), cv::IMREAD_UNCHANGED);
    CHECK(l.type() == CV_8UC1);
    CHECK(l.size() == cv::Size(160, 60));
    CHECK(fs::exists(dir / right_name(i)));
  }
  CHECK(left_name(12) == "0012_left.png");
  CHECK(scw::rectify::load_stereo_calibration((dir / "calibration.yml").string()).image_size ==
        cv::Size(160, 60));

  std::ifstream truth(dir / "truth.jsonl");
  std::string line;
  int lines = 0;
  while (std::getline(truth, line)) {
    const auto j = nlohmann::json::parse(line);
    for (const char* k :
         {"frame", "left", "right", "time_s", "severity", "deciding", "distance_m", "objects"})
      CHECK(j.contains(k));
    CHECK(j["frame"] == lines);
    CHECK(j["left"] == left_name(lines));
    REQUIRE(j["objects"].size() == 1);
    for (const char* k : {"id", "kind", "box_min_m", "box_max_m", "closest_m", "distance_m",
                          "disparity_px", "in_tunnel", "gap_m", "obstacle", "severity"})
      CHECK(j["objects"][0].contains(k));
    CHECK(j["objects"][0]["kind"] == "cyclist");
    ++lines;
  }
  CHECK(lines == 3);
  std::ifstream scene_file(dir / "scene.json");
  const auto scene = nlohmann::json::parse(scene_file);
  CHECK(scene["preset"] == "cyclist-crossing");
  CHECK(scene["frames"] == 3);
  CHECK(scene["frame_period_s"] == Approx(1.4));
  CHECK(scene["image_size"] == nlohmann::json::array({160, 60}));
  CHECK(scene["run"]["tiles"] == "8x4");
  CHECK(scene["run"]["max_disp"] == 56);
  const std::string cmd = scene["command"];
  CHECK(cmd == w.run_command);
  CHECK(cmd.rfind("scw run --calib " + (dir / "calibration.yml").string() + " --sequence " +
                      dir.string() +
                      " --min-disp 12 --max-disp 56 --window 21 --tiles 8x4 "
                      "--camera-height 1.2",
                  0) == 0);
  CHECK(cmd.find("--frame-period 1.4 ") != std::string::npos);
  CHECK(w.eval_command == "scw eval --truth " + dir.string() + " --results " +
                              (dir / "run" / "results.jsonl").string());

  SECTION("a folder holding a longer scene's frames is refused") {
    CHECK_THROWS_WITH(prepare_output_dir(dir.string(), 2), Catch::Contains("0002_left.png"));
    CHECK_NOTHROW(prepare_output_dir(dir.string(), 3));
  }
  SECTION("a folder that cannot be made is refused with its name") {
    CHECK_THROWS_WITH(write_scene(s, r, (dir / left_name(0) / "sub").string(), RenderOptions{}),
                      Catch::Contains("cannot create the output folder"));
  }
  fs::remove_all(dir);
}
