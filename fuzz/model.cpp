// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the classifier model file `scw run --classifier` loads (load_classifier: scw's
// parallelepiped JSON, or OpenCV's SVM and network files in YAML or XML).
#include "fuzz/fuzz_target.hpp"
#include "host/app/model_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The suffix a user's file would have for the text it holds (cv::FileStorage reads by text).
  const char first = size > 0 ? static_cast<char>(data[0]) : ' ';
  const char* name = first == '{' ? "model.json" : first == '<' ? "model.xml" : "model.yml";
  const auto path = scw::fuzz::write_scratch(name, data, size);
  scw::fuzz::expect_clear_error([&] { scw::app::load_classifier(path.string()); });
  return 0;
}
