// SPDX-License-Identifier: Apache-2.0
// Decoding one map point into its four bilinear taps, and which raw rows it really needs.
// Shared by the kernel (window check), the RTL's twin and the host's map planner, so that a
// map the host accepts can never trip the stage's window check.
#pragma once

#include <cstdint>

#include "hls/rectify/rectify_params.hpp"

namespace scw::hls::rectify {

/// The four taps of a source position: (x0, y0), (x0 + 1, y0), (x0, y0 + 1), (x0 + 1, y0 + 1)
/// with weights (S - fx)(S - fy), fx (S - fy), (S - fx) fy, fx fy, S = 2^F.
struct Taps {
  int x0 = 0, y0 = 0;  // floor of the position
  int fx = 0, fy = 0;  // fractional parts, 0 .. S - 1
  bool col0 = false, col1 = false;  // column x0 (x0 + 1) inside the image with nonzero weight
  bool row0 = false, row1 = false;  // row y0 (y0 + 1) inside the image, carrying weight
};

/// A tap contributes when its pixel is inside the image and its weight is nonzero. Row y0
/// always has weight (S - fy) > 0; row y0 + 1 only when fy > 0; likewise for columns. A row
/// "is needed" when it holds at least one contributing tap.
template <int F>
constexpr Taps decode_taps(const MapPoint& m, int width, int height) {
  Taps t;
  t.x0 = m.x >> F;  // arithmetic shift: floor for negative coordinates too
  t.y0 = m.y >> F;
  t.fx = m.x & ((1 << F) - 1);
  t.fy = m.y & ((1 << F) - 1);
  t.col0 = t.x0 >= 0 && t.x0 < width;
  t.col1 = t.fx != 0 && t.x0 + 1 >= 0 && t.x0 + 1 < width;
  const bool any_col = t.col0 || t.col1;
  t.row0 = any_col && t.y0 >= 0 && t.y0 < height;
  t.row1 = any_col && t.fy != 0 && t.y0 + 1 >= 0 && t.y0 + 1 < height;
  return t;
}

/// Whether raw row v + dy may be read while output row v is produced with lead D in a stage
/// of `rows` rows: the window is v + D - rows + 2 .. v + D - 1. Output row v starts once rows
/// up to v + D - 1 are in; the writer may run up to D + 1 rows ahead, so rows v + D and
/// v + D + 1 (which overwrites row v + D + 1 - rows) can be in flight: that row of slack is
/// what lets both sides run one beat per clock across row boundaries.
constexpr bool in_row_window(int dy, int lead_rows, int rows) {
  return dy >= lead_rows - rows + 2 && dy <= lead_rows - 1;
}

}  // namespace scw::hls::rectify
