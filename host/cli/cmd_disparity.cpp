// SPDX-License-Identifier: Apache-2.0
// `scw disparity`: SAD block-matching disparity of a rectified stereo pair through the streaming
// C++ model of the disparity stage; writes an 8-bit map and optionally the 16-bit x16 values and
// a colour picture (the work is host/disparity/disparity_files).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/cli/value_checks.hpp"
#include "host/disparity/disparity_files.hpp"

namespace scw::cli {
namespace {

void run_disparity(const disparity::FilesOptions& o) {
  const auto r = disparity::run_disparity_files(o, std::cerr);
  std::string wrote;
  for (const auto& f : r.written) wrote += (wrote.empty() ? "" : ", ") + f;
  std::cout << "pixels holding the invalid code " << r.invalid << ": " << r.invalid_pixels
            << " of " << r.d16.total() << "\n"
            << "wrote " << wrote << "\n";
}

}  // namespace

void add_disparity_command(CLI::App& app) {
  auto o = std::make_shared<disparity::FilesOptions>();
  auto* cmd = app.add_subcommand(
      "disparity",
      "SAD block-matching disparity of a rectified pair with the disparity stage's streaming "
      "model (P = 1)");
  std::string windows;
  for (const int n : disparity::kHostWindows)
    windows += (windows.empty() ? "" : ", ") + std::to_string(n);
  cmd->add_option("--left", o->left, "Rectified left image (colour is converted to grey)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--right", o->right, "Rectified right image")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--window", o->window, "SAD window N (N x N), built: " + windows)
      ->required()
      ->check(odd_window());
  cmd->add_option("--min-disp", o->min_disp, "Smallest candidate disparity (>= 0)")->required();
  cmd->add_option("--max-disp", o->max_disp,
                  "Largest candidate; at most " + std::to_string(disparity::kHostMaxNumDisp) +
                      " candidates (max - min + 1)")
      ->required();
  cmd->add_option("--mode", o->mode,
                  "thesis: plain SAD on raw pixels, nothing rejected, integer d, invalid 0; "
                  "opencv: cv::StereoBM's defaults (x-Sobel prefilter cap 31, texture 10, "
                  "uniqueness 15, sub-pixel, invalid (min-1)*16). scw run and scw sim share the "
                  "default; docs/disparity.md has the measurements that chose it")
      ->capture_default_str()
      ->check(CLI::IsMember({"thesis", "opencv"}));
  cmd->add_option("--prefilter-cap", o->prefilter_cap,
                  "x-Sobel cap (opencv mode's prefilter; also the texture measure's offset)")
      ->check(CLI::Range(1, 63));
  cmd->add_option("--texture", o->texture, "Texture threshold, 0 = off (overrides the mode)")
      ->check(non_negative("", "10"));
  cmd->add_option("--uniqueness", o->uniqueness,
                  "Uniqueness ratio in %, 0 = off (overrides the mode)")
      ->check(non_negative("%", "15"));
  cmd->add_option("--sad-limit", o->sad_limit, "Reject a minimum SAD above this, 0 = off")
      ->check(non_negative("", "0"));
  cmd->add_option("--edge-candidates", o->edge_candidates, disparity::kEdgeCandidatesHelp)
      ->capture_default_str()
      ->check(non_negative("", "32"));
  cmd->add_option("--out", o->out,
                  "8-bit PNG: 0 = invalid, else the integer disparity (x16 value >> 4, at most "
                  "255); with --min-disp 0 a valid d below 1 also reads 0")
      ->required();
  cmd->add_option("--out16", o->out16,
                  "16-bit PNG of the stage's values, disparity x 16 as int16 bit patterns "
                  "(cv::StereoBM's CV_16S output in opencv mode; invalid 0 in thesis mode)");
  cmd->add_option("--color", o->color,
                  "Colour picture (COLORMAP_JET over min .. max disparity, invalid black)");
  cmd->callback([o] { run_disparity(*o); });
}

}  // namespace scw::cli
