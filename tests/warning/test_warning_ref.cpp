// SPDX-License-Identifier: Apache-2.0
// The warning stage's fixed-point arithmetic against the floating-point Eigen reference: every
// disparity code over an image grid, severities, the thesis's worked example, to_fixed's errors.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"
#include "host/warning/reference.hpp"
#include "host/warning/setup.hpp"
#include "tests/warning/karlsruhe_like.hpp"

namespace {

using scw::test::karlsruhe_like;
using scw::test::kImageHeight;
using scw::test::kImageWidth;

using scw::hls::labelling::Object;
using scw::hls::warning::ObjectEval;
using scw::hls::warning::Severity;
using scw::hls::warning::WarningConfig;
using scw::host::warning::evaluate_ref;
using scw::host::warning::fold_ref;
using scw::host::warning::RefEval;
using scw::host::warning::RefFrame;
using scw::host::warning::to_fixed;
using scw::host::warning::WarningSetup;

/// The thesis configuration's stage: a 128 px reciprocal table, disparities searched to 64 px.
using Params = scw::hls::warning::WarningParams<128>;

constexpr int kFirstCode = 20 * 16, kLastCode = 64 * 16;  // d = 20 .. 64 px in 1/16 px
constexpr double kTol = 0.01;                             // 1 cm

/// Thesis-rig-like: f 1000 px, b 0.60 m, otherwise as karlsruhe_like().
WarningSetup thesis_rig_like() {
  WarningSetup s = karlsruhe_like();
  s.focal_px = 1000.0;
  s.baseline_m = 0.60;
  return s;
}

ObjectEval evaluate_fixed(const Object& o, const WarningSetup& s) {
  return scw::hls::warning::evaluate<Params>(o, to_fixed(s));
}

/// An object with closest point (u, v), disparity code dq and the given bounding box: one pixel's
/// sums, so both distance rules place it at dq.
Object make_object(int u, int v, int dq, int x_min, int y_min, int x_max, int y_max) {
  Object o;
  o.area = 1;
  o.sum_d = static_cast<std::uint64_t>(dq);
  o.sum_dd = static_cast<std::uint64_t>(dq) * static_cast<std::uint64_t>(dq);
  o.closest_x = static_cast<std::uint16_t>(u);
  o.closest_y = static_cast<std::uint16_t>(v);
  o.first_x = o.closest_x;
  o.first_y = o.closest_y;
  o.d_max = o.d_min = static_cast<std::uint16_t>(dq);
  o.x_min = static_cast<std::uint16_t>(x_min);
  o.x_max = static_cast<std::uint16_t>(x_max);
  o.y_min = static_cast<std::uint16_t>(y_min);
  o.y_max = static_cast<std::uint16_t>(y_max);
  return o;
}

/// The largest |fixed - float| of one quantity and where it happened.
struct WorstError {
  double err = 0.0;
  std::string where;
  void update(double e, const Object& o) {
    if (e <= err) return;
    err = e;
    std::ostringstream w;
    w << "u " << o.closest_x << " v " << o.closest_y << " d " << o.d_max / 16.0 << " px, box "
      << o.x_min << ".." << o.x_max << " x " << o.y_min << ".." << o.y_max;
    where = w.str();
  }
};

/// Why a severity may legitimately differ: the float value lies within 1 cm (the fixed-point
/// error bound checked above) of a decision boundary, so millimetre rounding may put the
/// fixed-point value on the other side. Four bands:
///   distance:   |judged D - high| or |judged D - medium| < 1 cm (eq. 5.2's thresholds)
///   boundary:   |signed gap| < 1 cm (the box touches the tunnel's edge: in or out may flip)
///   near:       |gap - near| < 1 cm (the outside rule's near test may flip)
///   min height: |H - min_height| < 1 cm (obstacle or not, so none or a severity, may flip)
/// For each band: objects inside it, those whose severities differ, and those that differ and
/// lie in this band only (a band with such objects is needed).
struct Band {
  long in = 0, differ = 0, only = 0;
};
enum BandId { kDistance, kBoundary, kNear, kMinHeight, kBands };
constexpr std::array<const char*, kBands> kBandNames{"distance", "tunnel boundary", "near",
                                                     "min height"};

struct SweepResult {
  WorstError x, y, z, w, h, dist, gap;
  long objects = 0, compared = 0, mismatches = 0;
  long obstacles = 0, in_tunnel = 0, too_close = 0;
  std::array<long, 4> by_severity{};
  std::array<Band, kBands> bands{};
  double differ_margin = 0.0;  // largest distance from its boundary of a float value whose
                               // severity differs from the fixed point's
  std::string first_mismatch;
};

/// Box shapes around the closest point, (left, up, right, down) in pixels, cycled through so
/// every decision of the stage is reached: one pixel, small, pedestrian-like, wide and tall.
constexpr std::array<std::array<int, 4>, 5> kShapes{
    {{0, 0, 0, 0}, {3, 5, 2, 7}, {20, 90, 25, 110}, {150, 10, 200, 300}, {60, 200, 5, 40}}};

SweepResult sweep(const WarningSetup& s) {
  const WarningConfig cfg = to_fixed(s);
  std::vector<int> us, vs;
  for (int u = 0; u < kImageWidth; u += 16) us.push_back(u);
  us.push_back(kImageWidth - 1);
  for (int v = 0; v < kImageHeight; v += 16) vs.push_back(v);
  vs.push_back(kImageHeight - 1);

  SweepResult r;
  for (int dq = kFirstCode; dq <= kLastCode; ++dq) {
    for (std::size_t iu = 0; iu < us.size(); ++iu) {
      for (std::size_t iv = 0; iv < vs.size(); ++iv) {
        const int u = us[iu], v = vs[iv];
        const auto& sh = kShapes[(static_cast<std::size_t>(dq) + iu + 3 * iv) % kShapes.size()];
        const Object o = make_object(u, v, dq, std::max(0, u - sh[0]), std::max(0, v - sh[1]),
                                     std::min(kImageWidth - 1, u + sh[2]),
                                     std::min(kImageHeight - 1, v + sh[3]));
        const ObjectEval e = scw::hls::warning::evaluate<Params>(o, cfg);
        const RefEval f = evaluate_ref(o, s);
        ++r.objects;
        REQUIRE(e.measurable == f.measurable);
        REQUIRE(e.too_close == f.too_close);
        r.x.update(std::abs(e.x_mm / 1000.0 - f.closest.x()), o);
        r.y.update(std::abs(e.y_mm / 1000.0 - f.closest.y()), o);
        r.z.update(std::abs(e.z_mm / 1000.0 - f.closest.z()), o);
        r.w.update(std::abs(e.width_mm / 1000.0 - f.width_m), o);
        r.h.update(std::abs(e.height_mm / 1000.0 - f.height_m), o);
        r.dist.update(std::abs(e.distance_mm / 1000.0 - f.distance_m), o);
        r.gap.update(std::abs(e.gap_mm / 1000.0 - f.gap_m), o);

        r.obstacles += f.obstacle;
        r.in_tunnel += f.in_tunnel;
        r.too_close += f.too_close;
        ++r.by_severity[static_cast<int>(f.severity)];
        const double jd = f.judged_distance_m();
        const std::array<bool, kBands> in{
            !f.too_close && (std::abs(jd - s.high_m) < kTol || std::abs(jd - s.medium_m) < kTol),
            std::abs(f.signed_gap_m) < kTol, std::abs(f.gap_m - s.near_m) < kTol,
            std::abs(f.height_m - s.min_height_m) < kTol};
        const bool differ = e.severity != f.severity;
        const int n_in = in[kDistance] + in[kBoundary] + in[kNear] + in[kMinHeight];
        if (n_in > 0) {
          if (differ) {
            // How far the float value lies from the boundary it was excluded for.
            double margin = kTol;
            if (in[kDistance])
              margin = std::min({margin, std::abs(jd - s.high_m), std::abs(jd - s.medium_m)});
            if (in[kBoundary]) margin = std::min(margin, std::abs(f.signed_gap_m));
            if (in[kNear]) margin = std::min(margin, std::abs(f.gap_m - s.near_m));
            if (in[kMinHeight]) margin = std::min(margin, std::abs(f.height_m - s.min_height_m));
            r.differ_margin = std::max(r.differ_margin, margin);
          }
          for (int k = 0; k < kBands; ++k) {
            Band& b = r.bands[static_cast<std::size_t>(k)];
            if (!in[static_cast<std::size_t>(k)]) continue;
            ++b.in;
            b.differ += differ;
            b.only += differ && n_in == 1;
          }
          continue;
        }
        ++r.compared;
        if (differ || e.in_tunnel != f.in_tunnel || e.obstacle != f.obstacle) {
          if (r.mismatches++ == 0) {
            std::ostringstream m;
            m << "u " << u << " v " << v << " dq " << dq << ": fixed "
              << scw::hls::warning::severity_name(e.severity) << " (D " << e.distance_mm
              << " mm, gap " << e.gap_mm << " mm, H " << e.height_mm << " mm), float "
              << scw::hls::warning::severity_name(f.severity) << " (D " << f.distance_m
              << " m, gap " << f.gap_m << " m, H " << f.height_m << " m)";
            r.first_mismatch = m.str();
          }
        }
      }
    }
  }
  return r;
}

std::string mm(double m) {
  std::ostringstream o;
  o.precision(3);
  o << std::fixed << m * 1000.0 << " mm";
  return o.str();
}

void check_sweep(const char* label, const WarningSetup& s) {
  const SweepResult r = sweep(s);
  std::ostringstream rep;
  rep << label << " (f " << s.focal_px << " px, b " << s.baseline_m << " m, c (" << s.cu_px << ", "
      << s.cv_px << ") px): " << r.objects << " objects, codes " << kFirstCode << ".." << kLastCode
      << "\n  worst |fixed - float|: x " << mm(r.x.err) << ", y " << mm(r.y.err) << ", z "
      << mm(r.z.err) << ", W " << mm(r.w.err) << ", H " << mm(r.h.err) << ", D " << mm(r.dist.err)
      << ", gap " << mm(r.gap.err) << "\n  worst D at " << r.dist.where << "\n  worst W at "
      << r.w.where << "\n  float severities: none " << r.by_severity[0] << ", low "
      << r.by_severity[1] << ", medium " << r.by_severity[2] << ", high " << r.by_severity[3]
      << "; in tunnel " << r.in_tunnel << ", too close " << r.too_close
      << "\n  severity compared on " << r.compared << " objects; excluded, within 1 cm of:";
  for (int k = 0; k < kBands; ++k) {
    const Band& b = r.bands[static_cast<std::size_t>(k)];
    rep << "\n    " << kBandNames[static_cast<std::size_t>(k)] << ": " << b.in << " objects, "
        << b.differ << " differ (" << b.only << " in this band only)";
  }
  rep << "\n  severities differ only within " << mm(r.differ_margin) << " of a boundary";
  WARN(rep.str());
  CHECK(r.x.err < kTol);
  CHECK(r.y.err < kTol);
  CHECK(r.z.err < kTol);
  CHECK(r.w.err < kTol);
  CHECK(r.h.err < kTol);
  CHECK(r.dist.err < kTol);
  CHECK(r.gap.err < kTol);
  INFO("first mismatch: " << r.first_mismatch);
  CHECK(r.mismatches == 0);
  // A severity can only flip where the value's own error reaches across the boundary.
  CHECK(r.differ_margin <= std::max({r.dist.err, r.gap.err, r.h.err}));
  // The sweep must reach every outcome, or equal severities would prove little.
  for (int k = 0; k < 4; ++k) CHECK(r.by_severity[static_cast<std::size_t>(k)] > 0);
  CHECK(r.in_tunnel > 0);
  CHECK(r.too_close > 0);
}

// ---- The thesis's worked example (section 5.4, Fig. 5.11 b) ----------------------------------
//
// Default setup (f 700 px, b 0.54 m, T = (-0.30, -1.20, 1.65) m, tunnel 1.5 x a 1.80 x 1.50 m
// car: x in [-1.65, 1.05] m, y in [-1.20, 1.05] m in camera coordinates) with the principal
// point at the centre of a 1280 x 480 image (the default (0, 0) would put the object's top above
// the image). A crossing bike right of the tunnel, standing on the road, 1.8 m high and long:
//   d = 805 / 16 = 50.3125 px    -> b/d = 10.733 mm/px, z = 7.5130 m
//   closest pixel (863, 266)     -> A = (2.3934, -0.2791, 7.5130) m, |A| = 7.8900 m,
//                                   1.34 m right of the tunnel's edge
//   box u 785..952, v 185..351   -> x 1.551 .. 3.354 m, y -1.197 .. 0.596 m: W 1.803 m,
//                                   H 1.792 m, 0.501 m right of the tunnel (gap <= near 1 m)
// so D = 7.89 - 1.65 = 6.24 m, outside the tunnel but near it and under 20 m: medium.
// (Measured from the box, an object whose box edge were 1.2 - 2 m beside the tunnel would be
// low with the default near_m = 1 m; below, the same bike moved 1 m further right is.)
constexpr int kBikeCode = 805, kBikeU = 863, kBikeV = 266;
constexpr int kBikeX0 = 785, kBikeX1 = 952, kBikeY0 = 185, kBikeY1 = 351;

Object bike(int shift_px = 0) {
  return make_object(kBikeU + shift_px, kBikeV, kBikeCode, kBikeX0 + shift_px, kBikeY0,
                     kBikeX1 + shift_px, kBikeY1);
}

}  // namespace

