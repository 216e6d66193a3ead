// SPDX-License-Identifier: Apache-2.0
// [rtl] scw_warning against the warning model clock for clock (the same cycle trace) under every
// stall pattern, both against a direct per-frame fold of evaluate(): random object tables that
// reach every branch of the arithmetic, empty and back-to-back frames, broken tables, camera
// set-ups from the Karlsruhe rig, the thesis and the ports' extremes, under both distance rules
// (objects with realistic and adversarial disparity sums); and its square root and distance
// rule alone, bit for bit.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Vwarning_a.h"
#include "Vwarning_a__Syms.h"
#include "Vwarning_a_scw_warning.h"
#include "Vwarning_b.h"
#include "Vwarning_b_scw_warning.h"
#include "Vwarning_rule.h"
#include "Vwarning_rule_scw_warning_rule.h"
#include "Vwarning_sqrt.h"
#include "Vwarning_sqrt_scw_warning_sqrt.h"
#include "hls/warning/warning.hpp"
#include "hls/warning/warning_params.hpp"
#include "host/reference/road_ref.hpp"
#include "host/vectors/warning_tables.hpp"
#include "host/warning/reference.hpp"
#include "host/warning/run_model.hpp"
#include "host/warning/setup.hpp"
#include "sim/core/join.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/warning_model.hpp"
#include "sim/rtl/verilated_harness.hpp"
#include "sim/rtl/warning_rtl.hpp"
#include "tests/common/twin_check.hpp"

// The first build's whole state is known: its harness skips the cycles in which it is still
// (sim/rtl/quiet_cycles.hpp), in every test below, which hold it to the model clock for clock.
SCW_MODEL_STATE(Vwarning_a)

namespace {

namespace hw = scw::hls::warning;
using hw::FrameResult;
using hw::ObjectEval;
using hw::ResultPacket;
using hw::Severity;
using hw::WarningConfig;
using scw::hls::labelling::LabelPacket;
using scw::hls::labelling::Object;
using scw::host::warning::WarningSetup;
using scw::sim::StallPattern;

// tests/warning/rtl.cmake builds the same two with -G.
using ParamsA = hw::WarningParams<64>;  // 1,024 table entries
using ParamsB = hw::WarningParams<32>;  // 512: a table the Karlsruhe rig's close range overruns
static_assert(scw::sim::warning_params_match<Vwarning_a_scw_warning, ParamsA>());
static_assert(scw::sim::warning_params_match<Vwarning_b_scw_warning, ParamsB>());
static_assert(Vwarning_a_scw_warning::Latency == hw::kLatency);
// isqrt_round's loop: 27 root bits, so any n below 2^58 (three squares of 29-bit coordinates).
static_assert(Vwarning_sqrt_scw_warning_sqrt::RootW == 27 &&
              Vwarning_sqrt_scw_warning_sqrt::InW == 58);
// The distance rule alone: its operand widths and depth are the C++ constants.
using Rule = Vwarning_rule_scw_warning_rule;
static_assert(Rule::AreaW == hw::kRuleAreaBits && Rule::SumW == hw::kRuleSumBits &&
              Rule::SquareW == hw::kRuleSquareBits && Rule::RootW == hw::kRuleRootBits &&
              Rule::Latency == hw::kRuleLatency);
static_assert(Vwarning_a_scw_warning::RuleLatency == hw::kRuleLatency);

// ---- words ------------------------------------------------------------------------------------

LabelPacket object_word(const Object& o, bool last = false) {
  LabelPacket p;
  p.data.is_status = false;
  p.data.object = o;
  p.last = last;
  return p;
}

LabelPacket status_word(std::uint32_t objects, bool last = true, bool tile = false,
                        bool object_overflow = false, bool stream_error = false) {
  LabelPacket p;
  p.data.is_status = true;
  p.data.status.objects = objects;
  p.data.status.tile_overflow = tile;
  p.data.status.object_overflow = object_overflow;
  p.data.status.stream_error = stream_error;
  p.last = last;
  return p;
}

/// A well-formed frame: the objects, then the status word counting them, with last.
void append_frame(std::vector<LabelPacket>& words, const std::vector<Object>& objects,
                  bool tile = false, bool object_overflow = false, bool stream_error = false) {
  for (const auto& o : objects) words.push_back(object_word(o));
  words.push_back(status_word(static_cast<std::uint32_t>(objects.size()), true, tile,
                              object_overflow, stream_error));
}

// ---- the independent expectation --------------------------------------------------------------

// ---- disparity sums ---------------------------------------------------------------------------

using Rng = std::mt19937_64;

std::uint64_t pick_u(Rng& rng, std::uint64_t a, std::uint64_t b) {
  return std::uniform_int_distribution<std::uint64_t>(a, b)(rng);
}

/// Area `area` and the sums of a random multiset of that many disparities whose largest is
/// d_max, as the labelling stage accumulates them: up to five distinct codes, spread below
/// d_max by nothing, a sixteenth, a quarter or all of it; now and then d_max is an outlier of
/// one to three pixels (the case the spread rule is for).
void realistic_sums(Rng& rng, Object& o, std::uint32_t area) {
  const std::uint64_t d_max = o.d_max;
  const std::uint64_t widths[] = {0, d_max / 16, d_max / 4, d_max};
  const std::uint64_t width = widths[pick_u(rng, 0, 3)];
  const int distinct = static_cast<int>(pick_u(rng, 1, 5));
  const bool outlier = pick_u(rng, 0, 3) == 0;
  std::uint64_t left = area, s1 = 0, s2 = 0;
  for (int i = 0; i < distinct && left > 0; ++i) {
    const std::uint64_t d = i == 0 ? d_max : d_max - pick_u(rng, 0, width);
    const std::uint64_t n = i + 1 == distinct ? left
                            : i == 0 && outlier ? std::min<std::uint64_t>(left, pick_u(rng, 1, 3))
                                                : pick_u(rng, 1, left);
    s1 += n * d;
    s2 += n * d * d;
    left -= n;
  }
  o.area = area;
  o.sum_d = s1;
  o.sum_dd = s2;
}

/// Mostly small objects, one in ten up to the widest area the rule reads (2^20 - 1 pixels).
void realistic_sums(Rng& rng, Object& o) {
  const std::uint64_t widest = (std::uint64_t{1} << hw::kRuleAreaBits) - 1;
  const auto area = static_cast<std::uint32_t>(pick_u(rng, 0, 9) == 0 ? pick_u(rng, 1, widest)
                                                                       : pick_u(rng, 1, 4000));
  realistic_sums(rng, o, area);
}

/// Sums no labelling stage sends, but the ports carry: A = 0, any 64-bit words (cut to the
/// rule's widths), S1^2 > A S2, the widest operands, means past 16 bits, garbage above the cut.
void adversarial_sums(Rng& rng, Object& o) {
  switch (pick_u(rng, 0, 7)) {
    case 0:  // den = 0: q saturates, dq = d_max
      o.area = static_cast<std::uint32_t>(pick_u(rng, 0, 1) ? 0 : rng() << 20);
      o.sum_d = rng();
      o.sum_dd = rng();
      break;
    case 1:
      o.area = static_cast<std::uint32_t>(rng());
      o.sum_d = rng();
      o.sum_dd = rng();
      break;
    case 2:  // a negative "variance": V = 0
      o.area = static_cast<std::uint32_t>(pick_u(rng, 1, 1000));
      o.sum_d = pick_u(rng, 1u << 20, (std::uint64_t{1} << hw::kRuleSumBits) - 1);
      o.sum_dd = pick_u(rng, 0, o.sum_d);
      break;
    case 3:  // the widest: V near 2^70, R near 2^35, num near 2^44
      o.area = static_cast<std::uint32_t>(((1u << hw::kRuleAreaBits) - 1) - pick_u(rng, 0, 3));
      o.sum_d = pick_u(rng, 0, 1) ? 0 : pick_u(rng, 0, 1u << 20);
      o.sum_dd = ~std::uint64_t{0} - pick_u(rng, 0, 1000);
      break;
    case 4: {  // a mean about 4096 px: q just below or past 16 bits
      const std::uint64_t a = pick_u(rng, 1, 1u << 15);
      const std::uint64_t d = pick_u(rng, 0xfff0, 0x10010);
      o.area = static_cast<std::uint32_t>(a);
      o.sum_d = a * d;
      o.sum_dd = a * d * d + pick_u(rng, 0, 1000);
      break;
    }
    case 5:  // realistic, and garbage above the bits the rule reads
      realistic_sums(rng, o);
      o.area |= static_cast<std::uint32_t>(rng() << hw::kRuleAreaBits);
      o.sum_d |= rng() << hw::kRuleSumBits;
      o.sum_dd |= rng() << hw::kRuleSquareBits;
      break;
    default:
      realistic_sums(rng, o);
  }
}

/// How TableGen fills area, sum_d and sum_dd.
enum class Sums { kRealistic, kAdversarial };

/// What the tables reached, counted over every object and frame folded.
struct Coverage {
  int not_measurable = 0, negative_code = 0, too_close = 0, past_table = 0, low = 0;
  int moved = 0;  // measurable, placed nearer than d_max says (the spread rule's dq < d_max)
  int tunnel[4] = {0, 0, 0, 0}, outside[4] = {0, 0, 0, 0};  // by severity
  int negative_x = 0, negative_y = 0, negative_distance = 0, saturated_root = 0;
  int ties = 0;         // frames where two obstacles tie in severity and judged distance
  int close_ties = 0;   // ... both too close, at different distances
  int no_obstacle = 0;  // frames with objects but no obstacle
};

std::int32_t judged(const ObjectEval& e) { return e.too_close ? 0 : e.distance_mm; }

/// The frame results of `words` as the stage defines them, frame by frame: evaluate() on every
/// object, the deciding obstacle by fold_table (worst severity, nearest, first), the status flags,
/// and stream_error where the table broke the packet rules. No clocks, no pipeline.
template <typename Params>
std::vector<FrameResult> fold_frames(const std::vector<LabelPacket>& words,
                                     const WarningConfig& cfg, Coverage* cov = nullptr) {
  std::vector<FrameResult> results;
  std::vector<ObjectEval> evals;
  std::vector<Object> objects;
  for (const auto& w : words) {
    if (!w.data.is_status) {
      objects.push_back(w.data.object);
      evals.push_back(hw::evaluate<Params>(w.data.object, cfg));
      if (!w.last) continue;
    }
    // The objects' part is the shared plain fold (its own ordering key, not decides_over).
    FrameResult r = scw::fixtures::fold_table<Params>(objects, cfg);
    if (w.data.is_status) {
      const auto& st = w.data.status;
      r.tile_overflow = st.tile_overflow;
      r.object_overflow = st.object_overflow;
      r.stream_error = st.stream_error || !w.last || st.objects != objects.size();
    } else {
      r.stream_error = true;
    }
    results.push_back(r);

    if (cov != nullptr) {
      for (std::size_t i = 0; i < evals.size(); ++i) {
        const ObjectEval& e = evals[i];
        const Object& o = objects[i];
        if (!e.measurable) {
          ++cov->not_measurable;
          if (e.d_q4 >= 0x8000u) ++cov->negative_code;
          continue;
        }
        if (e.d_q4 < o.d_max) ++cov->moved;
        if (e.too_close) ++cov->too_close;
        if (e.d_q4 >= static_cast<std::uint32_t>(Params::kTableSize)) ++cov->past_table;
        const auto sq = [](std::int64_t v) { return static_cast<std::uint64_t>(v * v); };
        if (sq(e.x_mm) + sq(e.y_mm) + sq(e.z_mm) >= (std::uint64_t{1} << 54)) ++cov->saturated_root;
        if (!e.obstacle) {
          ++cov->low;
          continue;
        }
        (e.in_tunnel ? cov->tunnel : cov->outside)[static_cast<int>(e.severity)]++;
        if (e.x_mm < 0) ++cov->negative_x;
        if (e.y_mm < 0) ++cov->negative_y;
        if (e.distance_mm < 0) ++cov->negative_distance;
        for (std::size_t j = 0; j < i; ++j) {
          const ObjectEval& f = evals[j];
          if (f.obstacle && f.severity == e.severity && judged(f) == judged(e)) {
            ++cov->ties;
            if (e.too_close && f.too_close && e.distance_mm != f.distance_mm) ++cov->close_ties;
          }
        }
      }
      if (!evals.empty() && r.index == 0xffff) ++cov->no_obstacle;
    }
    evals.clear();
    objects.clear();
  }
  return results;
}

// ---- object tables ----------------------------------------------------------------------------

/// Random objects of every kind the stage tells apart, placed in 3D with the camera of `s` so
/// that they land in (or next to) the tunnel at chosen distances, plus codes the table does not
/// cover and plain random fields; each with disparity sums as `sums` says (an exact copy of the
/// previous object keeps its). Seeded: the same seed gives the same tables.
class TableGen {
 public:
  TableGen(const WarningSetup& s, const WarningConfig& cfg, int table_size, std::uint64_t seed,
           Sums sums = Sums::kRealistic)
      : s_(s), cfg_(cfg), table_(table_size), rng_(seed), sums_(sums) {}

