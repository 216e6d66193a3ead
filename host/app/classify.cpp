// SPDX-License-Identifier: Apache-2.0
// Object classification (thesis 5.3.3): eq. 5.1's parallelepiped, OpenCV's SVM and MLP, CSV rows.
#include "host/app/classify.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace scw::app {

const std::array<const char*, kNumFeatures> kFeatureNames{"hu1", "hu2", "hu3", "width_m",
                                                          "height_m"};

std::array<double, kNumFeatures> to_array(const Features& f) {
  return {f.hu1, f.hu2, f.hu3, f.width_m, f.height_m};
}

Features from_array(const std::array<double, kNumFeatures>& a) {
  return {a[0], a[1], a[2], a[3], a[4]};
}

const char* to_string(ObjectClass c) {
  switch (c) {
    case ObjectClass::kPedestrian:
      return "pedestrian";
    case ObjectClass::kBike:
      return "bike";
    case ObjectClass::kOther:
      break;
  }
  return "other";
}

ObjectClass from_string(const std::string& s) {
  for (const ObjectClass c : kAllClasses)
    if (s == to_string(c)) return c;
  throw std::invalid_argument("unknown class '" + s + "'; expected pedestrian, bike or other");
}

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

constexpr int kFormatVersion = 1;
constexpr const char* kRootNode = "scw_classifier";
// OpenCV's own names for these models (StatModel::getDefaultName), so the node is also what
// cv::Algorithm::load<cv::ml::SVM>(path, "opencv_ml_svm") would look for.
constexpr const char* kSvmNode = "opencv_ml_svm";
constexpr const char* kAnnNode = "opencv_ml_ann_mlp";

std::size_t idx(ObjectClass c) { return static_cast<std::size_t>(c); }

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

// ---------------------------------------------------------------------------------------------
// Model files: one cv::FileStorage holding our node and, for the SVM and the network, OpenCV's.

cv::FileStorage open_for_write(const std::string& path) {
  // Checked first: cv::FileStorage would also log its own error line to stderr.
  if (!std::ofstream(path))
    throw std::runtime_error("cannot write model '" + path + "' (does its folder exist?)");
  cv::FileStorage fs;
  try {
    fs.open(path, cv::FileStorage::WRITE);
  } catch (const cv::Exception& e) {
    throw std::runtime_error("cannot write model '" + path + "': " + e.msg);
  }
  if (!fs.isOpened()) throw std::runtime_error("cannot write model '" + path + "'");
  return fs;
}

void write_doubles(cv::FileStorage& fs, const char* name,
                   const std::array<double, kNumFeatures>& a) {
  fs << name << "[";
  for (const double v : a) fs << v;
  fs << "]";
}

/// Writes the scw_classifier map's common head; the caller adds its fields and closes it.
void begin_root(cv::FileStorage& fs, ModelKind kind) {
  fs << kRootNode << "{";
  fs << "format" << kFormatVersion << "kind" << to_string(kind);
  fs << "features"
     << "[";
  for (const char* n : kFeatureNames) fs << n;
  fs << "]";
  fs << "classes"
     << "[";  // the label / output node of each class
  for (const ObjectClass c : kAllClasses) fs << to_string(c);
  fs << "]";
}

std::array<double, kNumFeatures> read_doubles(const cv::FileNode& node, const std::string& what,
                                              const std::string& path) {
  std::vector<double> v;
  if (node.isSeq()) node >> v;
  if (v.size() != kNumFeatures)
    throw std::runtime_error("model '" + path + "': " + what + " is not a list of " +
                             std::to_string(kNumFeatures) + " numbers");
  std::array<double, kNumFeatures> a{};
  std::copy(v.begin(), v.end(), a.begin());
  return a;
}

/// Each feature's mean and standard deviation over the training rows: the SVM and the network
/// see (x - mean) / std, so no feature dominates by its units (hu3 ~ 0.01, widths ~ 2 m).
struct Scaling {
  std::array<double, kNumFeatures> mean{}, std{};

