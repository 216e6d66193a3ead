// SPDX-License-Identifier: Apache-2.0
// The SVM and the network behind Classifier, shared by their training (classifiers.cpp) and
// their model file (model_file.cpp). Not part of classify.hpp: it needs OpenCV's ml module, which
// scw::host links privately.
#pragma once

#include <array>
#include <string>
#include <utility>

#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include "host/app/classifiers.hpp"

namespace scw::app::detail {

/// Each feature's mean and standard deviation over the training rows: the SVM and the network
/// see (x - mean) / std, so no feature dominates by its units (hu3 ~ 0.01, widths ~ 2 m).
struct Scaling {
  std::array<double, kNumFeatures> mean{}, std{};

  /// One CV_32F row of standardised features.
  cv::Mat apply(const Features& f) const;
  /// The "scaling" map of a model file, and reading it back (model_file.cpp).
  void write(cv::FileStorage& fs) const;
  static Scaling read(const cv::FileNode& root, const std::string& path);
};

class SvmClassifier final : public Classifier {
 public:
  SvmClassifier(cv::Ptr<cv::ml::SVM> svm, Scaling scaling)
      : svm_(std::move(svm)), scaling_(scaling) {}

  ObjectClass classify(const Features& f) const override;
  ModelKind kind() const override { return ModelKind::kSvm; }
  std::string describe() const override;
  void save(const std::string& path) const override;

 private:
  cv::Ptr<cv::ml::SVM> svm_;
  Scaling scaling_;
};

class AnnClassifier final : public Classifier {
 public:
  AnnClassifier(cv::Ptr<cv::ml::ANN_MLP> ann, Scaling scaling)
      : ann_(std::move(ann)), scaling_(scaling) {}

  ObjectClass classify(const Features& f) const override;
  ModelKind kind() const override { return ModelKind::kAnn; }
  std::string describe() const override;
  void save(const std::string& path) const override;

 private:
  cv::Ptr<cv::ml::ANN_MLP> ann_;
  Scaling scaling_;
};

}  // namespace scw::app::detail
