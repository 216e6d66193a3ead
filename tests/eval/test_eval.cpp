// SPDX-License-Identifier: Apache-2.0
// `scw eval`: hand-made truth and results with known errors give the right statistics; broken
// inputs are refused with the file and line; the plots put their marks where the data says.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "host/eval/chart.hpp"
#include "host/eval/compare.hpp"
#include "host/eval/plots.hpp"
#include "host/eval/records.hpp"
#include "host/eval/report.hpp"
#include "host/eval/surfaces.hpp"
#include "host/io/image_file.hpp"
#include "host/rectify/calibration.hpp"
#include "host/scene/write.hpp"

namespace {

namespace fs = std::filesystem;
namespace ev = scw::host::eval;
using Catch::Matchers::Contains;
using ev::Severity;

/// A truth line as scw scene writes it (objects left empty: eval does not read them).
std::string truth_line(int frame, const char* severity, std::optional<double> d) {
  nlohmann::json j = {{"frame", frame},
                      {"left", "x_left.png"},
                      {"right", "x_right.png"},
                      {"time_s", 0.1 * frame},
                      {"severity", severity},
                      {"deciding", d ? nlohmann::json(1) : nlohmann::json(nullptr)},
                      {"distance_m", d ? nlohmann::json(*d) : nlohmann::json(nullptr)},
                      {"objects", nlohmann::json::array()}};
  return j.dump() + "\n";
}

/// A results line as host/app/run.cpp's frame_json writes it, the fields eval ignores included.
std::string result_line(int frame, const char* severity, std::optional<double> d,
                        std::vector<std::string> flags = {}) {
  nlohmann::json j = {{"frame", frame},
                      {"severity", severity},
                      {"distance_m", d ? nlohmann::json(*d) : nlohmann::json(nullptr)},
                      {"closest_uv", nlohmann::json::array({10, 20})},
                      {"bbox", nlohmann::json::array({1, 2, 3, 4})},
                      {"in_tunnel", true},
                      {"objects", 1},
                      {"flags", flags}};
  return j.dump() + "\n";
}

ev::TruthFile truth_of(const std::string& text) {
  std::istringstream in(text);
  return ev::parse_truth(in, "scene/truth.jsonl");
}

ev::ResultsFile results_of(const std::string& text) {
  std::istringstream in(text);
  return ev::parse_results(in, "out/results.jsonl");
}

/// Three frames: 10 m read as 10.3 (+3 %), 20 m as 19.6 (-2 %), a truth without a distance; the
/// second frame's severity is wrong.
ev::EvalReport three_frames() {
  auto t = truth_of(truth_line(0, "high", 10.0) + truth_line(1, "medium", 20.0) +
                    truth_line(2, "none", std::nullopt));
  t.preset = "laser_range";
  const auto r = results_of(result_line(0, "high", 10.3) + result_line(1, "low", 19.6) +
                            result_line(2, "none", 5.0, {"too_close"}));
  return ev::compare(t, r);
}

/// The message of the std::runtime_error `f` throws ("" when it throws none).
template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

/// True when a pixel of exactly `bgr` lies within `r` px of `p`.
bool colour_near(const cv::Mat& img, cv::Point2d p, const cv::Scalar& bgr, int r = 1) {
  const cv::Vec3b want(static_cast<uchar>(bgr[0]), static_cast<uchar>(bgr[1]),
                       static_cast<uchar>(bgr[2]));
  const int u = static_cast<int>(std::lround(p.x)), v = static_cast<int>(std::lround(p.y));
  for (int y = v - r; y <= v + r; ++y)
    for (int x = u - r; x <= u + r; ++x)
      if (x >= 0 && y >= 0 && x < img.cols && y < img.rows && img.at<cv::Vec3b>(y, x) == want)
        return true;
  return false;
}

/// Pixels of exactly `bgr` inside `r`.
int count_colour(const cv::Mat& img, const cv::Rect& r, const cv::Scalar& bgr) {
  int n = 0;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x)
      n += colour_near(img, {static_cast<double>(x), static_cast<double>(y)}, bgr, 0);
  return n;
}

}  // namespace

