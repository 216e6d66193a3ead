// SPDX-License-Identifier: Apache-2.0
// Grid-compressed rectification maps: knots every G = 2^k pixels on chip, expanded into the map
// stream scw_rectify consumes (bilinear between four knots, one rounding). docs/rectify.md.
#pragma once

#include <array>
#include <cstdint>

#include "hls/common/beat.hpp"
#include "hls/common/stream.hpp"
#include "hls/rectify/rectify_params.hpp"

namespace scw::hls::rectify {

/// Knot columns (rows) for `pixels` pixels at G = 2^grid_log2: one at or beyond the last pixel.
constexpr int knot_count(int pixels, int grid_log2) { return ((pixels - 1) >> grid_log2) + 2; }

/// The signed knot coordinate width for images up to max_wh pixels on a side: an integer part of
/// clog2(max_wh) + 2 bits (KnotBits below) and knot_frac_bits fractional bits. The host's
/// default for a run-time size (host/rectify/map_grid.hpp) is the same expression.
constexpr int knot_bits(long long max_wh, int knot_frac_bits) {
  return clog2(max_wh) + 2 + knot_frac_bits;
}

/// One knot: the raw source position of output pixel (i G, j G), signed fixed point with
/// KnotFracBits fractional bits (more than the map's F, so that rounding the knots costs at
/// most 1/8 of the map's own rounding step: see MapGridParams).
struct KnotPoint {
  std::int32_t x = 0;
  std::int32_t y = 0;
  friend bool operator==(const KnotPoint& a, const KnotPoint& b) {
    return a.x == b.x && a.y == b.y;
  }
  friend bool operator!=(const KnotPoint& a, const KnotPoint& b) { return !(a == b); }
};

/// Built-in limits of one map expander; the single source the RTL (scw_rectify_map_grid) is
/// checked against.
///
/// - Knots sit at u = i G, v = j G for i = 0 .. ((W - 1) >> k) + 1 and likewise j: one knot
///   column (row) at or beyond the last pixel, so every pixel has its four knots.
/// - KnotFracBits = F + 2 by default. The expansion is exact until its single final rounding,
///   so a knot's rounding error reaches the map scaled by a convex weight: at most half a knot
///   step, 2^-(F+3) px = 1/8 of the map's own half-step 2^-(F+1). Two bits make knot rounding
///   negligible beside the output rounding (and beside the bilinear model error, which is what
///   G really decides); F + k bits would add k - 2 more bits to every knot word for nothing
///   measurable (docs/rectify.md).
/// - KnotBits: signed, integer part clog2(max(W, H)) + 2 bits, i.e. knots may lie up to
///   2^(clog2 max(W,H) + 1) >= 2 max(W, H) pixels either side of 0; the host clamps (and
///   counts) anything further out.
template <int P, int MaxWidthPx, int MaxHeight, int GridLog2, int FracBits = 5,
          int KnotFracBits = FracBits + 2>
struct MapGridParams {
  static constexpr int kPpc = P;
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kMaxHeight = MaxHeight;
  static constexpr int kGridLog2 = GridLog2;
  static constexpr int kGrid = 1 << GridLog2;  // G, pixels between knots
  static constexpr int kFracBits = FracBits;
  static constexpr int kKnotFracBits = KnotFracBits;
  static constexpr int kMaxWH = MaxWidthPx > MaxHeight ? MaxWidthPx : MaxHeight;
  static constexpr int kMaxKnotCols = knot_count(MaxWidthPx, GridLog2);
  static constexpr int kMaxKnotRows = knot_count(MaxHeight, GridLog2);
  /// Widths of the knot write address {row, col} (col in the low bits).
  static constexpr int kKnotColBits = clog2(kMaxKnotCols);
  static constexpr int kKnotRowBits = clog2(kMaxKnotRows);
  /// Signed knot coordinate width.
  static constexpr int kKnotBits = knot_bits(kMaxWH, KnotFracBits);
  /// The map stream's coordinate width, the rectify stage's (coord_bits).
  static constexpr int kCoordBits = coord_bits(kMaxWH, FracBits);
  /// The final shift: sum K w carries 2k + KnotFracBits fractional bits, the map F.
  static constexpr int kShift = 2 * GridLog2 + KnotFracBits - FracBits;
  /// Register stages from issuing a beat (the knot RAMs sample its address) to presenting it:
  /// knot RAM read, knot words, vertical differences, vertical blends (DSP M, P), R - L,
  /// horizontal blends (DSP M, P), + rounding half, shift and compares, clamp = output.
  static constexpr int kLatency = 11;
  using map_beat = MapBeat<P, kCoordBits>;
  static_assert(P == 1 || P == 2 || P == 4, "P must be 1, 2 or 4");
  static_assert(GridLog2 >= 1 && GridLog2 <= 6, "G = 2^GridLog2 must be 2 .. 64");
  static_assert(kGrid >= P, "the P pixels of a beat must share their knots: G >= P");
  static_assert(MaxWidthPx % P == 0, "MaxWidthPx must be a multiple of P");
  static_assert(MaxWidthPx > kGrid && MaxHeight > kGrid, "at least 3 knot columns and rows");
  static_assert(FracBits >= 1 && FracBits <= 8, "FracBits must be 1..8");
  static_assert(KnotFracBits >= FracBits, "knots need at least the map's precision");
  static_assert(kKnotBits <= 31, "knot coordinates must fit 32-bit signed integers");
  static_assert(kKnotBits + 2 * GridLog2 + 2 <= 62, "blends must fit 64-bit integers");
};

/// Run-time configuration (the RTL's cfg_* ports), stable while frames stream: the frame size
/// of the map (and of the raw and rectified images), width a multiple of P.
struct MapGridConfig {
  int width = 0;
  int height = 0;
};

/// The expander: a source of map beats in raster order (sof on the first beat of a frame, eol
/// on the last beat of every row), frame after frame, one beat per step(). The twin of
/// rtl_models/rectify/scw_rectify_map_grid.sv, clocked by sim::MapGridModel.
///
/// For output pixel (u, v): i = u >> k, j = v >> k, du = u & (G - 1), dv = v & (G - 1) and the
/// knots K00 = K(i, j), K10 = K(i + 1, j), K01 = K(i, j + 1), K11 = K(i + 1, j + 1) (x and y
/// alike, integers with KnotFracBits fractional bits):
///
///   L = K00 G + (K01 - K00) dv          (= K00 (G - dv) + K01 dv, exact)
///   R = K10 G + (K11 - K10) dv
///   c = L G + (R - L) du                (= sum of K (G - du|du)(G - dv|dv), exact)
///   m = (c + 2^(s - 1)) >> s,  s = 2k + KnotFracBits - F   (the one rounding, half up)
///   x = clamp(m_x, -S, W S),  y = clamp(m_y, -S, H S),  S = 2^F
///
/// The clamp is the host's (quantise_map), so a map point outside the image reads 0 exactly as
/// the full map's does. The vertical blends L, R depend only on the beat's knot column pair, so
/// the P pixels of a beat (G >= P: same knots) share them and differ only in du.
template <typename Params>
class MapGrid {
 public:
  static constexpr int P = Params::kPpc;
  static constexpr int K = Params::kGridLog2;
  static constexpr int G = Params::kGrid;
  static constexpr int F = Params::kFracBits;
  static constexpr int kShift = Params::kShift;
  using out_type = typename Params::map_beat;

