// SPDX-License-Identifier: Apache-2.0
// open_file_storage() (host/io/file_storage.hpp).
#include "host/io/file_storage.hpp"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace scw::host::io {
namespace {

/// Whether OpenCV's reader finishes on `path` within `seconds`, tried in a child process so a
/// reader that loops can be killed. Its verdict on the file is left to the caller's own open.
bool parses_in_time(const std::string& path, double seconds) {
  const pid_t child = fork();
  if (child < 0) return true;  // no process to spare: open it directly, as before
  if (child == 0) {
    try {
      cv::FileStorage fs(path, cv::FileStorage::READ);
    } catch (...) {
    }
    _exit(0);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    int status = 0;
    if (waitpid(child, &status, WNOHANG) == child) return true;
    if (std::chrono::steady_clock::now() > deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  return false;
}

}  // namespace

double reader_seconds() {
  const char* text = std::getenv("SCW_READER_SECONDS");
  if (text == nullptr) return 5.0;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(seconds > 0.0) || seconds > 3600.0)
    throw std::runtime_error(std::string("SCW_READER_SECONDS='") + text +
                             "' is not a number of seconds in (0, 3600]: set it to e.g. 5, or "
                             "unset it");
  return seconds;
}

cv::FileStorage open_file_storage(const std::string& path, const std::string& what,
                                  double seconds) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(what + ": cannot open it");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw std::runtime_error(what + ": byte " + std::to_string(nul) +
                             " is NUL, which no text file holds: not a YAML, XML or JSON file");
  if (!parses_in_time(path, seconds)) {
    std::ostringstream message;  // 5 s as "5", half a second as "0.5"
    message << what << ": OpenCV's reader did not finish it within " << seconds
            << " s: the file is malformed (YAML, XML or JSON as cv::FileStorage writes it)";
    throw std::runtime_error(message.str());
  }
  cv::FileStorage fs;
  fs.open(path, cv::FileStorage::READ);
  return fs;
}

}  // namespace scw::host::io
