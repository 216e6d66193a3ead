// SPDX-License-Identifier: Apache-2.0
// remove_ground(): a disparity map through the ground-removal cycle model.
#include "host/ground/run_model.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/frame_beats.hpp"
#include "sim/models/ground_model.hpp"

namespace scw::ground {
namespace {

using HostParams = hls::ground::GroundParams<kHostMaxWidthPx>;
using Beat = HostParams::in_beat;

}  // namespace

cv::Mat remove_ground(const cv::Mat& d16, const GroundConfig& cfg, std::int64_t* cycles) {
  if (d16.empty() || (d16.type() != CV_16SC1 && d16.type() != CV_16UC1))
    throw std::invalid_argument(
        "ground: the disparity map must be one 16-bit channel of disparity x 16 (CV_16S or "
        "CV_16U)");
  if (d16.cols > kHostMaxWidthPx)
    throw std::invalid_argument("ground: the map is " + std::to_string(d16.cols) +
                                " px wide; the host's build takes rows up to " +
                                std::to_string(kHostMaxWidthPx) + " px");
  hls::ground::check_config(cfg);  // names the field out of range

  const cv::Mat in = d16.isContinuous() ? d16 : d16.clone();
  const auto beats = sim::frame_beats_of<Beat>(in.ptr<std::uint16_t>(), in.cols, in.rows);
  using Model = sim::GroundModel<HostParams>;
  const auto model = std::make_unique<Model>(cfg);  // the line buffer: keep it off the stack

  cv::Mat out(d16.rows, d16.cols, d16.type());
  auto* dst = out.ptr<std::uint16_t>();
  std::size_t next = 0, done = 0;
  const std::int64_t limit = static_cast<std::int64_t>(beats.size()) + 16 * Model::kLatency;
  std::int64_t c = 0;
  for (; done < beats.size(); ++c) {
    if (c > limit) throw std::logic_error("ground: the model stopped producing output");
    const bool valid = next < beats.size();
    const auto o = model->eval(valid, valid ? beats[next] : Beat{}, true);
    model->tick();
    if (valid && o.in_ready) ++next;
    if (o.out_valid) dst[done++] = o.out.px[0];
  }
  if (model->kernel().error()) throw std::logic_error("ground: the model flagged a stream error");
  if (cycles != nullptr) *cycles = c;
  return out;
}

}  // namespace scw::ground