  /// Where a beat sits: column of beats and row.
  struct Pos {
    int col = 0, row = 0;
  };

  explicit MapGrid(const MapGridConfig& cfg = {}) : cfg_(cfg) {}
  const MapGridConfig& config() const { return cfg_; }

  /// The write port (knot_we/addr/data): knot (col, row) := k. Addresses outside the built grid
  /// are ignored (in the RTL they land in RAM words no read ever addresses).
  void write_knot(int col, int row, const KnotPoint& k) {
    if (col < 0 || col >= Params::kMaxKnotCols || row < 0 || row >= Params::kMaxKnotRows) return;
    knots_[static_cast<std::size_t>(row)][static_cast<std::size_t>(col)] = k;
  }
  const KnotPoint& knot(int col, int row) const {
    return knots_[static_cast<std::size_t>(row)][static_cast<std::size_t>(col)];
  }

  /// The next beat in raster order; moves on (frame after frame).
  Pos issue() {
    const Pos p = pos_;
    if (pos_.col != cols() - 1) {
      ++pos_.col;
    } else {
      pos_.col = 0;
      pos_.row = pos_.row == cfg_.height - 1 ? 0 : pos_.row + 1;
    }
    return p;
  }

  /// The map beat at `p`, from the knots as they are now.
  out_type expand(const Pos& p) const {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    const int u = p.col * P, v = p.row;
    const int i = u >> K, j = v >> K;
    const int du0 = u & (G - 1), dv = v & (G - 1);
    // The RTL keeps knots in four RAMs by (row parity, column parity), so K00, K10, K01, K11
    // are always four different RAMs: ARRAY_PARTITION cyclic factor=2 on both dimensions.
    // clang-format off
#pragma HLS ARRAY_PARTITION variable=knots_ cyclic factor=2 dim=1
#pragma HLS ARRAY_PARTITION variable=knots_ cyclic factor=2 dim=2
    // clang-format on
    const KnotPoint& k00 = knot(i, j);
    const KnotPoint& k10 = knot(i + 1, j);
    const KnotPoint& k01 = knot(i, j + 1);
    const KnotPoint& k11 = knot(i + 1, j + 1);
    // Q(KnotBits + k).KnotFracBits: a convex combination of knots times G.
    const std::int64_t lx = vertical(k00.x, k01.x, dv), rx = vertical(k10.x, k11.x, dv);
    const std::int64_t ly = vertical(k00.y, k01.y, dv), ry = vertical(k10.y, k11.y, dv);
    out_type b;
    for (int l = 0; l < P; ++l) {  // the beat's P pixels: P horizontal blends side by side
      // clang-format off
#pragma HLS UNROLL
      // clang-format on
      const int du = du0 + l;  // < G: the beat does not cross a knot column (G >= P)
      b.px[static_cast<std::size_t>(l)].x =
          clamp(round(horizontal(lx, rx, du)), -(1 << F), cfg_.width * (1 << F));
      b.px[static_cast<std::size_t>(l)].y =
          clamp(round(horizontal(ly, ry, du)), -(1 << F), cfg_.height * (1 << F));
    }
    b.sof = p.col == 0 && p.row == 0;
    b.eol = p.col == cols() - 1;
    return b;
  }

