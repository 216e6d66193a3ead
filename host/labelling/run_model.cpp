// SPDX-License-Identifier: Apache-2.0
// segment(): a disparity map through the labelling model, then the second pass.
#include "host/labelling/run_model.hpp"

#include <memory>
#include <regex>
#include <stdexcept>
#include <string>

#include "hls/labelling/labelling.hpp"
#include "host/labelling/second_pass.hpp"
#include "sim/models/labelling_model.hpp"

namespace scw::labelling {
namespace {

using HostParams = hls::labelling::LabellingParams<kHostMaxWidthPx, kHostMaxHeight, kHostMaxTiles,
                                                   kHostMaxTiles, kHostLabelsPerTile,
                                                   kHostMaxObjects>;

std::vector<HostParams::in_beat> frame_beats(const cv::Mat& d) {
  std::vector<HostParams::in_beat> beats;
  beats.reserve(d.total());
  for (int y = 0; y < d.rows; ++y)
    for (int x = 0; x < d.cols; ++x) {
      HostParams::in_beat b;
      b.px[0] = d.at<std::uint16_t>(y, x);
      b.sof = x == 0 && y == 0;
      b.eol = x == d.cols - 1;
      beats.push_back(b);
    }
  return beats;
}

}  // namespace

std::pair<int, int> parse_tiles(const std::string& text) {
  static const std::regex form("([1-9][0-9]{0,3})x([1-9][0-9]{0,3})");
  std::smatch m;
  if (!std::regex_match(text, m, form))
    throw std::runtime_error("--tiles '" + text +
                             "' is not of the form CxR: tile columns x tile rows, such as 4x2 "
                             "(1x1 to " +
                             std::to_string(kHostMaxTiles) + "x" + std::to_string(kHostMaxTiles) +
                             ")");
  return {std::stoi(m[1].str()), std::stoi(m[2].str())};
}

LabellingConfig grid_config(int width, int height, int tiles_x, int tiles_y, int floor,
                            int min_area) {
  if (tiles_x < 1 || tiles_y < 1)
    throw std::invalid_argument("labelling: a tile grid needs at least 1 x 1 tiles");
  LabellingConfig c;
  c.width = width;
  c.height = height;
  c.tile_w = (width + tiles_x - 1) / tiles_x;
  c.tile_h = (height + tiles_y - 1) / tiles_y;
  c.floor = floor;
  c.min_area = min_area;
  return c;
}

namespace {

bool same(const LabellingConfig& a, const LabellingConfig& b) {
  return a.width == b.width && a.height == b.height && a.tile_w == b.tile_w &&
         a.tile_h == b.tile_h && a.floor == b.floor && a.min_area == b.min_area;
}

/// One map through a stage that may have taken maps before, then the second pass.
Segmentation run_frame(sim::LabellingModel<HostParams>& model, const cv::Mat& disp_q4);

}  // namespace

Segmentation segment(const cv::Mat& disp_q4, const LabellingConfig& cfg) {
  if (disp_q4.empty() || disp_q4.type() != CV_16UC1)
    throw std::invalid_argument(
        "labelling: the disparity map must be one 16-bit channel of disparity x 16");
  if (disp_q4.cols != cfg.width || disp_q4.rows != cfg.height)
    throw std::invalid_argument("labelling: the configuration is for " +
                                std::to_string(cfg.width) + " x " + std::to_string(cfg.height) +
                                ", the map is " + std::to_string(disp_q4.cols) + " x " +
                                std::to_string(disp_q4.rows));
  hls::labelling::check_config<HostParams>(cfg);  // names the field out of range

  using Model = sim::LabellingModel<HostParams>;
  // One stage per thread and configuration takes a sequence's maps back to back, as the
  // pipeline's does: its descriptor RAMs (megabytes at the host's size) are not allocated and
  // zeroed again for every frame; the stage clears its tables clock by clock between frames
  // itself (its Init phase, run below before the frame is fed). A frame that fails leaves no
  // stage behind.
  thread_local std::unique_ptr<Model> model;
  thread_local LabellingConfig built{};
  if (!model || !same(built, cfg)) {
    model.reset();
    model = std::make_unique<Model>(cfg);
    built = cfg;
  }
  try {
    return run_frame(*model, disp_q4);
  } catch (...) {
    model.reset();
    throw;
  }
}

namespace {

Segmentation run_frame(sim::LabellingModel<HostParams>& m, const cv::Mat& disp_q4) {
  using Model = sim::LabellingModel<HostParams>;
  Model* const model = &m;
  auto& k = model->kernel();
  std::vector<std::int32_t> node_map(disp_q4.total(), 0);
  k.set_node_map(&node_map);
  while (k.phase() == Model::kernel_type::kInit) model->tick();

  const auto beats = frame_beats(disp_q4);
  Segmentation s;
  std::size_t next = 0;
  const std::int64_t limit = 64 * static_cast<std::int64_t>(beats.size()) + 4 * HostParams::kNodes;
  for (std::int64_t c = 0;; ++c) {
    if (c > limit) throw std::logic_error("labelling: the model did not finish the frame");
    const bool valid = next < beats.size();
    const auto o = model->eval(valid, valid ? beats[next] : HostParams::in_beat{}, true);
    model->tick();
    if (valid && o.in_ready) ++next;
    if (!o.out_valid) continue;
    if (!o.out.data.is_status) {
      s.objects.push_back(o.out.data.object);
      continue;
    }
    s.status = o.out.data.status;
    s.cycles = c + 1;
    break;
  }
  if (s.status.stream_error) throw std::logic_error("labelling: the model flagged a stream error");

  // Second pass: objects numbered in raster order of their first pixel.
  auto n = number_objects(s.objects, node_map, disp_q4.cols, disp_q4.rows,
                          [&k](int node) { return k.root(node); });
  s.labels = n.labels;
  s.objects_by_label = raster_sorted(s.objects);
  return s;
}

}  // namespace

}  // namespace scw::labelling