TEST_CASE("known errors give the right max, mean and agreement", "[eval]") {
  const auto r = three_frames();
  REQUIRE(r.frames.size() == 3);
  CHECK(r.preset == "laser_range");
  CHECK(r.frames[0].rel_error.value() == Approx(0.03));
  CHECK(r.frames[1].rel_error.value() == Approx(-0.02));
  CHECK_FALSE(r.frames[2].rel_error);
  CHECK(r.frames_with_distance == 2);
  CHECK(r.max_rel_distance_error.value() == Approx(0.03));
  CHECK(r.max_error_frame == 0);
  CHECK(r.mean_rel_distance_error.value() == Approx(0.025));
  CHECK(r.frames[0].agree);
  CHECK_FALSE(r.frames[1].agree);
  CHECK(r.severity_disagreements == 1);
  CHECK(r.severity_agreement == Approx(2.0 / 3.0));
  CHECK(r.frames[2].flags == std::vector<std::string>{"too_close"});
}

TEST_CASE("a distance missing on either side leaves the distance statistics, not the agreement",
          "[eval]") {
  const auto t = truth_of(truth_line(0, "low", 25.0) + truth_line(1, "low", std::nullopt) +
                          truth_line(2, "medium", 16.0));
  const auto r = results_of(result_line(0, "low", std::nullopt) + result_line(1, "low", 24.0) +
                            result_line(2, "medium", 15.2));
  const auto rep = ev::compare(t, r);
  CHECK(rep.frames_with_distance == 1);
  CHECK(rep.max_rel_distance_error.value() == Approx(0.05));
  CHECK(rep.mean_rel_distance_error.value() == Approx(0.05));
  CHECK(rep.max_error_frame == 2);
  CHECK(rep.severity_agreement == Approx(1.0));
}

TEST_CASE("no distance on any frame: no statistics, null in the JSON", "[eval]") {
  const auto rep = ev::compare(truth_of(truth_line(0, "none", std::nullopt)),
                               results_of(result_line(0, "low", std::nullopt)));
  CHECK(rep.frames_with_distance == 0);
  CHECK_FALSE(rep.max_rel_distance_error);
  CHECK_FALSE(rep.mean_rel_distance_error);
  CHECK(rep.severity_agreement == Approx(0.0));
  const auto j = ev::report_json(rep);
  CHECK(j["max_rel_distance_error"].is_null());
  CHECK(j["mean_rel_distance_error"].is_null());
  CHECK_FALSE(j.contains("preset"));
}

TEST_CASE("a true distance of 0 m has no relative error", "[eval]") {
  const auto rep = ev::compare(truth_of(truth_line(0, "high", 0.0)),
                               results_of(result_line(0, "high", 0.4)));
  CHECK_FALSE(rep.frames[0].rel_error);
  CHECK(rep.frames_with_distance == 0);
}

TEST_CASE("frames are matched by number, not by line", "[eval]") {
  const auto t = truth_of(truth_line(0, "low", 20.0) + truth_line(1, "high", 8.0));
  const auto r = results_of(result_line(1, "high", 8.8) + result_line(0, "low", 20.0));
  const auto rep = ev::compare(t, r);
  CHECK(rep.frames[1].frame == 1);
  CHECK(rep.frames[1].rel_error.value() == Approx(0.1));
  CHECK(rep.frames[0].rel_error.value() == Approx(0.0));
}

TEST_CASE("different frame counts and missing frames are refused with the file and line",
          "[eval]") {
  const auto t = truth_of(truth_line(0, "low", 20.0) + truth_line(1, "low", 19.0) +
                          truth_line(2, "low", 18.0));
  SECTION("results short of a frame") {
    const auto r = results_of(result_line(0, "low", 20.0) + result_line(1, "low", 19.0));
    const auto msg = error_of([&] { ev::compare(t, r); });
    CHECK_THAT(msg, Contains("no result for frame 2"));
    CHECK_THAT(msg, Contains("'scene/truth.jsonl' line 3"));
    CHECK_THAT(msg, Contains("holds 2 frames"));
    CHECK_THAT(msg, Contains("scw run"));
  }
  SECTION("a frame number the truth lacks") {
    const auto r = results_of(result_line(0, "low", 20.0) + result_line(1, "low", 19.0) +
                              result_line(2, "low", 18.0) + result_line(7, "low", 1.0));
    const auto msg = error_of([&] { ev::compare(t, r); });
    CHECK_THAT(msg, Contains("'out/results.jsonl' line 4"));
    CHECK_THAT(msg, Contains("frame 7 is not in the truth"));
  }
  SECTION("as many frames, one numbered wrong") {
    const auto r = results_of(result_line(0, "low", 20.0) + result_line(1, "low", 19.0) +
                              result_line(3, "low", 18.0));
    CHECK_THAT(error_of([&] { ev::compare(t, r); }), Contains("no result for frame 2"));
  }
}