  /// One beat: the body of an II=1 loop.
  out_type step() { return expand(issue()); }

 private:
  int cols() const { return cfg_.width / P; }

  static std::int64_t vertical(std::int32_t top, std::int32_t bottom, int dv) {
    return (std::int64_t{top} << K) + (std::int64_t{bottom} - top) * dv;
  }
  static std::int64_t horizontal(std::int64_t left, std::int64_t right, int du) {
    return (left << K) + (right - left) * du;
  }
  /// Round half up: an arithmetic shift is a floor for negative sums too.
  static std::int32_t round(std::int64_t c) {
    return static_cast<std::int32_t>((c + (std::int64_t{1} << (kShift - 1))) >> kShift);
  }
  static std::int32_t clamp(std::int32_t m, std::int32_t lo, std::int32_t hi) {
    return m < lo ? lo : (m > hi ? hi : m);
  }

  MapGridConfig cfg_;
  std::array<std::array<KnotPoint, Params::kMaxKnotCols>, Params::kMaxKnotRows> knots_{};
  Pos pos_;
};

// The loop labels name the loops in HLS reports; g++ would call them unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// The knot write port driven from an array of `cols` x `rows` knots (row after row), one knot
/// a clock, as sim::load_knots and the pipeline top's knot port load them.
template <typename Params>
void map_grid_load(MapGrid<Params>& g, const KnotPoint* knots, int cols, int rows) {
loop_knot_row:
  for (int j = 0; j < rows; ++j) {
  loop_knot_col:
    for (int i = 0; i < cols; ++i) {
      // clang-format off
#pragma HLS PIPELINE II=1
      // clang-format on
      g.write_knot(i, j, knots[j * cols + i]);
    }
  }
}

/// `n` map beats (frames of the configured size, back to back, continuing where the last call
/// stopped) to `out`, one a clock. What an HLS tool synthesises as the expander's top, after
/// map_grid_load; the port is hls::stream (or ArrayOut).
template <typename Params, typename Out, if_port<Out> = 0>
void map_grid_frame(MapGrid<Params>& g, Out& out, int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
loop_beat:
  for (int i = 0; i < n; ++i) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    out.write(g.step());
  }
}
#pragma GCC diagnostic pop

}  // namespace scw::hls::rectify
