// SPDX-License-Identifier: Apache-2.0
// Object classification of the application layer (thesis 5.3.3): features, three classifiers.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace scw::app {

/// The five features of one object (thesis 5.3.3): Hu's first three invariants of its
/// silhouette (eq. 2.7) and its 3D width and height in metres (eq. 3.12). This order is the
/// order of every feature vector, CSV column and model file in this module.
struct Features {
  double hu1 = 0, hu2 = 0, hu3 = 0, width_m = 0, height_m = 0;
};

inline constexpr std::size_t kNumFeatures = 5;
/// The features' names, as in the CSV header: hu1, hu2, hu3, width_m, height_m.
extern const std::array<const char*, kNumFeatures> kFeatureNames;

/// The features as an array, in Features' order.
std::array<double, kNumFeatures> to_array(const Features& f);
/// The inverse of to_array.
Features from_array(const std::array<double, kNumFeatures>& a);

/// The thesis's classes. The values index ClassRates tables and are the labels the SVM and the
/// neural network are trained on (the network's output node k is class k), so they are fixed.
enum class ObjectClass { kOther = 0, kPedestrian = 1, kBike = 2 };
inline constexpr std::size_t kNumClasses = 3;
inline constexpr std::array<ObjectClass, kNumClasses> kAllClasses{
    ObjectClass::kOther, ObjectClass::kPedestrian, ObjectClass::kBike};

/// "other", "pedestrian" or "bike".
const char* to_string(ObjectClass c);
/// The inverse of to_string(ObjectClass) (exact, lower case); std::invalid_argument naming the
/// accepted names otherwise.
ObjectClass from_string(const std::string& s);

/// One row of a training or test set.
struct LabelledFeatures {
  ObjectClass cls = ObjectClass::kOther;
  Features f;
};

/// Per-feature mean and standard deviation of one class.
struct ClassStats {
  Features mean, sigma;
};

/// Table 5.4: 146 frames of pedestrians. (The table lists height before width.)
inline constexpr ClassStats kTable54Pedestrian{{0.326, 0.065, 0.002, 0.73, 1.80},
                                               {0.045, 0.030, 0.002, 0.07, 0.10}};
/// Table 5.4: 233 frames of persons on bikes.
inline constexpr ClassStats kTable54Bike{{0.276, 0.003, 0.016, 2.03, 1.82},
                                         {0.066, 0.006, 0.017, 0.15, 0.06}};

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

/// Reads a model written by Classifier::save, whatever its kind. std::runtime_error naming the
/// path when it cannot be read, is not a scw classifier, or is of an unknown kind or version.
std::unique_ptr<Classifier> load_classifier(const std::string& path);

/// Reads feature rows from CSV: the header `class,hu1,hu2,hu3,width_m,height_m`, then one row
/// per object (class name as to_string(ObjectClass), five non-negative finite numbers). Blank
/// lines are skipped; spaces around fields and CRLF line ends are allowed. std::runtime_error
/// naming the file, the line and the column for a malformed header or row, an unknown class,
/// or a file without rows.
std::vector<LabelledFeatures> read_feature_csv(const std::string& path);
/// Writes rows in read_feature_csv's format, every value with 17 significant digits so it
/// reads back bit for bit. std::runtime_error naming the path when it cannot be written.
void write_feature_csv(const std::string& path, const std::vector<LabelledFeatures>& rows);

/// Synthetic stand-ins for the thesis's samples, which are not public: per_class rows of each
/// class, pedestrians first, then bikes, then other. Pedestrian and bike features follow
/// Table 5.4's means and standard deviations, each drawn from the gamma distribution with that
/// mean and deviation (features are never negative; for hu1 and the sizes it is close to the
/// normal). "Other" rows (trees, bushes, poles, signs) are half broad clutter over and around
/// both classes and half look-alikes: a class's gamma with twice its deviation. The same seed
/// gives the same rows with any standard library (own samplers on std::mt19937, whose sequence
/// the standard fixes). docs/classify.md gives the details and what classifiers score on them.
std::vector<LabelledFeatures> synthesize_table54(int per_class, unsigned seed);

/// Table 5.5 / 5.6's rates of one class over a set of rows.
struct ClassRates {
  int rows = 0;     // rows of this class
  int correct = 0;  // classified as this class
  /// Pedestrian and bike: classified as the other of the two (a pedestrian taken for a bike).
  /// Other: classified as pedestrian or bike (a tree taken for a person). The rest of a
  /// pedestrian's or bike's rows (rows - correct - false_match) were classified as other.
  int false_match = 0;
  double correct_pct() const { return rows ? 100.0 * correct / rows : 0.0; }
  double false_pct() const { return rows ? 100.0 * false_match / rows : 0.0; }
};

/// A classifier's results on a set of rows.
struct Evaluation {
  std::array<ClassRates, kNumClasses> by_class;  // indexed by ObjectClass
  /// confusion[true class][predicted class], indexed by ObjectClass.
  std::array<std::array<int, kNumClasses>, kNumClasses> confusion{};
  const ClassRates& operator[](ObjectClass c) const {
    return by_class[static_cast<std::size_t>(c)];
  }
};

/// Classifies every row and counts as Table 5.6 does.
Evaluation evaluate(const Classifier& classifier, const std::vector<LabelledFeatures>& rows);

}  // namespace scw::app
