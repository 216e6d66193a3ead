// SPDX-License-Identifier: Apache-2.0
// The application layer's three object classifiers (thesis 5.3.3, Table 5.6): eq. 5.1's
// parallelepiped, a support vector machine and a neural network, and their training.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "host/app/object_features.hpp"

namespace scw::app {

/// The kinds of classifier: eq. 5.1's parallelepiped (the thesis's "minimum distance
/// classifier"), a support vector machine and a neural network (Table 5.6's three rows).
enum class ModelKind { kParallelepiped, kSvm, kAnn };
/// "parallelepiped", "svm" or "ann": the names used by the CLI and in model files.
const char* to_string(ModelKind k);
/// The inverse of to_string; std::invalid_argument naming the accepted names otherwise.
ModelKind model_kind_from_string(const std::string& s);

/// A trained classifier of Features into ObjectClass.
class Classifier {
 public:
  virtual ~Classifier() = default;
  /// The class of one object.
  virtual ObjectClass classify(const Features& f) const = 0;
  virtual ModelKind kind() const = 0;
  /// One line on what this is, such as "svm (C_SVC, RBF, C = 10, gamma = 0.5, 207 support
  /// vectors)"; the same after load_classifier.
  virtual std::string describe() const = 0;
  /// Writes the model to one cv::FileStorage file (XML for .xml, JSON for .json, YAML for
  /// anything else) that load_classifier reads back; docs/classify.md describes it.
  /// std::runtime_error naming the path when it cannot be written.
  virtual void save(const std::string& path) const = 0;
};

/// Eq. 5.1's parallelepiped classifier. A sample belongs to a class when each of its five
/// features lies in the class's interval m +- s * sigma (inclusive). Inside both classes'
/// boxes, the class whose mean is nearer in the per-sigma Euclidean distance wins (the
/// "minimum distance" part; at equal distance, pedestrian); inside none, other.
class ParallelepipedClassifier final : public Classifier {
 public:
  /// s = 2 is Table 5.5's chosen compromise (Test 3); the stats default to Table 5.4.
  /// std::invalid_argument unless s > 0 and every sigma > 0, all finite.
  explicit ParallelepipedClassifier(double s = 2.0,
                                    const ClassStats& pedestrian = kTable54Pedestrian,
                                    const ClassStats& bike = kTable54Bike);

  ObjectClass classify(const Features& f) const override;
  ModelKind kind() const override { return ModelKind::kParallelepiped; }
  std::string describe() const override;
  void save(const std::string& path) const override;

  double s() const { return s_; }
  /// The stats of kPedestrian or kBike (std::invalid_argument for kOther).
  const ClassStats& stats(ObjectClass c) const;
  /// Whether every feature lies in stats(c)'s m +- s * sigma.
  bool inside(const Features& f, ObjectClass c) const;
  /// sqrt(sum(((x - m) / sigma)^2)) over the five features, for kPedestrian or kBike.
  double distance(const Features& f, ObjectClass c) const;

 private:
  double s_;
  ClassStats pedestrian_, bike_;
};

/// Training options. The defaults are what `scw train` uses; docs/classify.md says why.
struct TrainOptions {
  double s = 2.0;  // parallelepiped: interval half-width in sigmas (Table 5.5)
  // SVM: C_SVC with an RBF kernel (or a linear one) on standardised features. With svm_auto,
  // C and gamma come from cv::ml::SVM::trainAuto's 10-fold grid search instead.
  bool svm_linear = false;
  double svm_c = 10.0;
  double svm_gamma = 0.5;
  bool svm_auto = false;
  // Neural network: 5 - ann_hidden - 3 nodes (Fig. 5.10: 4), symmetric sigmoid, one-hot
  // targets, trained by resilient back-propagation (RPROP) for at most ann_iterations epochs.
  int ann_hidden = 4;
  int ann_iterations = 2000;
  // No seed: OpenCV's SVM (trainAuto's folds) and MLP (Nguyen-Widrow initial weights) draw
  // from their own generators, seeded with a constant, so the same rows train the same model.
  /// Named in error messages about the rows, such as a CSV file's name.
  std::string source = "the training rows";
};

/// The fewest rows of a class train_classifier accepts: of pedestrian and bike for the
/// parallelepiped (other rows are not used), of each class for the SVM and the network.
inline constexpr int kMinRowsPerClass = 10;

/// Trains a classifier of the given kind on rows. The parallelepiped takes each class's mean
/// and standard deviation (n - 1) of pedestrian and bike rows, as the thesis built Table 5.4;
/// the SVM and the network standardise each feature by its mean and standard deviation over
/// all rows, and keep them to standardise what they classify. std::invalid_argument naming
/// options.source when a class has fewer than kMinRowsPerClass rows or a feature does not
/// vary within a class (parallelepiped) or over the rows (SVM, network).
std::unique_ptr<Classifier> train_classifier(ModelKind kind,
                                             const std::vector<LabelledFeatures>& rows,
                                             const TrainOptions& options = {});

}  // namespace scw::app
