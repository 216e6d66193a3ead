// SPDX-License-Identifier: Apache-2.0
// [hls] With SCW_VENDOR_HLS_STREAM and a <hls_stream.h> on the include path (here a stand-in,
// tests/common/vendor_stub), scw::hls::stream is the vendor's ::hls::stream.
#include <catch2/catch.hpp>

#include <type_traits>

#include "hls/common/stream.hpp"

static_assert(std::is_same_v<scw::hls::stream<int, 4>, ::hls::stream<int>>,
              "the vendor flag maps the project's stream to ::hls::stream");

TEST_CASE("the vendor flag maps the stream to ::hls::stream", "[hls][stream]") {
  scw::hls::stream<int, 2> s("s");
  s.write(7);
  CHECK(s.read() == 7);
}
