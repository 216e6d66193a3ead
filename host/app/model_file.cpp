// SPDX-License-Identifier: Apache-2.0
// Model files: Classifier::save of each kind and load_classifier (host/app/model_file.hpp). One
// cv::FileStorage holds scw's node and, for the SVM and the network, OpenCV's own.
#include "host/app/model_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "host/app/classifiers_ml.hpp"
#include "host/io/file_storage.hpp"

namespace scw::app {

using detail::AnnClassifier;
using detail::Scaling;
using detail::SvmClassifier;

namespace {

constexpr int kFormatVersion = 1;
constexpr const char* kRootNode = "scw_classifier";
// OpenCV's own names for these models (StatModel::getDefaultName), so the node is also what
// cv::Algorithm::load<cv::ml::SVM>(path, "opencv_ml_svm") would look for.
constexpr const char* kSvmNode = "opencv_ml_svm";
constexpr const char* kAnnNode = "opencv_ml_ann_mlp";

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

}  // namespace

void Scaling::write(cv::FileStorage& fs) const {
  fs << "scaling"
     << "{";
  write_doubles(fs, "mean", mean);
  write_doubles(fs, "std", std);
  fs << "}";
}

Scaling Scaling::read(const cv::FileNode& root, const std::string& path) {
  Scaling s;
  s.mean = read_doubles(root["scaling"]["mean"], "scaling.mean", path);
  s.std = read_doubles(root["scaling"]["std"], "scaling.std", path);
  for (std::size_t i = 0; i < kNumFeatures; ++i)
    if (!std::isfinite(s.mean[i]) || !(s.std[i] > 0) || !std::isfinite(s.std[i]))
      throw std::runtime_error("model '" + path + "': scaling of " + kFeatureNames[i] +
                               " is not a finite mean and a positive standard deviation");
  return s;
}

namespace {

/// The SVM's and the network's file: scw's node with the scaling, then OpenCV's own model
/// under its default name.
void save_ml(const std::string& path, ModelKind kind, const Scaling& scaling, const char* node,
             const cv::Algorithm& model) {
  cv::FileStorage fs = open_for_write(path);
  begin_root(fs, kind);
  scaling.write(fs);
  fs << "}";
  fs << node << "{";
  model.write(fs);
  fs << "}";
}

}  // namespace

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

void SvmClassifier::save(const std::string& path) const {
  save_ml(path, kind(), scaling_, kSvmNode, *svm_);
}

void AnnClassifier::save(const std::string& path) const {
  save_ml(path, kind(), scaling_, kAnnNode, *ann_);
}

namespace {

/// Every matrix node under `n` ({rows, cols, dt, data}) must hold as many values as its size
/// says before OpenCV reads it: cv::read allocates rows x cols from the file's word alone, so a
/// damaged size asks for gigabytes (a fuzz finding, fuzz/regressions/model/).
void check_matrices(const cv::FileNode& n, const std::string& path, int depth = 0) {
  if (depth > 16) throw std::runtime_error("model '" + path + "' is nested too deeply");
  if (n.isMap() && !n["rows"].empty() && !n["cols"].empty() && !n["data"].empty()) {
    const auto whole = [&](const cv::FileNode& v) {
      if (!v.isInt()) throw std::runtime_error("model '" + path + "': a matrix size is not a number");
      return static_cast<long long>(static_cast<int>(v));
    };
    long long cn = 1;
    if (n["dt"].isString()) {
      const std::string dt = n["dt"];
      if (!dt.empty() && std::isdigit(static_cast<unsigned char>(dt[0]))) cn = std::atoll(dt.c_str());
    }
    const long long rows = whole(n["rows"]), cols = whole(n["cols"]);
    const long long have = static_cast<long long>(n["data"].size());
    if (rows < 0 || cols < 0 || cn < 1 || cn > 512 || rows * cols * cn != have)
      throw std::runtime_error("model '" + path + "' is damaged: a matrix of " +
                               std::to_string(rows) + " x " + std::to_string(cols) + " holds " +
                               std::to_string(have) + " values");
    return;
  }
  if (n.isMap() || n.isSeq())
    for (auto it = n.begin(); it != n.end(); ++it) check_matrices(*it, path, depth + 1);
}

std::unique_ptr<Classifier> read_classifier(const std::string& path) {
  // Checked first: cv::FileStorage would also log its own error line to stderr.
  if (!std::ifstream(path)) throw std::runtime_error("cannot open model '" + path + "'");
  cv::FileStorage fs;
  try {
    fs = host::io::open_file_storage(path, "model '" + path + "'");
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
  check_matrices(fs[node], path);
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

}  // namespace

std::unique_ptr<Classifier> load_classifier(const std::string& path) {
  // cv::FileStorage throws from any read of a node that is not what the read expects (a list of
  // text where numbers belong, say); the checks above name the common faults and throw
  // runtime_error, this the rest.
  try {
    return read_classifier(path);
  } catch (const std::runtime_error&) {
    throw;
  } catch (const cv::Exception& e) {
    throw std::runtime_error("model '" + path + "' is damaged, not a model `scw train` wrote (" +
                             e.err + ")");
  } catch (const std::exception& e) {  // from OpenCV's parser: a garbled string, say
    throw std::runtime_error("model '" + path + "' is damaged, not a model `scw train` wrote (" +
                             std::string(e.what()) + ")");
  }
}

}  // namespace scw::app
