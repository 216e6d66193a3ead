// SPDX-License-Identifier: Apache-2.0
// A downstream project's check of the installed scw: one random stereo frame through the
// disparity stage's C++ model and through scw_disparity Verilated from the installed RTL, under
// random input gaps and output backpressure; the two must give the same beats on the same
// cycles, and the model's map must equal the floating-point reference. Exit 0 when they do.
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <random>
#include <vector>

#include "host/reference/disparity_ref.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/join.hpp"
#include "sim/models/disparity_model.hpp"
#include "sim/rtl/disparity_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "Vdownstream_disparity.h"
#include "Vdownstream_disparity_scw_disparity.h"

namespace {

using namespace scw;
using Params = hls::disparity::DisparityParams<1, 32, 5, 6, 16>;
using Kernel = hls::disparity::Disparity<Params>;
using VM = Vdownstream_disparity;
static_assert(sim::disparity_params_match<Vdownstream_disparity_scw_disparity, Kernel>(),
              "the Verilated parameters (CMakeLists.txt) must be main.cpp's");

constexpr int kW = 32, kH = 16;

/// A random left image and the right one: the left shifted by 3 px, noise added.
std::pair<std::vector<std::uint8_t>, std::vector<std::uint8_t>> random_pair() {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> grey(0, 255), noise(-2, 2);
  std::vector<std::uint8_t> l(kW * kH), r(kW * kH);
  for (auto& p : l) p = static_cast<std::uint8_t>(grey(rng));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const int v = l[y * kW + std::min(kW - 1, x + 3)] + noise(rng);
      r[y * kW + x] = static_cast<std::uint8_t>(std::clamp(v, 0, 255));
    }
  return {l, r};
}

}  // namespace

int main() {
  hls::disparity::DisparityConfig cfg;
  cfg.width = kW;
  cfg.height = kH;
  cfg.num_disp = 6;
  const auto [l, r] = random_pair();
  const auto lb = sim::frame_beats_of<Params::pixel_beat>(l.data(), kW, kH);
  const auto rb = sim::frame_beats_of<Params::pixel_beat>(r.data(), kW, kH);
  const auto pattern = sim::StallPattern::parse("random:5");
  sim::DisparityModel<Params> cpp(cfg);
  auto rtl = sim::make_disparity_rtl<VM, Params>("downstream", cfg);
  const auto rc = sim::run_join(cpp, lb, rb, pattern, lb.size());
  const auto rr = sim::run_join(rtl, lb, rb, pattern, lb.size());
  const auto ref = reference::disparity_reference(l.data(), r.data(), kW, kH, Params::kWindow,
                                                  6, cfg);
  const auto expect = sim::frame_beats_of<Params::disp_beat>(ref.data(), kW, kH);
  const auto clean = [](const auto& run) { return run.violations.empty() && !run.timed_out; };
  const bool twins = clean(rc) && clean(rr) && rc.out == rr.out && rc.cycles == rr.cycles;
  const bool reference = rc.out == expect;
  std::cout << "scw_disparity from the installed RTL and the C++ model: " << rr.out.size()
            << " beats in " << rr.cycles << " cycles, "
            << (twins ? "the same beats on the same cycles" : "THEY DIFFER") << "; the model "
            << (reference ? "equals" : "DIFFERS FROM") << " the floating-point reference\n";
  return twins && reference ? 0 : 1;
}
