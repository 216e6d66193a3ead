// SPDX-License-Identifier: Apache-2.0
// Bad pixels of thesis mode, opencv mode (the disparity stage's model) and cv::StereoBM on pairs
// with a dense ground truth: what chose the commands' default mode (docs/disparity.md).
//
//   disparity_modes [--aloe DIR] [--scenes FRAMES] [--windows N,N,...] [--edge K,K,...]
//
// Always Tsukuba (SCW_DATA_DIR/tsukuba, d 0..15). --aloe DIR: Middlebury 2006 Aloe from DIR
// (aloeL.jpg, aloeR.jpg, aloeGT.png), halved to 641 x 555 so its 43..211 px fit d 0..127.
// --scenes F: F frames of each `scw scene` preset (and the sweep with lane markings), rendered
// raw, rectified with cv::remap through the rig's calibration, d 0..127 (`scw run`'s range);
// the truth of each rectified left pixel is f b / Z of the surface its ray hits (sky: unknown).
// Every image is read with host::io::read_grey_image (cv::IMREAD_GRAYSCALE), the CLI's reader.
// --edge K,...: opencv mode with edge_candidates = K, scored in the left edge band alone (the
// columns left of the valid region, where cv::StereoBM has no output), beside the valid region.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "host/disparity/run_model.hpp"
#include "host/io/image_file.hpp"
#include "host/io/tsukuba.hpp"
#include "host/rectify/calibration.hpp"
#include "host/scene/presets.hpp"
#include "host/scene/render.hpp"
#include "host/scene/write.hpp"