  Object next() {
    tie_ = false;
    Object o = shape();
    return tie_ ? o : finish(o);
  }

 private:
  Object shape() {
    switch (pick(0, 11)) {
      case 0:
      case 1:
        return in_tunnel(uni(0.3, s_.high_m));
      case 2:
        return in_tunnel(uni(s_.high_m, s_.medium_m));
      case 3:
        return in_tunnel(uni(s_.medium_m, 60.0));
      case 4:
        return outside(uni(0.02, s_.near_m), uni(1.0, 30.0));
      case 5:
        return outside(uni(s_.near_m + 0.05, 4.0), uni(1.0, 30.0));
      case 6:
        return low_object();
      case 7:
        return not_measurable();
      case 8:
        return with_code(random_box(), uni_code(table_, 0x7fff));  // past the table
      case 9:  // too close, inside the table (when d_limit leaves room)
        return with_code(random_box(),
                         uni_code(std::min<int>(cfg_.d_limit_q4, table_ - 1), table_ - 1));
      case 10:
        return tie_of_last();
      default:
        return with_code(random_box(), uni_code(0, 2 * table_));
    }
  }

  /// The object with its sums; the next tie copies it.
  Object finish(Object o) {
    if (sums_ == Sums::kAdversarial)
      adversarial_sums(rng_, o);
    else
      realistic_sums(rng_, o);
    last_ = o;
    return o;
  }

 public:
  /// Frames of 0 .. max_objects objects (a few empty), each closed by its status word; the
  /// labelling flags are set now and then, as an overflowing labelling stage would.
  std::vector<LabelPacket> frames(int n, int max_objects) {
    std::vector<LabelPacket> words;
    for (int f = 0; f < n; ++f) {
      std::vector<Object> objs;
      switch (pick(0, 6)) {
        case 0:
          break;
        case 1:  // objects, but none an obstacle
          for (int i = pick(1, 4); i > 0; --i)
            objs.push_back(finish(pick(0, 1) ? low_object() : not_measurable()));
          break;
        default:
          for (int i = pick(1, max_objects); i > 0; --i) objs.push_back(next());
      }
      append_frame(words, objs, pick(0, 6) == 0, pick(0, 6) == 0, pick(0, 9) == 0);
    }
    return words;
  }

  /// Uniformly random fields: boxes inside out, points outside them, any code.
  Object random_fields() {
    Object o = noise();
    o.x_min = u16();
    o.x_max = u16();
    o.y_min = u16();
    o.y_max = u16();
    o.closest_x = u16();
    o.closest_y = u16();
    // 1 .. 3 px now and then: at the widest settings that is where the root saturates.
    switch (pick(0, 3)) {
      case 0:
        o.d_max = u16();
        break;
      case 1:
        o.d_max = static_cast<std::uint16_t>(pick(16, 48));
        break;
      default:
        o.d_max = static_cast<std::uint16_t>(pick(16, 2 * table_));
    }
    return finish(o);
  }

