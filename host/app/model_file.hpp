// SPDX-License-Identifier: Apache-2.0
// A classifier's model file: what Classifier::save writes and load_classifier reads back, one
// cv::FileStorage holding scw's node and, for the SVM and the network, OpenCV's (docs/classify.md).
#pragma once

#include <memory>
#include <string>

#include "host/app/classifiers.hpp"

namespace scw::app {

/// Reads a model written by Classifier::save, whatever its kind. std::runtime_error naming the
/// path when it cannot be read, is not a scw classifier, or is of an unknown kind or version.
std::unique_ptr<Classifier> load_classifier(const std::string& path);

}  // namespace scw::app
