// SPDX-License-Identifier: Apache-2.0
// Warning stage: capacities, run-time configuration, the per-object arithmetic (eq. 2.18, 3.11,
// 3.12, 5.2) in fixed point, and the frame result (docs/warning.md).
#pragma once

#include <cstdint>

#include "hls/common/beat.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/road/road_params.hpp"

namespace scw::hls::warning {

/// Built-in capacity: the reciprocal table covers disparity codes 0 .. 16 * MaxDisparityPx - 1
/// (Q11.4). Objects whose closest disparity lies at or beyond the table are "too close".
template <int MaxDisparityPx>
struct WarningParams {
  static constexpr int kMaxDisparityPx = MaxDisparityPx;
  static constexpr int kTableSize = 16 * MaxDisparityPx;
  static_assert(MaxDisparityPx >= 2 && MaxDisparityPx <= 2048, "disparity codes fit Q11.4");
};

/// The distance rule's operand widths (docs/warning.md "The distance rule"): an object's area,
/// disparity sum and sum of squares are read from their low kRuleAreaBits, kRuleSumBits and
/// kRuleSquareBits bits. A labelling build of up to 2^20 - 1 pixels (1280 x 720 and below) never
/// has more: area < 2^20 and d < 2^15 bound the sums (sim/ checks each pipeline build).
inline constexpr int kRuleAreaBits = 20;
inline constexpr int kRuleSumBits = kRuleAreaBits + 15;
inline constexpr int kRuleSquareBits = kRuleAreaBits + 30;
/// The spread's root: A S2 - S1^2 < 2^70, so its rounded root has at most 36 bits.
inline constexpr int kRuleRootBits = kRuleSumBits;
/// Clocks the rule adds in front of the object pipeline (scw_warning_rule's Latency).
inline constexpr int kRuleLatency = 64;  // set from the RTL
/// Clocks from an input word's acceptance to its effect on the frame result (the RTL's
/// pipeline depth, `Latency` in scw_warning): the distance rule, then table read, b/d,
/// coordinates, squares, square root, tunnel test, severity, fold. Shared by the model, the RTL
/// and sim/.
inline constexpr int kLatency = kRuleLatency + 47;

/// Which disparity places an object.
enum class DistanceRule : std::uint8_t {
  kClosest = 0,  // the thesis's: its largest disparity, d_max (architecture 4.3)
  kSpread = 1,   // its front face: min(d_max, mean + k sd) of its disparities
};

/// Run-time configuration (the RTL's cfg_* ports), stable while frames stream. Lengths in mm.
/// host/warning/setup.hpp fills it from metres and pixels (to_fixed) and documents the defaults.
struct WarningConfig {
  std::uint32_t baseline_q8 = 0;  // b, mm Q12.8 (20 bits: up to 4 m, steps of 4 um)
  std::uint16_t focal_q4 = 0;     // f, px Q12.4
  std::uint16_t cu_q4 = 0;        // principal point of the left camera, px Q12.4
  std::uint16_t cv_q4 = 0;
  // The vehicle origin (front bumper centre, on the ground) in camera coordinates (x right,
  // y up, z ahead; thesis Fig. 5.4: -300, -1200, 1650).
  std::int16_t veh_x_mm = 0;
  std::int16_t veh_y_mm = 0;
  std::int16_t veh_z_mm = 0;
  std::uint16_t tunnel_half_w_mm = 0;  // half the tunnel's width, about the car's centre line
  std::uint16_t tunnel_h_mm = 0;       // the tunnel's height above the ground
  std::uint16_t high_mm = 0;           // eq. 5.2: in the tunnel, high when D <= high
  std::uint16_t medium_mm = 0;         //   medium when D < medium, else low
  std::uint16_t near_mm = 0;           // outside: medium when the gap to the tunnel <= near and
                                       //   D < medium, else low
  std::uint16_t min_height_mm = 0;     // objects lower than this (3D, eq. 3.12) are not obstacles
  std::uint16_t d_limit_q4 = 0;        // d_max >= this: closer than the search range measures
  DistanceRule rule = DistanceRule::kClosest;  // which disparity places an object
  std::uint8_t spread_q4 = 0;          // k of kSpread, Q4.4 (0 .. 15.9375)
  // A road line (hls::road::Line, the road stage's) comes with every frame, taken with its first
  // word, and an object's height is its top's above the road where it stands (road_height);
  // otherwise its box's height at its depth. The pipeline top always has it.
  bool road_height = false;
};

enum class Severity : std::uint8_t { kNone = 0, kLow = 1, kMedium = 2, kHigh = 3 };

/// "none", "low", "medium", "high": the one spelling results.jsonl, truth.jsonl, the vectors and
/// the printouts use ("?" for a code outside the four).
constexpr const char* severity_name(Severity s) {
  switch (s) {
    case Severity::kNone: return "none";
    case Severity::kLow: return "low";
    case Severity::kMedium: return "medium";
    case Severity::kHigh: return "high";
  }
  return "?";
}

/// `v / 2^n` rounded half up (an arithmetic shift of v + 2^(n-1), as the RTL does it).
constexpr std::int64_t rshift_round(std::int64_t v, int n) {
  return (v + (std::int64_t{1} << (n - 1))) >> n;
}

/// The reciprocal table: round(2^32 / dq) for a Q11.4 code dq >= 16 (d >= 1 px); 29 bits.
constexpr std::uint32_t recip(std::uint32_t dq) {
  return static_cast<std::uint32_t>(((std::uint64_t{1} << 32) + dq / 2) / dq);
}

/// floor(sqrt(n) + 1/2) for n < 2^(2 root_bits), trying root bits root_bits - 1 .. 0 (the RTL's
/// bit-serial square root, scw_warning_sqrt, with RootW = root_bits).
constexpr std::uint64_t isqrt_round_wide(labelling::u128 n, int root_bits) {
  std::uint64_t r = 0;
  for (int b = root_bits - 1; b >= 0; --b) {
    const std::uint64_t t = r | (std::uint64_t{1} << b);
    if (static_cast<labelling::u128>(t) * t <= n) r = t;
  }
  if (n - static_cast<labelling::u128>(r) * r > r) ++r;  // n >= (r + 1/2)^2 <=> n - r^2 > r
  return r;
}

/// floor(sqrt(n) + 1/2) for n < 2^52: what the RTL's bit-serial square root and its rounding
/// step give for the distance (27 root bits).
constexpr std::uint32_t isqrt_round(std::uint64_t n) {
  return static_cast<std::uint32_t>(isqrt_round_wide(n, 27));
}

/// The disparity (Q11.4 code) that places object `o` under `c.rule`. kSpread, exactly as
/// scw_warning_rule computes it from area A, S1 = sum d and S2 = sum d^2 (cut to the rule's
/// widths):
///   V = max(0, A S2 - S1^2)          (A^2 times the variance; never negative from a real object)
///   R = isqrt_round(V)                (A sd)
///   q = floor((16 S1 + k_q4 R + 8 A) / (16 A))   (mean + k sd, rounded; 65535 when it does not
///                                                 fit 16 bits, A = 0 included)
///   d = min(d_max, q)                 (never nearer than the object's closest pixel)
constexpr std::uint32_t rule_disparity(const labelling::Object& o, const WarningConfig& c) {
  if (c.rule != DistanceRule::kSpread) return o.d_max;
  using u128 = labelling::u128;
  auto low = [](std::uint64_t v, int bits) { return v & ((std::uint64_t{1} << bits) - 1); };
  const u128 a = low(o.area, kRuleAreaBits);
  const u128 s1 = low(o.sum_d, kRuleSumBits);
  const u128 s2 = low(o.sum_dd, kRuleSquareBits);
  const u128 as2 = a * s2, s1s1 = s1 * s1;
  const u128 v = as2 > s1s1 ? as2 - s1s1 : 0;
  const u128 r = isqrt_round_wide(v, kRuleRootBits);
  const u128 num = 16 * s1 + u128{c.spread_q4} * r + 8 * a;
  const u128 den = 16 * a;
  const u128 q = (den == 0 || num / den > 0xffff) ? 0xffff : num / den;
  return static_cast<std::uint32_t>(q < o.d_max ? q : u128{o.d_max});
}

/// The slope bits a road line's `a` carries on the port (18).
inline constexpr std::int64_t kMaxSlopeCode = (std::int64_t{1} << road::kSlopeBits) - 1;

/// The road line that comes with a frame (road_height): d_road(v) = b + a v, code x 2^12.
using RoadLine = road::Line;

/// Whether the top of `o`'s box, row y_min - 1/2, lies at least min_height above the road where
/// the object stands, at the rule's disparity dq (docs/warning.md "Height above the road"). The
/// road's disparity at that row is b + a (y_min - 1/2); the object stands where the road's
/// disparity is dq, and the height between is H (dq - d_road) / dq with H = baseline / a the
/// camera height the slope gives (a = 2^16 baseline / H, code x 2^12 a row). In integers:
///   D = dq 2^13 - 2 b - a (2 y_min - 1)     (code x 2^13; within +-2^37)
///   height >= min_height  <=>  baseline_q8 D >= 32 min_height_mm a dq
/// (both sides below 2^58). A flat road (a = 0) puts every object with D >= 0 above it.
struct RoadHeight {
  std::int64_t lhs = 0;  // baseline_q8 D
  std::int64_t rhs = 0;  // 32 min_height_mm a dq
};
constexpr RoadHeight road_height(const labelling::Object& o, std::uint32_t dq, const RoadLine& road,
                                  const WarningConfig& c) {
  const std::int64_t a = road.a & kMaxSlopeCode;
  const std::int64_t d =
      (std::int64_t{dq} << 13) - 2 * std::int64_t{road.b} - a * (2 * std::int64_t{o.y_min} - 1);
  return RoadHeight{std::int64_t{c.baseline_q8} * d,
                    32 * std::int64_t{c.min_height_mm} * a * std::int64_t{dq}};
}

/// One object as the warning stage sees it. Lengths in mm, camera coordinates unless named v_.
struct ObjectEval {
  std::uint32_t d_q4 = 0;   // the disparity that places it (rule_disparity), Q11.4
  bool measurable = false;  // d_q4 >= 1 px; otherwise too far to place and never an obstacle
  bool too_close = false;   // d_max >= d_limit: at most `distance_mm` away (an upper bound)
  std::int64_t s_q20 = 0;   // b / d: mm per pixel at the object's depth, Q.20
  std::int32_t x_mm = 0, y_mm = 0, z_mm = 0;  // closest point, eq. 2.18
  std::int32_t x0_mm = 0, x1_mm = 0;          // left and right bounding-box edges at that depth
  std::int32_t y_top_mm = 0, y_bot_mm = 0;    // top and bottom edges
  std::int32_t width_mm = 0, height_mm = 0;   // eq. 3.12
  std::int32_t above_road_mm = 0;  // road_height: the top's height above the road where the
                                   //   object stands (the model's report; the RTL compares only)
  std::int32_t distance_mm = 0;               // eq. 3.11 minus veh_z: from the bumper
  std::int32_t gap_mm = 0;                    // to the tunnel's cross-section, 0 = inside
  bool in_tunnel = false;
  bool obstacle = false;                      // measurable and height >= min_height (and, with
                                              //   road_height, its top as high above the road)
  Severity severity = Severity::kNone;        // kNone unless an obstacle
};

/// The per-object arithmetic of the stage, exactly as the RTL pipeline computes it.
/// Pixel edges: a bounding box [x_min, x_max] spans x_min - 1/2 .. x_max + 1/2 (so W and H count
/// pixels, never 0); all coordinates of an object use the rule's disparity d (d_max under the
/// thesis's rule). Codes past the table read its last entry; check_config keeps d_limit inside
/// the table, so they are too close.
template <typename Params>
constexpr ObjectEval evaluate(const labelling::Object& o, const WarningConfig& c,
                              const RoadLine& road = {}) {
  ObjectEval e;
  const std::uint32_t dq = rule_disparity(o, c);
  e.d_q4 = dq;
  e.measurable = dq >= 16 && dq < 0x8000u;
  if (!e.measurable) return e;
  e.too_close = o.d_max >= c.d_limit_q4;
  const std::uint32_t index = dq < Params::kTableSize ? dq : Params::kTableSize - 1;
  // S = b / d = b_q8 * 2^-8 * 16 / dq mm/px = b_q8 * recip * 2^-36; kept Q.20.
  e.s_q20 = rshift_round(static_cast<std::int64_t>(c.baseline_q8) * recip(index), 16);
  auto at = [&](std::int64_t px_q4) {  // S * (pixel offset, Q.4) in mm
    return static_cast<std::int32_t>(rshift_round(e.s_q20 * px_q4, 24));
  };
  const std::int64_t cu = c.cu_q4, cv = c.cv_q4;
  e.x_mm = at(16 * std::int64_t{o.closest_x} - cu);
  e.y_mm = at(cv - 16 * std::int64_t{o.closest_y});
  e.z_mm = at(c.focal_q4);
  e.x0_mm = at(16 * std::int64_t{o.x_min} - 8 - cu);
  e.x1_mm = at(16 * std::int64_t{o.x_max} + 8 - cu);
  e.y_top_mm = at(cv - (16 * std::int64_t{o.y_min} - 8));
  e.y_bot_mm = at(cv - (16 * std::int64_t{o.y_max} + 8));
  e.width_mm = e.x1_mm - e.x0_mm;
  e.height_mm = e.y_top_mm - e.y_bot_mm;
  const std::uint64_t xx = static_cast<std::uint64_t>(std::int64_t{e.x_mm} * e.x_mm);
  const std::uint64_t yy = static_cast<std::uint64_t>(std::int64_t{e.y_mm} * e.y_mm);
  const std::uint64_t zz = static_cast<std::uint64_t>(std::int64_t{e.z_mm} * e.z_mm);
  e.distance_mm = static_cast<std::int32_t>(isqrt_round(xx + yy + zz)) - c.veh_z_mm;
  // The tunnel's cross-section in vehicle coordinates: |xv| <= half_w, 0 <= yv <= h.
  const std::int32_t vx0 = e.x0_mm - c.veh_x_mm, vx1 = e.x1_mm - c.veh_x_mm;
  const std::int32_t vy_top = e.y_top_mm - c.veh_y_mm, vy_bot = e.y_bot_mm - c.veh_y_mm;
  const std::int32_t hw = c.tunnel_half_w_mm, th = c.tunnel_h_mm;
  auto mx = [](std::int32_t a, std::int32_t b) { return a > b ? a : b; };
  const std::int32_t gx = mx(0, mx(vx0 - hw, -hw - vx1));
  const std::int32_t gy = mx(0, mx(vy_bot - th, -vy_top));
  e.gap_mm = mx(gx, gy);
  e.in_tunnel = e.gap_mm == 0;
  e.obstacle = e.height_mm >= c.min_height_mm;
  if (c.road_height) {
    // Its top must also reach min_height above the road where it stands.
    const RoadHeight h = road_height(o, dq, road, c);
    e.obstacle = e.obstacle && h.lhs >= h.rhs;
    const std::int64_t per_mm = 32 * std::int64_t{road.a & kMaxSlopeCode} * dq;
    const std::int64_t mm = per_mm > 0 ? h.lhs / per_mm : (h.lhs >= 0 ? 0x7fffffff : -0x7fffffff);
    e.above_road_mm = static_cast<std::int32_t>(mm > 0x7fffffff ? 0x7fffffff
                                                : mm < -0x7fffffff ? -0x7fffffff : mm);
  }
  if (!e.obstacle) return e;
  // Too close: closer than the search range can measure, so judged as if at the bumper.
  const std::int32_t d = e.too_close ? 0 : e.distance_mm;
  if (e.in_tunnel) {
    e.severity = d <= c.high_mm     ? Severity::kHigh
                 : d < c.medium_mm ? Severity::kMedium
                                   : Severity::kLow;
  } else {
    e.severity = (e.gap_mm <= c.near_mm && d < c.medium_mm) ? Severity::kMedium : Severity::kLow;
  }
  return e;
}

/// Whether obstacle `a` decides the frame rather than `b`: worse severity, then the smaller
/// judged distance (0 when too close), then the earlier object (b came first when equal).
constexpr bool decides_over(const ObjectEval& a, const ObjectEval& b) {
  if (a.severity != b.severity) return a.severity > b.severity;
  const std::int32_t da = a.too_close ? 0 : a.distance_mm;
  const std::int32_t db = b.too_close ? 0 : b.distance_mm;
  return da < db;
}

/// The stage's one output word per frame.
struct FrameResult {
  Severity severity = Severity::kNone;  // worst over the frame's obstacles; kNone if there is none
  bool in_tunnel = false;               // the deciding object's
  bool too_close = false;               // the deciding object's d_max reached d_limit
  bool tile_overflow = false;           // carried from the labelling status word
  bool object_overflow = false;
  bool stream_error = false;  // labelling's, or the table broke the packet rules (docs/warning.md)
  std::uint16_t objects = 0;    // words of the frame's object table
  std::uint16_t obstacles = 0;  // of those, obstacles
  std::uint16_t index = 0xffff;  // deciding object's position in the table, 0xffff = none
  std::int32_t distance_mm = 0;  // deciding object, from the bumper (upper bound when too_close)
  // The deciding object's closest point, its disparity (Q11.4) and bounding box.
  std::uint16_t closest_x = 0, closest_y = 0, d_max = 0;
  std::uint16_t x_min = 0, x_max = 0, y_min = 0, y_max = 0;

  friend bool operator==(const FrameResult& a, const FrameResult& b) {
    return a.severity == b.severity && a.in_tunnel == b.in_tunnel && a.too_close == b.too_close &&
           a.tile_overflow == b.tile_overflow && a.object_overflow == b.object_overflow &&
           a.stream_error == b.stream_error && a.objects == b.objects &&
           a.obstacles == b.obstacles && a.index == b.index && a.distance_mm == b.distance_mm &&
           a.closest_x == b.closest_x && a.closest_y == b.closest_y && a.d_max == b.d_max &&
           a.x_min == b.x_min && a.x_max == b.x_max && a.y_min == b.y_min && a.y_max == b.y_max;
  }
  friend bool operator!=(const FrameResult& a, const FrameResult& b) { return !(a == b); }
};

using ResultPacket = Packet<FrameResult>;

}  // namespace scw::hls::warning
