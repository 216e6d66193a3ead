// SPDX-License-Identifier: Apache-2.0
// `scw train`: trains an object classifier on feature rows, saves it, prints Table 5.6's rates
// (the work is host/app/classify.hpp's).
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/app/classify.hpp"
#include "host/cli/commands.hpp"

namespace scw::cli {
namespace {

struct TrainOptions {
  std::string features, out, model = "svm", test, features_out;
  int synthesize = 0;
  unsigned seed = 1;
  std::string svm_kernel = "rbf";
  app::TrainOptions train;
};

void run_train(TrainOptions& o) {
  if (o.features.empty() && o.synthesize == 0)
    throw std::runtime_error(
        "scw train needs rows: --features F.csv (header class,hu1,hu2,hu3,width_m,height_m), "
        "or --synthesize N for synthetic stand-ins");
  if (o.out.empty() && o.features_out.empty())
    throw std::runtime_error(
        "nothing to do: give --out MODEL to train, or --features-out F.csv "
        "with --synthesize to write synthetic rows");
  std::vector<app::LabelledFeatures> rows;
  std::string source;
  if (o.synthesize > 0) {
    rows = app::synthesize_table54(o.synthesize, o.seed);
    source = o.features_out.empty() ? "synthetic rows" : o.features_out;
    if (!o.features_out.empty()) app::write_feature_csv(o.features_out, rows);
    std::cout << "scw train: " << (o.features_out.empty() ? "drew " : "wrote ")
              << app::row_counts(rows) << (o.features_out.empty() ? "" : " to " + o.features_out)
              << ": SYNTHETIC stand-ins drawn from Table 5.4's means and deviations (seed "
              << o.seed << "), not the thesis's samples (docs/classify.md)\n";
  } else {
    rows = app::read_feature_csv(o.features);
    source = o.features;
  }
  if (o.out.empty()) return;
  // Before training, which trainAuto makes minutes long: a missing folder fails the save.
  if (const auto dir = std::filesystem::path(o.out).parent_path();
      !dir.empty() && !std::filesystem::is_directory(dir))
    throw std::runtime_error("cannot write model '" + o.out + "': no folder '" + dir.string() +
                             "'");
  // Read before training, so a bad test file stops the run before a model is written.
  std::vector<app::LabelledFeatures> test;
  if (!o.test.empty()) test = app::read_feature_csv(o.test);

  const app::ModelKind kind = app::model_kind_from_string(o.model);
  o.train.svm_linear = o.svm_kernel == "linear";
  o.train.source = source;
  std::cout << "scw train: " << app::to_string(kind) << " on " << app::row_counts(rows) << " of "
            << source << "\n";
  const auto classifier = app::train_classifier(kind, rows, o.train);
  classifier->save(o.out);
  std::cout << "scw train: " << classifier->describe() << ", saved to " << o.out << "\n";

  std::vector<std::pair<std::string, app::Evaluation>> sets;
  sets.emplace_back("training (" + source + ")", app::evaluate(*classifier, rows));
  if (!o.test.empty()) sets.emplace_back("test (" + o.test + ")", app::evaluate(*classifier, test));
  std::cout << "\n" << app::rates_table(sets);
  for (const auto& [name, e] : sets) std::cout << "\n" << app::confusion_table(name, e);
}

}  // namespace

void add_train_command(CLI::App& app) {
  auto o = std::make_shared<TrainOptions>();
  auto* cmd = app.add_subcommand(
      "train",
      "Trains an object classifier (thesis 5.3.3: pedestrian, bike, other from Hu moments 1-3 "
      "and 3D width and height), saves it and prints Table 5.6's rates; or writes synthetic "
      "feature rows to try it on");
  auto* features =
      cmd->add_option("--features", o->features,
                      "Training rows: CSV with the header class,hu1,hu2,hu3,width_m,height_m; "
                      "class is pedestrian, bike or other")
          ->check(CLI::ExistingFile);
  auto* synth =
      cmd->add_option("--synthesize", o->synthesize,
                      "Instead of --features: N synthetic rows per class, drawn from Table "
                      "5.4's statistics (stand-ins: the thesis's samples are not public)")
          ->check(CLI::PositiveNumber);
  features->excludes(synth);
  cmd->add_option("--features-out", o->features_out,
                  "With --synthesize: write the synthetic rows to this CSV")
      ->needs(synth);
  cmd->add_option("--out", o->out,
                  "Model file to write: XML for .xml, JSON for .json, YAML otherwise (.yml); "
                  "`load_classifier` and the application layer read it");
  cmd->add_option("--model", o->model,
                  "Classifier: ann (5-4-3 network, Fig. 5.10), svm (C_SVC, one-vs-one) or "
                  "parallelepiped (eq. 5.1, the thesis's minimum distance classifier)")
      ->capture_default_str()
      ->check(CLI::IsMember({"ann", "svm", "parallelepiped"}));
  cmd->add_option("--test", o->test, "Test rows (same CSV format): rates reported beside training")
      ->check(CLI::ExistingFile);
  cmd->add_option("--seed", o->seed,
                  "With --synthesize: seeds the synthetic rows (training itself is repeatable: "
                  "OpenCV seeds its SVM and network with constants)")
      ->capture_default_str()
      ->needs(synth);
  cmd->add_option("--s", o->train.s, "parallelepiped: intervals m +- s sigma (Table 5.5)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--svm-kernel", o->svm_kernel, "svm: rbf or linear")
      ->capture_default_str()
      ->check(CLI::IsMember({"rbf", "linear"}));
  cmd->add_option("--svm-c", o->train.svm_c, "svm: C, the cost of a margin violation")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--svm-gamma", o->train.svm_gamma, "svm: RBF gamma on standardised features")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--svm-auto", o->train.svm_auto,
                "svm: choose C and gamma by OpenCV's 10-fold grid search (trainAuto)");
  cmd->add_option("--ann-hidden", o->train.ann_hidden, "ann: hidden nodes (Fig. 5.10: 4)")
      ->capture_default_str()
      ->check(CLI::Range(2, 1000));  // OpenCV: a hidden layer has at least 2 nodes
  cmd->add_option("--ann-iterations", o->train.ann_iterations,
                  "ann: at most this many RPROP epochs")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  cmd->callback([o] { run_train(*o); });
}

}  // namespace scw::cli
