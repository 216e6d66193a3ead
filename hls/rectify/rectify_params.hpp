// SPDX-License-Identifier: Apache-2.0
// Rectify stage: compile-time parameters, the map stream's element and the run-time config.
#pragma once

#include <cstdint>

#include "hls/common/beat.hpp"
#include "hls/common/bits.hpp"

namespace scw::hls::rectify {

/// One element of the map stream: the source position of one output pixel in the raw image,
/// signed fixed point with F fractional bits (x = column, y = row; x = 3.5 is 3.5 * 2^F).
/// The host clamps coordinates to [-2^F, W * 2^F] x [-2^F, H * 2^F] (every position outside
/// gives 0, exactly as the clamped one does), so CoordBits bits hold them.
struct MapPoint {
  std::int32_t x = 0;
  std::int32_t y = 0;
  friend bool operator==(const MapPoint& a, const MapPoint& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const MapPoint& a, const MapPoint& b) { return !(a == b); }
};

/// One transfer on the map stream: a beat of the source positions of P consecutive output
/// pixels. CoordBits is the width of each signed coordinate in the packed RTL word ({y, x} per
/// pixel, pixel 0 in the low bits; sim::BeatLayout).
template <int P, int CoordBits>
struct MapBeat : Beat<MapPoint, P> {
  static constexpr int kCoordBits = CoordBits;
};

/// The map stream's signed coordinate width for images up to max_wh pixels on a side at
/// frac_bits fractional bits: it holds -2^F .. max_wh * 2^F. The rectify stage and the map grid
/// that feeds it both take it.
constexpr int coord_bits(long long max_wh, int frac_bits) {
  return clog2(max_wh * (1LL << frac_bits) + 1) + 1;
}

/// Built-in limits of one rectify stage; the single source the RTL (scw_rectify) is checked
/// against. Rows raw rows are kept in block RAM (a power of two, so the row slot is a bit
/// field); a map is served when every raw row an output row needs lies in that window
/// (see map_taps.hpp and docs/rectify.md).
template <int P, int MaxWidthPx, int MaxHeight, int Rows, int FracBits = 5>
struct RectifyParams {
  static constexpr int kPpc = P;
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kMaxHeight = MaxHeight;
  static constexpr int kRows = Rows;
  static constexpr int kFracBits = FracBits;
  /// Signed coordinate width: holds -2^F .. max(W, H) * 2^F.
  static constexpr int kCoordBits =
      coord_bits(MaxWidthPx > MaxHeight ? MaxWidthPx : MaxHeight, FracBits);
  /// Register stages from accepting a map beat to presenting its output beat: RAM addresses,
  /// RAM read + window compares, bank registers + tap enables, bank pick, tap differences,
  /// horizontal blend (DSP M, P), b - a, vertical blend + round (DSP M, P). Shared by the
  /// RTL, sim/ and the tests (docs/rectify.md).
  static constexpr int kLatency = 10;
  using pixel_beat = Beat<pixel_t, P>;
  using map_beat = MapBeat<P, kCoordBits>;
  static_assert(P == 1 || P == 2 || P == 4, "P must be 1, 2 or 4");
  static_assert(MaxWidthPx % (2 * P) == 0, "MaxWidthPx must be a multiple of 2 * P");
  static_assert(Rows >= 4 && (Rows & (Rows - 1)) == 0, "Rows must be a power of two >= 4");
  static_assert(FracBits >= 1 && FracBits <= 8, "FracBits must be 1..8");
  static_assert(kCoordBits <= 31, "coordinates must fit 32-bit signed integers");
};

/// Run-time configuration (the RTL's cfg_* ports), stable while frames stream.
/// `lead_rows` (D) is how many raw rows ahead of output row v the stage waits for: output row
/// v starts once raw rows up to v + D - 1 (or the frame's last row) have arrived, and can
/// read raw rows v + D - Rows + 2 .. v + D - 1 (map_taps.hpp). The host picks D from the maps.
struct RectifyConfig {
  int width = 0;      // pixels, a multiple of P, <= MaxWidthPx
  int height = 0;     // rows, <= MaxHeight
  int lead_rows = 1;  // D, 1 .. Rows - 1
};

/// Sticky error bits (the RTL's err_o).
enum RectifyError : std::uint8_t {
  kErrRawGeometry = 1,  // raw stream: sof/eol not where cfg width x height puts them
  kErrMapGeometry = 2,  // map stream: sof/eol not where cfg width x height puts them
  kErrMapWindow = 4,    // a map tap needed a raw row outside the stage's row window
};

}  // namespace scw::hls::rectify
