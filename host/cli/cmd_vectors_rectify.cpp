// SPDX-License-Identifier: Apache-2.0
// `scw vectors rectify`: writes a golden vector set of the rectify stage
// (host/vectors/rectify_set.hpp), with the Verilated scw_rectify built for the CLI.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "Vcli_rectify_p2.h"
#include "Vcli_rectify_p2_scw_rectify.h"
#include "host/cli/commands.hpp"
#include "host/cli/set_options.hpp"
#include "host/vectors/rectify_set.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/core/join.hpp"
#include "sim/rtl/rectify_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"

namespace scw::cli {
namespace {

namespace vec = scw::vectors;
using RtlParams = vec::RectifyRtlParams;
static_assert(sim::rectify_params_match<Vcli_rectify_p2_scw_rectify, RtlParams>());

vec::RectifyRtlRun run_rtl(const hls::rectify::RectifyConfig& cfg,
                           const std::vector<RtlParams::pixel_beat>& raw,
                           const std::vector<RtlParams::map_beat>& map,
                           const sim::StallPattern& pattern, std::size_t beats) {
  auto rtl = sim::make_rectify_rtl<Vcli_rectify_p2, RtlParams>("rectify", cfg);
  vec::RectifyRtlRun r;
  r.run = sim::run_join(rtl, raw, map, pattern, beats);
  r.err = static_cast<std::uint8_t>(rtl.dut().err_o);
  return r;
}

void print(const vec::RectifySetSummary& s, const std::string& out) {
  std::cout << "C++ model: " << s.beats << " beats equal the integer reference (" << s.cycles
            << " cycles, stalls " << s.stalls << ")\n";
  if (s.rtl)
    std::cout << "RTL: " << s.rtl_beats << " beats equal the integer reference and the C++ "
              << "model, cycle for cycle\n";
  std::cout << "wrote " << out << "/ (" << s.frames << " frame(s) of " << s.width << "x" << s.height
            << ", P = " << s.ppc << ", lead " << s.lead_rows << " rows, " << s.rows_needed << " of "
            << s.rows << " raw rows in flight)\n";
}

}  // namespace

void add_vectors_rectify_command(CLI::App& vectors) {
  struct Options {
    int frames = 0;  // 0: as given
    std::string preset;
    SetOut set;
    int ppc = vec::kRectifyVecRtlPpc;
    std::string engine = "rtl", stalls = "both", data_dir = "data/chessboard", build = "vectors";
    vec::UserCalibratedPair pair;
    std::string camera = "left";
    std::vector<int> roi{352, 112};  // chessboard: top-left of the rectified ROI (on the board)
    std::vector<int> size;           // chessboard: the ROI's size (default: 128 x 96, thesis: all)
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "rectify", "Write a rectify golden vector set (raw + map in, rectified pixels out)");
  auto* preset = cmd->add_option("--preset", o->preset,
                                 "shift, rotation, barrel (64x32 test card) or chessboard_left, "
                                 "chessboard_right (128x96 crop of the bundled pair, real "
                                 "calibration)");
  preset->check(CLI::IsMember(vec::rectify_presets()));
  auto* left =
      cmd->add_option("--left", o->pair.left,
                      "Your raw left images (instead of a preset), a frame each, back to back")
          ->check(CLI::ExistingFile);
  auto* right = cmd->add_option("--right", o->pair.right, "Your raw right images, as many")
                    ->check(CLI::ExistingFile);
  auto* calib = cmd->add_option("--calib", o->pair.calib,
                                "Your pair's calibration: OpenCV FileStorage M1 D1 M2 D2 R T, as "
                                "scw run --calib reads it")
                    ->check(CLI::ExistingFile);
  left->needs(right)->needs(calib)->excludes(preset);
  right->needs(left);
  calib->needs(left);
  cmd->add_option("--camera", o->camera, "With --left/--right: the camera the set rectifies")
      ->check(CLI::IsMember({"left", "right"}));
  cmd->add_option("--ppc", o->ppc, "Pixels per beat")->check(CLI::IsMember({1, 2, 4}));
  cmd->add_option("--engine", o->engine,
                  "rtl: expected output from the Verilated stage (P = 2), also checked against "
                  "the C++ model; cpp: the C++ model only")
      ->check(CLI::IsMember({"cpp", "rtl"}));
  cmd->add_option("--stalls", o->stalls,
                  "Stalls while generating (the vectors do not depend on them): none, idle, "
                  "backpressure, both or random:<seed>");
  cmd->add_option("--config", o->build,
                  "vectors: frames up to 128 x 96 (the committed sets; --engine rtl checks the "
                  "Verilated stage); thesis: the thesis build (1280 x 480, 64 raw rows; "
                  "--engine cpp). The chessboard presets then take the whole image unless --roi "
                  "and --size pick a band: this calibration's whole image needs 81 raw rows")
      ->check(CLI::IsMember(vec::rectify_builds()));
  add_set_frames_option(cmd, o->frames);
  add_set_out_options(cmd, o->set);
  cmd->add_option("--data-dir", o->data_dir,
                  "Folder with left01.jpg, right01.jpg and derived_stereo_calibration_helper.yml");
  cmd->add_option("--roi", o->roi,
                  "Chessboard or your pair: top-left X Y of the rectified ROI (default 352 112)")
      ->expected(2);
  cmd->add_option("--size", o->size,
                  "Chessboard or your pair: W H of the rectified ROI (default 128 96; --config "
                  "thesis: the whole image from 0 0)")
      ->expected(2);
  cmd->callback([o, cmd] {
    if (o->preset.empty() && o->pair.left.empty())
      throw CLI::ValidationError(
          "give --preset NAME, or your raw pair with --left L --right R --calib C");
    const auto stalls = sim::StallPattern::parse(o->stalls);  // a bad pattern before any work
    const bool rtl = o->engine == "rtl";
    if (rtl) vec::check_rectify_rtl_ppc(o->ppc, o->build);
    // The thesis build takes the whole image (from 0 0) unless --size says otherwise.
    const bool whole = o->build == "thesis" && o->size.empty();
    const cv::Size size = !o->size.empty() ? cv::Size(o->size[0], o->size[1])
                          : whole          ? cv::Size()
                                           : vec::kRectifyCropSize;
    const cv::Point roi = whole ? cv::Point() : cv::Point(o->roi[0], o->roi[1]);
    o->pair.right_camera = o->camera == "right";
    auto f = o->preset.empty() ? vec::rectify_frame(o->pair, roi, size)
                               : vec::rectify_preset(o->preset, o->data_dir, roi, size);
    const std::string name = o->preset.empty() ? o->camera + " camera" : o->preset;
    const vec::RectifyRtl engine = rtl ? vec::RectifyRtl(run_rtl) : vec::RectifyRtl();
    if (o->frames > 0) vec::repeat_frames(f.raw, o->frames);
    write_set_parts(*cmd, o->set, f.raw.size(), [&](const auto& r, const auto& dir) {
      auto part = f;
      part.raw = vec::frames_in(f.raw, r);
      print(vec::write_rectify_set(part, name, o->ppc, stalls, engine, dir, o->build),
            dir.string());
    });
  });
}

}  // namespace scw::cli