 private:
  double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int pick(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(pick(0, 0xffff)); }
  std::uint16_t uni_code(int lo, int hi) { return static_cast<std::uint16_t>(pick(lo, hi)); }
  static std::uint16_t px(double v) {
    return static_cast<std::uint16_t>(std::clamp(std::lround(v), 0L, 65535L));
  }

  /// What the stage must ignore: d_min, the first pixel and the moments.
  Object noise() {
    Object o;
    o.first_x = u16();
    o.first_y = u16();
    for (std::uint64_t* m :
         {&o.m10, &o.m01, &o.m20, &o.m11, &o.m02, &o.m30, &o.m21, &o.m12, &o.m03})
      *m = rng_();
    return o;
  }

  /// The box [xl, xr] x [yb, yt] (camera coordinates, m) at depth z through the camera.
  Object box(double xl, double xr, double yb, double yt, double z) {
    Object o = noise();
    const double f = s_.focal_px;
    o.x_min = px(s_.cu_px + f * xl / z);
    o.x_max = px(s_.cu_px + f * xr / z);
    o.y_min = px(s_.cv_px - f * yt / z);
    o.y_max = px(s_.cv_px - f * yb / z);
    o.closest_x = static_cast<std::uint16_t>(pick(o.x_min, o.x_max));
    o.closest_y = static_cast<std::uint16_t>(pick(o.y_min, o.y_max));
    o.d_max = px(16.0 * f * s_.baseline_m / z);
    o.d_min = static_cast<std::uint16_t>(pick(0, o.d_max));
    last_ = o;
    return o;
  }

  double tx() const { return s_.vehicle_origin.x(); }
  double ty() const { return s_.vehicle_origin.y(); }
  double tz() const { return s_.vehicle_origin.z(); }

  /// Standing on the road in the tunnel, `dist` m ahead of the bumper.
  Object in_tunnel(double dist) {
    const double hwm = s_.tunnel_half_width_m(), w = uni(0.2, 2.0), c = uni(-hwm, hwm);
    const double yb = ty() + uni(0.0, 0.3);
    return box(tx() + c - w / 2, tx() + c + w / 2, yb, yb + uni(s_.min_height_m + 0.05, 2.2),
               tz() + dist);
  }
  /// Beside or above the tunnel, `gap` m from it.
  Object outside(double gap, double dist) {
    const double hwm = s_.tunnel_half_width_m(), w = uni(0.2, 2.0);
    const double yb = ty() + uni(0.0, 0.3), yt = yb + uni(s_.min_height_m + 0.05, 2.2);
    switch (pick(0, 2)) {
      case 0:
        return box(tx() + hwm + gap, tx() + hwm + gap + w, yb, yt, tz() + dist);
      case 1:
        return box(tx() - hwm - gap - w, tx() - hwm - gap, yb, yt, tz() + dist);
      default: {
        const double top = ty() + s_.tunnel_height_m() + gap;
        return box(tx() - w / 2, tx() + w / 2, top, top + uni(0.6, 2.0), tz() + dist);
      }
    }
  }
  /// Lower than min_height: a kerb, a road marking.
  Object low_object() {
    const double w = uni(0.2, 3.0), c = uni(-3.0, 3.0), yb = ty() + uni(0.0, 0.05);
    return box(tx() + c - w / 2, tx() + c + w / 2, yb, yb + uni(0.0, s_.min_height_m - 0.08),
               tz() + uni(0.5, 40.0));
  }
  Object not_measurable() {
    Object o = in_tunnel(uni(0.5, 30.0));
    o.d_max = pick(0, 1) ? static_cast<std::uint16_t>(pick(0, 15))
                         : static_cast<std::uint16_t>(pick(0x8000, 0xffff));
    last_ = o;
    return o;
  }
  Object random_box() {
    return box(uni(-8.0, 6.0), uni(6.0, 9.0), uni(-3.0, 0.0), uni(0.0, 4.0), uni(1.0, 60.0));
  }
  Object with_code(Object o, std::uint16_t code) {
    o.d_max = code;
    last_ = o;
    return o;
  }
  /// The previous object again (a tie in everything), or its closest point, code and sums
  /// under another box (a tie in severity and distance, most of the time).
  Object tie_of_last() {
    tie_ = true;
    Object o = last_;
    if (pick(0, 1)) {
      o.x_min = static_cast<std::uint16_t>(std::max(0, o.x_min - pick(0, 3)));
      o.x_max = static_cast<std::uint16_t>(std::min(65535, o.x_max + pick(0, 3)));
      o.y_min = static_cast<std::uint16_t>(std::max(0, o.y_min - pick(0, 3)));
      o.first_x = u16();
    }
    return o;
  }

