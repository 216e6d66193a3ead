// SPDX-License-Identifier: Apache-2.0
// [hls] scw::hls::stream: a bounded FIFO in a fixed ring that names itself when a read or write
// would block for ever; the array views and the look-ahead register the frame functions use.
#include <catch2/catch.hpp>

#include <string>
#include <type_traits>

#include "hls/common/stream.hpp"

namespace hls = scw::hls;

TEST_CASE("a stream is a bounded FIFO in order, wrapping its ring", "[hls][stream]") {
  hls::stream<int, 3> s("s");
  CHECK(s.empty());
  for (int round = 0; round < 4; ++round) {  // head and tail pass the end of the ring
    s.write(10 * round);
    s.write(10 * round + 1);
    CHECK(s.size() == 2);
    CHECK(s.read() == 10 * round);
    s.write(10 * round + 2);
    s.write(10 * round + 3);
    CHECK(s.full());
    CHECK(s.read() == 10 * round + 1);
    CHECK(s.read() == 10 * round + 2);
    CHECK(s.read() == 10 * round + 3);
    CHECK(s.empty());
  }
}

TEST_CASE("a stream that would block names itself", "[hls][stream]") {
  hls::stream<int, 2> s("disparity_out");
  CHECK_THROWS_WITH(s.read(), Catch::Contains("'disparity_out': read while empty"));
  s.write(1);
  s.write(2);
  CHECK_THROWS_WITH(s.write(3), Catch::Contains("'disparity_out': write while full (depth 2)"));
  CHECK(s.read() == 1);
}

TEST_CASE("array views and the look-ahead offer every beat once, in order", "[hls][stream]") {
  const int in[] = {4, 5, 6};
  int out[3] = {};
  hls::ArrayIn<int> a(in, 3);
  hls::ArrayOut<int> b(out);
  hls::Lookahead<int> ahead;
  for (int clock = 0; clock < 6; ++clock) {
    ahead.fill(a);
    if (ahead.valid && clock % 2 == 0) {  // a stage that takes every other clock
      b.write(ahead.beat);
      ahead.take();
    }
  }
  CHECK(b.written() == 3);
  CHECK(out[0] == 4);
  CHECK(out[2] == 6);
  CHECK(a.empty());
  CHECK(hls::ArrayIn<int>(nullptr, 5).empty());  // an absent input is an empty one
}