TEST_CASE("malformed lines are refused with the file, the line and the field", "[eval]") {
  const std::string good = result_line(0, "low", 20.0);
  struct Case {
    const char* what;
    std::string text;
    const char* expect;
  };
  const std::vector<Case> cases = {
      {"not JSON", good + "{\"frame\": 1, \"severity\": \n", "line 2: not JSON"},
      {"not an object", good + "[1, 2]\n", "line 2: not a JSON object"},
      {"no severity", good + R"({"frame": 1, "distance_m": 3, "flags": []})" "\n",
       "line 2: no \"severity\""},
      {"an unknown severity",
       good + R"({"frame": 1, "severity": "severe", "distance_m": 3, "flags": []})" "\n",
       "not one of none, low, medium, high"},
      {"a distance that is text",
       good + R"({"frame": 1, "severity": "low", "distance_m": "3", "flags": []})" "\n",
       "\"distance_m\" is \"3\""},
      {"no flags", good + R"({"frame": 1, "severity": "low", "distance_m": 3})" "\n",
       "line 2: no \"flags\""},
      {"a negative frame", good + result_line(-1, "low", 3.0), "line 2: \"frame\" is -1"},
      {"a frame twice", good + "\n" + result_line(0, "low", 3.0), "line 3: frame 0 again"},
      {"no frames", "\n\n", "holds no frames"},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    const auto msg = error_of([&] { results_of(c.text); });
    CHECK_THAT(msg, Contains("'out/results.jsonl'"));
    CHECK_THAT(msg, Contains(c.expect));
  }
  // A truth line lacking its distance; and a truth file given as results (it has no flags).
  CHECK_THAT(error_of([] { truth_of(R"({"frame": 0, "severity": "low"})"); }),
             Contains("'scene/truth.jsonl' line 1: no \"distance_m\""));
  CHECK_THAT(error_of([] { results_of(truth_line(0, "low", 3.0)); }), Contains("no \"flags\""));
}

TEST_CASE("read_truth takes the folder, with the preset from scene.json", "[eval]") {
  const fs::path dir = fs::temp_directory_path() / "scw_test_eval_truth";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "truth.jsonl") << truth_line(0, "low", 20.0) << truth_line(1, "low", 19.0);
  SECTION("without scene.json") {
    const auto t = ev::read_truth(dir);
    CHECK(t.frames.size() == 2);
    CHECK(t.preset.empty());
    CHECK(t.frames[1].line == 2);
  }
  SECTION("with scene.json") {
    std::ofstream(dir / "scene.json") << R"({"preset": "cyclist_crossing", "frames": 2})";
    CHECK(ev::read_truth(dir).preset == "cyclist_crossing");
    CHECK(ev::read_truth(dir / "truth.jsonl").preset == "cyclist_crossing");
  }
  SECTION("a broken scene.json") {
    std::ofstream(dir / "scene.json") << "{";
    CHECK_THAT(error_of([&] { ev::read_truth(dir); }), Contains("scene.json' is not JSON"));
  }
  SECTION("a folder without truth.jsonl") {
    CHECK_THAT(error_of([&] { ev::read_truth(dir / "nothing"); }), Contains("cannot read"));
  }
  fs::remove_all(dir);
}

