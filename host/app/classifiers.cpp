// SPDX-License-Identifier: Apache-2.0
// The parallelepiped, OpenCV's SVM and MLP as classifiers, and their training
// (host/app/classifiers.hpp); their model files are model_file.cpp's.
#include "host/app/classifiers.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "host/app/classifiers_ml.hpp"

namespace scw::app {

using detail::AnnClassifier;
using detail::Scaling;
using detail::SvmClassifier;

const char* to_string(ModelKind k) {
  switch (k) {
    case ModelKind::kSvm:
      return "svm";
    case ModelKind::kAnn:
      return "ann";
    case ModelKind::kParallelepiped:
      break;
  }
  return "parallelepiped";
}

ModelKind model_kind_from_string(const std::string& s) {
  for (const ModelKind k : {ModelKind::kParallelepiped, ModelKind::kSvm, ModelKind::kAnn})
    if (s == to_string(k)) return k;
  throw std::invalid_argument("unknown model kind '" + s +
                              "'; expected parallelepiped, svm or ann");
}

namespace {

bool all_finite(const Features& f) {
  for (const double v : to_array(f))
    if (!std::isfinite(v)) return false;
  return true;
}

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// Mean and sample standard deviation (n - 1) of each feature over rows.
ClassStats stats_of(const std::vector<const Features*>& rows) {
  std::array<double, kNumFeatures> sum{}, mean{}, ss{}, sd{};
  for (const Features* f : rows) {
    const auto a = to_array(*f);
    for (std::size_t i = 0; i < kNumFeatures; ++i) sum[i] += a[i];
  }
  const double n = static_cast<double>(rows.size());
  for (std::size_t i = 0; i < kNumFeatures; ++i) mean[i] = sum[i] / n;
  for (const Features* f : rows) {  // two passes: one would cancel where the mean dwarfs the spread
    const auto a = to_array(*f);
    for (std::size_t i = 0; i < kNumFeatures; ++i) ss[i] += (a[i] - mean[i]) * (a[i] - mean[i]);
  }
  for (std::size_t i = 0; i < kNumFeatures; ++i) sd[i] = std::sqrt(ss[i] / (n - 1));
  return {from_array(mean), from_array(sd)};
}

void check_varies(const ClassStats& st, const std::string& which, const TrainOptions& o) {
  const auto m = to_array(st.mean), sd = to_array(st.sigma);
  for (std::size_t i = 0; i < kNumFeatures; ++i)
    // Relative: a constant column leaves a rounding residue of ~1e-16 of its value.
    if (!(sd[i] > 1e-12 * std::abs(m[i])) || !(sd[i] > 0) || !std::isfinite(sd[i]))
      throw std::invalid_argument(o.source + ": " + kFeatureNames[i] + " has standard deviation " +
                                  fmt(sd[i]) + " over " + which +
                                  "; every feature must vary to be scaled by it");
}

void check_counts(ModelKind kind, const std::vector<LabelledFeatures>& rows,
                  const TrainOptions& o) {
  std::array<int, kNumClasses> n{};
  for (const auto& r : rows) ++n[class_index(r.cls)];
  for (const ObjectClass c : kAllClasses) {
    if (kind == ModelKind::kParallelepiped && c == ObjectClass::kOther) continue;
    if (n[class_index(c)] < kMinRowsPerClass)
      throw std::invalid_argument(
          o.source + ": " + std::to_string(n[class_index(c)]) + " rows of class '" + to_string(c) +
          "'; training the " + to_string(kind) + " classifier needs at least " +
          std::to_string(kMinRowsPerClass) + " rows of each of " +
          (kind == ModelKind::kParallelepiped ? "pedestrian and bike (other rows are not used)"
                                              : "pedestrian, bike and other"));
  }
}

std::unique_ptr<Classifier> train_parallelepiped(const std::vector<LabelledFeatures>& rows,
                                                 const TrainOptions& o) {
  std::vector<const Features*> ped, bike;
  for (const auto& r : rows) {
    if (r.cls == ObjectClass::kPedestrian) ped.push_back(&r.f);
    if (r.cls == ObjectClass::kBike) bike.push_back(&r.f);
  }
  const ClassStats sp = stats_of(ped), sb = stats_of(bike);
  check_varies(sp, "the pedestrian rows", o);
  check_varies(sb, "the bike rows", o);
  return std::make_unique<ParallelepipedClassifier>(o.s, sp, sb);
}

/// The standardised samples (CV_32F, one row each) and the scaling used.
std::pair<cv::Mat, Scaling> standardise(const std::vector<LabelledFeatures>& rows,
                                        const TrainOptions& o) {
  std::vector<const Features*> all;
  for (const auto& r : rows) all.push_back(&r.f);
  const ClassStats st = stats_of(all);
  check_varies(st, "all rows", o);
  Scaling sc{to_array(st.mean), to_array(st.sigma)};
  cv::Mat samples(static_cast<int>(rows.size()), static_cast<int>(kNumFeatures), CV_32F);
  for (std::size_t r = 0; r < rows.size(); ++r)
    sc.apply(rows[r].f).copyTo(samples.row(static_cast<int>(r)));
  return {samples, sc};
}

std::unique_ptr<Classifier> train_svm(const std::vector<LabelledFeatures>& rows,
                                      const TrainOptions& o) {
  auto [samples, scaling] = standardise(rows, o);
  cv::Mat labels(static_cast<int>(rows.size()), 1, CV_32S);
  for (std::size_t r = 0; r < rows.size(); ++r)
    labels.at<int>(static_cast<int>(r)) = static_cast<int>(rows[r].cls);
  auto svm = cv::ml::SVM::create();
  svm->setType(cv::ml::SVM::C_SVC);  // several classes: OpenCV votes one-vs-one, as the thesis
  svm->setKernel(o.svm_linear ? cv::ml::SVM::LINEAR : cv::ml::SVM::RBF);
  svm->setC(o.svm_c);
  svm->setGamma(o.svm_gamma);
  svm->setTermCriteria(
      cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, 100000, 1e-6));
  const auto data = cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, labels);
  const bool ok = o.svm_auto ? svm->trainAuto(data, 10) : svm->train(data);
  if (!ok || !svm->isTrained()) throw std::runtime_error(o.source + ": OpenCV's SVM did not train");
  return std::make_unique<SvmClassifier>(svm, scaling);
}

