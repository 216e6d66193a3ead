// SPDX-License-Identifier: Apache-2.0
// sim::Fifo: registered flags, bounds, occupancy and per-frame stamps.
#include <catch2/catch.hpp>

#include "sim/core/channel.hpp"

using scw::hls::Beat;
using scw::hls::Packet;
using scw::sim::Fifo;
using B = Beat<std::uint8_t, 1>;

TEST_CASE("a pushed beat is visible one cycle later, a freed slot too", "[sim][fifo]") {
  Fifo<int> f("f", 2);
  REQUIRE(f.can_push());
  f.push(1);
  CHECK_FALSE(f.can_pop());  // not before the edge
  f.commit(0);
  REQUIRE(f.can_pop());
  f.push(2);
  f.commit(1);
  CHECK(f.size() == 2);
  CHECK_FALSE(f.can_push());  // full: a pop in this cycle does not make room in this cycle
  f.pop();
  CHECK_FALSE(f.can_push());
  f.commit(2);
  CHECK(f.can_push());
  CHECK(f.front() == 2);
  CHECK(f.max_occupancy() == 2);
  CHECK(f.pushes() == 2);
  CHECK(f.pops() == 1);
}

TEST_CASE("misuse of a FIFO is an error naming it, not silent corruption", "[sim][fifo]") {
  Fifo<int> f("left_rect", 1);
  f.push(1);
  CHECK_THROWS_WITH(f.push(2), Catch::Contains("left_rect"));
  f.commit(0);
  CHECK_THROWS_WITH(f.push(3), Catch::Contains("left_rect"));
  Fifo<int> e("empty_one", 1);
  CHECK_THROWS_WITH(e.pop(), Catch::Contains("empty_one"));
  CHECK_THROWS_AS(Fifo<int>("zero", 0), std::invalid_argument);
}

TEST_CASE("frames are stamped at sof for pixel streams and after last for packets",
          "[sim][fifo][timestamps]") {
  Fifo<B> f("pix", 8);
  const bool sofs[] = {true, false, false, true, false};
  for (int c = 0; c < 5; ++c) {
    B b;
    b.sof = sofs[c];
    f.push(b);
    f.commit(10 + c);
    f.pop();
    f.commit(20 + c);
  }
  REQUIRE(f.frames().size() == 2);
  CHECK(f.frames()[0].first_push == 10);
  CHECK(f.frames()[0].last_push == 12);
  CHECK(f.frames()[1].first_push == 13);
  CHECK(f.frames()[1].last_push == 14);
  CHECK(f.frames()[1].first_pop == 23);
  CHECK(f.frames()[1].last_pop == 24);

  Fifo<Packet<int>> p("obj", 8);
  const bool lasts[] = {false, true, true, false, true};
  for (int c = 0; c < 5; ++c) {
    p.push({c, lasts[c]});
    p.commit(c);
  }
  REQUIRE(p.frames().size() == 3);
  CHECK(p.frames()[0].first_push == 0);
  CHECK(p.frames()[0].last_push == 1);
  CHECK(p.frames()[1].first_push == 2);
  CHECK(p.frames()[1].last_push == 2);
  CHECK(p.frames()[2].first_push == 3);
  CHECK(p.frames()[2].last_push == 4);
}
