// SPDX-License-Identifier: Apache-2.0
// The floating-point and reference chain (host/pipeline/reference_chain.hpp).
#include "host/pipeline/reference_chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>

#include "host/labelling/run_model.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/reference/labelling_ref.hpp"
#include "host/reference/stereo_bm.hpp"

namespace scw::host::pipeline {

ReferenceFrame reference_frame(const cv::Mat& left, const cv::Mat& right, int window_n,
                               const StageOptions& opt, int frames) {
  ReferenceChain chain(window_n, opt);
  for (int k = 1; k < frames; ++k) chain.next(left, right);
  return chain.next(left, right);
}

ReferenceChain::ReferenceChain(int window_n, const StageOptions& opt)
    : window_n_(window_n), opt_(opt) {
  if (opt.mode != disparity::Mode::opencv)
    throw std::invalid_argument("the reference chain runs cv::StereoBM: opencv mode only");
}

ReferenceFrame ReferenceChain::next(const cv::Mat& left, const cv::Mat& right) {
  const StageOptions& opt = opt_;
  const int w = left.cols, h = left.rows;
  auto cfg = disparity::mode_config(opt.mode, w, h, opt.dmin);
  cfg.num_disp = opt.num_disp;
  cfg.edge_candidates = opt.edge_candidates;
  const cv::Mat l = left.isContinuous() ? left : left.clone();
  const cv::Mat r = right.isContinuous() ? right : right.clone();
  // cv::StereoBM takes multiples of 16 candidates; other ranges (the thesis's 45) go through the
  // direct reference, plain loops over every window, equal to StereoBM where both apply.
  // cv::StereoBM has no left edge band either.
  auto d = opt.num_disp % 16 == 0 && cfg.edge_candidates == 0
               ? reference::stereo_bm(l.ptr<std::uint8_t>(), r.ptr<std::uint8_t>(), w, h, window_n_,
                                      opt.num_disp, cfg, true)
               : reference::disparity_reference(l.ptr<std::uint8_t>(), r.ptr<std::uint8_t>(), w, h,
                                                window_n_, opt.num_disp, cfg);
  ReferenceFrame f;
  f.disparity = cv::Mat(h, w, CV_16S);
  std::memcpy(f.disparity.data, d.data(), d.size() * sizeof(std::uint16_t));
  // The road reference runs as the stage does, always: it removes the road only with opt.road,
  // and the warning reference measures heights above the frame's road.
  const auto w_setup = warning_setup(w, h, opt);
  auto rsetup = road::rig_setup(w_setup.baseline_m, w_setup.focal_px, w_setup.cv_px,
                                opt.camera_height_m, opt.camera_pitch_deg);
  rsetup.min_count = opt.road_min_count;
  rsetup.enable = opt.road;
  const auto rcfg = road::to_fixed(rsetup);
  if (!started_) road_ = reference::to_px(rcfg.nominal);
  started_ = true;
  f.road = road_;
  const auto step = reference::road_reference(f.disparity.clone(), f.road, rcfg);
  f.disparity = step.kept;
  road_ = step.next;
  std::memcpy(d.data(), f.disparity.data, d.size() * sizeof(std::uint16_t));
  const int invalid = static_cast<std::int16_t>(hls::disparity::invalid_code(cfg));
  const auto lcfg = labelling::grid_config(w, h, opt.tiles_x, opt.tiles_y,
                                           invalid > 0 ? invalid : 0, opt.min_area);
  f.objects = reference::labelling_reference(d.data(), w, h, lcfg).objects;
  f.result = host::warning::fold_ref(f.objects, w_setup, &f.road);
  return f;
}

std::string reference_mismatch(const hls::warning::FrameResult& got, const ReferenceFrame& ref,
                               int w, int h, const StageOptions& opt) {
  std::ostringstream why;
  const auto differ = [&why](const char* what, long a, long b) {
    if (a != b) why << (why.tellp() > 0 ? ", " : "") << what << " " << a << " (reference " << b << ")";
  };
  differ("objects", got.objects, ref.result.objects);
  differ("obstacles", got.obstacles, ref.result.obstacles);
  differ("severity", static_cast<int>(got.severity), static_cast<int>(ref.result.severity));
  const bool has = got.index != 0xffff, ref_has = ref.result.index >= 0;
  differ("deciding object", has, ref_has);
  if (!has || !ref_has || why.tellp() > 0) return why.str();
  // The stage lists objects by root node, the reference by first pixel: the deciding object
  // is found in the reference's list by its closest point, largest disparity and box.
  const auto setup = warning_setup(w, h, opt);
  const auto same = [&got](const hls::labelling::Object& o) {
    return got.closest_x == o.closest_x && got.closest_y == o.closest_y && got.d_max == o.d_max &&
           got.x_min == o.x_min && got.x_max == o.x_max && got.y_min == o.y_min &&
           got.y_max == o.y_max;
  };
  const auto& dec = ref.objects[static_cast<std::size_t>(ref.result.index)];
  auto mine = ref.result.deciding;
  double tol = host::warning::distance_tolerance_m(mine, setup);
  if (!same(dec)) {
    // Another obstacle decided. That is right only when the two are as near as the stage can
    // tell apart: the reference distances within both tolerances (a near-tie that the stage's
    // millimetres and the reference's doubles may break either way).
    const auto it = std::find_if(ref.objects.begin(), ref.objects.end(), same);
    if (it == ref.objects.end()) return "the deciding object is none of the reference's objects";
    mine = host::warning::evaluate_ref(*it, setup, &ref.road);
    const double both = tol + host::warning::distance_tolerance_m(mine, setup);
    if (std::abs(mine.distance_m - ref.result.deciding.distance_m) >= both) {
      why << "deciding object at (" << got.closest_x << ", " << got.closest_y << "), "
          << mine.distance_m << " m; the reference's at (" << dec.closest_x << ", "
          << dec.closest_y << "), " << ref.result.deciding.distance_m << " m";
      return why.str();
    }
    tol = host::warning::distance_tolerance_m(mine, setup);
  }
  const double dist = got.distance_mm / 1000.0;
  if (std::abs(dist - mine.distance_m) >= tol)
    why << "distance " << dist << " m (reference " << mine.distance_m << " m, within " << tol
        << " m)";
  return why.str();
}

std::string object_mismatch(std::vector<hls::labelling::Object> objects, const ReferenceFrame& ref) {
  const auto by_first = [](const hls::labelling::Object& a, const hls::labelling::Object& b) {
    return std::make_pair(a.first_y, a.first_x) < std::make_pair(b.first_y, b.first_x);
  };
  auto want = ref.objects;
  std::sort(objects.begin(), objects.end(), by_first);
  std::sort(want.begin(), want.end(), by_first);
  if (objects == want) return "";
  return "object words: " + std::to_string(objects.size()) + " objects, the reference's " +
         std::to_string(want.size()) + ", not the same set";
}

std::string decision_boundary(const ReferenceFrame& ref, int w, int h, const StageOptions& opt) {
  constexpr double kCm = 0.01, kCodePx = 1.0 / 16;
  const auto s = warning_setup(w, h, opt);
  for (std::size_t i = 0; i < ref.objects.size(); ++i) {
    const auto e = host::warning::evaluate_ref(ref.objects[i], s, &ref.road);
    const double d = host::warning::rule_disparity_px(ref.objects[i], s);
    std::ostringstream why;
    why << "object " << i << ": ";
    if (std::abs(d - 1.0) <= kCodePx) {
      why << "rule disparity " << d << " px, measurable from 1 px";
    } else if (!e.measurable) {
      continue;
    } else if (std::abs(e.height_m - s.min_height_m) < kCm ||
               std::abs(e.above_road_m - s.min_height_m) < kCm) {
      why << "height " << e.height_m << " m, " << e.above_road_m << " m above the road, min "
          << s.min_height_m << " m";
    } else if (e.obstacle && (std::abs(e.signed_gap_m) < kCm || std::abs(e.gap_m - s.near_m) < kCm)) {
      why << "gap " << e.signed_gap_m << " m to the tunnel, near " << s.near_m << " m";
    } else if (e.obstacle && !e.too_close &&
               (std::abs(e.distance_m - s.high_m) < host::warning::distance_tolerance_m(e, s) ||
                std::abs(e.distance_m - s.medium_m) < host::warning::distance_tolerance_m(e, s))) {
      why << "distance " << e.distance_m << " m, thresholds " << s.high_m << " and " << s.medium_m
          << " m";
    } else {
      continue;
    }
    return why.str();
  }
  return "";
}

}  // namespace scw::host::pipeline
