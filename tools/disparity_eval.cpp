// SPDX-License-Identifier: Apache-2.0
// Disparity reference vs cv::StereoBM (agreement, pixel for pixel) and Tsukuba accuracy against
// the ground truth, for thesis mode, opencv mode and cv::StereoBM (docs/disparity.md).
//
//   disparity_eval [--tsukuba DIR] [--urban LEFT.pgm RIGHT.pgm NUMDISP] [--list K]
//
// Without options: Tsukuba from SCW_DATA_DIR/tsukuba. --urban adds an agreement run on a
// further grey pair (e.g. the Karlsruhe urban pair, which may not be redistributed) at
// windows 21 and 9, minDisparity 0. --list K prints up to K differing pixels per comparison.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/reference/stereo_bm.hpp"

namespace {

using scw::hls::disparity::DisparityConfig;

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> px;
};

Image load_grey(const std::string& path) {
  cv::Mat m = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (m.empty()) throw std::runtime_error("cannot read " + path);
  if (m.channels() == 3) cv::cvtColor(m, m, cv::COLOR_BGR2GRAY);
  if (m.type() != CV_8UC1) throw std::runtime_error(path + " is not 8-bit");
  Image img;
  img.width = m.cols;
  img.height = m.rows;
  img.px.assign(m.begin<std::uint8_t>(), m.end<std::uint8_t>());
  return img;
}

std::vector<std::uint16_t> stereo_bm(const Image& l, const Image& r, int n, int num_disp,
                                     const DisparityConfig& cfg, bool optimized) {
  return scw::reference::stereo_bm(l.px.data(), r.px.data(), l.width, l.height, n, num_disp, cfg,
                                   optimized);
}

struct Region {
  int u0, u1, v0, v1;
  bool inside(int u, int v) const { return u >= u0 && u < u1 && v >= v0 && v < v1; }
};
Region valid_region(int w, int h, int n, int dmin, int num_disp) {
  const int r = n / 2, dmax = dmin + num_disp - 1;
  return {r + std::max(dmax, 0), w - r + std::min(dmin, 0), r, h - r};
}

/// Why the reference's value differs at one pixel: the SAD curve on the prefiltered images.
std::string explain(const Image& l, const Image& r, int u, int v, int n, int num_disp,
                    const DisparityConfig& cfg) {
  const auto pl =
      scw::reference::prefilter_xsobel_reference(l.px.data(), l.width, l.height, cfg.prefilter_cap);
  const auto pr =
      scw::reference::prefilter_xsobel_reference(r.px.data(), r.width, r.height, cfg.prefilter_cap);
  std::vector<int> sad(static_cast<std::size_t>(num_disp));
  int best = 0;
  for (int k = 0; k < num_disp; ++k) {
    sad[k] = scw::reference::sad_reference(pl.data(), pr.data(), l.width, u, v, cfg.dmin + k, n);
    if (sad[k] < sad[best]) best = k;
  }
  int ties = 0, last_min = best;
  for (int k = 0; k < num_disp; ++k)
    if (sad[k] == sad[best]) ++ties, last_min = k;
  const int thresh = sad[best] + sad[best] * cfg.uniqueness_ratio / 100;
  std::string s = "min SAD " + std::to_string(sad[best]) +
                  " at d=" + std::to_string(cfg.dmin + best) + ", thresh " + std::to_string(thresh);
  if (ties > 1)
    s += ", TIE x" + std::to_string(ties) + " (largest d " + std::to_string(cfg.dmin + last_min) +
         ")";
  s += "; SAD:";
  for (int k = 0; k < num_disp; ++k) s += " " + std::to_string(sad[k]);
  return s;
}

struct Agreement {
  long region = 0, region_same = 0, outside = 0, outside_same = 0;
  long ref_only_invalid = 0, cv_only_invalid = 0, both_valid_diff = 0;
  int max_valid_diff = 0;
};