  cv::Mat apply(const Features& f) const {
    cv::Mat row(1, static_cast<int>(kNumFeatures), CV_32F);
    const auto a = to_array(f);
    for (std::size_t i = 0; i < kNumFeatures; ++i)
      row.at<float>(0, static_cast<int>(i)) = static_cast<float>((a[i] - mean[i]) / std[i]);
    return row;
  }
  void write(cv::FileStorage& fs) const {
    fs << "scaling"
       << "{";
    write_doubles(fs, "mean", mean);
    write_doubles(fs, "std", std);
    fs << "}";
  }
  static Scaling read(const cv::FileNode& root, const std::string& path) {
    Scaling s;
    s.mean = read_doubles(root["scaling"]["mean"], "scaling.mean", path);
    s.std = read_doubles(root["scaling"]["std"], "scaling.std", path);
    for (std::size_t i = 0; i < kNumFeatures; ++i)
      if (!std::isfinite(s.mean[i]) || !(s.std[i] > 0) || !std::isfinite(s.std[i]))
        throw std::runtime_error("model '" + path + "': scaling of " + kFeatureNames[i] +
                                 " is not a finite mean and a positive standard deviation");
    return s;
  }
};

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

// ---------------------------------------------------------------------------------------------
// SVM and network.

class SvmClassifier final : public Classifier {
 public:
  SvmClassifier(cv::Ptr<cv::ml::SVM> svm, Scaling scaling)
      : svm_(std::move(svm)), scaling_(scaling) {}

  ObjectClass classify(const Features& f) const override {
    if (!all_finite(f)) return ObjectClass::kOther;
    const int label = static_cast<int>(std::lround(svm_->predict(scaling_.apply(f))));
    return label >= 0 && label < static_cast<int>(kNumClasses) ? static_cast<ObjectClass>(label)
                                                               : ObjectClass::kOther;
  }
  ModelKind kind() const override { return ModelKind::kSvm; }
  std::string describe() const override {
    std::ostringstream s;
    s << "svm (C_SVC, " << (svm_->getKernelType() == cv::ml::SVM::LINEAR ? "linear" : "RBF")
      << ", C = " << svm_->getC();
    if (svm_->getKernelType() == cv::ml::SVM::RBF) s << ", gamma = " << svm_->getGamma();
    s << ", " << svm_->getSupportVectors().rows << " support vectors)";
    return s.str();
  }
  void save(const std::string& path) const override {
    cv::FileStorage fs = open_for_write(path);
    begin_root(fs, kind());
    scaling_.write(fs);
    fs << "}";
    fs << kSvmNode << "{";
    svm_->write(fs);
    fs << "}";
  }

 private:
  cv::Ptr<cv::ml::SVM> svm_;
  Scaling scaling_;
};

class AnnClassifier final : public Classifier {
 public:
  AnnClassifier(cv::Ptr<cv::ml::ANN_MLP> ann, Scaling scaling)
      : ann_(std::move(ann)), scaling_(scaling) {}

