// SPDX-License-Identifier: Apache-2.0
// The thesis's FPGA clock and its Table 5.7 (processing times): the one place scw's cycle
// counts are turned into milliseconds and set beside the thesis's.
#pragma once

#include <cstdint>

namespace scw::host::pipeline::thesis {

/// The thesis FPGA's clock (section 5.5.4), MHz.
inline constexpr double kClockMhz = 125.0;

/// Cycles at kClockMhz in ms.
constexpr double ms(std::int64_t cycles) {
  return static_cast<double>(cycles) / (kClockMhz * 1000.0);
}

/// A row of Table 5.7, ms on the thesis's CPU, GPU and FPGA, and the block of ours that does
/// that work.
struct StageTime {
  const char* name;
  const char* block;
  double cpu, gpu, fpga;
};
inline constexpr StageTime kTable57[] = {
    {"stereo rectification", "rectify_left", 3.5, 0.2, 1.0},
    {"disparity map", "disparity", 16.7, 5.4, 6.8},
    {"segmentation", "labelling", 14.1, 3.3, 1.4},
    {"collision warning", "warning", 3.1, 0.7, 0.3},
};

/// The whole chain's frame period and latency, ms (Table 5.7).
struct ChainTime {
  double cpu, gpu, fpga;
};
inline constexpr ChainTime kPeriodMs{37.4, 9.6, 6.8};
inline constexpr ChainTime kLatencyMs{37.4, 9.6, 9.5};

}  // namespace scw::host::pipeline::thesis