Agreement compare(const std::vector<std::uint16_t>& ref, const std::vector<std::uint16_t>& cv,
                  const Image& l, const Image& r, int n, int num_disp, const DisparityConfig& cfg,
                  int list) {
  const Region reg = valid_region(l.width, l.height, n, cfg.dmin, num_disp);
  const std::uint16_t inv = scw::hls::disparity::invalid_code(cfg);
  Agreement a;
  int listed = 0;
  for (int v = 0; v < l.height; ++v)
    for (int u = 0; u < l.width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * l.width + u;
      const bool same = ref[i] == cv[i];
      if (!reg.inside(u, v)) {
        ++a.outside;
        a.outside_same += same;
        continue;
      }
      ++a.region;
      a.region_same += same;
      if (same) continue;
      if (ref[i] == inv)
        ++a.ref_only_invalid;
      else if (cv[i] == inv)
        ++a.cv_only_invalid;
      else {
        ++a.both_valid_diff;
        a.max_valid_diff = std::max(a.max_valid_diff, std::abs(static_cast<std::int16_t>(ref[i]) -
                                                               static_cast<std::int16_t>(cv[i])));
      }
      if (listed++ < list)
        std::printf("      (u %d, v %d) ref %d cv %d: %s\n", u, v,
                    static_cast<std::int16_t>(ref[i]), static_cast<std::int16_t>(cv[i]),
                    explain(l, r, u, v, n, num_disp, cfg).c_str());
    }
  return a;
}

void print_agreement(const char* what, const Agreement& a) {
  std::printf(
      "    %-22s valid region %6.3f %% (%ld of %ld; %ld differ: ref-only invalid %ld, "
      "cv-only invalid %ld, both valid %ld, max |diff| %d/16); outside %s\n",
      what, 100.0 * a.region_same / a.region, a.region_same, a.region, a.region - a.region_same,
      a.ref_only_invalid, a.cv_only_invalid, a.both_valid_diff, a.max_valid_diff,
      a.outside_same == a.outside ? "all equal" : "DIFFER");
}