  WarningSetup s_;
  WarningConfig cfg_;
  int table_;
  Rng rng_;
  Sums sums_;
  bool tie_ = false;
  Object last_{};
};

// ---- runs -------------------------------------------------------------------------------------

/// The model and the RTL on `words` under every stall pattern until `frames_n` results have
/// left: the same cycle trace and outputs (check_twin_runs), and every result equal to
/// `expected`.
template <typename VM, typename Params>
void check_twins(const std::vector<LabelPacket>& words, const WarningConfig& cfg,
                 const std::vector<FrameResult>& expected) {
  for (const auto& pattern : StallPattern::all(3)) {
    INFO("stalls " << pattern.name());
    scw::sim::WarningModel<Params> cpp(cfg);
    auto rtl = scw::sim::make_warning_rtl<VM, Params>("warning", cfg);
    const auto rc = scw::sim::run_stream(cpp, words, pattern, expected.size(), 200'000);
    const auto rr = scw::sim::run_stream(rtl, words, pattern, expected.size(), 200'000);
    scw::test::check_twin_runs(rc, rr);
    REQUIRE(rr.out.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      INFO("frame " << i);
      CHECK(rr.out[i].last);
      CHECK(rr.out[i].data == expected[i]);
    }
  }
}

template <typename VM, typename Params>
Coverage check_tables(const std::vector<LabelPacket>& words, const WarningConfig& cfg) {
  Coverage cov;
  const auto expected = fold_frames<Params>(words, cfg, &cov);
  check_twins<VM, Params>(words, cfg, expected);
  return cov;
}

struct Camera {
  const char* name;
  double f, b, cu, cv;
};
// Karlsruhe sequences (1344 x 391) and the thesis's rig (640 x 480).
constexpr Camera kKarlsruhe{"Karlsruhe-like", 700.0, 0.54, 672.0, 195.0};
constexpr Camera kThesis{"thesis-like", 1000.0, 0.6, 640.0, 240.0};

/// A distance rule and its k, set on a configuration.
struct RuleCase {
  const char* name;
  hw::DistanceRule rule;
  std::uint8_t spread_q4;
};
constexpr RuleCase kRuleCases[] = {{"closest", hw::DistanceRule::kClosest, 0},
                                   {"spread k 0.75", hw::DistanceRule::kSpread, 12},
                                   {"spread k 0", hw::DistanceRule::kSpread, 0},
                                   {"spread k 2.5", hw::DistanceRule::kSpread, 40},
                                   {"spread k 15.94", hw::DistanceRule::kSpread, 255}};

WarningConfig with_rule(WarningConfig cfg, const RuleCase& r) {
  cfg.rule = r.rule;
  cfg.spread_q4 = r.spread_q4;
  return cfg;
}

WarningSetup setup_of(const Camera& c, double d_limit_px) {
  WarningSetup s;
  s.focal_px = c.f;
  s.baseline_m = c.b;
  s.cu_px = c.cu;
  s.cv_px = c.cv;
  s.d_limit_px = d_limit_px;
  return s;
}

void require_full_coverage(const Coverage& c) {
  CHECK(c.not_measurable > 0);
  CHECK(c.negative_code > 0);
  CHECK(c.too_close > 0);
  CHECK(c.past_table > 0);
  CHECK(c.low > 0);
  for (int s = 1; s <= 3; ++s) {
    INFO("severity " << s);
    CHECK(c.tunnel[s] > 0);
  }
  CHECK(c.outside[1] > 0);
  CHECK(c.outside[2] > 0);
  CHECK(c.outside[3] == 0);  // outside the tunnel is at most medium
  CHECK(c.negative_x > 0);
  CHECK(c.negative_y > 0);
  CHECK(c.ties > 0);
  CHECK(c.close_ties > 0);
  CHECK(c.no_obstacle > 0);
}

}  // namespace

TEST_CASE("scw_warning equals the model and the direct fold on random tables", "[warning][rtl]") {
  for (const Camera& cam : {kKarlsruhe, kThesis}) {
    // d_limit at the table's end, and inside it (codes between are too close but in the table).
    for (double d_limit : {64.0, 48.0}) {
      for (const RuleCase& rule : kRuleCases) {
        DYNAMIC_SECTION(cam.name << ", d_limit " << d_limit << " px, 64 px table, " << rule.name) {
          const WarningSetup s = setup_of(cam, d_limit);
          const WarningConfig cfg = with_rule(scw::host::warning::to_fixed(s), rule);
          TableGen gen(s, cfg, ParamsA::kTableSize,
                       1000 + static_cast<std::uint64_t>(d_limit) + 7 * rule.spread_q4);
          const auto words = gen.frames(40, 40);
          const Coverage c = check_tables<Vwarning_a, ParamsA>(words, cfg);
          require_full_coverage(c);
          if (rule.rule == hw::DistanceRule::kSpread) CHECK(c.moved > 0);
        }
      }
    }
  }
}

TEST_CASE("scw_warning with a 32 px table equals the model and the direct fold", "[warning][rtl]") {
  for (const Camera& cam : {kKarlsruhe, kThesis}) {
    for (double d_limit : {32.0, 20.0}) {
      for (const RuleCase& rule : {kRuleCases[0], kRuleCases[1]}) {
        DYNAMIC_SECTION(cam.name << ", d_limit " << d_limit << " px, 32 px table, " << rule.name) {
          const WarningSetup s = setup_of(cam, d_limit);
          const WarningConfig cfg = with_rule(scw::host::warning::to_fixed(s), rule);
          TableGen gen(s, cfg, ParamsB::kTableSize, 2000 + static_cast<std::uint64_t>(d_limit));
          const auto words = gen.frames(30, 30);
          const Coverage c = check_tables<Vwarning_b, ParamsB>(words, cfg);
          CHECK(c.past_table > 0);
          CHECK(c.too_close > 0);
          CHECK(c.tunnel[3] > 0);
        }
      }
    }
  }
}

TEST_CASE("scw_warning equals the model on adversarial disparity sums", "[warning][rtl]") {
  // Area 0, random 64-bit sums, S1^2 > A S2, the widest operands, means past 16 bits: the
  // spread rule still places every object exactly as rule_disparity() does.
  for (const Camera& cam : {kKarlsruhe, kThesis}) {
    for (const RuleCase& rule : kRuleCases) {
      DYNAMIC_SECTION(cam.name << ", " << rule.name) {
        const WarningSetup s = setup_of(cam, 64.0);
        const WarningConfig cfg = with_rule(scw::host::warning::to_fixed(s), rule);
        TableGen gen(s, cfg, ParamsA::kTableSize, 4000 + rule.spread_q4, Sums::kAdversarial);
        const auto words = gen.frames(30, 30);
        const Coverage c = check_tables<Vwarning_a, ParamsA>(words, cfg);
        CHECK(c.tunnel[3] > 0);
        CHECK(c.not_measurable > 0);
      }
    }
  }
}

TEST_CASE("scw_warning equals the model at the extremes of every port", "[warning][rtl]") {
  // The widest products and sums the ports allow: 4 km baseline, 4096 px focal length, boxes
  // anywhere in 0 .. 65535, the vehicle at the int16 corners; the root saturates (n >= 2^54).
  WarningConfig wide;
  wide.baseline_q8 = (1u << 20) - 1;
  wide.focal_q4 = 0xffff;
  wide.cu_q4 = 0;
  wide.cv_q4 = 0xffff;
  wide.veh_x_mm = 32767;
  wide.veh_y_mm = -32768;
  wide.veh_z_mm = 32767;
  wide.tunnel_half_w_mm = 0xffff;
  wide.tunnel_h_mm = 0xffff;
  wide.high_mm = 0xffff;
  wide.medium_mm = 0xffff;
  wide.near_mm = 0xffff;
  wide.min_height_mm = 0;
  wide.d_limit_q4 = ParamsA::kTableSize;
  // The narrowest: 1/256 mm baseline, 1/16 px focal length, zero tunnel and thresholds (too
  // close is then medium = 0: low outside the tunnel), the highest minimum height.
  WarningConfig narrow;
  narrow.baseline_q8 = 1;
  narrow.focal_q4 = 1;
  narrow.cu_q4 = 0xffff;
  narrow.cv_q4 = 0;
  narrow.veh_x_mm = -32768;
  narrow.veh_y_mm = 32767;
  narrow.veh_z_mm = -32768;
  narrow.d_limit_q4 = 16;
  // Everything an obstacle, in a tunnel of zero size, the bumper 32.8 m ahead of the camera:
  // objects behind it have negative distances.
  WarningConfig zero_height = narrow;
  zero_height.min_height_mm = 0;
  zero_height.baseline_q8 = 12345;
  zero_height.focal_q4 = 9999;
  zero_height.veh_z_mm = 32767;
  for (const auto& [name, cfg_closest] :
       {std::pair<const char*, WarningConfig>{"widest", wide},
        {"narrowest", narrow},
        {"zero tunnel", zero_height}}) {
    // The thesis's rule with realistic sums, and the spread rule (the widest k too) with
    // adversarial ones.
    for (const RuleCase& rule : {kRuleCases[0], kRuleCases[1], kRuleCases[4]}) {
      DYNAMIC_SECTION(name << ", " << rule.name) {
        const WarningConfig cfg = with_rule(cfg_closest, rule);
        const bool closest = rule.rule == hw::DistanceRule::kClosest;
        TableGen gen(setup_of(kKarlsruhe, 64.0), cfg, ParamsA::kTableSize, 77,
                     closest ? Sums::kRealistic : Sums::kAdversarial);
        std::vector<LabelPacket> words;
        for (int f = 0; f < 25; ++f) {
          std::vector<Object> objs;
          for (int i = 0; i < f % 9; ++i) objs.push_back(gen.random_fields());
          append_frame(words, objs);
        }
        const Coverage c = check_tables<Vwarning_a, ParamsA>(words, cfg);
        if (closest && std::string(name) == "widest") CHECK(c.saturated_root >= 3);
        if (closest && std::string(name) == "zero tunnel") CHECK(c.negative_distance > 0);
      }
    }
  }
  SECTION("random configurations") {
    std::mt19937_64 rng(5);
    auto u = [&rng](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
    for (int k = 0; k < 4; ++k) {
      WarningConfig cfg;
      cfg.baseline_q8 = static_cast<std::uint32_t>(u(1, (1 << 20) - 1));
      cfg.focal_q4 = static_cast<std::uint16_t>(u(1, 0xffff));
      cfg.cu_q4 = static_cast<std::uint16_t>(u(0, 0xffff));
      cfg.cv_q4 = static_cast<std::uint16_t>(u(0, 0xffff));
      cfg.veh_x_mm = static_cast<std::int16_t>(u(-32768, 32767));
      cfg.veh_y_mm = static_cast<std::int16_t>(u(-32768, 32767));
      cfg.veh_z_mm = static_cast<std::int16_t>(u(-32768, 32767));
      cfg.tunnel_half_w_mm = static_cast<std::uint16_t>(u(0, 0xffff));
      cfg.tunnel_h_mm = static_cast<std::uint16_t>(u(0, 0xffff));
      cfg.high_mm = static_cast<std::uint16_t>(u(0, 0xffff));
      cfg.medium_mm = static_cast<std::uint16_t>(u(cfg.high_mm, 0xffff));
      cfg.near_mm = static_cast<std::uint16_t>(u(0, 0xffff));
      cfg.min_height_mm = static_cast<std::uint16_t>(u(0, 0xffff));
      cfg.d_limit_q4 = static_cast<std::uint16_t>(u(16, ParamsB::kTableSize));
      cfg.rule = k % 2 ? hw::DistanceRule::kSpread : hw::DistanceRule::kClosest;
      cfg.spread_q4 = static_cast<std::uint8_t>(u(0, 255));
      INFO("configuration " << k);
      TableGen gen(setup_of(kThesis, 32.0), cfg, ParamsB::kTableSize, 300 + k,
                   k % 4 == 3 ? Sums::kAdversarial : Sums::kRealistic);
      std::vector<LabelPacket> words;
      for (int f = 0; f < 12; ++f) {
        std::vector<Object> objs;
        for (int i = 0; i < (f * 5) % 11; ++i) objs.push_back(gen.random_fields());
        append_frame(words, objs);
      }
      check_tables<Vwarning_b, ParamsB>(words, cfg);
    }
  }
}

TEST_CASE("scw_warning passes empty and back-to-back frames like the model", "[warning][rtl]") {
  const WarningSetup s = setup_of(kKarlsruhe, 64.0);
  const WarningConfig cfg = scw::host::warning::to_fixed(s);
  TableGen gen(s, cfg, ParamsA::kTableSize, 9);
  SECTION("status words only") {
    std::vector<LabelPacket> words;
    for (int f = 0; f < 50; ++f) append_frame(words, {}, f % 3 == 0, f % 5 == 0, f % 7 == 0);
    const auto expected = fold_frames<ParamsA>(words, cfg);
    for (const auto& r : expected) {
      CHECK(r.severity == Severity::kNone);
      CHECK(r.index == 0xffff);
      CHECK(r.objects == 0);
    }
    check_twins<Vwarning_a, ParamsA>(words, cfg, expected);
  }
  SECTION("one-object frames, empty frames between") {
    std::vector<LabelPacket> words;
    for (int f = 0; f < 60; ++f)
      append_frame(words, f % 4 == 3 ? std::vector<Object>{} : std::vector<Object>{gen.next()});
    check_twins<Vwarning_a, ParamsA>(words, cfg, fold_frames<ParamsA>(words, cfg));
  }
  SECTION("frames shorter and longer than the pipeline") {
    std::vector<LabelPacket> words;
    constexpr int L = hw::kLatency;
    for (int n : {2, L - 2, L - 1, L, 0, 1, 2 * L - 2, 3}) {
      std::vector<Object> objs;
      for (int i = 0; i < n; ++i) objs.push_back(gen.next());
      append_frame(words, objs);
    }
    check_twins<Vwarning_a, ParamsA>(words, cfg, fold_frames<ParamsA>(words, cfg));
  }
}

TEST_CASE("scw_warning flags broken tables like the model, the next frame correct",
          "[warning][rtl]") {
  const WarningSetup s = setup_of(kThesis, 64.0);
  const WarningConfig cfg = scw::host::warning::to_fixed(s);
  TableGen gen(s, cfg, ParamsA::kTableSize, 21);
  auto objects = [&gen](int n) {
    std::vector<Object> v;
    for (int i = 0; i < n; ++i) v.push_back(gen.next());
    return v;
  };
  const auto good = objects(6);
  // `words` and then a good frame: the first `frames_n` results flag an error (when
  // `broken`), the last is clean.
  auto check = [&](std::vector<LabelPacket> words, std::size_t frames_n, bool broken = true) {
    append_frame(words, good);
    const auto expected = fold_frames<ParamsA>(words, cfg);
    REQUIRE(expected.size() == frames_n + 1);
    for (std::size_t i = 0; i < frames_n; ++i) CHECK(expected[i].stream_error == broken);
    CHECK_FALSE(expected.back().stream_error);
    CHECK(expected.back().objects == good.size());
    check_twins<Vwarning_a, ParamsA>(words, cfg, expected);
  };
  SECTION("a status word without last") {
    std::vector<LabelPacket> words;
    for (const auto& o : objects(5)) words.push_back(object_word(o));
    words.push_back(status_word(5, false));
    words.push_back(status_word(0, false));  // an empty frame, also without last
    check(words, 2);
  }
  SECTION("last on an object word, no status") {
    std::vector<LabelPacket> words;
    const auto objs = objects(4);
    for (std::size_t i = 0; i < objs.size(); ++i)
      words.push_back(object_word(objs[i], i + 1 == objs.size()));
    words.push_back(object_word(objects(1)[0], true));  // a frame of one such word
    check(words, 2);
  }
  SECTION("the wrong object count") {
    std::vector<LabelPacket> words;
    for (std::uint32_t claimed : {4u, 6u, 0u, 65536u + 5u}) {
      for (const auto& o : objects(5)) words.push_back(object_word(o));
      words.push_back(status_word(claimed));
    }
    check(words, 4);
  }
  SECTION("the labelling stage's own flags pass through") {
    std::vector<LabelPacket> words;
    append_frame(words, objects(3), true, false, false);
    append_frame(words, objects(3), false, true, false);
    append_frame(words, {}, true, true, false);
    const auto expected = fold_frames<ParamsA>(words, cfg);
    CHECK(expected[0].tile_overflow);
    CHECK(expected[1].object_overflow);
    CHECK(expected[2].tile_overflow);
    CHECK(expected[2].object_overflow);
    check(words, 3, false);
  }
  SECTION("the labelling stage's stream error passes through") {
    std::vector<LabelPacket> words;
    append_frame(words, objects(3), false, false, true);
    append_frame(words, {}, true, true, true);
    check(words, 2);
  }
}

TEST_CASE("scw_warning decides ties like the model: the earlier obstacle", "[warning][rtl]") {
  const WarningSetup s = setup_of(kKarlsruhe, 64.0);
  const WarningConfig cfg = scw::host::warning::to_fixed(s);
  const double f = s.focal_px, b = s.baseline_m;
  // A car-sized box in the lane, `dist` m from the bumper, shifted `dx` m sideways.
  auto car = [&](double dist, double dx) {
    const double z = s.vehicle_origin.z() + dist, x = s.vehicle_origin.x() + dx;
    const double yb = s.vehicle_origin.y(), yt = yb + 1.5;
    Object o;
    o.x_min = static_cast<std::uint16_t>(std::lround(s.cu_px + f * (x - 0.9) / z));
    o.x_max = static_cast<std::uint16_t>(std::lround(s.cu_px + f * (x + 0.9) / z));
    o.y_min = static_cast<std::uint16_t>(std::lround(s.cv_px - f * yt / z));
    o.y_max = static_cast<std::uint16_t>(std::lround(s.cv_px - f * yb / z));
    o.closest_x = static_cast<std::uint16_t>((o.x_min + o.x_max) / 2);
    o.closest_y = o.y_max;
    o.area = 1u + static_cast<std::uint32_t>((o.x_max - o.x_min) * (o.y_max - o.y_min));
    // every pixel at one code: either rule places it there
    scw::fixtures::set_uniform_code(o, static_cast<std::uint16_t>(std::lround(16.0 * f * b / z)));
    return o;
  };
  Object a = car(8.0, 0.0), a_wider = a;
  a_wider.x_min = static_cast<std::uint16_t>(a.x_min - 2);
  a_wider.x_max = static_cast<std::uint16_t>(a.x_max + 2);
  // Too close at two distances: both judged at 0, so the first decides.
  Object near1 = car(2.0, 0.0), near2 = car(1.0, 0.3);
  const Object farther = car(15.0, 0.0);
  std::vector<LabelPacket> words;
  append_frame(words, {farther, a, a_wider});    // tie in severity and distance: index 1
  append_frame(words, {a_wider, a, farther});    // index 0
  append_frame(words, {farther, near1, near2});  // both too close: index 1
  append_frame(words, {farther, near2, near1});  // index 1 again, the other object
  const auto expected = fold_frames<ParamsA>(words, cfg);
  REQUIRE(expected.size() == 4);
  CHECK(expected[0].index == 1);
  CHECK(expected[0].severity == Severity::kHigh);
  CHECK(expected[1].index == 0);
  CHECK(expected[1].x_min == a_wider.x_min);
  CHECK(expected[2].index == 1);
  CHECK(expected[2].too_close);
  CHECK(expected[3].index == 1);
  CHECK(expected[3].d_max == near2.d_max);
  CHECK(expected[2].distance_mm != expected[3].distance_mm);
  // The physics, roughly: a car 8 m ahead of the bumper is about 8 m away.
  CHECK(std::abs(expected[0].distance_mm - 8000) < 200);
  check_twins<Vwarning_a, ParamsA>(words, cfg, expected);
}

TEST_CASE("scw_warning shows a frame's result kLatency clocks after its status word",
          "[warning][rtl]") {
  const WarningSetup s = setup_of(kKarlsruhe, 64.0);
  const WarningConfig cfg = scw::host::warning::to_fixed(s);
  TableGen gen(s, cfg, ParamsA::kTableSize, 3);
  std::vector<LabelPacket> words;
  append_frame(words, {gen.next(), gen.next()});
  const auto expected = fold_frames<ParamsA>(words, cfg);
  scw::sim::WarningModel<ParamsA> cpp(cfg);
  auto rtl = scw::sim::make_warning_rtl<Vwarning_a, ParamsA>("warning", cfg);
  const StallPattern none{};
  const auto rc = scw::sim::run_stream(cpp, words, none, 1);
  const auto rr = scw::sim::run_stream(rtl, words, none, 1);
  scw::test::check_twin_runs(rc, rr);
  for (const auto* r : {&rc, &rr}) {
    std::int64_t taken = -1, shown = -1;
    for (std::size_t c = 0; c < r->trace.size(); ++c) {
      const auto& t = r->trace[c];
      if (t.in_valid && t.in_ready) taken = static_cast<std::int64_t>(c);  // the status word
      if (t.out_valid && shown < 0) shown = static_cast<std::int64_t>(c);
    }
    CHECK(shown - taken == hw::kLatency);
  }
  REQUIRE(rr.out.size() == 1);
  CHECK(rr.out[0].data == expected[0]);
}

TEST_CASE("scw_warning idle between frames is skipped and answers as if clocked throughout",
          "[warning][rtl]") {
  // Frames of objects with long gaps between them, the output stalled in some windows: the
  // Verilated stage and the model side by side, every port compared at every cycle. The RTL's
  // pipeline runs on (its delay rings go round) while it waits, so its idle cycles form a loop
  // of several cycles, which the harness skips and leaves at every phase.
  const WarningSetup s = setup_of(kThesis, 64.0);
  const WarningConfig cfg = scw::host::warning::to_fixed(s);
  TableGen gen(s, cfg, ParamsA::kTableSize, 17);
  scw::sim::WarningModel<ParamsA> cpp(cfg);
  auto rtl = scw::sim::make_warning_rtl<Vwarning_a, ParamsA>("warning", cfg);
  std::size_t results = 0;
  std::int64_t cycles = 0;
  for (int f = 0; f < 12; ++f) {
    std::vector<LabelPacket> words;
    std::vector<Object> objs;
    for (int i = 0; i < f % 5; ++i) objs.push_back(gen.next());
    append_frame(words, objs);
    const int gap = 2000 + 137 * f;  // ends at a different phase of the loop each time
    std::size_t pos = 0;
    for (int c = 0; pos < words.size() || c < gap; ++c, ++cycles) {
      const bool valid = pos < words.size() && c % 3 != 1;
      const bool out_ready = (cycles / 500) % 4 != 3;
      const LabelPacket w = valid ? words[pos] : LabelPacket{};
      const auto oc = cpp.eval(valid, w, out_ready);
      const auto orr = rtl.eval(valid, w, out_ready);
      INFO("frame " << f << ", cycle " << cycles);
      REQUIRE(orr.in_ready == oc.in_ready);
      REQUIRE(orr.out_valid == oc.out_valid);
      if (oc.out_valid) REQUIRE(orr.out == oc.out);
      if (oc.out_valid && out_ready) ++results;
      if (valid && oc.in_ready) ++pos;
      cpp.tick();
      rtl.tick();
    }
  }
  CHECK(results == 12);
  // Most of the run was idle; the harness skipped most of it.
  CHECK(rtl.harness().skipped() > static_cast<std::uint64_t>(cycles) / 2);
}

TEST_CASE("scw_warning_sqrt equals isqrt_round at every rounding boundary", "[warning][rtl]") {
  // Around r^2 (floor), r^2 + r (n - r^2 > r rounds up), for every r below 3000 and random
  // ones up to 2^27, where the loop saturates; then n from 2^54 up (clamped), and random n.
  std::vector<std::uint64_t> ns;
  std::mt19937_64 rng(17);
  std::vector<std::uint64_t> roots;
  for (std::uint64_t r = 0; r < 3000; ++r) roots.push_back(r);
  for (int i = 0; i < 3000; ++i) roots.push_back(rng() >> 37);
  for (std::uint64_t r :
       {(1ull << 26) - 1, 1ull << 26, (1ull << 27) - 2, (1ull << 27) - 1, 1ull << 27})
    roots.push_back(r);
  for (std::uint64_t r : roots)
    for (std::uint64_t base : {r * r, r * r + r})
      for (int d = -1; d <= 1; ++d)
        if (base + static_cast<std::uint64_t>(d) < (1ull << 58) && (base > 0 || d >= 0))
          ns.push_back(base + static_cast<std::uint64_t>(d));
  for (std::uint64_t n :
       {(1ull << 54) - 1, 1ull << 54, (1ull << 54) + 1, (1ull << 57), (1ull << 58) - 1})
    ns.push_back(n);
  for (int i = 0; i < 20000; ++i) ns.push_back(rng() >> (6 + rng() % 58));

  using Sqrt = Vwarning_sqrt_scw_warning_sqrt;
  const std::size_t latency = Sqrt::Latency;
  const auto ctx = scw::sim::single_model_context();
  auto m = std::make_unique<Vwarning_sqrt>(ctx.get(), "sqrt");
  std::size_t fed = 0, bad = 0, checked = 0;
  // Idle clocks (en low) now and then: the pipeline must hold.
  while (fed < ns.size() + latency) {
    const bool en = rng() % 4 != 0;
    m->en_i = en;
    m->n_i = ns[std::min(fed, ns.size() - 1)];
    m->clk_i = 0;
    m->eval();
    m->clk_i = 1;
    m->eval();
    if (en) ++fed;
    if (fed >= latency && fed - latency < ns.size()) {
      const std::uint64_t n = ns[fed - latency];
      ++checked;
      if (m->root_o != hw::isqrt_round(n) && ++bad <= 5)
        FAIL_CHECK("n = " << n << ": RTL " << m->root_o << ", isqrt_round " << hw::isqrt_round(n));
    }
  }
  Verilated::threadContextp(ctx.get());  // see sim/rtl/verilated_harness.hpp
  m->final();
  m.reset();
  CHECK(checked >= ns.size());
  CHECK(bad == 0);
}

namespace {

/// One case of the rule alone: the object's fields it reads.
struct RuleIn {
  std::uint32_t area = 0;
  std::uint64_t sum_d = 0, sum_dd = 0;
  std::uint16_t d_max = 0;
};

/// Cases that reach every part of scw_warning_rule: realistic multisets, the square root's
/// rounding boundaries (V = r^2 - 1, r^2, r^2 + r, r^2 + r + 1, small and near 2^70), the
/// quotient's (means about 4096 px, where q leaves 16 bits), d_max on either side of q, and
/// adversarial words.
std::vector<RuleIn> rule_cases(Rng& rng, int n) {
  std::vector<RuleIn> v;
  auto u16 = [&rng] { return static_cast<std::uint16_t>(rng()); };
  constexpr std::uint64_t kS2Max = (std::uint64_t{1} << hw::kRuleSquareBits) - 1;
  while (static_cast<int>(v.size()) < n) {
    RuleIn c;
    Object o;
    switch (pick_u(rng, 0, 9)) {
      case 0:
      case 1:
      case 2: {  // realistic: d_max the largest code
        o.d_max = pick_u(rng, 0, 3) ? static_cast<std::uint16_t>(pick_u(rng, 0, 0x7fff)) : u16();
        realistic_sums(rng, o);
        break;
      }
      case 3: {  // A = 1: V = S2 - S1^2 at the root's rounding boundaries
        const std::uint64_t s1 = pick_u(rng, 0, 1u << 22);
        const std::uint64_t r = pick_u(rng, 0, 1) ? pick_u(rng, 0, 3000) : pick_u(rng, 0, 1u << 24);
        const std::uint64_t vs[] = {r * r - (r > 0), r * r, r * r + r, r * r + r + 1};
        o.area = 1;
        o.sum_d = s1;
        o.sum_dd = s1 * s1 + vs[pick_u(rng, 0, 3)];
        o.d_max = u16();
        break;
      }
      case 4: {  // S1 = 0, A = 2^19 .. 2^20 - 1: V = A S2 = r^2, r^2 + r or r^2 + r +- A, r ~ 2^34
        const std::uint64_t a = pick_u(rng, 1u << 19, (1u << 20) - 1);
        const std::uint64_t m = pick_u(rng, 1, (std::uint64_t{1} << 35) / a - 1);  // r = a m < 2^35
        const std::uint64_t r = a * m;
        std::uint64_t s2 = 0;
        switch (pick_u(rng, 0, 3)) {
          case 0: s2 = a * m * m; break;      // V = r^2
          case 1: s2 = m * (r + 1); break;    // V = r^2 + r: not rounded up
          case 2: s2 = m * (r + 1) + 1; break;  // V = r^2 + r + A: rounded up
          default: s2 = m * (r + 1) - 1;      // V = r^2 + r - A
        }
        if (s2 > kS2Max) continue;
        o.area = static_cast<std::uint32_t>(a);
        o.sum_d = 0;
        o.sum_dd = s2;
        o.d_max = u16();
        break;
      }
      case 5: {  // a uniform mean about 4096 px, plus a little spread: q about 2^16
        const std::uint64_t a = pick_u(rng, 1, 1u << 18);
        const std::uint64_t d = pick_u(rng, 0xffe0, 0x10020);
        o.area = static_cast<std::uint32_t>(a);
        o.sum_d = a * d;
        o.sum_dd = a * d * d + pick_u(rng, 0, 1) * pick_u(rng, 0, 1u << 20);
        o.d_max = pick_u(rng, 0, 1) ? 0xffff : u16();
        break;
      }
      case 6:  // d_max near q: realistic, then d_max moved a little
        o.d_max = static_cast<std::uint16_t>(pick_u(rng, 16, 0x7fff));
        realistic_sums(rng, o);
        o.d_max = static_cast<std::uint16_t>(o.d_max - pick_u(rng, 0, std::min<int>(o.d_max, 40)));
        break;
      case 7:  // A = 1, anything
        o.area = 1;
        o.sum_d = rng();
        o.sum_dd = rng();
        o.d_max = u16();
        break;
      default:
        o.d_max = u16();
        adversarial_sums(rng, o);
    }
    c.area = o.area;
    c.sum_d = o.sum_d;
    c.sum_dd = o.sum_dd;
    c.d_max = o.d_max;
    v.push_back(c);
  }
  return v;
}

}  // namespace

TEST_CASE("scw_warning_rule equals rule_disparity bit for bit", "[warning][rtl]") {
  Rng rng(29);
  const RuleCase extra[] = {{"spread k 1/16", hw::DistanceRule::kSpread, 1},
                            {"spread k 1", hw::DistanceRule::kSpread, 16},
                            {"spread k 8", hw::DistanceRule::kSpread, 128},
                            {"spread k 12.06", hw::DistanceRule::kSpread, 193}};
  std::vector<RuleCase> rules(std::begin(kRuleCases), std::end(kRuleCases));
  rules.insert(rules.end(), std::begin(extra), std::end(extra));

  const std::size_t latency = Rule::Latency;
  const auto ctx = scw::sim::single_model_context();
  auto m = std::make_unique<Vwarning_rule>(ctx.get(), "rule");
  auto clock = [&m] {
    m->clk_i = 0;
    m->eval();
    m->clk_i = 1;
    m->eval();
  };
  auto low = [](std::uint64_t v, int bits) { return v & ((std::uint64_t{1} << bits) - 1); };
  std::size_t bad = 0, checked = 0, moved = 0, saturated = 0, zero_v = 0;
  for (const RuleCase& rc : rules) {
    INFO(rc.name);
    WarningConfig cfg;
    cfg.rule = rc.rule;
    cfg.spread_q4 = rc.spread_q4;
    // cfg_* are static: set, then a clock before the first case.
    m->cfg_rule_i = static_cast<std::uint8_t>(rc.rule);
    m->cfg_spread_i = rc.spread_q4;
    m->en_i = 0;
    clock();
    const auto cases = rule_cases(rng, 4000);
    std::size_t fed = 0;
    // Idle clocks (en low) now and then: the pipeline must hold.
    while (fed < cases.size() + latency) {
      const bool en = rng() % 4 != 0;
      const RuleIn& in = cases[std::min(fed, cases.size() - 1)];
      m->en_i = en;
      m->area_i = static_cast<std::uint32_t>(low(in.area, hw::kRuleAreaBits));
      m->sum_d_i = low(in.sum_d, hw::kRuleSumBits);
      m->sum_dd_i = low(in.sum_dd, hw::kRuleSquareBits);
      m->d_max_i = in.d_max;
      clock();
      if (en) ++fed;
      if (fed >= latency && fed - latency < cases.size()) {
        const RuleIn& c = cases[fed - latency];
        Object o;
        o.area = c.area;
        o.sum_d = c.sum_d;
        o.sum_dd = c.sum_dd;
        o.d_max = c.d_max;
        const std::uint32_t want = hw::rule_disparity(o, cfg);
        ++checked;
        if (want < c.d_max) ++moved;
        const std::uint64_t a = low(c.area, hw::kRuleAreaBits);
        const std::uint64_t s1 = low(c.sum_d, hw::kRuleSumBits);
        const std::uint64_t s2 = low(c.sum_dd, hw::kRuleSquareBits);
        using u128 = scw::hls::labelling::u128;
        if (u128{a} * s2 <= u128{s1} * s1) ++zero_v;
        if (a == 0 || u128{16} * s1 >= (u128{16} * a) << 16) ++saturated;
        if (m->dq_o != want && ++bad <= 5)
          FAIL_CHECK("area " << c.area << ", sum_d " << c.sum_d << ", sum_dd " << c.sum_dd
                             << ", d_max " << c.d_max << ": RTL " << m->dq_o
                             << ", rule_disparity " << want);
      }
    }
  }
  Verilated::threadContextp(ctx.get());  // see sim/rtl/verilated_harness.hpp
  m->final();
  m.reset();
  CHECK(checked >= rules.size() * 4000);  // held outputs are checked again
  CHECK(bad == 0);
  // What the cases reached (moved: the spread rule placed the object nearer than d_max).
  INFO("moved " << moved << ", saturated " << saturated << ", V = 0 " << zero_v);
  CHECK(moved > 1000);
  CHECK(saturated > 100);
  CHECK(zero_v > 100);
}

namespace {

/// A road line a frame: a flat road seen from 0.8 .. 2.5 m with a pitch of -3 .. 3 degrees
/// (camera `s`), and now and then the port's extremes (a = 0, the widest slope, b at +-2^31).
std::vector<hw::RoadLine> random_roads(const WarningSetup& s, int frames, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> height(0.8, 2.5), pitch(-0.052, 0.052), u(0, 1);
  std::vector<hw::RoadLine> roads;
  for (int f = 0; f < frames; ++f) {
    const double a_px = s.baseline_m / height(rng);
    const double horizon = s.cv_px - s.focal_px * std::tan(pitch(rng));
    hw::RoadLine r{static_cast<std::int32_t>(std::lround(a_px * scw::hls::road::kPxUnit)),
                   static_cast<std::int32_t>(std::lround(-a_px * horizon *
                                                         scw::hls::road::kPxUnit))};
    const double x = u(rng);
    if (x < 0.05) r.a = 0;
    else if (x < 0.1) r.a = (1 << 18) - 1;
    else if (x < 0.13) r.b = INT32_MIN;
    else if (x < 0.16) r.b = INT32_MAX;
    roads.push_back(r);
  }
  return roads;
}

}  // namespace

TEST_CASE("scw_warning with a road line a frame equals the model, heights above the road",
          "[warning][rtl]") {
  const WarningSetup s = setup_of(kKarlsruhe, 64.0);
  for (const RuleCase& rule : {kRuleCases[0], kRuleCases[1]}) {
    DYNAMIC_SECTION(rule.name) {
      WarningConfig cfg = with_rule(scw::host::warning::to_fixed(s), rule);
      cfg.road_height = true;
      // Well-formed tables (a road line goes with each `last`-closed frame).
      TableGen gen(s, cfg, ParamsA::kTableSize, 3000 + rule.spread_q4);
      std::vector<std::vector<LabelPacket>> frames;
      std::vector<LabelPacket> words;
      for (int f = 0; f < 40; ++f) {
        std::vector<Object> objects(static_cast<std::size_t>(f % 13));
        for (auto& o : objects) o = gen.next();
        scw::hls::labelling::FrameStatus st;
        st.objects = static_cast<std::uint32_t>(objects.size());
        frames.push_back(scw::warning::table_words(objects, st));
        words.insert(words.end(), frames.back().begin(), frames.back().end());
      }
      const auto roads = random_roads(s, static_cast<int>(frames.size()), 77 + rule.spread_q4);
      std::vector<scw::hls::Packet<hw::RoadLine>> lines;
      for (const auto& r : roads) lines.push_back({r, true});

      // Each frame alone through the stage's HLS top with its line, and without one (box
      // heights).
      const auto alone = [](const std::vector<LabelPacket>& w, const WarningConfig& c,
                            const hw::RoadLine* road) {
        hw::Warning<ParamsA> k(c);
        std::vector<ResultPacket> out(w.size());
        REQUIRE(hw::warning_frame(k, w.data(), static_cast<int>(w.size()), out.data(), road) == 1);
        return out[0].data;
      };
      WarningConfig box = cfg;
      box.road_height = false;
      std::vector<FrameResult> expected;
      int differ = 0, above = 0, below = 0, compared = 0;
      for (std::size_t f = 0; f < frames.size(); ++f) {
        expected.push_back(alone(frames[f], cfg, &roads[f]));
        if (expected.back() != alone(frames[f], box, nullptr)) ++differ;
        for (const auto& w : frames[f]) {
          if (w.data.is_status) continue;
          const ObjectEval e = hw::evaluate<ParamsA>(w.data.object, cfg, roads[f]);
          if (!e.measurable) continue;
          // The floating-point reference with the same road in px agrees away from the
          // threshold (its disparity is the rule's unrounded one).
          const scw::reference::RoadLinePx px = scw::reference::to_px(roads[f]);
          const auto ref = scw::host::warning::evaluate_ref(w.data.object, s, &px);
          // Compared where both place the object at one disparity (TableGen's sums are not
          // always an object's) inside the stage's table, and no height is at the threshold.
          if (roads[f].a > 0 && std::abs(ref.disparity_px - e.d_q4 / 16.0) < 1.0 / 16 &&
              e.d_q4 < static_cast<std::uint32_t>(ParamsA::kTableSize) &&
              std::abs(ref.above_road_m - s.min_height_m) >
                  0.05 * std::abs(ref.above_road_m) + 0.02 &&
              std::abs(ref.height_m - s.min_height_m) > 0.05 * ref.height_m + 0.02) {
            INFO("frame " << f << " road " << roads[f].a << " " << roads[f].b << " y_min "
                          << w.data.object.y_min << " d " << ref.disparity_px << " dq "
                          << e.d_q4 << " above the road: ref " << ref.above_road_m
                          << " fixed " << e.above_road_mm);
            CHECK(ref.obstacle == e.obstacle);
            ++compared;
          }
          (e.obstacle ? above : below)++;
        }
      }
      CHECK(differ > 0);  // the road changes some frames' results
      CHECK(compared > 50);
      CHECK(above > 0);
      CHECK(below > 0);
      for (const auto& pattern : StallPattern::all(3)) {
        INFO("stalls " << pattern.name());
        scw::sim::WarningRoadModel<ParamsA> cpp(cfg);
        auto rtl = scw::sim::make_warning_road_rtl<Vwarning_a, ParamsA>("warning", cfg);
        const auto rc = scw::sim::run_join(cpp, words, lines, pattern, expected.size(), 400'000);
        const auto rr = scw::sim::run_join(rtl, words, lines, pattern, expected.size(), 400'000);
        scw::test::check_twin_runs(rc, rr);
        REQUIRE(rr.out.size() == expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) {
          const FrameResult& g = rr.out[i].data;
          const FrameResult& x = expected[i];
          INFO("frame " << i << ": got severity " << int(g.severity) << " index " << g.index
                        << " objects " << g.objects << " obstacles " << g.obstacles << " d "
                        << g.distance_mm << " err " << g.stream_error << "; expected "
                        << int(x.severity) << " " << x.index << " " << x.objects << " "
                        << x.obstacles << " " << x.distance_mm << " " << x.stream_error);
          CHECK(g == x);
        }
      }
    }
  }
}

TEST_CASE("scw_warning waits for a frame's road line and takes it with the first word only",
          "[warning][rtl]") {
  const WarningSetup s = setup_of(kThesis, 64.0);
  WarningConfig cfg = scw::host::warning::to_fixed(s);
  cfg.road_height = true;
  TableGen gen(s, cfg, ParamsA::kTableSize, 4242);
  const auto words = gen.frames(6, 5);
  scw::sim::WarningRoadModel<ParamsA> cpp(cfg);
  auto rtl = scw::sim::make_warning_road_rtl<Vwarning_a, ParamsA>("warning", cfg);
  const scw::hls::Packet<hw::RoadLine> line{{29491, -29491 * 240}, true};
  // No line: the first word waits, and so does the stage.
  for (int c = 0; c < 5; ++c) {
    const auto oc = cpp.eval(true, words[0], false, {}, true);
    const auto orr = rtl.eval(true, words[0], false, {}, true);
    CHECK_FALSE(oc.a_ready);
    CHECK_FALSE(orr.a_ready);
    CHECK(oc.b_ready == orr.b_ready);
    CHECK(oc.b_ready);  // it would take one
    cpp.tick();
    rtl.tick();
  }
  // With one, both are taken together; the frame's next words take none.
  auto oc = cpp.eval(true, words[0], true, line, true);
  auto orr = rtl.eval(true, words[0], true, line, true);
  CHECK(oc.a_ready);
  CHECK(orr.a_ready);
  CHECK(oc.b_ready);
  CHECK(orr.b_ready);
  cpp.tick();
  rtl.tick();
  if (!words[0].last) {
    oc = cpp.eval(true, words[1], true, line, true);
    orr = rtl.eval(true, words[1], true, line, true);
    CHECK(oc.a_ready);
    CHECK(orr.a_ready);
    CHECK_FALSE(oc.b_ready);
    CHECK_FALSE(orr.b_ready);
  }
}