TEST_CASE("the JSON holds the summary, both severity sequences and every frame", "[eval]") {
  const auto j = ev::report_json(three_frames());
  CHECK(j["frames"] == 3);
  CHECK(j["frames_with_distance"] == 2);
  CHECK(j["max_rel_distance_error"].get<double>() == Approx(0.03));
  CHECK(j["mean_rel_distance_error"].get<double>() == Approx(0.025));
  CHECK(j["severity_agreement"].get<double>() == Approx(2.0 / 3.0));
  CHECK(j["severity_truth"] == nlohmann::json({"high", "medium", "none"}));
  CHECK(j["severity_measured"] == nlohmann::json({"high", "low", "none"}));
  CHECK(j["preset"] == "laser_range");
  REQUIRE(j["per_frame"].size() == 3);
  const auto& f1 = j["per_frame"][1];
  CHECK(f1["frame"] == 1);
  CHECK(f1["true_distance_m"].get<double>() == Approx(20.0));
  CHECK(f1["measured_distance_m"].get<double>() == Approx(19.6));
  CHECK(f1["rel_error"].get<double>() == Approx(-0.02));
  CHECK(f1["true_severity"] == "medium");
  CHECK(f1["measured_severity"] == "low");
  CHECK(f1["flags"].empty());
  const auto& f2 = j["per_frame"][2];
  CHECK(f2["true_distance_m"].is_null());
  CHECK(f2["rel_error"].is_null());
  CHECK(f2["flags"] == nlohmann::json({"too_close"}));
}

TEST_CASE("the table marks disagreements and states the thesis's bar", "[eval]") {
  std::ostringstream out;
  ev::print_report(out, three_frames());
  const std::string s = out.str();
  CHECK_THAT(s, Contains("+3.00"));
  CHECK_THAT(s, Contains("-2.00"));
  CHECK_THAT(s, Contains("medium   low       *"));
  CHECK_THAT(s, Contains("3.00 % at frame 0"));
  CHECK_THAT(s, Contains("thesis bar 5 %: within"));
  CHECK_THAT(s, Contains("2 / 3"));
  CHECK_THAT(s, Contains("too_close"));
}

TEST_CASE("round ticks", "[eval]") {
  CHECK(ev::nice_step(-6.0, 6.0, 8) == Approx(2.0));
  CHECK(ev::nice_step(6.0, 30.0, 8) == Approx(5.0));
  CHECK(ev::nice_step(0.0, 0.9, 8) == Approx(0.1));
  const auto [lo, hi] = ev::widen_to_step(-6.2, 6.0, 2.0);
  CHECK(lo == Approx(-8.0));
  CHECK(hi == Approx(6.0));
  const auto ticks = ev::numeric_ticks(-1.0, 1.0, 0.5);
  REQUIRE(ticks.size() == 5);
  CHECK(ticks[0].label == "-1.0");
  CHECK(ticks[2].label == "0.0");
  CHECK(ticks[4].label == "1.0");
}

TEST_CASE("the distance plot: every error on the scale, dots where the data puts them",
          "[eval]") {
  // Errors of +3 %, -2 % and +12 % (beyond the bar) at 10, 20 and 28 m.
  const auto t = truth_of(truth_line(0, "high", 10.0) + truth_line(1, "medium", 20.0) +
                          truth_line(2, "low", 28.0) + truth_line(3, "none", std::nullopt));
  const auto r = results_of(result_line(0, "high", 10.3) + result_line(1, "low", 19.6) +
                            result_line(2, "low", 31.36) + result_line(3, "none", std::nullopt));
  const auto rep = ev::compare(t, r);
  const cv::Mat img = ev::distance_error_plot(rep);
  REQUIRE(img.size() == ev::kPlotSize);
  REQUIRE(img.type() == CV_8UC3);
  CHECK(img.at<cv::Vec3b>(0, 0) == cv::Vec3b(255, 255, 255));

  const ev::Axes a = ev::distance_axes(rep);
  CHECK(a.y0 <= -6.0);
  CHECK(a.y1 >= 12.0);
  CHECK(a.x0 < 10.0);
  CHECK(a.x1 > 28.0);
  // The mapping itself: the range's corners are the plot area's.
  CHECK(a.to_px(a.x0, a.y0).x == Approx(a.area.x));
  CHECK(a.to_px(a.x0, a.y0).y == Approx(a.area.y + a.area.height));
  CHECK(a.to_px(a.x1, a.y1).x == Approx(a.area.x + a.area.width));
  CHECK(a.to_px(a.x1, a.y1).y == Approx(a.area.y));

  CHECK(colour_near(img, a.to_px(10.0, 3.0), ev::kWithinBarBgr));
  CHECK(colour_near(img, a.to_px(20.0, -2.0), ev::kWithinBarBgr));
  CHECK(colour_near(img, a.to_px(28.0, 12.0), ev::kBeyondBarBgr));
  CHECK_FALSE(colour_near(img, a.to_px(28.0, 12.0), ev::kWithinBarBgr, 2));
  // Nothing at a place no frame is.
  CHECK_FALSE(colour_near(img, a.to_px(15.0, -4.0), ev::kWithinBarBgr, 3));
  // The dashed bar lines: the bar's orange on the +5 % and -5 % rows, between the dashes too
  // far from the dots to be anything else.
  int on_bar = 0;
  for (const double y : {5.0, -5.0})
    for (double x = a.x0; x < a.x1; x += (a.x1 - a.x0) / 40)
      on_bar += colour_near(img, a.to_px(x, y), ev::kBarBgr, 1);
  CHECK(on_bar > 40);
}

