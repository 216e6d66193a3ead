// SPDX-License-Identifier: Apache-2.0
// read_stream_image(), the report and the files of `scw stream` (host/pipeline/stream_run.hpp).
#include "host/pipeline/stream_run.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>

#include "host/io/image_file.hpp"
#include "host/io/json_file.hpp"
#include "host/pipeline/thesis_figures.hpp"
#include "host/vectors/line_buffer_set.hpp"
#include "sim/core/stall.hpp"

namespace scw::host::pipeline {

cv::Mat read_stream_image(const StreamOptions& o, int max_width_px) {
  sim::StallPattern::parse(o.stalls);  // reject a bad pattern before any work
  cv::Mat img = io::read_grey_image(o.image);
  if (!o.roi.empty()) {
    const cv::Rect r(o.roi[0], o.roi[1], o.roi[2], o.roi[3]);
    if (r.width <= 0 || r.height <= 0 || (r & cv::Rect(0, 0, img.cols, img.rows)) != r)
      throw std::runtime_error("--roi " + std::to_string(r.x) + " " + std::to_string(r.y) + " " +
                               std::to_string(r.width) + " " + std::to_string(r.height) +
                               " is not inside the " + std::to_string(img.cols) + " x " +
                               std::to_string(img.rows) + " image");
    img = img(r).clone();
  }
  if (img.cols > max_width_px || img.cols % o.ppc != 0 || img.cols / o.ppc < 2)
    throw std::runtime_error("image '" + o.image + "' is " + std::to_string(img.cols) +
                             " px wide: the line buffer holds rows of up to " +
                             std::to_string(max_width_px) + " px, in whole beats of " +
                             std::to_string(o.ppc) + " px; crop or resize it");
  return img;
}

nlohmann::json stream_report_json(const sim::SimReport& r) {
  nlohmann::json j;
  j["cycles"] = r.cycles;
  for (const auto& f : r.fifos)
    j["fifos"].push_back({{"name", f.name},
                          {"producer", f.producer},
                          {"consumer", f.consumer},
                          {"depth", f.depth},
                          {"max_occupancy", f.max_occupancy},
                          {"beats", f.beats}});
  for (const auto& s : r.stages) {
    nlohmann::json st{{"name", s.name}, {"frames", nlohmann::json::array()}};
    for (const auto& f : s.frames)
      st["frames"].push_back({{"first_in", f.first_in},
                              {"last_in", f.last_in},
                              {"first_out", f.first_out},
                              {"last_out", f.last_out}});
    j["stages"].push_back(st);
  }
  return j;
}

void write_stream_files(const StreamOptions& o, const StreamRun& r, const cv::Mat& grey) {
  const std::filesystem::path dir(o.out_dir);
  std::filesystem::create_directories(dir);
  nlohmann::json j = stream_report_json(r.report);
  j["engine"] = o.engine;
  j["ppc"] = r.ppc;
  j["clock_mhz"] = thesis::kClockMhz;
  io::write_json(dir / "report.json", j);
  vectors::write_line_buffer_set(dir / "vectors", {r.ppc, r.max_width_px, r.rows, r.latency},
                                 grey, r.input, r.expected);
}

}  // namespace scw::host::pipeline