std::unique_ptr<Classifier> train_ann(const std::vector<LabelledFeatures>& rows,
                                      const TrainOptions& o) {
  if (o.ann_hidden < 2 || o.ann_iterations < 1)  // OpenCV refuses a hidden layer of 1 node
    throw std::invalid_argument("the network needs at least 2 hidden nodes and 1 iteration");
  auto [samples, scaling] = standardise(rows, o);
  cv::Mat targets(static_cast<int>(rows.size()), static_cast<int>(kNumClasses), CV_32F,
                  cv::Scalar(0));
  for (std::size_t r = 0; r < rows.size(); ++r)  // one-hot: output node k is class k
    targets.at<float>(static_cast<int>(r), static_cast<int>(rows[r].cls)) = 1.0f;
  auto ann = cv::ml::ANN_MLP::create();
  ann->setLayerSizes(cv::Mat_<int>(
      {1, 3}, {static_cast<int>(kNumFeatures), o.ann_hidden, static_cast<int>(kNumClasses)}));
  ann->setActivationFunction(cv::ml::ANN_MLP::SIGMOID_SYM);
  ann->setTrainMethod(cv::ml::ANN_MLP::RPROP);
  ann->setTermCriteria(
      cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, o.ann_iterations, 1e-7));
  const auto data = cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, targets);
  // Inputs are standardised already; OpenCV's own input scaling would only repeat it.
  if (!ann->train(data, cv::ml::ANN_MLP::NO_INPUT_SCALE) || !ann->isTrained())
    throw std::runtime_error(o.source + ": OpenCV's ANN_MLP did not train");
  return std::make_unique<AnnClassifier>(ann, scaling);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// SVM and network.