TEST_CASE("fixed point agrees with the float reference to 1 cm: Karlsruhe-like rig",
          "[ref][warning]") {
  check_sweep("Karlsruhe-like", karlsruhe_like());
}

TEST_CASE("fixed point agrees with the float reference to 1 cm: thesis-rig-like",
          "[ref][warning]") {
  check_sweep("thesis-rig-like", thesis_rig_like());
}

TEST_CASE("reference by hand: a pixel at the principal point", "[ref][warning]") {
  const WarningSetup s = karlsruhe_like();
  // d = 27 px: z = 0.54 * 700 / 27 = 14 m; one pixel is 0.02 m wide and high.
  const RefEval r = evaluate_ref(make_object(640, 240, 27 * 16, 640, 240, 640, 240), s);
  REQUIRE(r.measurable);
  CHECK(r.closest.x() == Approx(0.0).margin(1e-12));
  CHECK(r.closest.y() == Approx(0.0).margin(1e-12));
  CHECK(r.closest.z() == Approx(14.0));
  CHECK(r.width_m == Approx(0.02));
  CHECK(r.height_m == Approx(0.02));
  CHECK(r.distance_m == Approx(14.0 - 1.65));
  CHECK_FALSE(r.obstacle);
  CHECK(r.severity == Severity::kNone);
  // The pixel is 0.3 m right of the car's centre line and 1.2 m above the road: in the tunnel,
  // its left edge 1.35 - 0.29 m inside the right wall and its bottom 2.25 - 1.19 m below the roof.
  CHECK(r.in_tunnel);
  CHECK(r.signed_gap_m == Approx(-1.06));
  // Codes below 1 px and negative (top bit) codes cannot be placed.
  CHECK_FALSE(evaluate_ref(make_object(640, 240, 15, 640, 240, 640, 240), s).measurable);
  CHECK_FALSE(evaluate_ref(make_object(640, 240, 0x8400, 640, 240, 640, 240), s).measurable);
}