  ObjectClass classify(const Features& f) const override {
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
  ModelKind kind() const override { return ModelKind::kAnn; }
  std::string describe() const override {
    const cv::Mat sizes = ann_->getLayerSizes();
    std::ostringstream s;
    s << "ann (";
    for (int i = 0; i < static_cast<int>(sizes.total()); ++i)
      s << (i ? "-" : "") << sizes.at<int>(i);
    s << ", symmetric sigmoid, "
      << (ann_->getTrainMethod() == cv::ml::ANN_MLP::RPROP ? "RPROP" : "back-propagation") << ")";
    return s.str();
  }
  void save(const std::string& path) const override {
    cv::FileStorage fs = open_for_write(path);
    begin_root(fs, kind());
    scaling_.write(fs);
    fs << "}";
    fs << kAnnNode << "{";
    ann_->write(fs);
    fs << "}";
  }

 private:
  cv::Ptr<cv::ml::ANN_MLP> ann_;
  Scaling scaling_;
};

void check_counts(ModelKind kind, const std::vector<LabelledFeatures>& rows,
                  const TrainOptions& o) {
  std::array<int, kNumClasses> n{};
  for (const auto& r : rows) ++n[idx(r.cls)];
  for (const ObjectClass c : kAllClasses) {
    if (kind == ModelKind::kParallelepiped && c == ObjectClass::kOther) continue;
    if (n[idx(c)] < kMinRowsPerClass)
      throw std::invalid_argument(
          o.source + ": " + std::to_string(n[idx(c)]) + " rows of class '" + to_string(c) +
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

void ParallelepipedClassifier::save(const std::string& path) const {
  cv::FileStorage fs = open_for_write(path);
  begin_root(fs, kind());
  fs << "s" << s_;
  for (const ObjectClass c : {ObjectClass::kPedestrian, ObjectClass::kBike}) {
    fs << to_string(c) << "{";
    write_doubles(fs, "mean", to_array(stats(c).mean));
    write_doubles(fs, "sigma", to_array(stats(c).sigma));
    fs << "}";
  }
  fs << "}";
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

std::unique_ptr<Classifier> load_classifier(const std::string& path) {
  // Checked first: cv::FileStorage would also log its own error line to stderr.
  if (!std::ifstream(path)) throw std::runtime_error("cannot open model '" + path + "'");
  cv::FileStorage fs;
  try {
    fs.open(path, cv::FileStorage::READ);
  } catch (const cv::Exception& e) {
    throw std::runtime_error("cannot read model '" + path +
                             "': not a cv::FileStorage file (YAML, XML or JSON) written by "
                             "`scw train`");
  }
  if (!fs.isOpened()) throw std::runtime_error("cannot read model '" + path + "'");
  const cv::FileNode root = fs[kRootNode];
  if (!root.isMap())
    throw std::runtime_error("'" + path + "' is not a scw classifier (no " + kRootNode +
                             " map); models are written by `scw train`");
  if (root["format"].empty() || static_cast<int>(root["format"]) != kFormatVersion)
    throw std::runtime_error("model '" + path + "' has format " +
                             (root["format"].empty()
                                  ? std::string("(none)")
                                  : std::to_string(static_cast<int>(root["format"]))) +
                             "; this scw reads format " + std::to_string(kFormatVersion));
  std::vector<std::string> names;
  if (root["features"].isSeq()) root["features"] >> names;
  if (names != std::vector<std::string>(kFeatureNames.begin(), kFeatureNames.end()))
    throw std::runtime_error("model '" + path +
                             "' was not trained on the features hu1, hu2, hu3, width_m, height_m "
                             "in this order");
  ModelKind kind{};
  try {
    kind = model_kind_from_string(static_cast<std::string>(root["kind"]));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("model '" + path + "': " + e.what());
  }
  switch (kind) {
    case ModelKind::kParallelepiped: {
      const double s = root["s"].isReal() || root["s"].isInt() ? static_cast<double>(root["s"]) : 0;
      ClassStats st[2];
      for (int i = 0; i < 2; ++i) {
        const std::string n = i == 0 ? "pedestrian" : "bike";
        st[i].mean = from_array(read_doubles(root[n]["mean"], n + ".mean", path));
        st[i].sigma = from_array(read_doubles(root[n]["sigma"], n + ".sigma", path));
      }
      try {
        return std::make_unique<ParallelepipedClassifier>(s, st[0], st[1]);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error("model '" + path + "': " + e.what());
      }
    }
    case ModelKind::kSvm:
    case ModelKind::kAnn:
      break;
  }
  const Scaling scaling = Scaling::read(root, path);
  const char* node = kind == ModelKind::kSvm ? kSvmNode : kAnnNode;
  if (!fs[node].isMap())
    throw std::runtime_error("model '" + path + "' of kind " + to_string(kind) + " has no " + node +
                             " map");
  try {
    if (kind == ModelKind::kSvm) {
      auto svm = cv::ml::SVM::create();
      svm->read(fs[node]);
      if (svm->isTrained() && svm->getVarCount() == static_cast<int>(kNumFeatures))
        return std::make_unique<SvmClassifier>(svm, scaling);
    } else {
      auto ann = cv::ml::ANN_MLP::create();
      ann->read(fs[node]);
      const cv::Mat sizes = ann->getLayerSizes();
      if (ann->isTrained() && sizes.total() >= 2 &&
          sizes.at<int>(0) == static_cast<int>(kNumFeatures) &&
          sizes.at<int>(static_cast<int>(sizes.total()) - 1) == static_cast<int>(kNumClasses))
        return std::make_unique<AnnClassifier>(ann, scaling);
    }
  } catch (const cv::Exception& e) {
    throw std::runtime_error("model '" + path + "': OpenCV cannot read its " + node + ": " + e.msg);
  }
  throw std::runtime_error("model '" + path + "': its " + node +
                           " is not a trained model of 5 features and 3 classes");
}

// ---------------------------------------------------------------------------------------------
// CSV rows.

namespace {

const std::string kCsvHeader = "class,hu1,hu2,hu3,width_m,height_m";
// The header's names, so an error can name its column.
constexpr std::array<const char*, kNumFeatures + 1> kCsvColumns{
    "class", "hu1", "hu2", "hu3", "width_m", "height_m"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  for (;;) {
    const auto comma = line.find(',');
    out.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return out;
    line.remove_prefix(comma + 1);
  }
}

}  // namespace

std::vector<LabelledFeatures> read_feature_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open feature rows '" + path + "'");
  const auto where = [&](int line, std::size_t col) {
    std::string w = path + ", line " + std::to_string(line);
    if (col > 0) w += ", column " + std::to_string(col) + " (" + kCsvColumns[col - 1] + ")";
    return w + ": ";
  };
  std::vector<LabelledFeatures> rows;
  std::string text;
  int line = 0;
  bool header = false;
  while (std::getline(in, text)) {
    ++line;
    if (trim(text).empty()) continue;
    const auto fields = split(text);
    if (!header) {
      std::string got;
      for (std::size_t i = 0; i < fields.size(); ++i) (got += i ? "," : "") += fields[i];
      if (line == 1 && got.size() >= 3 && got.compare(0, 3, "\xEF\xBB\xBF") == 0)
        got.erase(0, 3);  // a byte-order mark from a spreadsheet
      if (got != kCsvHeader)
        throw std::runtime_error(where(line, 0) + "the header is '" + got + "'; expected '" +
                                 kCsvHeader + "'");
      header = true;
      continue;
    }
    if (fields.size() != kCsvColumns.size())
      throw std::runtime_error(where(line, 0) + std::to_string(fields.size()) +
                               " columns; expected " + std::to_string(kCsvColumns.size()) + " (" +
                               kCsvHeader + ")");
    LabelledFeatures r;
    try {
      r.cls = from_string(std::string(fields[0]));
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(where(line, 1) + e.what());
    }
    std::array<double, kNumFeatures> v{};
    for (std::size_t i = 0; i < kNumFeatures; ++i) {
      const std::string_view f = fields[i + 1];
      const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v[i]);
      if (f.empty() || ec != std::errc() || end != f.data() + f.size())
        throw std::runtime_error(where(line, i + 2) + "'" + std::string(f) + "' is not a number");
      // Hu's first three invariants and sizes are never negative: a negative value is a
      // shifted or swapped column.
      if (!std::isfinite(v[i]) || v[i] < 0)
        throw std::runtime_error(where(line, i + 2) + std::string(f) +
                                 " is not a finite number >= 0");
    }
    r.f = from_array(v);
    rows.push_back(r);
  }
  if (!header)
    throw std::runtime_error(path + ": empty; expected the header '" + kCsvHeader +
                             "' and one row per object");
  if (rows.empty())
    throw std::runtime_error(path + ": the header but no rows; expected one row per object");
  return rows;
}

void write_feature_csv(const std::string& path, const std::vector<LabelledFeatures>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write feature rows '" + path + "'");
  out.imbue(std::locale::classic());
  out << std::setprecision(17) << kCsvHeader << "\n";
  for (const auto& r : rows) {
    out << to_string(r.cls);
    for (const double v : to_array(r.f)) out << "," << v;
    out << "\n";
  }
  if (!out.flush()) throw std::runtime_error("cannot write feature rows '" + path + "'");
}

// ---------------------------------------------------------------------------------------------
// Synthetic rows.

namespace {

/// Samplers on std::mt19937, whose sequence the standard fixes (unlike std::*_distribution's),
/// so a seed gives the same rows with any standard library.
class Sampler {
 public:
  explicit Sampler(unsigned seed) : mt_(seed) {}

  double uniform() {  // in (0, 1), 53 bits
    const std::uint64_t a = mt_() >> 5, b = mt_() >> 6;
    return (static_cast<double>((a << 26) + b) + 0.5) / 9007199254740992.0;
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double normal() {  // Marsaglia's polar method, one value per pair kept for simplicity
    for (;;) {
      const double u = 2 * uniform() - 1, v = 2 * uniform() - 1, q = u * u + v * v;
      if (q > 0 && q < 1) return u * std::sqrt(-2 * std::log(q) / q);
    }
  }
  double exponential(double mean) { return -mean * std::log(uniform()); }
  /// Gamma with shape k and scale 1 (Marsaglia and Tsang 2000; k < 1 by the k + 1 boost).
  double gamma(double k) {
    if (k < 1) return gamma(k + 1) * std::pow(uniform(), 1 / k);
    const double d = k - 1.0 / 3, c = 1 / std::sqrt(9 * d);
    for (;;) {
      double x = 0, v = 0;
      do {
        x = normal();
        v = 1 + c * x;
      } while (v <= 0);
      v = v * v * v;
      const double u = uniform();
      if (u < 1 - 0.0331 * x * x * x * x) return d * v;
      if (std::log(u) < 0.5 * x * x + d * (1 - v + std::log(v))) return d * v;
    }
  }
  /// The gamma distribution with this mean and standard deviation (shape (m / sd)^2, scale
  /// sd^2 / m): non-negative, and near the normal when m / sd is large.
  double gamma_ms(double mean, double sd) {
    const double k = (mean / sd) * (mean / sd);
    return sd * sd / mean * gamma(k);
  }

 private:
  std::mt19937 mt_;
};

Features draw(Sampler& g, const ClassStats& st, double widen) {
  const auto m = to_array(st.mean), sd = to_array(st.sigma);
  std::array<double, kNumFeatures> a{};
  for (std::size_t i = 0; i < kNumFeatures; ++i) a[i] = g.gamma_ms(m[i], widen * sd[i]);
  return from_array(a);
}

/// Trees, bushes, poles and signs as the labelling stage segments them: anything from a
/// compact blob (hu1 near its minimum 1 / 2 pi, a disc) to a thin pole, up to 4 m each way.
Features clutter(Sampler& g) {
  Features f;
  f.hu1 = g.uniform(0.16, 0.60);
  f.hu2 = g.uniform(0, f.hu1 * f.hu1);  // hu1^2 - hu2 = 4 (eta20 eta02 - eta11^2) >= 0
  f.hu3 = g.exponential(0.02);
  f.width_m = g.uniform(0.2, 4.0);
  f.height_m = g.uniform(0.3, 4.0);
  return f;
}

}  // namespace

std::vector<LabelledFeatures> synthesize_table54(int per_class, unsigned seed) {
  if (per_class < 0) throw std::invalid_argument("synthesize_table54: per_class must be >= 0");
  Sampler g(seed);
  std::vector<LabelledFeatures> rows;
  rows.reserve(3 * static_cast<std::size_t>(per_class));
  for (int i = 0; i < per_class; ++i)
    rows.push_back({ObjectClass::kPedestrian, draw(g, kTable54Pedestrian, 1)});
  for (int i = 0; i < per_class; ++i)
    rows.push_back({ObjectClass::kBike, draw(g, kTable54Bike, 1)});
  for (int i = 0; i < per_class; ++i) {
    const double u = g.uniform();
    // Half clutter; half look-alikes (a bush the size of a person, a fence as wide as a bike):
    // a class's distribution at twice its spread, so some fall inside the class's box, as
    // Table 5.5's "other" column shows real trees and bushes do.
    const Features f = u < 0.5    ? clutter(g)
                       : u < 0.75 ? draw(g, kTable54Pedestrian, 2)
                                  : draw(g, kTable54Bike, 2);
    rows.push_back({ObjectClass::kOther, f});
  }
  return rows;
}

// ---------------------------------------------------------------------------------------------

Evaluation evaluate(const Classifier& classifier, const std::vector<LabelledFeatures>& rows) {
  Evaluation e;
  for (const auto& r : rows) {
    const ObjectClass p = classifier.classify(r.f);
    ++e.confusion[idx(r.cls)][idx(p)];
    ClassRates& cr = e.by_class[idx(r.cls)];
    ++cr.rows;
    if (p == r.cls)
      ++cr.correct;
    else if (p != ObjectClass::kOther)
      ++cr.false_match;  // a named class other than the true one
  }
  return e;
}

}  // namespace scw::app
