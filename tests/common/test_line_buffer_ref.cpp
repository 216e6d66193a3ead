// SPDX-License-Identifier: Apache-2.0
// hls::LineBuffer against the whole-image reference, for P = 1, 2, 4 and several row counts.
#include <catch2/catch.hpp>

#include "host/reference/line_buffer_ref.hpp"
#include "tests/common/primitive_configs.hpp"

namespace {

template <int P, int W, int Rows>
void check_kernel() {
  scw::hls::LineBuffer<std::uint8_t, scw::hls::LineBufferParams<P, W, Rows>> lb;
  // Frames of different heights and widths back to back, through one kernel instance.
  const int sizes[][2] = {{W, 9}, {W / 2, 3}, {W, 1}, {W, 6}};
  std::uint64_t seed = 100;
  for (const auto& wh : sizes) {
    const auto img = scw::test::random_image(wh[0], wh[1], seed++);
    const auto in = scw::sim::frame_beats<P>(img.data(), wh[0], wh[1]);
    const auto ref = scw::reference::line_buffer_reference<P, Rows>(img.data(), wh[0], wh[1]);
    for (std::size_t i = 0; i < in.size(); ++i) REQUIRE(lb.step(in[i]) == ref[i]);
  }
  CHECK_FALSE(lb.error());
}

}  // namespace

TEST_CASE("hls::LineBuffer equals the whole-image reference", "[hls][line_buffer]") {
  check_kernel<1, 8, 2>();
  check_kernel<1, 40, 5>();
  check_kernel<2, 32, 3>();
  check_kernel<4, 64, 4>();
}

TEST_CASE("hls::LineBuffer flags a row longer than its RAM", "[hls][line_buffer][malformed]") {
  scw::hls::LineBuffer<std::uint8_t, scw::hls::LineBufferParams<1, 8, 2>> lb;
  const auto img = scw::test::random_image(10, 2, 1);
  for (const auto& b : scw::sim::frame_beats<1>(img.data(), 10, 2)) lb.step(b);
  CHECK(lb.error());
}