TEST_CASE("the thesis's worked example: 7.89 m from the camera, 6.24 m from the bumper, medium",
          "[ref][warning]") {
  const WarningSetup s = karlsruhe_like();
  const Object o = bike();
  const RefEval f = evaluate_ref(o, s);
  const ObjectEval e = evaluate_fixed(o, s);
  INFO("float: |A| " << f.camera_distance_m << " m, D " << f.distance_m << " m, gap " << f.gap_m
                     << " m, W " << f.width_m << " m, H " << f.height_m << " m; fixed: D "
                     << e.distance_mm << " mm, gap " << e.gap_mm << " mm");
  CHECK(f.camera_distance_m == Approx(7.89).margin(kTol));
  CHECK(f.distance_m == Approx(6.24).margin(kTol));
  CHECK(e.distance_mm + to_fixed(s).veh_z_mm == Approx(7890).margin(10));
  CHECK(e.distance_mm == Approx(6240).margin(10));
  // Standing on the road, about 1.8 m high, its closest point 1.2 - 2 m beside the tunnel.
  CHECK(f.bottom_right.y() == Approx(s.vehicle_origin.y()).margin(kTol));
  CHECK(f.height_m == Approx(1.8).margin(0.02));
  const double beside = f.closest.x() - s.vehicle_origin.x() - s.tunnel_half_width_m();
  CHECK(beside > 1.2);
  CHECK(beside < 2.0);
  CHECK_FALSE(f.in_tunnel);
  CHECK_FALSE(e.in_tunnel);
  CHECK(f.gap_m == Approx(0.50).margin(kTol));
  CHECK(f.obstacle);
  CHECK(e.obstacle);
  CHECK(f.severity == Severity::kMedium);
  CHECK(e.severity == Severity::kMedium);

  // One metre further right (94 px at 10.7 mm/px) the gap exceeds near_m: low.
  const RefEval far_f = evaluate_ref(bike(94), s);
  const ObjectEval far_e = evaluate_fixed(bike(94), s);
  CHECK(far_f.gap_m == Approx(1.51).margin(kTol));
  CHECK(far_f.severity == Severity::kLow);
  CHECK(far_e.severity == Severity::kLow);
  // Moved left into the tunnel at the same depth (6.24 m <= 10 m): high.
  const RefEval in_f = evaluate_ref(bike(-200), s);
  const ObjectEval in_e = evaluate_fixed(bike(-200), s);
  CHECK(in_f.in_tunnel);
  CHECK(in_f.severity == Severity::kHigh);
  CHECK(in_e.severity == Severity::kHigh);
}

