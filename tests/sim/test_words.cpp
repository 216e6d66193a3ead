// SPDX-License-Identifier: Apache-2.0
// The word field tables (sim/words/fields.hpp): each word packs to the documented bit
// positions and unpacks to the same value, signed fields and enums included.
#include <catch2/catch.hpp>

#include "sim/words/disparity_cfg.hpp"
#include "sim/words/labelling_cfg.hpp"
#include "sim/words/labelling_pack.hpp"
#include "sim/words/pipeline_pack.hpp"
#include "sim/words/road_cfg.hpp"
#include "sim/words/warning_cfg.hpp"
#include "sim/words/warning_pack.hpp"

namespace {
using namespace scw;
using hls::warning::FrameResult;
using hls::warning::Severity;

FrameResult sample_result() {
  FrameResult r;
  r.severity = Severity::kHigh;
  r.too_close = true;
  r.stream_error = true;
  r.objects = 7;
  r.obstacles = 3;
  r.index = 0xffff;
  r.distance_mm = -1234;  // an upper bound below the bumper: negative, two's complement
  r.closest_x = 100;
  r.y_max = 0xbeef;
  return r;
}
}  // namespace

TEST_CASE("the warning result word packs its fields at their places and back", "[sim][words]") {
  using Layout = sim::BeatLayout<hls::warning::ResultPacket>;
  const FrameResult r = sample_result();
  const sim::Bits w = Layout::payload({r, true});
  CHECK(w.get(0, 2) == 3);                                    // severity high
  CHECK(w.get(2, 1) == 0);                                    // in_tunnel
  CHECK(w.get(3, 1) == 1);                                    // too_close
  CHECK(w.get(6, 1) == 1);                                    // stream_error
  CHECK(w.get(7, 16) == 7);                                   // objects
  CHECK(w.get(39, 16) == 0xffff);                             // index
  CHECK(w.get(55, 32) == static_cast<std::uint32_t>(-1234));  // distance_mm, 32 bits
  CHECK(w.get(87, 16) == 100);                                // closest_x
  CHECK(w.get(Layout::kPayloadBits - 16, 16) == 0xbeef);      // y_max, the top field
  const auto back = Layout::from_payload(w, true);
  CHECK(back.last);
  CHECK(back.data == r);
  CHECK(back.data.distance_mm == -1234);
}

TEST_CASE("the pipeline result word is the warning word and both input flags", "[sim][words]") {
  using Layout = sim::BeatLayout<hls::pipeline::PipelineResultPacket>;
  hls::pipeline::PipelineResultPacket p;
  p.data.frame = sample_result();
  p.data.input_error_right = true;
  p.last = true;
  const sim::Bits w = Layout::payload(p);
  CHECK(w.get(Layout::kFrameBits, 1) == 0);
  CHECK(w.get(Layout::kFrameBits + 1, 1) == 1);
  const auto back = Layout::from_payload(w, true);
  CHECK(back.data.frame == p.data.frame);
  CHECK_FALSE(back.data.input_error_left);
  CHECK(back.data.input_error_right);
}

TEST_CASE("the labelling word packs objects and status words through their tables",
          "[sim][words]") {
  using Layout = sim::BeatLayout<hls::Packet<hls::labelling::LabelWord>>;
  hls::Packet<hls::labelling::LabelWord> o;
  o.data.object.area = 4321;
  o.data.object.x_min = 12;
  o.data.object.sum_dd = 0x0123456789abcdefull;
  const sim::Bits wo = Layout::payload(o);
  CHECK(wo.get(0, 1) == 0);
  CHECK(wo.get(1, pkg::AreaBits) == 4321);
  CHECK(wo.get(1 + pkg::AreaBits, pkg::CoordBits) == 12);
  CHECK(wo.get(Layout::kPayloadBits - pkg::SumBits, pkg::SumBits) == 0x0123456789abcdefull);
  const auto ob = Layout::from_payload(wo, false);
  CHECK_FALSE(ob.data.is_status);
  CHECK(ob.data.object.area == 4321);
  CHECK(ob.data.object.sum_dd == 0x0123456789abcdefull);

  hls::Packet<hls::labelling::LabelWord> s;
  s.data.is_status = true;
  s.data.status.objects = 9;
  s.data.status.object_overflow = true;
  s.last = true;
  const sim::Bits ws = Layout::payload(s);
  CHECK(ws.get(0, 1) == 1);
  CHECK(ws.get(1, pkg::AreaBits) == 9);
  CHECK(ws.get(1 + pkg::AreaBits, 3) == 0b010);  // tile_overflow, object_overflow, stream_error
  const auto sb = Layout::from_payload(ws, true);
  CHECK(sb.data.is_status);
  CHECK(sb.data.status.objects == 9);
  CHECK(sb.data.status.object_overflow);
  CHECK_FALSE(sb.data.status.tile_overflow);
}

