// SPDX-License-Identifier: Apache-2.0
// [app] Object classification (thesis 5.3.3): eq. 5.1, SVM and network, CSV rows, `scw train`.
#include <CLI/CLI.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/app/classify.hpp"

namespace scw::cli {
void add_train_command(CLI::App& app);  // host/cli/cmd_train.cpp, compiled into this test
}  // namespace scw::cli

namespace {

using namespace scw::app;
using Catch::Contains;

Features shifted(const ClassStats& st, std::size_t feature, double sigmas) {
  auto a = to_array(st.mean);
  a[feature] += sigmas * to_array(st.sigma)[feature];
  return from_array(a);
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

const std::string kHeader = "class,hu1,hu2,hu3,width_m,height_m\n";

// The held-out comparison below trains on 200 synthetic rows per class (seed 1) and tests on
// 500 others (seed 2): SVM 97.2 / 96.2 / 71.4 % correct (pedestrian / bike / other), network
// 96.4 / 92.8 / 65.0 %. Over training seeds 1..10, each tested on 1000 rows per class, the
// correct rates ranged (docs/classify.md):
//   SVM (C = 10, gamma = 0.5):  pedestrian 95.9-98.0 %, bike 94.7-97.5 %, other 68.4-74.6 %
//   network 5-4-3:              pedestrian 95.3-98.1 %, bike 90.6-97.4 %, other 55.6-67.0 %
// while the Bayes rule on the generating densities reaches 97.8 / 97.8 / 85.6 %. The bounds
// sit below every seed's result by one to three binomial standard deviations of a 500-row
// rate (1.2 % at 92 %, 2.2 % at 60 %) and far above chance and above eq. 5.1's 79 %, so they
// catch a broken scaling, label order or model; OpenCV trains deterministically, so they do
// not flicker.
constexpr double kSvmClassMin = 90, kSvmOtherMin = 60;
constexpr double kAnnClassMin = 88, kAnnOtherMin = 50;
// Nobody took a pedestrian for a bike or the reverse in Table 5.6; here at most 0.3 %.
constexpr double kMaxCrossPct = 2;

TEST_CASE("Table 5.4's statistics in feature order", "[app]") {
  // The table lists height before width; Features keeps hu1, hu2, hu3, width_m, height_m.
  CHECK(kTable54Pedestrian.mean.width_m == 0.73);
  CHECK(kTable54Pedestrian.mean.height_m == 1.80);
  CHECK(kTable54Pedestrian.sigma.width_m == 0.07);
  CHECK(kTable54Bike.mean.width_m == 2.03);
  CHECK(kTable54Bike.sigma.height_m == 0.06);
  CHECK(kTable54Bike.mean.hu3 == 0.016);
  CHECK(std::string(kFeatureNames[3]) == "width_m");
  const Features f{1, 2, 3, 4, 5};
  const auto a = to_array(f);
  CHECK(a == std::array<double, kNumFeatures>{1, 2, 3, 4, 5});
  CHECK(to_array(from_array(a)) == a);
}

TEST_CASE("class and model names round-trip and unknown names are refused", "[app]") {
  for (const ObjectClass c : kAllClasses) CHECK(from_string(to_string(c)) == c);
  CHECK(std::string(to_string(ObjectClass::kPedestrian)) == "pedestrian");
  CHECK_THROWS_WITH(from_string("car"), Contains("unknown class 'car'") && Contains("bike"));
  CHECK_THROWS_AS(from_string("Pedestrian"), std::invalid_argument);
  for (const ModelKind k : {ModelKind::kParallelepiped, ModelKind::kSvm, ModelKind::kAnn})
    CHECK(model_kind_from_string(to_string(k)) == k);
  CHECK_THROWS_WITH(model_kind_from_string("knn"), Contains("svm"));
}

TEST_CASE("parallelepiped: each class's mean is that class and far away is other", "[app]") {
  const ParallelepipedClassifier p;  // Table 5.4, s = 2 (Table 5.5's Test 3)
  CHECK(p.s() == 2.0);
  CHECK(p.classify(kTable54Pedestrian.mean) == ObjectClass::kPedestrian);
  CHECK(p.classify(kTable54Bike.mean) == ObjectClass::kBike);
  CHECK(p.distance(kTable54Bike.mean, ObjectClass::kBike) == 0.0);
  // A pedestrian's shape 5 m wide (a hedge), a 4 m tall bike, and nothing at all.
  CHECK(p.classify(shifted(kTable54Pedestrian, 3, 60)) == ObjectClass::kOther);
  CHECK(p.classify(shifted(kTable54Bike, 4, 36)) == ObjectClass::kOther);
  CHECK(p.classify(Features{}) == ObjectClass::kOther);
  // One feature out of its interval is enough, whichever it is.
  for (std::size_t i = 0; i < kNumFeatures; ++i) {
    CHECK(p.classify(shifted(kTable54Pedestrian, i, 2.5)) == ObjectClass::kOther);
    CHECK(p.classify(shifted(kTable54Bike, i, -2.5)) == ObjectClass::kOther);
    CHECK(p.classify(shifted(kTable54Bike, i, 1.9)) == ObjectClass::kBike);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(p.classify({nan, 0.065, 0.002, 0.73, 1.80}) == ObjectClass::kOther);
  CHECK_THROWS_AS(p.stats(ObjectClass::kOther), std::invalid_argument);
}

TEST_CASE("parallelepiped: the interval size s decides a borderline sample", "[app]") {
  // A pedestrian 1.5 sigma wider than the mean (0.835 m): outside at s = 1, inside at s = 3.
  const Features wide = shifted(kTable54Pedestrian, 3, 1.5);
  CHECK(ParallelepipedClassifier(1.0).classify(wide) == ObjectClass::kOther);
  CHECK(ParallelepipedClassifier(2.0).classify(wide) == ObjectClass::kPedestrian);
  CHECK(ParallelepipedClassifier(3.0).classify(wide) == ObjectClass::kPedestrian);
  // A bike whose hu3 is 2.5 sigma high (0.0585): other until s = 3.
  const Features odd = shifted(kTable54Bike, 2, 2.5);
  CHECK(ParallelepipedClassifier(1.0).classify(odd) == ObjectClass::kOther);
  CHECK(ParallelepipedClassifier(2.0).classify(odd) == ObjectClass::kOther);
  CHECK(ParallelepipedClassifier(3.0).classify(odd) == ObjectClass::kBike);
  CHECK_THROWS_AS(ParallelepipedClassifier(0.0), std::invalid_argument);
  ClassStats flat = kTable54Bike;
  flat.sigma.hu2 = 0;
  CHECK_THROWS_WITH(ParallelepipedClassifier(2.0, kTable54Pedestrian, flat),
                    Contains("bike") && Contains("hu2"));
}

TEST_CASE("parallelepiped: inside both boxes the per-sigma nearer mean wins", "[app]") {
  // Boxes that overlap (Table 5.4's cannot below s = 5.9, where 0.73 + 0.07 s = 2.03 - 0.15 s).
  const ClassStats a{{1, 1, 1, 1, 1}, {1, 1, 1, 1, 1}};
  const ClassStats b{{2, 2, 2, 2, 2}, {2, 2, 2, 2, 2}};
  const ParallelepipedClassifier p(2.0, a, b);
  const Features x{1.4, 1.4, 1.4, 1.4, 1.4};
  REQUIRE(p.inside(x, ObjectClass::kPedestrian));
  REQUIRE(p.inside(x, ObjectClass::kBike));
  // In metres x is nearer a's mean (0.4 against 0.6 per feature), in sigmas nearer b's (0.3).
  CHECK(p.distance(x, ObjectClass::kPedestrian) == Approx(0.4 * std::sqrt(5.0)));
  CHECK(p.distance(x, ObjectClass::kBike) == Approx(0.3 * std::sqrt(5.0)));
  CHECK(p.classify(x) == ObjectClass::kBike);
  CHECK(p.classify({1.2, 1.2, 1.2, 1.2, 1.2}) == ObjectClass::kPedestrian);
  CHECK(p.classify({3.5, 3.5, 3.5, 3.5, 3.5}) == ObjectClass::kBike);  // b's box only
  CHECK(p.classify({6.5, 2, 2, 2, 2}) == ObjectClass::kOther);
}

TEST_CASE("synthetic rows follow Table 5.4 and repeat with their seed", "[app]") {
  const auto rows = synthesize_table54(4000, 3);
  REQUIRE(rows.size() == 12000);
  CHECK(rows[0].cls == ObjectClass::kPedestrian);
  CHECK(rows[4000].cls == ObjectClass::kBike);
  CHECK(rows[11999].cls == ObjectClass::kOther);
  for (const auto& r : rows)
    for (const double v : to_array(r.f)) REQUIRE((std::isfinite(v) && v >= 0));
  // Training eq. 5.1 on them gives back Table 5.4: means within 4 standard errors, deviations
  // within 15 % (bike hu2 is a gamma of shape 0.25, whose sample deviation scatters by ~4 %).
  TrainOptions o;
  const auto c = train_classifier(ModelKind::kParallelepiped, rows, o);
  const auto& p = dynamic_cast<const ParallelepipedClassifier&>(*c);
  for (const ObjectClass cls : {ObjectClass::kPedestrian, ObjectClass::kBike}) {
    const ClassStats& want = cls == ObjectClass::kPedestrian ? kTable54Pedestrian : kTable54Bike;
    const auto m = to_array(p.stats(cls).mean), sd = to_array(p.stats(cls).sigma);
    const auto wm = to_array(want.mean), wsd = to_array(want.sigma);
    for (std::size_t i = 0; i < kNumFeatures; ++i) {
      INFO(to_string(cls) << " " << kFeatureNames[i]);
      CHECK(std::abs(m[i] - wm[i]) < 4 * wsd[i] / std::sqrt(4000.0));
      CHECK(sd[i] == Approx(wsd[i]).epsilon(0.15));
    }
  }
  const auto again = synthesize_table54(50, 3), other = synthesize_table54(50, 4);
  const auto first = synthesize_table54(4000, 3);
  CHECK(to_array(again[7].f) == to_array(first[7].f));  // the first pedestrians agree
  CHECK(to_array(again[7].f) != to_array(other[7].f));
  CHECK(synthesize_table54(0, 1).empty());
}

TEST_CASE("eq. 5.1 with Table 5.4 on synthetic rows", "[app]") {
  // Independent features: a class row lies in all five intervals with probability about
  // 0.95^5 = 79 % at s = 2 (the thesis measured 91.6 % / 87.3 % on real, correlated samples).
  const auto rows = synthesize_table54(2000, 5);
  const auto at = [&](double s) { return evaluate(ParallelepipedClassifier(s), rows); };
  const Evaluation e1 = at(1), e2 = at(2), e3 = at(3);
  CHECK(e2[ObjectClass::kPedestrian].correct_pct() > 75);
  CHECK(e2[ObjectClass::kBike].correct_pct() > 75);
  CHECK(e2[ObjectClass::kPedestrian].false_match == 0);
  CHECK(e2[ObjectClass::kBike].false_match == 0);
  // Table 5.5's trend: a wider interval finds more and lets in more others.
  CHECK(e1[ObjectClass::kPedestrian].correct < e2[ObjectClass::kPedestrian].correct);
  CHECK(e2[ObjectClass::kPedestrian].correct < e3[ObjectClass::kPedestrian].correct);
  CHECK(e1[ObjectClass::kOther].false_match < e2[ObjectClass::kOther].false_match);
  CHECK(e2[ObjectClass::kOther].false_match < e3[ObjectClass::kOther].false_match);
  // The look-alikes are drawn so that s = 2 and 3 admit about Table 5.5's 15.5 % and 27.5 %.
  CHECK(e2[ObjectClass::kOther].false_pct() > 8);
  CHECK(e2[ObjectClass::kOther].false_pct() < 20);
  CHECK(e3[ObjectClass::kOther].false_pct() > 20);
  CHECK(e3[ObjectClass::kOther].false_pct() < 35);
  // The counts add up: every row lands in exactly one cell.
  for (const ObjectClass c : kAllClasses) {
    const auto& row = e2.confusion[static_cast<std::size_t>(c)];
    CHECK(row[0] + row[1] + row[2] == e2[c].rows);
    CHECK(row[static_cast<std::size_t>(c)] == e2[c].correct);
  }
  CHECK(e2[ObjectClass::kOther].correct + e2[ObjectClass::kOther].false_match == 2000);
}

TEST_CASE("SVM and network classify held-out synthetic rows", "[app]") {
  const auto train = synthesize_table54(200, 1);
  const auto test = synthesize_table54(500, 2);
  const Evaluation box = evaluate(ParallelepipedClassifier(), test);
  for (const ModelKind kind : {ModelKind::kSvm, ModelKind::kAnn}) {
    const auto c = train_classifier(kind, train);
    REQUIRE(c->kind() == kind);
    const Evaluation e = evaluate(*c, test);
    const double class_min = kind == ModelKind::kSvm ? kSvmClassMin : kAnnClassMin;
    const double other_min = kind == ModelKind::kSvm ? kSvmOtherMin : kAnnOtherMin;
    INFO(c->describe() << ": pedestrian " << e[ObjectClass::kPedestrian].correct_pct()
                       << " %, bike " << e[ObjectClass::kBike].correct_pct() << " %, other "
                       << e[ObjectClass::kOther].correct_pct() << " %");
    CHECK(e[ObjectClass::kPedestrian].correct_pct() > class_min);
    CHECK(e[ObjectClass::kBike].correct_pct() > class_min);
    CHECK(e[ObjectClass::kOther].correct_pct() > other_min);
    CHECK(e[ObjectClass::kPedestrian].false_pct() <= kMaxCrossPct);
    CHECK(e[ObjectClass::kBike].false_pct() <= kMaxCrossPct);
    // As in Table 5.6, both find more pedestrians and bikes than eq. 5.1 at s = 2.
    CHECK(e[ObjectClass::kPedestrian].correct > box[ObjectClass::kPedestrian].correct);
    CHECK(e[ObjectClass::kBike].correct > box[ObjectClass::kBike].correct);
    // The same rows train the same model (OpenCV seeds its generators with constants).
    const auto again = train_classifier(kind, train);
    int differ = 0;
    for (const auto& r : test) differ += c->classify(r.f) != again->classify(r.f);
    CHECK(differ == 0);
    // What cannot be measured is not a pedestrian.
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(c->classify({0.3, 0.05, inf, 0.7, 1.8}) == ObjectClass::kOther);
  }
}

TEST_CASE("every kind saves and loads back to identical predictions", "[app]") {
  const auto train = synthesize_table54(100, 11);
  const auto test = synthesize_table54(300, 12);
  struct Case {
    ModelKind kind;
    const char* path;
  };
  for (const Case& k : {Case{ModelKind::kSvm, "classify_test_svm.yml"},
                        Case{ModelKind::kAnn, "classify_test_ann.yml"},
                        Case{ModelKind::kParallelepiped, "classify_test_box.yml"},
                        Case{ModelKind::kSvm, "classify_test_svm.xml"},
                        Case{ModelKind::kAnn, "classify_test_ann.json"}}) {
    INFO(k.path);
    const auto c = train_classifier(k.kind, train);
    c->save(k.path);
    const auto loaded = load_classifier(k.path);
    REQUIRE(loaded->kind() == k.kind);
    CHECK(loaded->describe() == c->describe());
    int differ = 0;
    for (const auto& r : test) differ += c->classify(r.f) != loaded->classify(r.f);
    CHECK(differ == 0);
  }
  CHECK_THROWS_WITH(ParallelepipedClassifier().save("classify_test_no_dir/box.yml"),
                    Contains("classify_test_no_dir/box.yml"));
  // The Table 5.4 defaults too, with a non-default s.
  ParallelepipedClassifier(1.5).save("classify_test_table54.yml");
  const auto t54 = load_classifier("classify_test_table54.yml");
  const auto& p = dynamic_cast<const ParallelepipedClassifier&>(*t54);
  CHECK(p.s() == 1.5);
  CHECK(to_array(p.stats(ObjectClass::kBike).sigma) == to_array(kTable54Bike.sigma));
}

TEST_CASE("load_classifier refuses what is not a model", "[app]") {
  CHECK_THROWS_WITH(load_classifier("classify_test_missing.yml"),
                    Contains("classify_test_missing.yml"));
  write_text("classify_test_rows.csv", kHeader + "bike,0.3,0.01,0.02,2,1.8\n");
  CHECK_THROWS_WITH(load_classifier("classify_test_rows.csv"), Contains("classify_test_rows.csv"));
  write_text("classify_test_foreign.yml", "%YAML:1.0\n---\nfoo: 1\n");
  CHECK_THROWS_WITH(load_classifier("classify_test_foreign.yml"), Contains("not a scw classifier"));
  write_text("classify_test_v9.yml", "%YAML:1.0\n---\nscw_classifier:\n  format: 9\n  kind: svm\n");
  CHECK_THROWS_WITH(load_classifier("classify_test_v9.yml"), Contains("format 9"));
  write_text("classify_test_kind.yml",
             "%YAML:1.0\n---\nscw_classifier:\n  format: 1\n  kind: knn\n  features: [hu1, hu2, "
             "hu3, width_m, height_m]\n");
  CHECK_THROWS_WITH(load_classifier("classify_test_kind.yml"),
                    Contains("unknown model kind 'knn'"));
  write_text("classify_test_nosvm.yml",
             "%YAML:1.0\n---\nscw_classifier:\n  format: 1\n  kind: svm\n  features: [hu1, hu2, "
             "hu3, width_m, height_m]\n  scaling: {mean: [0, 0, 0, 0, 0], std: [1, 1, 1, 1, 1]}\n");
  CHECK_THROWS_WITH(load_classifier("classify_test_nosvm.yml"), Contains("opencv_ml_svm"));
}

TEST_CASE("feature CSV reads back bit for bit", "[app]") {
  const auto rows = synthesize_table54(20, 9);
  write_feature_csv("classify_test_roundtrip.csv", rows);
  const auto back = read_feature_csv("classify_test_roundtrip.csv");
  REQUIRE(back.size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CHECK(back[i].cls == rows[i].cls);
    CHECK(to_array(back[i].f) == to_array(rows[i].f));
  }
  // Spaces, CRLF and blank lines are fine.
  write_text("classify_test_loose.csv",
             "class, hu1, hu2, hu3, width_m, height_m\r\n\r\n pedestrian , 0.3,0.06, 0.002 ,0.7,"
             "1.8\r\nother,0.2,0,1e-3,3,4\r\n");
  const auto loose = read_feature_csv("classify_test_loose.csv");
  REQUIRE(loose.size() == 2);
  CHECK(loose[0].cls == ObjectClass::kPedestrian);
  CHECK(loose[0].f.hu3 == 0.002);
  CHECK(loose[1].f.height_m == 4.0);
}

TEST_CASE("feature CSV errors name the file and the line and column", "[app]") {
  const std::string f = "classify_test_bad.csv";
  const auto fails_with = [&](const std::string& text, const std::string& what) {
    write_text(f, text);
    CHECK_THROWS_WITH(read_feature_csv(f), Contains(f) && Contains(what));
  };
  fails_with(kHeader + "bike,0.3,0.01,0.02,2,1.8\npedestrian,0.3,0.06,x,0.7,1.8\n",
             "line 3, column 4 (hu3): 'x' is not a number");
  fails_with(kHeader + "car,0.3,0.01,0.02,2,1.8\n",
             "line 2, column 1 (class): unknown class 'car'");
  fails_with(kHeader + "bike,0.3,0.01,0.02,2\n", "line 2: 5 columns; expected 6");
  fails_with(kHeader + "bike,0.3,0.01,0.02,2,1.8,7\n", "line 2: 7 columns");
  fails_with(kHeader + "bike,0.3,0.01,0.02,-2,1.8\n", "line 2, column 5 (width_m): -2 is not");
  fails_with(kHeader + "bike,0.3,0.01,0.02,2,nan\n", "line 2, column 6 (height_m)");
  fails_with(kHeader + "bike,0.3,,0.02,2,1.8\n", "line 2, column 3 (hu2): '' is not a number");
  fails_with(kHeader + "bike,0.3,0.01 0.02,0.02,2,1.8\n", "column 3 (hu2)");
  fails_with("label,hu1,hu2,hu3,w,h\nbike,0.3,0.01,0.02,2,1.8\n",
             "line 1: the header is 'label,hu1,hu2,hu3,w,h'");
  fails_with("", "empty");
  fails_with(kHeader, "no rows");
  CHECK_THROWS_WITH(read_feature_csv("classify_test_absent.csv"),
                    Contains("classify_test_absent.csv"));
}

TEST_CASE("training refuses too few rows of a class and names the source", "[app]") {
  auto rows = synthesize_table54(30, 1);
  rows.erase(rows.begin() + 60 + kMinRowsPerClass - 1, rows.end());  // 9 others left
  TrainOptions o;
  o.source = "F.csv";
  CHECK_THROWS_WITH(train_classifier(ModelKind::kSvm, rows, o),
                    Contains("F.csv") && Contains("9 rows of class 'other'"));
  CHECK_THROWS_WITH(train_classifier(ModelKind::kAnn, rows, o), Contains("at least 10"));
  // The parallelepiped does not use others.
  CHECK_NOTHROW(train_classifier(ModelKind::kParallelepiped, rows, o));
  rows.erase(rows.begin() + 5, rows.begin() + 30);  // 5 pedestrians left
  CHECK_THROWS_WITH(train_classifier(ModelKind::kParallelepiped, rows, o),
                    Contains("5 rows of class 'pedestrian'"));
  // A feature that never varies cannot be scaled.
  auto flat = synthesize_table54(20, 2);
  for (auto& r : flat) r.f.hu3 = 0.01;
  CHECK_THROWS_WITH(train_classifier(ModelKind::kSvm, flat, o),
                    Contains("F.csv") && Contains("hu3"));
}

/// Runs `scw train ARGS` through the command's own registration, as main.cpp does.
std::string scw_train(const std::vector<std::string>& args) {
  CLI::App app{"scw"};
  scw::cli::add_train_command(app);
  std::vector<std::string> argv{"scw", "train"};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<const char*> cargv;
  for (const auto& a : argv) cargv.push_back(a.c_str());
  std::ostringstream out;
  auto* old = std::cout.rdbuf(out.rdbuf());
  try {
    app.parse(static_cast<int>(cargv.size()), cargv.data());
  } catch (...) {
    std::cout.rdbuf(old);
    throw;
  }
  std::cout.rdbuf(old);
  return out.str();
}

TEST_CASE("scw train: synthesize rows then train and evaluate every kind", "[app]") {
  const std::string wrote =
      scw_train({"--synthesize", "60", "--features-out", "cli_train_rows.csv"});
  CHECK_THAT(wrote, Contains("180 rows") && Contains("SYNTHETIC"));
  const auto rows = read_feature_csv("cli_train_rows.csv");
  const auto want = synthesize_table54(60, 1);
  REQUIRE(rows.size() == want.size());
  CHECK(to_array(rows[100].f) == to_array(want[100].f));

  write_feature_csv("cli_train_test.csv", synthesize_table54(40, 2));
  for (const char* kind : {"svm", "ann", "parallelepiped"}) {
    const std::string model = std::string("cli_train_") + kind + ".yml";
    const std::string out = scw_train({"--features", "cli_train_rows.csv", "--out", model,
                                       "--model", kind, "--test", "cli_train_test.csv"});
    INFO(out);
    CHECK_THAT(out, Contains(std::string(kind) + " (") && Contains("saved to " + model) &&
                        Contains("training (cli_train_rows.csv)") &&
                        Contains("test (cli_train_test.csv)") && Contains("correct"));
    CHECK(load_classifier(model)->kind() == model_kind_from_string(kind));
  }
  // Options reach the trainer.
  const std::string lin = scw_train({"--synthesize", "30", "--out", "cli_train_linear.yml",
                                     "--svm-kernel", "linear", "--svm-c", "2"});
  CHECK_THAT(lin, Contains("svm (C_SVC, linear, C = 2"));
  const std::string box = scw_train({"--synthesize", "30", "--out", "cli_train_box.yml", "--model",
                                     "parallelepiped", "--s", "3"});
  CHECK_THAT(box, Contains("m +- 3 sigma"));
}

TEST_CASE("scw train: clear errors", "[app]") {
  write_text("cli_train_bad.csv",
             kHeader + "bike,0.3,0.01,0.02,2,1.8\nbike,0.3,0.01,0.02,2m,1.8\n");
  CHECK_THROWS_WITH(scw_train({"--features", "cli_train_bad.csv", "--out", "cli_train_bad.yml"}),
                    Contains("cli_train_bad.csv, line 3, column 5 (width_m)"));
  write_text("cli_train_few.csv", kHeader + "bike,0.3,0.01,0.02,2,1.8\n");
  CHECK_THROWS_WITH(scw_train({"--features", "cli_train_few.csv", "--out", "cli_train_few.yml"}),
                    Contains("cli_train_few.csv: 0 rows of class 'other'"));
  CHECK_THROWS_WITH(scw_train({"--out", "cli_train_none.yml"}), Contains("--features"));
  CHECK_THROWS_WITH(scw_train({"--synthesize", "5"}), Contains("nothing to do"));
  CHECK_THROWS_AS(
      scw_train({"--features", "cli_train_few.csv", "--synthesize", "5", "--out", "x.yml"}),
      CLI::ParseError);
  CHECK_THROWS_AS(scw_train({"--features", "cli_train_few.csv", "--features-out", "x.csv"}),
                  CLI::ParseError);
  CHECK_THROWS_AS(scw_train({"--synthesize", "50", "--out", "x.yml", "--model", "knn"}),
                  CLI::ParseError);
  CHECK_THROWS_AS(scw_train({"--synthesize", "50", "--out", "x.yml", "--ann-hidden", "1"}),
                  CLI::ParseError);
  CHECK_THROWS_WITH(scw_train({"--synthesize", "50", "--out", "cli_train_no_dir/m.yml"}),
                    Contains("no folder 'cli_train_no_dir'"));
}

}  // namespace
