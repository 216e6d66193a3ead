// SPDX-License-Identifier: Apache-2.0
// Labelling stage: compile-time capacities, run-time configuration, the join rule and the
// object descriptor the stage emits (docs/labelling.md).
#pragma once

#include <algorithm>
#include <cstdint>

#include "hls/common/beat.hpp"
#include "hls/common/bits.hpp"

namespace scw::hls::labelling {

/// One input disparity, Q11.4 in 16 bits as the disparity stage emits it.
using disp_t = std::uint16_t;

/// Wide enough for S_3(65535) S_0(65535) (about 2^78).
__extension__ typedef unsigned __int128 u128;

/// The bits each stored descriptor field needs at a MaxWidthPx x MaxHeight frame: the one source
/// of the widths. The RTL computes the same numbers as localparams of scw_labelling (AreaW ..
/// M03W, public) and sim::labelling_params_match checks them equal. An object is a set of the
/// frame's pixels and every term is non-negative, so each field is at most its value for the
/// whole frame; tests/labelling/test_labelling_hls.cpp checks that a full-frame object meets each
/// bound exactly at 1280 x 480.
struct DescWidths {
  int area = 0;  // 1 .. W H
  int x = 0;     // a column, 0 .. W - 1 (x_min, x_max, closest_x, first_x)
  int y = 0;     // a row, 0 .. H - 1
  int d = 0;     // an object pixel's disparity, 1 .. 0x7fff (positive as int16)
  int sum_d = 0;   // sum of d over the object (<= W H 0x7fff)
  int sum_dd = 0;  // sum of d^2 (<= W H 0x7fff^2)
  // m_pq <= S_p(W) S_q(H), S_k(n) = sum_{i < n} i^k; in the order m10 m01 m20 m11 m02 m30 m21
  // m12 m03.
  int m[9] = {};
  /// Every field's bits together: what one descriptor RAM word holds.
  constexpr int total() const {
    int t = area + 4 * x + 4 * y + 2 * d + sum_d + sum_dd;
    for (int w : m) t += w;
    return t;
  }
};

/// Bits that hold 0 .. v (at least 1).
constexpr int bits_for(u128 v) {
  int b = 1;
  while (b < 128 && (v >> b) != 0) ++b;
  return b;
}

/// S_k(n) = sum_{i=0}^{n-1} i^k for k = 0 .. 3, closed forms.
constexpr u128 power_sum(int n, int k) {
  const u128 m = static_cast<u128>(n);
  const u128 s1 = m * (m - 1) / 2;
  switch (k) {
    case 0: return m;
    case 1: return s1;
    case 2: return (m - 1) * m * (2 * m - 1) / 6;
    default: return s1 * s1;
  }
}

constexpr DescWidths desc_widths(int max_width_px, int max_height) {
  DescWidths w;
  const int pq[9][2] = {{1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {3, 0}, {2, 1}, {1, 2}, {0, 3}};
  w.area = bits_for(static_cast<u128>(max_width_px) * max_height);
  w.x = bits_for(static_cast<u128>(max_width_px - 1));
  w.y = bits_for(static_cast<u128>(max_height - 1));
  w.d = 15;
  const u128 pixels = static_cast<u128>(max_width_px) * max_height;
  w.sum_d = bits_for(pixels * 0x7fff);
  w.sum_dd = std::min(64, bits_for(pixels * 0x7fff * 0x7fff));  // Object's 64 bits
  for (int i = 0; i < 9; ++i)
    w.m[i] = std::min(64, bits_for(power_sum(max_width_px, pq[i][0]) *
                                   power_sum(max_height, pq[i][1])));  // Object's 64 bits
  return w;
}

/// Built-in capacities of one stage. The image is cut into tiles, at most MaxTilesX x MaxTilesY;
/// a frame's pixels may use MaxTilesX x MaxTilesY x LabelsPerTile labels (nodes) in all, any tile
/// as many as it needs (each lane draws on its own equal share), and a frame may report up to
/// MaxObjects objects.
/// `Lanes` pixels per beat, each to its own lane: lane i labels the i-th of `Lanes` vertical
/// strips of whole tile columns, one pixel per clock, and the strips are joined after the frame
/// (docs/labelling.md "Lanes").
template <int MaxWidthPx, int MaxHeight, int MaxTilesX, int MaxTilesY, int LabelsPerTile,
          int MaxObjects, int Lanes = 1>
struct LabellingParams {
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kMaxHeight = MaxHeight;
  static constexpr int kMaxTilesX = MaxTilesX;
  static constexpr int kMaxTilesY = MaxTilesY;
  static constexpr int kLabelsPerTile = LabelsPerTile;
  static constexpr int kMaxObjects = MaxObjects;
  static constexpr int kLanes = Lanes;
  /// Nodes: the labels of a frame, kLaneNodes a lane. Lane i numbers its own from
  /// i * kLaneStride up, in the order its pixels need them; with lanes the stride is a power of
  /// two, so that a node's lane and its address in the lane's banks are bit fields of its number
  /// (node numbers then run below kNodeSpace, with gaps).
  static constexpr int kNodes = MaxTilesX * MaxTilesY * LabelsPerTile;
  static constexpr int kLaneNodes = kNodes / Lanes;
  static constexpr int kLaneStride = Lanes == 1 ? kLaneNodes : pow2_at_least(kLaneNodes);
  static constexpr int kNodeSpace = Lanes * kLaneStride;
  /// Each lane's row buffer holds a strip of up to this many pixels, of up to this many tile
  /// columns; its input FIFO holds this many beats, enough that a strip's burst of beats
  /// (arriving Lanes times faster than the lane takes them) never holds the stream.
  static constexpr int kLaneWidthPx = MaxWidthPx / Lanes;
  static constexpr int kLaneTilesX = MaxTilesX / Lanes;
  static constexpr int kLaneFifo = kLaneWidthPx / Lanes > 2 ? kLaneWidthPx / Lanes : 2;
  using in_beat = Beat<disp_t, Lanes>;
  static constexpr DescWidths kWidths = desc_widths(MaxWidthPx, MaxHeight);
  static_assert(MaxWidthPx >= 2 && MaxHeight >= 1, "an image of at least 2 x 1");
  static_assert(MaxWidthPx <= 65535 && MaxHeight <= 65535, "coordinates travel in 16 bits");
  static_assert(MaxTilesX >= 1 && MaxTilesY >= 1 && LabelsPerTile >= 1 && MaxObjects >= 1,
                "capacities are at least 1");
  static_assert(Lanes == 1 || Lanes == 2 || Lanes == 4, "1, 2 or 4 lanes (pixels per beat)");
  static_assert(MaxTilesX % Lanes == 0 && MaxWidthPx % Lanes == 0,
                "the tile columns and the width split evenly over the lanes");
};

/// Run-time configuration (the RTL's cfg_* ports), stable while frames stream.
struct LabellingConfig {
  int width = 0;     // pixels, <= MaxWidthPx
  int height = 0;    // rows, <= MaxHeight
  int tile_w = 0;    // tile size in pixels: ceil(width / tile_w) <= MaxTilesX tile columns
  int tile_h = 0;    //   and ceil(height / tile_h) <= MaxTilesY tile rows; the last tile of a
                     //   row or column may be smaller
  int floor = 0;     // background: a pixel is valid when 0 < d (as int16) and d > floor
                     // (Q11.4; set it to the disparity stage's invalid code when that is > 0)
  int min_area = 1;  // objects with fewer pixels are not reported
};

/// The thesis's join (eq. 3.10 with absolute difference): two valid 4-neighbours join when
/// 10 |d_cur - d_nb| < d_cur, d_cur being the pixel later in raster order. Exact in integers.
constexpr bool joins(disp_t d_cur, disp_t d_nb) {
  const int diff = static_cast<int>(d_cur) - static_cast<int>(d_nb);
  return 10 * (diff < 0 ? -diff : diff) < static_cast<int>(d_cur);
}

/// Whether a disparity is an object pixel under `cfg` (docs/labelling.md).
constexpr bool is_valid(disp_t d, const LabellingConfig& cfg) {
  return d != 0 && d < 0x8000u && static_cast<int>(d) > cfg.floor;
}

/// One object: u = column, v = row, pixel coordinates from 0 at the top left.
struct Object {
  std::uint32_t area = 0;                      // pixels
  std::uint16_t x_min = 0, x_max = 0, y_min = 0, y_max = 0;  // bounding box, inclusive
  std::uint16_t d_min = 0, d_max = 0;          // Q11.4
  std::uint16_t closest_x = 0, closest_y = 0;  // first pixel in raster order holding d_max
  std::uint16_t first_x = 0, first_y = 0;      // first pixel in raster order
  // Raw moments m_pq = sum u^p v^q, p + q <= 3 (m00 = area).
  std::uint64_t m10 = 0, m01 = 0, m20 = 0, m11 = 0, m02 = 0, m30 = 0, m21 = 0, m12 = 0, m03 = 0;
  // The disparity's sum and sum of squares (Q11.4 codes): its mean and spread, from which the
  // warning stage's distance rule reads the object's front face (docs/warning.md).
  std::uint64_t sum_d = 0, sum_dd = 0;

  friend bool operator==(const Object& a, const Object& b) {
    return a.area == b.area && a.x_min == b.x_min && a.x_max == b.x_max && a.y_min == b.y_min &&
           a.y_max == b.y_max && a.d_min == b.d_min && a.d_max == b.d_max &&
           a.closest_x == b.closest_x && a.closest_y == b.closest_y && a.first_x == b.first_x &&
           a.first_y == b.first_y && a.m10 == b.m10 && a.m01 == b.m01 && a.m20 == b.m20 &&
           a.m11 == b.m11 && a.m02 == b.m02 && a.m30 == b.m30 && a.m21 == b.m21 &&
           a.m12 == b.m12 && a.m03 == b.m03 && a.sum_d == b.sum_d && a.sum_dd == b.sum_dd;
  }
  friend bool operator!=(const Object& a, const Object& b) { return !(a == b); }
};

/// The descriptor of one pixel (u, v) with disparity d: an object of one pixel.
constexpr Object pixel_object(int u, int v, disp_t d) {
  Object o;
  const auto x = static_cast<std::uint16_t>(u), y = static_cast<std::uint16_t>(v);
  const std::uint64_t uu = static_cast<std::uint64_t>(u), vv = static_cast<std::uint64_t>(v);
  o.area = 1;
  o.x_min = o.x_max = o.closest_x = o.first_x = x;
  o.y_min = o.y_max = o.closest_y = o.first_y = y;
  o.d_min = o.d_max = d;
  o.m10 = uu;
  o.m01 = vv;
  o.m20 = uu * uu;
  o.m11 = uu * vv;
  o.m02 = vv * vv;
  o.m30 = uu * uu * uu;
  o.m21 = uu * uu * vv;
  o.m12 = uu * vv * vv;
  o.m03 = vv * vv * vv;
  o.sum_d = d;
  o.sum_dd = std::uint64_t{d} * d;
  return o;
}

/// The descriptor of the union of two disjoint pixel sets. Symmetric; ties in the closest and
/// first points go to the earlier pixel in raster order.
constexpr Object merge(const Object& a, const Object& b) {
  auto before = [](int ya, int xa, int yb, int xb) { return ya < yb || (ya == yb && xa < xb); };
  auto mn = [](std::uint16_t p, std::uint16_t q) { return p < q ? p : q; };
  auto mx = [](std::uint16_t p, std::uint16_t q) { return p > q ? p : q; };
  Object o;
  o.area = a.area + b.area;
  o.x_min = mn(a.x_min, b.x_min);
  o.x_max = mx(a.x_max, b.x_max);
  o.y_min = mn(a.y_min, b.y_min);
  o.y_max = mx(a.y_max, b.y_max);
  o.d_min = mn(a.d_min, b.d_min);
  o.d_max = mx(a.d_max, b.d_max);
  const bool a_closest = a.d_max > b.d_max ||
                         (a.d_max == b.d_max &&
                          before(a.closest_y, a.closest_x, b.closest_y, b.closest_x));
  o.closest_x = a_closest ? a.closest_x : b.closest_x;
  o.closest_y = a_closest ? a.closest_y : b.closest_y;
  const bool a_first = before(a.first_y, a.first_x, b.first_y, b.first_x);
  o.first_x = a_first ? a.first_x : b.first_x;
  o.first_y = a_first ? a.first_y : b.first_y;
  o.m10 = a.m10 + b.m10;
  o.m01 = a.m01 + b.m01;
  o.m20 = a.m20 + b.m20;
  o.m11 = a.m11 + b.m11;
  o.m02 = a.m02 + b.m02;
  o.m30 = a.m30 + b.m30;
  o.m21 = a.m21 + b.m21;
  o.m12 = a.m12 + b.m12;
  o.m03 = a.m03 + b.m03;
  o.sum_d = a.sum_d + b.sum_d;
  o.sum_dd = a.sum_dd + b.sum_dd;
  return o;
}

/// `o` with every field cut to its width: what a descriptor RAM stores (a no-op on every
/// descriptor of a frame that fits, which is what the widths promise).
constexpr Object narrow(const Object& o, const DescWidths& w) {
  auto cut = [](std::uint64_t v, int bits) {
    return bits >= 64 ? v : v & ((std::uint64_t{1} << bits) - 1);
  };
  Object n = o;
  n.area = static_cast<std::uint32_t>(cut(o.area, w.area));
  n.x_min = static_cast<std::uint16_t>(cut(o.x_min, w.x));
  n.x_max = static_cast<std::uint16_t>(cut(o.x_max, w.x));
  n.closest_x = static_cast<std::uint16_t>(cut(o.closest_x, w.x));
  n.first_x = static_cast<std::uint16_t>(cut(o.first_x, w.x));
  n.y_min = static_cast<std::uint16_t>(cut(o.y_min, w.y));
  n.y_max = static_cast<std::uint16_t>(cut(o.y_max, w.y));
  n.closest_y = static_cast<std::uint16_t>(cut(o.closest_y, w.y));
  n.first_y = static_cast<std::uint16_t>(cut(o.first_y, w.y));
  n.d_min = static_cast<std::uint16_t>(cut(o.d_min, w.d));
  n.d_max = static_cast<std::uint16_t>(cut(o.d_max, w.d));
  std::uint64_t* m[9] = {&n.m10, &n.m01, &n.m20, &n.m11, &n.m02, &n.m30, &n.m21, &n.m12, &n.m03};
  for (int i = 0; i < 9; ++i) *m[i] = cut(*m[i], w.m[i]);
  n.sum_d = cut(o.sum_d, w.sum_d);
  n.sum_dd = cut(o.sum_dd, w.sum_dd);
  return n;
}

/// The frame's closing word.
struct FrameStatus {
  std::uint32_t objects = 0;     // objects reported in this frame
  bool tile_overflow = false;    // a lane ran out of labels (its kLaneNodes)
  bool object_overflow = false;  // more than MaxObjects objects reached MinArea
  bool stream_error = false;     // the input broke the frame geometry (docs/streaming.md)

  friend bool operator==(const FrameStatus& a, const FrameStatus& b) {
    return a.objects == b.objects && a.tile_overflow == b.tile_overflow &&
           a.object_overflow == b.object_overflow && a.stream_error == b.stream_error;
  }
};

/// One word of the output burst: the frame's objects, then its status (with `last`).
struct LabelWord {
  bool is_status = false;
  Object object;       // when !is_status
  FrameStatus status;  // when is_status

  friend bool operator==(const LabelWord& a, const LabelWord& b) {
    return a.is_status == b.is_status &&
           (a.is_status ? a.status == b.status : a.object == b.object);
  }
  friend bool operator!=(const LabelWord& a, const LabelWord& b) { return !(a == b); }
};

using LabelPacket = Packet<LabelWord>;

}  // namespace scw::hls::labelling