namespace {

using namespace scw;
namespace sc = scw::host::scene;

/// A grey pair and its truth: CV_32F disparity in pixels, NaN where unknown.
struct Pair {
  std::string name;
  cv::Mat left, right, truth;
  int dmin = 0, dmax = 15;
};

/// Over truth pixels of the valid region (where every candidate's window lies inside both
/// images): the share with no disparity or |d - truth| > 1 px (bad), and the share with a
/// disparity (density). Thesis mode rejects nothing there, so all its pixels count as values.
struct Score {
  long pixels = 0, missing = 0, wrong = 0;
  void add(const Score& s) { pixels += s.pixels, missing += s.missing, wrong += s.wrong; }
  double bad() const { return 100.0 * static_cast<double>(missing + wrong) / pixels; }
  double density() const { return 100.0 * static_cast<double>(pixels - missing) / pixels; }
  double bad_of_valid() const {
    return pixels > missing ? 100.0 * static_cast<double>(wrong) / (pixels - missing) : 0.0;
  }
};

/// Over columns u_begin .. u_end - 1 (default: the valid region's).
Score score(const cv::Mat& d16, bool rejects, std::int16_t invalid, const Pair& p, int n,
            int u_begin = -1, int u_end = -1) {
  const int r = n / 2;
  if (u_begin < 0) u_begin = r + std::max(p.dmax, 0);
  if (u_end < 0) u_end = p.left.cols - r;
  Score s;
  for (int v = r; v < p.left.rows - r; ++v)
    for (int u = u_begin; u < u_end; ++u) {
      const float t = p.truth.at<float>(v, u);
      if (std::isnan(t)) continue;
      ++s.pixels;
      const std::int16_t d = d16.at<std::int16_t>(v, u);
      if (rejects && d == invalid)
        ++s.missing;
      else if (std::abs(d / 16.0 - t) > 1.0)
        ++s.wrong;
    }
  return s;
}

/// thesis mode, opencv mode, cv::StereoBM (opencv mode's settings) on one pair at window n.
std::array<Score, 3> score_pair(const Pair& p, int n) {
  std::array<Score, 3> out;
  const auto th = disparity::mode_config(disparity::Mode::thesis, p.left.cols, p.left.rows, p.dmin);
  const auto oc = disparity::mode_config(disparity::Mode::opencv, p.left.cols, p.left.rows, p.dmin);
  const cv::Mat a = disparity::disparity_image(p.left, p.right, n, p.dmin, p.dmax, th);
  const cv::Mat b = disparity::disparity_image(p.left, p.right, n, p.dmin, p.dmax, oc);
  const auto bm = cv::StereoBM::create(p.dmax - p.dmin + 1, n);
  bm->setMinDisparity(p.dmin);
  bm->setPreFilterType(cv::StereoBM::PREFILTER_XSOBEL);
  bm->setPreFilterCap(oc.prefilter_cap);
  bm->setTextureThreshold(oc.texture_threshold);
  bm->setUniquenessRatio(oc.uniqueness_ratio);
  bm->setSpeckleWindowSize(0);
  bm->setDisp12MaxDiff(-1);
  cv::Mat c;
  bm->compute(p.left, p.right, c);
  const auto inv = static_cast<std::int16_t>(hls::disparity::invalid_code(oc));
  out[0] = score(a, false, 0, p, n);
  out[1] = score(b, true, inv, p, n);
  out[2] = score(c, true, inv, p, n);
  return out;
}

Pair tsukuba() {
  const std::string dir = std::string(SCW_DATA_DIR) + "/tsukuba";
  const auto [left, right] = host::io::read_tsukuba_pair(dir);
  Pair p{"Tsukuba", left, right, {}, 0, 15};
  const cv::Mat gt = host::io::read_tsukuba_truth(dir);
  gt.convertTo(p.truth, CV_32F, 1.0 / 16);  // value / 16 px
  p.truth.setTo(std::numeric_limits<float>::quiet_NaN(), gt == 0);
  return p;
}

Pair aloe(const std::string& dir) {
  const cv::Mat l = host::io::read_grey_image(dir + "/aloeL.jpg");
  const cv::Mat r = host::io::read_grey_image(dir + "/aloeR.jpg");
  const cv::Mat gt = host::io::read_grey_image(dir + "/aloeGT.png");
  const cv::Size half((l.cols + 1) / 2, (l.rows + 1) / 2);
  Pair p{"Aloe (half size)", {}, {}, {}, 0, 127};
  cv::resize(l, p.left, half, 0, 0, cv::INTER_AREA);
  cv::resize(r, p.right, half, 0, 0, cv::INTER_AREA);
  cv::Mat g;
  cv::resize(gt, g, half, 0, 0, cv::INTER_NEAREST);  // keeps 0 = unknown whole
  g.convertTo(p.truth, CV_32F, 0.5);                   // value px at full size
  p.truth.setTo(std::numeric_limits<float>::quiet_NaN(), g == 0);
  return p;
}

/// One preset's frames, rendered, rectified, with their truth.
std::vector<Pair> scenes(const std::string& preset, int frames, bool markings) {
  const sc::StereoRig rig;
  const sc::Renderer renderer(rig);
  const auto calib_path = std::filesystem::temp_directory_path() / "disparity_modes_calib.yml";
  sc::write_calibration(calib_path.string(), rig);
  const auto rect = rectify::rectify_calibration(rectify::load_stereo_calibration(calib_path.string()));
  std::filesystem::remove(calib_path);
  const double f = rect.P1.at<double>(0, 0), cx = rect.P1.at<double>(0, 2),
               cy = rect.P1.at<double>(1, 2);
  const double fb = -rect.P2.at<double>(0, 3);  // f times the baseline, px m
  const cv::Matx33d r1t = cv::Matx33d(rect.R1).t();
  const cv::Vec3d origin = rig.centre_in_vehicle(sc::Side::left);
  const cv::Size size = rig.image_size;

  const sc::Sequence seq = sc::make_preset(preset, frames);
  std::vector<Pair> out;
  for (const sc::SceneFrame& fr : seq.frames) {
    const sc::RenderOptions ro{1.0, seq.seed, markings};
    const sc::StereoImages raw = renderer.render_pair(fr, ro);
    Pair p{preset + (markings ? " + markings" : "") + " frame " + std::to_string(fr.index),
           {}, {}, cv::Mat(size, CV_32F), 0, 127};
    cv::remap(raw.left, p.left, rect.map1_x, rect.map1_y, cv::INTER_LINEAR);
    cv::remap(raw.right, p.right, rect.map2_x, rect.map2_y, cv::INTER_LINEAR);
    for (int v = 0; v < size.height; ++v)
      for (int u = 0; u < size.width; ++u) {
        float& t = p.truth.at<float>(v, u);
        t = std::numeric_limits<float>::quiet_NaN();
        const float mx = rect.map1_x.at<float>(v, u), my = rect.map1_y.at<float>(v, u);
        if (mx < 0 || my < 0 || mx > size.width - 1 || my > size.height - 1) continue;  // no raw
        const cv::Vec3d dr((u - cx) / f, (v - cy) / f, 1.0);  // rectified frame, z = 1
        const cv::Vec3d dv = rig.left_dir_to_vehicle(r1t * dr);
        const sc::Hit h = sc::cast_ray(origin, dv, fr.objects, 1.0 / f, 1, seq.seed);
        if (!std::isfinite(h.distance_m)) continue;  // sky
        t = static_cast<float>(fb / (h.distance_m / cv::norm(dr)));
      }
    out.push_back(std::move(p));
  }
  return out;
}

/// opencv mode with edge_candidates = k: {the band r + dmin .. r + dmax - 1, the valid region}.
std::array<Score, 2> score_edge(const Pair& p, int n, int k) {
  auto oc = disparity::mode_config(disparity::Mode::opencv, p.left.cols, p.left.rows, p.dmin);
  oc.edge_candidates = k;
  const cv::Mat d = disparity::disparity_image(p.left, p.right, n, p.dmin, p.dmax, oc);
  const auto inv = static_cast<std::int16_t>(hls::disparity::invalid_code(oc));
  const int r = n / 2;
  return {score(d, true, inv, p, n, r + p.dmin, r + p.dmax), score(d, true, inv, p, n)};
}

void print_edge_row(const std::string& what, int n, int k, const std::array<Score, 2>& s) {
  std::printf("  %-34s %3d %4d %7ld   %6.2f %% (%5.1f, %5.2f)   %6.2f %% (%5.1f, %5.2f)\n",
              what.c_str(), n, k, s[0].pixels, s[0].bad(), s[0].density(), s[0].bad_of_valid(),
              s[1].bad(), s[1].density(), s[1].bad_of_valid());
}

void print_row(const std::string& what, int n, const std::array<Score, 3>& s) {
  std::printf("  %-34s %3d %8ld", what.c_str(), n, s[0].pixels);
  for (const Score& x : s)
    std::printf("   %6.2f %% (%5.1f, %5.2f)", x.bad(), x.density(), x.bad_of_valid());
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::string aloe_dir;
  int scene_frames = 0;
  std::vector<int> windows{5, 9, 15, 21}, edges;
  const auto list = [](const char* arg) {
    std::vector<int> v;
    std::stringstream ss(arg);
    for (std::string w; std::getline(ss, w, ',');) v.push_back(std::stoi(w));
    return v;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--aloe" && i + 1 < argc) {
      aloe_dir = argv[++i];
    } else if (a == "--scenes" && i + 1 < argc) {
      scene_frames = std::atoi(argv[++i]);
    } else if (a == "--windows" && i + 1 < argc) {
      windows = list(argv[++i]);
    } else if (a == "--edge" && i + 1 < argc) {
      edges = list(argv[++i]);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--aloe DIR] [--scenes FRAMES] [--windows N,N,...] [--edge K,...]\n",
                   argv[0]);
      return 2;
    }
  }
  try {
    if (!edges.empty()) {
      std::printf(
          "opencv mode, edge_candidates K: bad %% of the truth pixels (density %%, bad %% of those "
          "with a disparity)\n  %-34s %3s %4s %7s   %-26s   %-26s\n",
          "pair", "N", "K", "pixels", "left edge band", "valid region");
      std::vector<Pair> pairs{tsukuba()};
      if (!aloe_dir.empty()) pairs.push_back(aloe(aloe_dir));
      for (const Pair& p : pairs)
        for (const int n : windows)
          for (const int k : edges) print_edge_row(p.name, n, k, score_edge(p, n, k));
      for (const char* preset : {"cyclist-crossing", "street-crossing"}) {
        if (scene_frames <= 0) break;
        const auto frames = scenes(preset, scene_frames, false);
        for (const int n : windows)
          for (const int k : edges) {
            std::array<Score, 2> sum{};
            for (const Pair& p : frames) {
              const auto s = score_edge(p, n, k);
              sum[0].add(s[0]);
              sum[1].add(s[1]);
            }
            print_edge_row(std::string(preset) + " (" + std::to_string(frames.size()) + " fr)", n,
                           k, sum);
          }
      }
      return 0;
    }
    std::printf(
        "bad %% = truth pixels of the valid region with no disparity or |d - truth| > 1 px "
        "(density %%, bad %% of the pixels with a disparity)\n  %-34s %3s %8s   %-26s   %-26s   %-26s\n",
        "pair", "N", "pixels", "thesis mode", "opencv mode", "cv::StereoBM");
    std::vector<Pair> pairs{tsukuba()};
    if (!aloe_dir.empty()) pairs.push_back(aloe(aloe_dir));
    for (const Pair& p : pairs)
      for (const int n : windows) print_row(p.name, n, score_pair(p, n));
    if (scene_frames > 0) {
      struct Set {
        const char* preset;
        bool markings;
      };
      for (const Set set : {Set{"distance-sweep", false}, Set{"distance-sweep", true},
                            Set{"cyclist-crossing", false}, Set{"pedestrian-running", false}}) {
        const auto frames = scenes(set.preset, scene_frames, set.markings);
        for (const int n : windows) {
          std::array<Score, 3> sum{};
          for (const Pair& p : frames) {
            const auto s = score_pair(p, n);
            for (int k = 0; k < 3; ++k) sum[k].add(s[k]);
          }
          print_row(std::string(set.preset) + (set.markings ? " + markings" : "") + " (" +
                        std::to_string(frames.size()) + " fr)",
                    n, sum);
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "disparity_modes: %s\n", e.what());
    return 1;
  }
  return 0;
}