/// Over ground-truth pixels (gt > 0) of the valid region: the share (%) with no disparity or
/// |d - gt| > 1 px; the share with a disparity; among those, the share with |d - gt| > 1 px.
/// gt is 8-bit, value / scale pixels.
struct Accuracy {
  long pixels = 0;
  double bad = 0, density = 0, bad_of_valid = 0;
};
Accuracy accuracy(const std::vector<std::uint16_t>& disp, bool has_invalid, std::uint16_t inv,
                  const Image& gt, int scale, const Region& reg) {
  long n = 0, missing = 0, wrong = 0;
  for (int v = reg.v0; v < reg.v1; ++v)
    for (int u = reg.u0; u < reg.u1; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * gt.width + u;
      if (gt.px[i] == 0) continue;
      ++n;
      if (has_invalid && disp[i] == inv) {
        ++missing;
        continue;
      }
      const double d = static_cast<std::int16_t>(disp[i]) / 16.0;
      if (std::abs(d - static_cast<double>(gt.px[i]) / scale) > 1.0) ++wrong;
    }
  Accuracy a;
  a.pixels = n;
  a.bad = 100.0 * static_cast<double>(missing + wrong) / static_cast<double>(n);
  a.density = 100.0 * static_cast<double>(n - missing) / static_cast<double>(n);
  a.bad_of_valid =
      n > missing ? 100.0 * static_cast<double>(wrong) / static_cast<double>(n - missing) : 0;
  return a;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void run_agreement(const Image& l, const Image& r, int n, int num_disp, int list,
                   const DisparityConfig& cfg, const char* label) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto ref = scw::reference::disparity_reference(l.px.data(), r.px.data(), l.width, l.height,
                                                       n, num_disp, cfg);
  std::printf(
      "  N=%d, minDisparity %d, numDisparities %d, cap %d, texture %d, uniqueness %d "
      "%s (reference %.1f s)\n",
      n, cfg.dmin, num_disp, cfg.prefilter_cap, cfg.texture_threshold, cfg.uniqueness_ratio, label,
      seconds_since(t0));
  for (const bool opt : {true, false}) {
    const auto cv = stereo_bm(l, r, n, num_disp, cfg, opt);
    print_agreement(opt ? "setUseOptimized(true)" : "setUseOptimized(false)",
                    compare(ref, cv, l, r, n, num_disp, cfg, opt ? list : 0));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string tsukuba = std::string(SCW_DATA_DIR) + "/tsukuba";
  std::string urban_l, urban_r;
  int urban_nd = 0, list = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--tsukuba" && i + 1 < argc) {
      tsukuba = argv[++i];
    } else if (a == "--urban" && i + 3 < argc) {
      urban_l = argv[++i];
      urban_r = argv[++i];
      urban_nd = std::atoi(argv[++i]);
    } else if (a == "--list" && i + 1 < argc) {
      list = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--tsukuba DIR] [--urban LEFT RIGHT NUMDISP] [--list K]\n",
                   argv[0]);
      return 2;
    }
  }
  try {
    const Image l = load_grey(tsukuba + "/scene1.row3.col3.ppm");
    const Image r = load_grey(tsukuba + "/scene1.row3.col4.ppm");
    const Image gt = load_grey(tsukuba + "/truedisp.row3.col3.pgm");
    constexpr int kNumDisp = 16, kGtScale = 16;
    std::printf("OpenCV %s, Tsukuba %d x %d, range 0..15 (numDisparities 16)\n", CV_VERSION,
                l.width, l.height);
    std::printf("Agreement of the reference (opencv mode) with cv::StereoBM, same 16-bit value:\n");
    for (const int n : {5, 9, 15, 21})
      run_agreement(l, r, n, kNumDisp, list, scw::hls::disparity::opencv_mode(l.width, l.height, 0),
                    "(defaults)");
    // preFilterCap > 31 and a window > 21 take StereoBM's 32-bit (non-`useShorts`) path.
    run_agreement(l, r, 9, kNumDisp, list,
                  scw::hls::disparity::opencv_mode(l.width, l.height, 0, 63), "(int path)");
    run_agreement(l, r, 23, kNumDisp, list, scw::hls::disparity::opencv_mode(l.width, l.height, 0),
                  "(int path)");
    run_agreement(l, r, 9, kNumDisp, list,
                  scw::hls::disparity::opencv_mode(l.width, l.height, 0, 31, 0, 0),
                  "(no rejection)");
    run_agreement(l, r, 9, kNumDisp, list,
                  scw::hls::disparity::opencv_mode(l.width, l.height, 4, 31, 10, 15), "(dmin 4)");

    std::printf(
        "\nTsukuba accuracy: %% of ground-truth pixels in the valid region with no "
        "disparity or |d - gt| > 1 px\n");
    std::printf("  bad %% (density %%, bad %% of the pixels with a disparity)\n");
    std::printf("  %-4s %-7s %-24s %-24s %-24s\n", "N", "pixels", "thesis mode", "opencv mode",
                "cv::StereoBM");
    for (const int n : {5, 9, 15, 21}) {
      const auto th_cfg = scw::hls::disparity::thesis_mode(l.width, l.height, 0);
      const auto cv_cfg = scw::hls::disparity::opencv_mode(l.width, l.height, 0);
      const auto th = scw::reference::disparity_reference(l.px.data(), r.px.data(), l.width,
                                                          l.height, n, kNumDisp, th_cfg);
      const auto oc = scw::reference::disparity_reference(l.px.data(), r.px.data(), l.width,
                                                          l.height, n, kNumDisp, cv_cfg);
      const auto bm = stereo_bm(l, r, n, kNumDisp, cv_cfg, true);
      const Region reg = valid_region(l.width, l.height, n, 0, kNumDisp);
      const std::uint16_t inv = scw::hls::disparity::invalid_code(cv_cfg);
      // Thesis mode rejects nothing: every pixel of the valid region carries a disparity (its
      // invalid code 0 is also d = 0, so it cannot be told apart anyway).
      const Accuracy a[3] = {accuracy(th, false, 0, gt, kGtScale, reg),
                             accuracy(oc, true, inv, gt, kGtScale, reg),
                             accuracy(bm, true, inv, gt, kGtScale, reg)};
      std::printf("  %-4d %-7ld", n, a[0].pixels);
      for (const Accuracy& x : a) {
        char cell[64];
        std::snprintf(cell, sizeof cell, "%.2f (%.1f, %.2f)", x.bad, x.density, x.bad_of_valid);
        std::printf(" %-24s", cell);
      }
      std::printf("\n");
    }

    if (!urban_l.empty()) {
      const Image ul = load_grey(urban_l), ur = load_grey(urban_r);
      std::printf("\n%s | %s: %d x %d\n", urban_l.c_str(), urban_r.c_str(), ul.width, ul.height);
      for (const int n : {21, 9})
        run_agreement(ul, ur, n, urban_nd, list,
                      scw::hls::disparity::opencv_mode(ul.width, ul.height, 0), "(defaults)");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "disparity_eval: %s\n", e.what());
    return 1;
  }
  return 0;
}
