// SPDX-License-Identifier: Apache-2.0
// write_line_buffer_set() (host/vectors/line_buffer_set.hpp).
#include "host/vectors/line_buffer_set.hpp"

#include "host/vectors/vector_set.hpp"

namespace scw::vectors {

void write_line_buffer_set(const std::filesystem::path& dir, const LineBufferSetConfig& c,
                           const cv::Mat& grey, const std::vector<sim::Bits>& input,
                           const std::vector<sim::Bits>& expected) {
  VectorWriter vw(dir, "line_buffer",
                  {{"ppc", c.ppc},
                   {"max_width_px", c.max_width_px},
                   {"rows", c.rows},
                   {"width", grey.cols},
                   {"height", grey.rows},
                   {"latency", c.latency}},
                  "scw_line_buffer: each beat with the same columns of the 2 rows above");
  vw.add_image("input.png", "input", grey);
  vw.add_hex("input.hex", "input", input, pixel_beat_layout(c.ppc, 8));
  vw.add_hex("expected.hex", "expected", expected, pixel_beat_layout(c.ppc * c.rows, 8));
  vw.finish();
}

}  // namespace scw::vectors