namespace detail {

cv::Mat Scaling::apply(const Features& f) const {
  cv::Mat row(1, static_cast<int>(kNumFeatures), CV_32F);
  const auto a = to_array(f);
  for (std::size_t i = 0; i < kNumFeatures; ++i)
    row.at<float>(0, static_cast<int>(i)) = static_cast<float>((a[i] - mean[i]) / std[i]);
  return row;
}

ObjectClass SvmClassifier::classify(const Features& f) const {
  if (!all_finite(f)) return ObjectClass::kOther;
  const int label = static_cast<int>(std::lround(svm_->predict(scaling_.apply(f))));
  return label >= 0 && label < static_cast<int>(kNumClasses) ? static_cast<ObjectClass>(label)
                                                             : ObjectClass::kOther;
}

std::string SvmClassifier::describe() const {
  std::ostringstream s;
  s << "svm (C_SVC, " << (svm_->getKernelType() == cv::ml::SVM::LINEAR ? "linear" : "RBF")
    << ", C = " << svm_->getC();
  if (svm_->getKernelType() == cv::ml::SVM::RBF) s << ", gamma = " << svm_->getGamma();
  s << ", " << svm_->getSupportVectors().rows << " support vectors)";
  return s.str();
}

ObjectClass AnnClassifier::classify(const Features& f) const {
  if (!all_finite(f)) return ObjectClass::kOther;
  cv::Mat out;
  ann_->predict(scaling_.apply(f), out);
  // The thesis's output nodes sum to one; OpenCV's do not (no softmax), but the class is the
  // largest output either way. Ties go to the lower index, so other before the two classes.
  int best = 0;
  for (int k = 1; k < static_cast<int>(kNumClasses); ++k)
    if (out.at<float>(0, k) > out.at<float>(0, best)) best = k;
  return static_cast<ObjectClass>(best);
}

std::string AnnClassifier::describe() const {
  const cv::Mat sizes = ann_->getLayerSizes();
  std::ostringstream s;
  s << "ann (";
  for (int i = 0; i < static_cast<int>(sizes.total()); ++i)
    s << (i ? "-" : "") << sizes.at<int>(i);
  s << ", symmetric sigmoid, "
    << (ann_->getTrainMethod() == cv::ml::ANN_MLP::RPROP ? "RPROP" : "back-propagation") << ")";
  return s.str();
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Parallelepiped.

ParallelepipedClassifier::ParallelepipedClassifier(double s, const ClassStats& pedestrian,
                                                   const ClassStats& bike)
    : s_(s), pedestrian_(pedestrian), bike_(bike) {
  if (!(s > 0) || !std::isfinite(s))
    throw std::invalid_argument("the interval size s must be positive and finite, not " + fmt(s));
  for (const ClassStats* st : {&pedestrian_, &bike_}) {
    const auto m = to_array(st->mean), sd = to_array(st->sigma);
    for (std::size_t i = 0; i < kNumFeatures; ++i)
      if (!std::isfinite(m[i]) || !(sd[i] > 0) || !std::isfinite(sd[i]))
        throw std::invalid_argument(std::string("the ") +
                                    (st == &pedestrian_ ? "pedestrian" : "bike") +
                                    " class needs a finite mean and a positive standard "
                                    "deviation of " +
                                    kFeatureNames[i]);
  }
}

const ClassStats& ParallelepipedClassifier::stats(ObjectClass c) const {
  if (c == ObjectClass::kPedestrian) return pedestrian_;
  if (c == ObjectClass::kBike) return bike_;
  throw std::invalid_argument("the parallelepiped classifier has no box for class 'other'");
}

bool ParallelepipedClassifier::inside(const Features& f, ObjectClass c) const {
  const ClassStats& st = stats(c);
  const auto x = to_array(f), m = to_array(st.mean), sd = to_array(st.sigma);
  for (std::size_t i = 0; i < kNumFeatures; ++i)
    if (!(std::abs(x[i] - m[i]) <= s_ * sd[i])) return false;  // NaN is outside
  return true;
}

double ParallelepipedClassifier::distance(const Features& f, ObjectClass c) const {
  const ClassStats& st = stats(c);
  const auto x = to_array(f), m = to_array(st.mean), sd = to_array(st.sigma);
  double sum = 0;
  for (std::size_t i = 0; i < kNumFeatures; ++i)
    sum += ((x[i] - m[i]) / sd[i]) * ((x[i] - m[i]) / sd[i]);
  return std::sqrt(sum);
}

ObjectClass ParallelepipedClassifier::classify(const Features& f) const {
  const bool ped = inside(f, ObjectClass::kPedestrian), bike = inside(f, ObjectClass::kBike);
  if (ped && bike)
    return distance(f, ObjectClass::kBike) < distance(f, ObjectClass::kPedestrian)
               ? ObjectClass::kBike
               : ObjectClass::kPedestrian;
  if (ped) return ObjectClass::kPedestrian;
  if (bike) return ObjectClass::kBike;
  return ObjectClass::kOther;
}

std::string ParallelepipedClassifier::describe() const {
  return "parallelepiped (eq. 5.1, m +- " + fmt(s_) + " sigma)";
}

// ---------------------------------------------------------------------------------------------

std::unique_ptr<Classifier> train_classifier(ModelKind kind,
                                             const std::vector<LabelledFeatures>& rows,
                                             const TrainOptions& options) {
  check_counts(kind, rows, options);
  switch (kind) {
    case ModelKind::kSvm:
      return train_svm(rows, options);
    case ModelKind::kAnn:
      return train_ann(rows, options);
    case ModelKind::kParallelepiped:
      break;
  }
  return train_parallelepiped(rows, options);
}

}  // namespace scw::app