TEST_CASE("fold_ref picks worst severity, then nearest, then earliest, like the stage",
          "[ref][warning]") {
  const WarningSetup s = karlsruhe_like();
  const WarningConfig cfg = to_fixed(s);
  // A road marking (too low), a far car in the tunnel (low), the bike (medium), a second bike
  // identical to the first (the earlier one decides), a nearer medium object further out.
  const Object marking = make_object(640, 400, 40 * 16, 500, 398, 780, 402);
  const Object car = make_object(640, 250, 272, 600, 200, 680, 260);  // d 17 px: D 20.6 m
  const std::vector<Object> table{marking, car, bike(), bike()};
  const RefFrame f = fold_ref(table, s);
  CHECK(f.objects == 4);
  CHECK(f.obstacles == 3);
  CHECK(f.index == 2);
  CHECK(f.severity == Severity::kMedium);

  // The stage's own fold rule (decides_over) over the fixed-point evaluations agrees.
  auto fold_fixed = [&](const std::vector<Object>& t) {
    int best = -1;
    ObjectEval be;
    for (std::size_t i = 0; i < t.size(); ++i) {
      const ObjectEval e = scw::hls::warning::evaluate<Params>(t[i], cfg);
      if (!e.obstacle) continue;
      if (best < 0 || scw::hls::warning::decides_over(e, be)) {
        best = static_cast<int>(i);
        be = e;
      }
    }
    return best;
  };
  CHECK(fold_fixed(table) == f.index);

  // A nearer medium object (the bike 0.5 px disparity closer) wins over the earlier bike.
  const Object nearer =
      make_object(kBikeU, kBikeV, kBikeCode + 8, kBikeX0, kBikeY0, kBikeX1, kBikeY1);
  const std::vector<Object> t2{car, bike(), nearer};
  CHECK(fold_ref(t2, s).index == 2);
  CHECK(fold_fixed(t2) == 2);
  // High beats a nearer medium; too close (judged 0 m) beats any distance at equal severity.
  const Object in_tunnel = bike(-200);
  const Object too_close = make_object(640, 300, 64 * 16, 560, 200, 720, 479);
  const std::vector<Object> t3{nearer, in_tunnel, too_close};
  const RefFrame f3 = fold_ref(t3, s);
  CHECK(f3.index == 2);
  CHECK(f3.deciding.too_close);
  CHECK(f3.severity == Severity::kHigh);
  CHECK(fold_fixed(t3) == 2);
  CHECK(fold_ref({}, s).index == -1);
  CHECK(fold_ref({marking}, s).severity == Severity::kNone);
}