TEST_CASE("the distance plot without any distance is still a labelled chart", "[eval]") {
  const auto rep = ev::compare(truth_of(truth_line(0, "none", std::nullopt)),
                               results_of(result_line(0, "none", std::nullopt)));
  const cv::Mat img = ev::distance_error_plot(rep, cv::Size(640, 360));
  CHECK(img.size() == cv::Size(640, 360));
  const ev::Axes a = ev::distance_axes(rep, img.size());
  // No dot in the plot area (the legend's sample dot is above it); the bar is drawn.
  CHECK(count_colour(img, a.area, ev::kWithinBarBgr) == 0);
  CHECK(count_colour(img, a.area, ev::kBarBgr) > 100);
}

TEST_CASE("the severity plot: truth and measurement at their levels per frame", "[eval]") {
  const char* truth_sev[] = {"none", "low", "medium", "high", "high", "medium"};
  const char* meas_sev[] = {"none", "low", "low", "high", "medium", "medium"};
  std::string t, r;
  for (int i = 0; i < 6; ++i) {
    t += truth_line(i, truth_sev[i], 10.0);
    r += result_line(i, meas_sev[i], 10.0);
  }
  const auto rep = ev::compare(truth_of(t), results_of(r));
  const cv::Mat img = ev::severity_plot(rep);
  REQUIRE(img.size() == ev::kPlotSize);
  REQUIRE(img.type() == CV_8UC3);
  const ev::Axes a = ev::severity_axes(rep);
  for (int i = 0; i < 6; ++i) {
    INFO("frame " << i);
    const double x = i;
    const double meas = static_cast<double>(*ev::parse_severity(meas_sev[i]));
    const double tru = static_cast<double>(*ev::parse_severity(truth_sev[i]));
    CHECK(colour_near(img, a.to_px(x, meas), ev::kMeasuredBgr));
    // Where they differ the truth's wide line shows alone at its own level, on the shade.
    if (meas != tru) {
      CHECK(colour_near(img, a.to_px(x, tru), ev::kTruthBgr));
      CHECK(colour_near(img, a.to_px(x, (meas + tru) / 2), ev::kDisagreeBgr));
    } else {
      CHECK_FALSE(colour_near(img, a.to_px(x, 1.5 + (tru < 2 ? 1 : -1)), ev::kDisagreeBgr, 3));
    }
  }
}

TEST_CASE("a plot is written, and a path that cannot be written is refused by name", "[eval]") {
  const fs::path p = fs::temp_directory_path() / "scw_test_eval_plot.png";
  scw::host::io::write_image(p, cv::Mat(10, 10, CV_8UC3, cv::Scalar::all(255)));
  CHECK(fs::file_size(p) > 0);
  fs::remove(p);
  const cv::Mat img(10, 10, CV_8UC3);
  CHECK_THROWS_WITH(scw::host::io::write_image("/nonexistent_dir/x.png", img),
                    Catch::Contains("/nonexistent_dir/x.png"));
  CHECK_THROWS_WITH(scw::host::io::write_image(p.string() + ".nosuchformat", img),
                    Catch::Contains("nosuchformat"));
}

