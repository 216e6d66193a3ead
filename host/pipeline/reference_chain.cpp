// SPDX-License-Identifier: Apache-2.0
// The floating-point and reference chain (host/pipeline/reference_chain.hpp).
#include "host/pipeline/reference_chain.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include "host/labelling/run_model.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/reference/labelling_ref.hpp"
#include "host/reference/stereo_bm.hpp"

namespace scw::host::pipeline {

ReferenceFrame reference_frame(const cv::Mat& left, const cv::Mat& right, int window_n,
                               const StageOptions& opt, int frames) {
  if (opt.mode != disparity::Mode::opencv)
    throw std::invalid_argument("the reference chain runs cv::StereoBM: opencv mode only");
  const int w = left.cols, h = left.rows;
  auto cfg = disparity::mode_config(opt.mode, w, h, opt.dmin);
  cfg.num_disp = opt.num_disp;
  const cv::Mat l = left.isContinuous() ? left : left.clone();
  const cv::Mat r = right.isContinuous() ? right : right.clone();
  // cv::StereoBM takes multiples of 16 candidates; other ranges (the thesis's 45) go through the
  // direct reference, plain loops over every window, equal to StereoBM where both apply.
  auto d =
      opt.num_disp % 16 == 0
          ? reference::stereo_bm(l.ptr<std::uint8_t>(), r.ptr<std::uint8_t>(), w, h, window_n,
                                 opt.num_disp, cfg, true)
          : reference::disparity_reference(l.ptr<std::uint8_t>(), r.ptr<std::uint8_t>(), w, h,
                                           window_n, opt.num_disp, cfg);
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
  f.road = reference::to_px(rcfg.nominal);
  const cv::Mat map = f.disparity.clone();
  for (int k = 0; k < frames; ++k) {
    const auto step = reference::road_reference(map, f.road, rcfg);
    f.disparity = step.kept;
    if (k + 1 < frames) f.road = step.next;
  }
  std::memcpy(d.data(), f.disparity.data, d.size() * sizeof(std::uint16_t));
  const int invalid = static_cast<std::int16_t>(hls::disparity::invalid_code(cfg));
  const auto lcfg = labelling::grid_config(w, h, opt.tiles_x, opt.tiles_y,
                                           invalid > 0 ? invalid : 0, opt.min_area);
  f.objects = reference::labelling_reference(d.data(), w, h, lcfg).objects;
  f.result = host::warning::fold_ref(f.objects, w_setup, &f.road);
  return f;
}

}  // namespace scw::host::pipeline