TEST_CASE("the warning and road configuration words pack their fields at their places and back",
          "[sim][words]") {
  using sim::words::pack_word;
  using sim::words::unpack_word;
  hls::warning::WarningConfig w;
  w.baseline_q8 = 0xfffff;  // the 20-bit field full
  w.focal_q4 = 11200;
  w.veh_x_mm = -300;  // two's complement, sign-extended back
  w.veh_z_mm = 1650;
  w.d_limit_q4 = 1024;
  w.rule = hls::warning::DistanceRule::kSpread;
  w.spread_q4 = 0xff;
  const sim::Bits ww = pack_word(w, sim::warning_cfg::kConfigFields);
  CHECK(ww.width() == 237);
  CHECK(ww.get(0, 20) == 0xfffff);
  CHECK(ww.get(20, 16) == 11200);
  CHECK(ww.get(68, 16) == 0xfed4);  // -300
  CHECK(ww.get(100, 16) == 1650);
  CHECK(ww.get(212, 16) == 1024);
  CHECK(ww.get(228, 1) == 1);
  CHECK(ww.get(229, 8) == 0xff);  // spread_q4, the top field
  const auto wb = unpack_word<hls::warning::WarningConfig>(ww, sim::warning_cfg::kConfigFields);
  CHECK(wb.veh_x_mm == -300);
  CHECK(wb.rule == hls::warning::DistanceRule::kSpread);
  CHECK(pack_word(wb, sim::warning_cfg::kConfigFields) == ww);

  hls::road::RoadConfig r;
  r.enable = true;
  r.nominal = {0x3ffff, -613417};  // the largest slope: 18 bits, read back as a code, not signed
  r.a_min = 0x20000;               // bit 17 set: a code, not a negative number
  r.h_max = 1023;
  r.min_count = 0xfffff;
  const sim::Bits rw = pack_word(r, sim::road_cfg::kConfigFields);
  CHECK(rw.width() == 173);
  CHECK(rw.get(0, 1) == 1);
  CHECK(rw.get(1, 18) == 0x3ffff);
  CHECK(rw.get(19, 32) == static_cast<std::uint32_t>(-613417));
  CHECK(rw.get(51, 18) == 0x20000);
  CHECK(rw.get(97, 10) == 1023);
  CHECK(rw.get(153, 20) == 0xfffff);  // min_count, the top field
  const auto rb = unpack_word<hls::road::RoadConfig>(rw, sim::road_cfg::kConfigFields);
  CHECK(rb == r);
  CHECK(rb.a_min == 0x20000);

  hls::disparity::DisparityConfig d;
  d.dmin = 2047;
  d.num_disp = 0;    // all of a 45-candidate build: 45 on the port
  d.sad_limit = -1;  // off: 0 on the port
  d.texture_threshold = 0x7fffffff;
  d.uniqueness_ratio = 15;
  d.opencv_invalid = true;
  d.edge_candidates = 99;  // above the candidates: all of them
  const sim::Bits dw =
      pack_word(sim::disparity_cfg::port_config<45>(d), sim::disparity_cfg::kConfigFields);
  CHECK(dw.width() == 109);
  CHECK(dw.get(0, 12) == 2047);
  CHECK(dw.get(12, 8) == 45);
  CHECK(dw.get(27, 32) == 0);
  CHECK(dw.get(59, 32) == 0x7fffffff);
  CHECK(dw.get(91, 8) == 15);
  CHECK(dw.get(100, 1) == 1);   // opencv_invalid
  CHECK(dw.get(101, 8) == 45);  // edge_candidates, the top field

  hls::labelling::LabellingConfig l;
  l.tile_w = 70000;  // wider than 16 bits: saturates (such a tile never closes in a frame)
  l.tile_h = 13;
  l.floor = -16;  // an invalid code below 0: two's complement
  l.min_area = 123456;
  const sim::Bits lw =
      pack_word(sim::labelling_cfg::port_config(l), sim::labelling_cfg::kConfigFields);
  CHECK(lw.width() == 80);
  CHECK(lw.get(0, 16) == 0xffff);
  CHECK(lw.get(16, 16) == 13);
  CHECK(lw.get(32, 16) == 0xfff0);
  CHECK(lw.get(48, 32) == 123456);  // min_area, the top field
  CHECK(unpack_word<hls::labelling::LabellingConfig>(lw, sim::labelling_cfg::kConfigFields).floor ==
        -16);
}