TEST_CASE("to_fixed names the value that does not fit its port", "[ref][warning]") {
  using Catch::Matchers::Contains;
  WarningSetup s = karlsruhe_like();
  REQUIRE_NOTHROW(to_fixed(s));
  auto throws_naming = [](const WarningSetup& bad, const char* what) {
    INFO(what);
    CHECK_THROWS_AS(to_fixed(bad), std::invalid_argument);
    CHECK_THROWS_WITH(to_fixed(bad), Contains(what));
  };
  WarningSetup b = s;
  b.baseline_m = 4.2;  // Q12.8 mm in 20 bits: below 4.096 m
  throws_naming(b, "baseline");
  b.baseline_m = 0.0;
  throws_naming(b, "baseline");
  WarningSetup h = s;
  h.high_m = 70.0;  // 16-bit mm: up to 65.535 m
  throws_naming(h, "high threshold");
  WarningSetup m = s;
  m.medium_m = -1.0;
  throws_naming(m, "medium threshold");
  WarningSetup n = s;
  n.near_m = 66.0;
  throws_naming(n, "near distance");
  WarningSetup mh = s;
  mh.min_height_m = 100.0;
  throws_naming(mh, "minimum height");
  WarningSetup t = s;
  t.tunnel_scale = 30.0;  // half width 0.5 * 30 * 1.8 = 27 m still fits 16-bit mm,
  t.car_height_m = 30.0;  // but a 900 m high tunnel does not
  throws_naming(t, "tunnel height");
  WarningSetup d = s;
  d.d_limit_px = 0.5;
  throws_naming(d, "disparity limit");
}