namespace {

/// A scene folder as scw scene leaves it, without the pictures: scene.json and calibration.yml.
fs::path scene_folder(const std::string& name, const std::string& preset, int frames,
                      double pitch_rad) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  nlohmann::json j = {{"preset", preset}, {"frames", frames}, {"seed", 1},
                      {"rig", {{"pitch_rad", pitch_rad}}}};
  std::ofstream(dir / "scene.json") << j.dump();
  scw::host::scene::StereoRig rig;
  rig.pitch_rad = pitch_rad;
  scw::host::scene::write_calibration((dir / "calibration.yml").string(), rig);
  return dir;
}

/// Where a vehicle point lands in the rectified left image of a camera pitched by `pitch_rad`
/// (cv::stereoRectify's R1, P1): the test's own rig, not the one eval read back.
cv::Point projected(double pitch_rad, const fs::path& dir, const cv::Vec3d& p) {
  scw::host::scene::StereoRig rig;
  rig.pitch_rad = pitch_rad;
  const auto rect = scw::rectify::rectify_calibration(
      scw::rectify::load_stereo_calibration((dir / "calibration.yml").string()));
  const cv::Mat c = rect.R1 * cv::Mat(rig.vehicle_to_left(p));
  const cv::Mat& P = rect.P1;
  const double z = c.at<double>(2);
  return {static_cast<int>(std::lround(P.at<double>(0, 0) * c.at<double>(0) / z + P.at<double>(0, 2))),
          static_cast<int>(std::lround(P.at<double>(1, 1) * c.at<double>(1) / z + P.at<double>(1, 2)))};
}

}  // namespace

TEST_CASE("surfaces: a label's pixels are traced back to what the scene shows there", "[eval]") {
  struct Probe {
    cv::Vec3d at;
    const char* surface;
  };
  auto check = [](const fs::path& dir, double pitch_rad, int frame,
                  const std::vector<Probe>& probes) {
    const auto view = ev::load_scene_view(dir);
    REQUIRE(view);
    cv::Mat labels(view->map_x.size(), CV_16UC1, cv::Scalar(0));
    for (std::size_t k = 0; k < probes.size(); ++k) {
      const cv::Point c = projected(pitch_rad, dir, probes[k].at);
      INFO(probes[k].surface << " at " << c);
      REQUIRE(cv::Rect(1, 1, labels.cols - 2, labels.rows - 2).contains(c));
      labels(cv::Rect(c.x - 1, c.y - 1, 3, 3)).setTo(static_cast<int>(k + 1));
    }
    for (std::size_t k = 0; k < probes.size(); ++k) {
      const ev::Surface s = ev::object_surface(*view, frame, labels, static_cast<int>(k + 1));
      CHECK(s.name == probes[k].surface);
      CHECK(s.share == 1.0);
    }
    CHECK_THAT(error_of([&] { ev::object_surface(*view, frame, labels, 99); }),
               Contains("no pixel of object 99"));
  };
  SECTION("the distance sweep: the pedestrian 30 m ahead, the road, the sky") {
    const fs::path dir = scene_folder("scw_test_eval_sweep", "distance-sweep", 2, 0.0);
    check(dir, 0.0, 0, {{{0.0, 0.9, 30.2}, "pedestrian"}, {{-1.0, 0.0, 12.0}, "road"},
                   {{0.0, 20.0, 200.0}, "sky"}});
    fs::remove_all(dir);
  }
  SECTION("a street seen by a pitched camera: the crossing pedestrian, a pavement, a kerb") {
    const double pitch = 3.141592653589793 / 180.0;
    const fs::path dir = scene_folder("scw_test_eval_street", "street-crossing", 41, pitch);
    check(dir, pitch, 20, {{{0.0, 0.9, 9.2}, "pedestrian"}, {{-6.5, 0.12, 20.0}, "pavement"},
                    {{-5.3, 0.06, 12.0}, "kerb"}, {{1.0, 0.0, 14.0}, "road"}});
    CHECK(ev::is_street_surface("pavement"));
    CHECK_FALSE(ev::is_street_surface("pedestrian"));
    fs::remove_all(dir);
  }
  SECTION("a truth folder without its scene is not traced") {
    const fs::path dir = fs::temp_directory_path() / "scw_test_eval_noscene";
    fs::create_directories(dir);
    CHECK_FALSE(ev::load_scene_view(dir));
    std::ofstream(dir / "scene.json") << R"({"preset": "not-a-preset"})";
    CHECK_FALSE(ev::load_scene_view(dir));
    fs::remove_all(dir);
  }
}
