// SPDX-License-Identifier: Apache-2.0
// Opening a user's cv::FileStorage file (YAML, XML or JSON: a calibration, a classifier model)
// so that a malformed one is refused with a message, never a hang.
#pragma once

#include <string>

#include <opencv2/core/persistence.hpp>

namespace scw::host::io {

/// The time OpenCV's reader is given: 5 s, or the environment's SCW_READER_SECONDS (a number > 0;
/// a large model file on a slow disk may need more; the fuzz targets' replays take 1 s, since a
/// file that loops costs its whole limit). Throws std::runtime_error naming the variable when it
/// is set to anything else.
double reader_seconds();

/// Opens `path` for reading. Throws std::runtime_error starting with `what` (e.g. "calibration
/// 'x.yml'") when the file holds a NUL byte (no text format does), when OpenCV refuses it, or
/// when OpenCV's reader does not finish within `seconds`: OpenCV 4.6's YAML reader loops forever
/// on some malformed files (found by fuzzing: "%YAML:1.\n   -u\n:\n"), so the file is first
/// parsed in a child process that is killed if it takes longer. Returns an unopened FileStorage
/// when OpenCV opens nothing without throwing, as cv::FileStorage::open does.
cv::FileStorage open_file_storage(const std::string& path, const std::string& what,
                                  double seconds = reader_seconds());

}  // namespace scw::host::io
