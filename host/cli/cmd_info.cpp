// SPDX-License-Identifier: Apache-2.0
// `scw info`: what this build contains (stages, primitives, tool versions it was built with).
#include <iostream>

#include <opencv2/core/version.hpp>

#include "host/cli/commands.hpp"
#include "sim/core/stall.hpp"

namespace scw::cli {

void add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Show what this build of scw contains");
  cmd->callback([] {
    std::cout << "scw 0.1.0\n"
              << "  OpenCV " << CV_VERSION << "\n"
              << "  stream beat: P pixels of 8 bits, packed {eol, sof, px[P-1..0]}\n"
              << "  primitives: fifo, stream_reg, skid_buf, ram_sdp, line_buffer "
                 "(RTL in rtl_models/common, C++ twins in sim/ and hls/common)\n"
              << "  stall patterns:";
    for (const auto& p : sim::StallPattern::all(1)) std::cout << " " << p.name();
    std::cout << "\n  stages: rectify, disparity, labelling (C++ and RTL); warning (to come)\n";
  });
}

}  // namespace scw::cli
