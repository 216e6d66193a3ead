// SPDX-License-Identifier: Apache-2.0
// What every fuzz target shares: a scratch folder for parsers that take a path, and the oracle.
// A parser given a bad file must refuse it with a message for the user: scw's parsers throw
// std::runtime_error or std::invalid_argument naming the file and what is wrong, and the CLI prints
// it. Anything else is a finding: a crash or sanitizer report (libFuzzer stops on those itself), or
// an exception of another type (cv::Exception, nlohmann::json's, std::out_of_range from a string
// index...), whose message speaks of the library, not of the file. Those abort, so libFuzzer keeps
// the input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeinfo>
#include <unistd.h>

namespace scw::fuzz {

/// This process's scratch folder (made once; one process runs one input at a time).
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("scw_fuzz_" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

/// The input written to scratch()/name, returned.
inline std::filesystem::path write_scratch(const std::string& name, const std::uint8_t* data,
                                           std::size_t size) {
  const auto path = scratch() / name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data),
                                              static_cast<std::streamsize>(size));
  return path;
}

/// Runs `parse`; returns whether it accepted the input. A refusal must be one of scw's own
/// errors; any other exception aborts with its type and message.
template <typename Parse>
bool expect_clear_error(Parse parse) {
  try {
    parse();
    return true;
  } catch (const std::runtime_error&) {
    return false;
  } catch (const std::invalid_argument&) {
    return false;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not a clear error: %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
}

}  // namespace scw::fuzz
