// SPDX-License-Identifier: Apache-2.0
// Warning stage golden vectors: the presets, the model run and its checks, the files.
#include "host/vectors/warning_set.hpp"

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/pipeline/pipeline_params.hpp"
#include "hls/warning/warning.hpp"
#include "host/vectors/labelling_set.hpp"
#include "host/vectors/object_tables.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/core/stall.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/warning_model.hpp"
#include "sim/words/labelling_pack.hpp"
#include "sim/words/pack.hpp"
#include "sim/words/warning_cfg.hpp"
#include "sim/words/warning_pack.hpp"
// The object placement and random tables the [hls] and [rtl] tests use: the vectors exercise
// the same branches, and a plain fold of evaluate() checks every frame independently of the
// clocked kernel.
#include "host/vectors/warning_tables.hpp"

namespace scw::vectors {
namespace {

using hls::labelling::FrameStatus;
using hls::labelling::LabelPacket;
using hls::labelling::Object;
using hls::warning::FrameResult;
using hls::warning::ObjectEval;
using hls::warning::ResultPacket;
using hls::warning::Severity;
using hls::warning::WarningConfig;
using host::warning::WarningSetup;

using OutLayout = sim::BeatLayout<ResultPacket>;
using Shape = WarningShape;

WarningFrame expect(std::string name, std::vector<Object> t, Severity sev, bool tunnel, bool close,
                    int index) {
  WarningFrame f;
  f.name = std::move(name);
  f.objects = std::move(t);
  f.check_severity = true;
  f.severity = sev;
  f.in_tunnel = tunnel;
  f.too_close = close;
  f.index = index;
  return f;
}

/// An object with closest point (u, v), disparity code dq at every pixel and the given bounding
/// box.
Object make_object(int u, int v, int dq, int x_min, int y_min, int x_max, int y_max) {
  Object o;
  o.closest_x = static_cast<std::uint16_t>(u);
  o.closest_y = static_cast<std::uint16_t>(v);
  o.first_x = o.closest_x;
  o.first_y = o.closest_y;
  o.d_min = static_cast<std::uint16_t>(dq);
  o.x_min = static_cast<std::uint16_t>(x_min);
  o.x_max = static_cast<std::uint16_t>(x_max);
  o.y_min = static_cast<std::uint16_t>(y_min);
  o.y_max = static_cast<std::uint16_t>(y_max);
  o.area = 1u + static_cast<std::uint32_t>((x_max - x_min) * (y_max - y_min));
  fixtures::set_uniform_code(o, o.d_min);
  return o;
}

// ---- thesis: one frame per rule of eq. 5.2, back to back ----

/// The thesis's worked example (5.4), as tests/warning/test_warning_ref.cpp derives it: a bike
/// right of the tunnel on a 1280 x 480 image (f 700 px, b 0.54 m, principal point at the
/// centre), d = 805 / 16 px: |A| = 7.89 m from the camera, D = 6.24 m from the bumper, its box
/// 0.50 m right of the tunnel (within near_m = 1 m) and D < 20 m: medium. `shift_px` moves it
/// sideways at the same depth.
Object bike(int shift_px = 0) {
  return make_object(863 + shift_px, 266, 805, 785 + shift_px, 185, 952 + shift_px, 351);
}

std::vector<WarningFrame> thesis_frames(const WarningSetup& s) {
  const double lane = s.vehicle_origin.x();  // the tunnel's centre line, camera x
  // Upright boxes on the road in the tunnel at 8, 15 and 30 m depth (D about 6.4, 13.4, 28.4 m).
  const Object car8 = fixtures::place_box(s, lane, 8.0, 1.6, 1.4);
  const Object car15 = fixtures::place_box(s, lane, 15.0, 1.6, 1.4);
  const Object car30 = fixtures::place_box(s, lane, 30.0, 1.6, 1.4);
  // A road marking 5 m ahead in the tunnel, 5 cm high: below min_height (0.5 m).
  const Object marking = fixtures::place_box(s, lane, 5.0, 1.0, 0.05);
  // Too far to place: d_max below 1 px.
  Object far = fixtures::place_box(s, lane, 20.0, 1.6, 1.4);
  far.d_min = 12;
  fixtures::set_uniform_code(far, 12);
  // Too close: d_max at or past d_limit (64 px = code 1024), judged as at the bumper. One inside
  // the table, one past its end (code 2048 = 128 px reads the last entry).
  Object close_in = fixtures::place_box(s, lane, 5.0, 1.6, 1.4);
  fixtures::set_uniform_code(close_in, 1100);
  Object close_past = close_in;
  fixtures::set_uniform_code(close_past, 2100);
  // Well right of the tunnel (over 2 m beside it, beyond near_m): too close but low.
  Object close_side = fixtures::place_box(s, lane + 4.0, 5.0, 1.0, 1.4);
  fixtures::set_uniform_code(close_side, 1100);

  using S = Severity;
  return {
      expect("worked example: 7.89 m from the camera, 6.24 m from the bumper, outside the tunnel "
             "but near it: medium",
             {bike()}, S::kMedium, false, false, 0),
      expect("the bike 1 m further right: beyond near_m, low", {bike(94)}, S::kLow, false, false,
             0),
      expect("the bike moved into the tunnel at 6.24 m: high", {bike(-200)}, S::kHigh, true, false,
             0),
      expect("in the tunnel at 30, 15, 8 m: low, medium, high; the high one decides",
             {car30, car15, car8}, S::kHigh, true, false, 2),
      expect("in the tunnel at 15 m: medium", {car15}, S::kMedium, true, false, 0),
      expect("in the tunnel at 30 m: low", {car30}, S::kLow, true, false, 0),
      expect("a road marking below the minimum height and an object too far to measure: no "
             "obstacle",
             {marking, far}, S::kNone, false, false, -1),
      expect("empty frame", {}, S::kNone, false, false, -1),
      expect("high at 6.24 m, then a too-close object in the tunnel, judged at 0 m: it decides",
             {bike(-200), close_in}, S::kHigh, true, true, 1),
      expect("too close past the table's end (code 2100), and too close beside the tunnel (low)",
             {close_side, close_past}, S::kHigh, true, true, 1),
      expect("too close but over 2 m beside the tunnel: low", {close_side}, S::kLow, false, true,
             0),
      expect("two identical bikes and the marking: the earlier bike decides",
             {marking, bike(), bike()}, S::kMedium, false, false, 1),
      expect("empty frame again", {}, S::kNone, false, false, -1),
  };
}

WarningPreset thesis() {
  WarningPreset p;
  p.setup.cu_px = 640.0;  // the default rig with the principal point at the image centre
  p.setup.cv_px = 240.0;
  p.frames = thesis_frames(p.setup);
  p.description =
      "scw warning stage: 13 hand-placed object tables back to back (1280x480 image, f 700 px, "
      "b 0.54 m, principal point 640,240, thesis vehicle geometry and eq. 5.2 thresholds, "
      "d_limit 64 px): the thesis's worked example (7.89 m from the camera, 6.24 m from the "
      "bumper, medium outside the tunnel) and the same bike 1 m further right (low) and in the "
      "tunnel (high); in-tunnel high, medium, low; a road marking below the minimum height and "
      "an unmeasurable object; too-close objects inside and past the reciprocal table; a tie; "
      "two empty frames";
  return p;
}

// ---- random: seeded tables over the whole range ----

constexpr std::uint32_t kRandomSeed = 20240531;
constexpr int kRandomFrames = 64;

WarningPreset random_preset() {
  WarningPreset p;
  p.setup = fixtures::karlsruhe_setup();  // d_limit 127 px: codes from 2032 up, some past the table
  p.width = 1344;
  p.height = 391;
  std::mt19937 rng(kRandomSeed);
  for (int i = 0; i < kRandomFrames; ++i) {
    WarningFrame f;
    f.name = "random " + std::to_string(i);
    // 0 .. 24 objects, so that empty and one-object frames occur too.
    f.objects =
        fixtures::random_table(rng, p.setup, static_cast<int>(rng() % 25), p.width, p.height);
    // The labelling stage's capacity flags, now and then (they only pass through).
    f.flags.tile_overflow = rng() % 10 == 0;
    f.flags.object_overflow = rng() % 10 == 0;
    p.frames.push_back(std::move(f));
  }
  p.description =
      "scw warning stage: 64 random object tables of 0..24 objects (seed " +
      std::to_string(kRandomSeed) +
      ", 1344x391 image, f 700 px, b 0.54 m, principal point 672,195.5, d_limit 127 px) back to "
      "back: boxes 2..40 m ahead, 6 m either side, 0.1..2.5 m in size, 1 in 10 unmeasurable, 1 "
      "in 10 too close (some past the 128 px table), 1 in 10 an exact copy of an earlier one, the "
      "others each with 1..12 random disparities up to its d_max (area, sum_d, sum_dd); "
      "tile_overflow and object_overflow each set on about 1 frame in 10";
  return p;
}

// ---- malformed: every way the table can break the packet rules, each followed by a good frame

WarningPreset malformed() {
  WarningPreset p;
  p.setup = fixtures::thesis_setup();
  const WarningSetup& s = p.setup;
  const double lane = s.vehicle_origin.x();
  // All beyond 9.4 m (d below the 64 px limit), so the results vary in severity and distance.
  const Object a = fixtures::place_box(s, lane, 25.0, 1.6, 1.4);        // in the tunnel: low
  const Object b = fixtures::place_box(s, lane + 3.0, 12.0, 1.0, 1.6);  // beside it
  const Object c = fixtures::place_box(s, lane - 0.5, 10.0, 0.8, 1.2);  // in the tunnel: high
  auto frame = [](std::string name, std::vector<Object> t, Shape shape) {
    WarningFrame f;
    f.name = std::move(name);
    f.objects = std::move(t);
    f.shape = shape;
    return f;
  };
  auto flagged = [&](std::string name, bool tile, bool obj, bool err) {
    WarningFrame f = frame(std::move(name), {a, c}, Shape::kGood);
    f.flags.tile_overflow = tile;
    f.flags.object_overflow = obj;
    f.flags.stream_error = err;
    return f;
  };
  p.frames = {
      frame("good", {a, b}, Shape::kGood),
      frame("status word without last", {a, c}, Shape::kStatusNoLast),
      frame("good after it", {b, c}, Shape::kGood),
      frame("last on the final object, no status word", {c, a, b}, Shape::kLastNoStatus),
      frame("good after it", {a}, Shape::kGood),
      frame("last on the only object, no status word", {b}, Shape::kLastNoStatus),
      frame("good after it", {c, b}, Shape::kGood),
      frame("status counts one object fewer than sent", {a, b, c}, Shape::kWrongCount),
      frame("good after it", {b}, Shape::kGood),
      flagged("labelling's tile_overflow", true, false, false),
      frame("good after it", {a, b}, Shape::kGood),
      flagged("labelling's object_overflow", false, true, false),
      frame("good after it", {c}, Shape::kGood),
      flagged("labelling's stream_error", false, false, true),
      frame("good after it", {b, a}, Shape::kGood),
      flagged("all three labelling flags", true, true, true),
      frame("empty, good after it", {}, Shape::kGood),
  };
  p.description =
      "scw warning stage: 17 object tables back to back (1280x480 image, f 1000 px, b 0.6 m, "
      "principal point 640,240, d_limit 64 px), each broken one followed by a good one: a status "
      "word without last, last on the final object without a status word (twice, once a "
      "one-object table), a status word counting one object fewer, and labelling's "
      "tile_overflow, object_overflow, stream_error and all three set";
  return p;
}

// ---- running and checking ----

std::vector<LabelPacket> frame_words(const WarningFrame& f) {
  std::vector<LabelPacket> w;
  for (const Object& o : f.objects) {
    LabelPacket p;
    p.data.object = o;
    w.push_back(p);
  }
  if (f.shape == Shape::kLastNoStatus) {
    if (w.empty()) throw std::logic_error("vectors warning: 'last without status' needs objects");
    w.back().last = true;
    return w;
  }
  LabelPacket st;
  st.data.is_status = true;
  st.data.status = f.flags;
  st.data.status.objects =
      static_cast<std::uint32_t>(f.objects.size()) - (f.shape == Shape::kWrongCount ? 1u : 0u);
  st.last = f.shape != Shape::kStatusNoLast;
  w.push_back(st);
  return w;
}

/// What the stage must report for a frame: a plain fold of evaluate() over its objects, and the
/// flags as docs/warning.md states them (not the kernel's code).
template <typename Params>
FrameResult expected_result(const WarningFrame& f, const WarningConfig& cfg) {
  FrameResult r = fixtures::fold_table<Params>(f.objects, cfg);
  if (f.shape == Shape::kLastNoStatus) {
    r.stream_error = true;
    return r;
  }
  r.tile_overflow = f.flags.tile_overflow;
  r.object_overflow = f.flags.object_overflow;
  r.stream_error = f.flags.stream_error || f.shape != Shape::kGood;
  return r;
}

template <typename Params>
void check_frame(const WarningFrame& f, const FrameResult& got, const WarningConfig& cfg) {
  const std::string at = "vectors warning: frame '" + f.name + "': ";
  if (got != expected_result<Params>(f, cfg))
    throw std::logic_error(at + "the model's result differs from a plain fold of evaluate()");
  if (!f.check_severity) return;
  const int index = got.index == 0xffff ? -1 : got.index;
  if (got.severity != f.severity || got.in_tunnel != f.in_tunnel || got.too_close != f.too_close ||
      index != f.index)
    throw std::runtime_error(at + "the model gives " + severity_name(got.severity) +
                             (got.in_tunnel ? " in" : " outside") + " the tunnel, too_close " +
                             std::to_string(got.too_close) + ", index " + std::to_string(index) +
                             "; the preset was placed for " + severity_name(f.severity) +
                             (f.in_tunnel ? " in" : " outside") + " the tunnel, too_close " +
                             std::to_string(f.too_close) + ", index " + std::to_string(f.index));
}

/// Every word back to back through one stage, no stalls, from reset; one result per frame.
template <typename Params>
std::vector<ResultPacket> run_model(const WarningConfig& cfg, const std::vector<LabelPacket>& in,
                                    std::size_t frames, std::int64_t& cycles) {
  sim::WarningModel<Params> model(cfg);
  std::vector<ResultPacket> out;
  std::size_t next = 0;
  const std::int64_t limit = static_cast<std::int64_t>(in.size()) + 4 * hls::warning::kLatency + 16;
  for (cycles = 0; out.size() < frames || next < in.size(); ++cycles) {
    if (cycles > limit) throw std::logic_error("vectors warning: the model did not finish");
    const bool valid = next < in.size();
    const auto o = model.eval(valid, valid ? in[next] : LabelPacket{}, true);
    if (o.out_valid) {
      if (!o.out.last) throw std::logic_error("vectors warning: a result without `last`");
      out.push_back(o.out);
    }
    model.tick();
    if (valid && o.in_ready) ++next;
  }
  // Nothing more may come out: one result per frame.
  for (int t = 0; t < 2 * hls::warning::kLatency; ++t) {
    if (model.eval(false, LabelPacket{}, true).out_valid)
      throw std::logic_error("vectors warning: more results than frames");
    model.tick();
  }
  return out;
}

nlohmann::json out_layout() {
  nlohmann::json l = stream_beat_layout(OutLayout::kPayloadBits);
  l["result_fields"] = field_layout(sim::warning_word::kResultFields);
  l["severity_codes"] = {{"none", 0}, {"low", 1}, {"medium", 2}, {"high", 3}};
  return l;
}

std::string b01(bool v) { return v ? "1" : "0"; }

/// Every frame's words back to back; `closing` gets each frame's closing word, a line of in.hex.
std::vector<LabelPacket> stream_words(const WarningPreset& p, std::vector<std::size_t>& closing) {
  std::vector<LabelPacket> in;
  for (const WarningFrame& f : p.frames) {
    const auto w = frame_words(f);
    in.insert(in.end(), w.begin(), w.end());
    closing.push_back(in.size() - 1);
  }
  return in;
}

/// The model's results, each checked, and the same again under stalls.
template <typename Params>
std::vector<ResultPacket> checked_results(const WarningPreset& p, const WarningConfig& cfg,
                                          const std::vector<LabelPacket>& in,
                                          std::int64_t& cycles) {
  const auto out = run_model<Params>(cfg, in, p.frames.size(), cycles);
  if (out.size() != p.frames.size())
    throw std::logic_error("vectors warning: the model closed another number of frames");
  for (std::size_t i = 0; i < out.size(); ++i) check_frame<Params>(p.frames[i], out[i].data, cfg);
  // A replay stalls both sides; the results it must see cannot depend on that.
  sim::WarningModel<Params> m(cfg);
  const auto r = sim::run_stream(m, in, sim::StallPattern{sim::StallKind::kBoth, 0}, out.size(),
                                 4 * static_cast<std::int64_t>(in.size()) + 100'000);
  if (r.timed_out || !r.violations.empty() || r.out != out)
    throw std::logic_error("vectors warning: the model's results change under stalls");
  return out;
}

nlohmann::json setup_json(const WarningSetup& s) {
  const bool spread = s.distance_rule == hls::warning::DistanceRule::kSpread;
  return {{"focal_px", s.focal_px},
          {"baseline_m", s.baseline_m},
          {"cu_px", s.cu_px},
          {"cv_px", s.cv_px},
          {"vehicle_x_m", s.vehicle_origin.x()},
          {"vehicle_y_m", s.vehicle_origin.y()},
          {"vehicle_z_m", s.vehicle_origin.z()},
          {"car_width_m", s.car_width_m},
          {"car_height_m", s.car_height_m},
          {"tunnel_scale", s.tunnel_scale},
          {"high_m", s.high_m},
          {"medium_m", s.medium_m},
          {"near_m", s.near_m},
          {"min_height_m", s.min_height_m},
          {"d_limit_px", s.d_limit_px},
          {"distance_rule", spread ? "spread" : "closest"},
          {"spread_k", s.spread_k}};
}

using Rows = std::vector<std::vector<std::string>>;

/// One in_words.csv row: the fields the stage reads of a word (0 for the other shape's).
std::vector<std::string> word_row(std::size_t frame, std::size_t line, const LabelPacket& w) {
  const auto& d = w.data;
  const Object& ob = d.object;
  const bool st = d.is_status;
  auto v = [&](unsigned x) { return st ? std::string("0") : std::to_string(x); };
  return {std::to_string(frame),
          std::to_string(line),
          b01(w.last),
          b01(st),
          v(ob.x_min),
          v(ob.x_max),
          v(ob.y_min),
          v(ob.y_max),
          v(ob.d_max),
          v(ob.closest_x),
          v(ob.closest_y),
          v(ob.area),
          st ? std::string("0") : std::to_string(ob.sum_d),
          st ? std::string("0") : std::to_string(ob.sum_dd),
          st ? std::to_string(d.status.objects) : "0",
          b01(st && d.status.tile_overflow),
          b01(st && d.status.object_overflow),
          b01(st && d.status.stream_error)};
}

/// One expected_objects.csv row: what the stage computes of an object, for debugging a mismatch.
std::vector<std::string> eval_row(std::size_t frame, std::size_t line, std::size_t k,
                                  const ObjectEval& e) {
  return {std::to_string(frame),
          std::to_string(line),
          std::to_string(k),
          std::to_string(e.d_q4),
          b01(e.measurable),
          b01(e.too_close),
          std::to_string(e.x_mm),
          std::to_string(e.y_mm),
          std::to_string(e.z_mm),
          std::to_string(e.width_mm),
          std::to_string(e.height_mm),
          std::to_string(e.distance_mm),
          std::to_string(e.gap_mm),
          b01(e.in_tunnel),
          b01(e.obstacle),
          severity_name(e.severity)};
}

std::string cell(bool v) { return b01(v); }
std::string cell(hls::warning::Severity v) { return severity_name(v); }
template <typename T>
std::string cell(T v) {
  return std::to_string(v);
}

/// One expected.csv row: a frame's result and the input line that closed the frame.
std::vector<std::string> result_row(std::size_t frame, std::size_t closing, const FrameResult& r) {
  std::vector<std::string> row = {std::to_string(frame), std::to_string(closing)};
  sim::words::for_each(sim::warning_word::kResultFields,
                       [&](const auto& f) { row.push_back(cell(r.*f.member)); });
  return row;
}

void write_files(const std::filesystem::path& dir, const WarningPreset& p,
                 const nlohmann::json& config, const WarningConfig& cfg,
                 const std::vector<LabelPacket>& in, const std::vector<ResultPacket>& out,
                 const Rows& word_rows, const Rows& eval_rows, const Rows& result_rows) {
  const auto in_bits = sim::pack_all(in);
  const auto out_bits = sim::pack_all(out);
  VectorWriter vw(dir, "warning", config, p.description);
  // The configuration word the testbench puts on cfg_warning_i (its values in config.cfg).
  add_config_hex<WarningConfig>(vw, "cfg.hex",
                                sim::words::pack_word(cfg, sim::warning_cfg::kConfigFields),
                                sim::warning_cfg::kConfigFields, false);
  vw.add_hex("in.hex", "input", in_bits, labelling_word_layout());
  vw.add_csv("in_words.csv", "input",
             {"frame", "word", "last", "is_status", "x_min", "x_max", "y_min", "y_max", "d_max",
              "closest_x", "closest_y", "area", "sum_d", "sum_dd", "objects", "tile_overflow",
              "object_overflow", "stream_error"},
             word_rows);
  vw.add_hex("expected.hex", "expected", out_bits, out_layout());
  vw.add_csv("expected.csv", "expected",
             sim::words::column_names({"frame", "closing_word"}, sim::warning_word::kResultFields),
             result_rows);
  vw.add_csv(
      "expected_objects.csv", "expected",
      {"frame", "word", "index", "d_q4", "measurable", "too_close", "x_mm", "y_mm", "z_mm",
       "width_mm", "height_mm", "distance_mm", "gap_mm", "in_tunnel", "obstacle", "severity"},
      eval_rows);
  vw.finish();
}

}  // namespace

const std::vector<std::string>& warning_presets() {
  static const std::vector<std::string> kNames = {"thesis", "random", "malformed"};
  return kNames;
}

WarningPreset warning_preset(const std::string& name) {
  if (name == "thesis") return thesis();
  if (name == "random") return random_preset();
  if (name == "malformed") return malformed();
  throw std::invalid_argument("vectors warning: no preset '" + name +
                              "' (there are: thesis, random, malformed)");
}

WarningPreset warning_user_preset(const UserTables& u) {
  WarningPreset p;
  p.setup = u.setup;
  p.build = u.build;
  p.width = u.width;
  p.height = u.height;
  if (p.setup.cu_px == 0.0 && p.setup.cv_px == 0.0) {  // as scw run: the image centre
    p.setup.cu_px = 0.5 * (u.width - 1);
    p.setup.cv_px = 0.5 * (u.height - 1);
  }
  const auto tables = read_object_tables(u.objects, u.status);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    WarningFrame f;
    f.name = "frame " + std::to_string(i);
    f.objects = tables[i].objects;
    f.flags = tables[i].flags;
    p.frames.push_back(std::move(f));
  }
  if (p.frames.empty())
    throw std::runtime_error(u.objects.string() +
                             ": no rows, and no status rows: no frame to send");
  p.description = "scw warning stage: " + std::to_string(p.frames.size()) + " object tables from " +
                  u.objects.filename().string() +
                  (u.status.empty() ? "" : " and " + u.status.filename().string()) +
                  ", objects in a " + std::to_string(u.width) + "x" + std::to_string(u.height) +
                  " image; each frame checked against a plain fold of evaluate()";
  return p;
}

namespace {

template <typename Params>
WarningSetSummary write_set(const WarningPreset& p, const std::filesystem::path& dir) {
  const WarningConfig cfg = host::warning::to_fixed(p.setup);
  hls::warning::check_config<Params>(cfg);
  std::vector<std::size_t> closing;  // each frame's closing word, a line of in.hex
  const std::vector<LabelPacket> in = stream_words(p, closing);
  WarningSetSummary sum;
  const auto out = checked_results<Params>(p, cfg, in, sum.cycles);
  const nlohmann::json config = {{"build", p.build},
                                 {"max_disparity_px", Params::kMaxDisparityPx},
                                 {"table_size", Params::kTableSize},
                                 {"latency", hls::warning::kLatency},
                                 {"cfg", field_values(sim::warning_cfg::kConfigFields, cfg)},
                                 {"setup", setup_json(p.setup)},
                                 {"image_width", p.width},
                                 {"image_height", p.height},
                                 {"frames", p.frames.size()},
                                 {"words_in", in.size()},
                                 {"words_out", out.size()}};
  // in_words.csv: every input word and its line in in.hex; expected_objects.csv: what the stage
  // computes of each object word.
  Rows word_rows, eval_rows, result_rows;
  std::size_t line = 0;
  for (std::size_t fi = 0; fi < p.frames.size(); ++fi) {
    const auto w = frame_words(p.frames[fi]);
    for (std::size_t k = 0; k < w.size(); ++k, ++line) {
      word_rows.push_back(word_row(fi, line, w[k]));
      if (w[k].data.is_status) continue;
      eval_rows.push_back(
          eval_row(fi, line, k, hls::warning::evaluate<Params>(w[k].data.object, cfg)));
    }
    result_rows.push_back(result_row(fi, closing[fi], out[fi].data));
  }
  write_files(dir, p, config, cfg, in, out, word_rows, eval_rows, result_rows);
  sum.frames = p.frames.size();
  sum.words_in = in.size();
  sum.results = out.size();
  sum.objects = eval_rows.size();
  return sum;
}

}  // namespace

const std::vector<std::string>& warning_builds() {
  static const std::vector<std::string> kNames = {"vectors", "small", "tsukuba", "thesis"};
  return kNames;
}

WarningSetSummary write_warning_set(const WarningPreset& p, const std::filesystem::path& dir) {
  if (p.build == "vectors") return write_set<WarningVecParams>(p, dir);
  if (p.build == "small") return write_set<hls::pipeline::SmallPipeline<1>::warning>(p, dir);
  if (p.build == "tsukuba") return write_set<hls::pipeline::TsukubaPipeline<1>::warning>(p, dir);
  if (p.build == "thesis") return write_set<hls::pipeline::ThesisPipeline<1>::warning>(p, dir);
  throw std::invalid_argument("vectors warning: no build '" + p.build +
                              "' (vectors, small, tsukuba, thesis)");
}

}  // namespace scw::vectors
