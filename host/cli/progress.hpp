// SPDX-License-Identifier: Apache-2.0
// The progress line of the commands that work through many frames (scw run, scw scene).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <string>

namespace scw::cli {

/// One line on stderr that redraws itself on a terminal, one line per step otherwise (logs stay
/// readable): "[#####.....] 3/10 frames  note".
class Progress {
 public:
  explicit Progress(std::size_t total) : total_(total), tty_(isatty(STDERR_FILENO) != 0) {}
  void show(std::size_t done, const std::string& note = {}) {
    const int width = 30;
    const int filled = static_cast<int>(width * done / std::max<std::size_t>(total_, 1));
    std::cerr << (tty_ ? "\r" : "") << "[" << std::string(filled, '#')
              << std::string(width - filled, '.') << "] " << done << "/" << total_ << " frames"
              << (note.empty() ? "" : "  " + note) << (tty_ ? "\033[K" : "\n") << std::flush;
    if (tty_ && done == total_) std::cerr << "\n";
  }

 private:
  std::size_t total_;
  bool tty_;
};

}  // namespace scw::cli
