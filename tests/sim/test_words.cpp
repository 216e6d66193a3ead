// SPDX-License-Identifier: Apache-2.0
// The word field tables (sim/words/fields.hpp): each word packs to the documented bit
// positions and unpacks to the same value, signed fields and enums included.
#include <catch2/catch.hpp>

#include "sim/words/labelling_pack.hpp"
#include "sim/words/pipeline_pack.hpp"
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
