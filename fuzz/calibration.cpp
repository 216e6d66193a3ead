// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the stereo calibration reader (load_stereo_calibration, cv::FileStorage YAML, XML
// or JSON) that `scw rectify` and `scw run --calib` take from users.
#include "fuzz/fuzz_target.hpp"
#include "host/rectify/calibration.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // cv::FileStorage picks the format from the text; the suffix only has to be one it reads.
  const auto path = scw::fuzz::write_scratch("calibration.yml", data, size);
  scw::fuzz::expect_clear_error([&] {
    scw::rectify::load_stereo_calibration(path.string(), cv::Size(64, 48));
  });
  return 0;
}