namespace {

/// `o` carrying the area and sums of the disparity codes `d` (d_min, d_max from them too).
Object with_codes(Object o, const std::vector<int>& d) {
  o.area = static_cast<std::uint32_t>(d.size());
  o.sum_d = o.sum_dd = 0;
  for (int c : d) {
    o.sum_d += static_cast<std::uint64_t>(c);
    o.sum_dd += static_cast<std::uint64_t>(c) * static_cast<std::uint64_t>(c);
  }
  o.d_min = static_cast<std::uint16_t>(*std::min_element(d.begin(), d.end()));
  o.d_max = static_cast<std::uint16_t>(*std::max_element(d.begin(), d.end()));
  return o;
}

}  // namespace

TEST_CASE("the spread rule: fixed point within one code of the float reference", "[ref][warning]") {
  std::mt19937 rng(23);
  for (const double k : {0.0, 0.75, 1.0, 2.5, 15.9375}) {
    WarningSetup s = thesis_rig_like();
    s.spread_k = k;
    const WarningConfig cfg = to_fixed(s);
    double worst = 0.0;
    for (int i = 0; i < 3000; ++i) {
      // A face at one code with noise, and a few edge outliers nearer or farther.
      const int n = 1 + static_cast<int>(rng() % (i % 3 == 0 ? 20 : 20000));
      const int centre = 16 + static_cast<int>(rng() % 2000);
      std::normal_distribution<double> noise(0.0, 1.0 + rng() % 40);
      std::vector<int> d;
      for (int j = 0; j < n; ++j) {
        const int outlier = rng() % 50 == 0 ? static_cast<int>(rng() % 200) - 100 : 0;
        d.push_back(std::clamp(static_cast<int>(std::lround(centre + noise(rng))) + outlier, 1,
                               0x7fff));
      }
      const Object o = with_codes(make_object(320, 240, 0, 300, 200, 340, 300), d);
      const double fixed_px = scw::hls::warning::rule_disparity(o, cfg) / 16.0;
      const double ref_px = scw::host::warning::rule_disparity_px(o, s);
      worst = std::max(worst, std::abs(fixed_px - ref_px));
      REQUIRE(fixed_px <= o.d_max / 16.0);
    }
    INFO("k " << k << ": worst |fixed - reference| " << worst << " px");
    // The root is rounded (0.5 / A codes of error times k) and the quotient rounded (half a code).
    CHECK(worst <= 1.0 / 16.0);
  }
}

TEST_CASE("the spread rule ignores edge outliers that move the closest rule", "[ref][warning]") {
  // A face at 25 px (code 400) with one code of noise, and 1 % of pixels 2 px nearer (what block
  // matching leaves at an object's edges, docs/scene.md).
  std::vector<int> d;
  for (int j = 0; j < 2000; ++j) d.push_back(399 + j % 3);
  for (int j = 0; j < 20; ++j) d.push_back(432);
  const Object o = with_codes(make_object(320, 240, 0, 300, 200, 340, 300), d);
  WarningSetup s = thesis_rig_like();
  s.distance_rule = scw::hls::warning::DistanceRule::kClosest;
  CHECK(scw::hls::warning::rule_disparity(o, to_fixed(s)) == 432);
  s.distance_rule = scw::hls::warning::DistanceRule::kSpread;
  s.spread_k = 0.75;
  const auto code = scw::hls::warning::rule_disparity(o, to_fixed(s));
  // mean 400.3, sd 3.3: mean + 0.75 sd = 402.8 -> 403.
  CHECK(code == 403);
  CHECK(evaluate_ref(o, s).disparity_px == Approx(402.8 / 16).margin(0.01));
  // A malformed object (area 0, or sums no pixel set has) falls back to d_max or its mean.
  Object bad = o;
  bad.area = 0;
  CHECK(scw::hls::warning::rule_disparity(bad, to_fixed(s)) == 432);
  bad = o;
  bad.sum_dd = 0;  // S1^2 > A S2: no spread
  CHECK(scw::hls::warning::rule_disparity(bad, to_fixed(s)) ==
        (16 * o.sum_d + 8 * o.area) / (16 * o.area));
}
