// SPDX-License-Identifier: Apache-2.0
// evaluate() and the rates tables (host/app/classify_rates.hpp).
#include "host/app/classify_rates.hpp"

#include <algorithm>
#include <cstdio>

namespace scw::app {
namespace {

std::string pct(double v) {
  char b[16];
  std::snprintf(b, sizeof b, "%6.2f%%", v);
  return b;
}

std::string num(int v, int w) {
  char b[16];
  std::snprintf(b, sizeof b, "%*d", w, v);
  return b;
}

}  // namespace

Evaluation evaluate(const Classifier& classifier, const std::vector<LabelledFeatures>& rows) {
  Evaluation e;
  for (const auto& r : rows) {
    const ObjectClass p = classifier.classify(r.f);
    ++e.confusion[class_index(r.cls)][class_index(p)];
    ClassRates& cr = e.by_class[class_index(r.cls)];
    ++cr.rows;
    if (p == r.cls)
      ++cr.correct;
    else if (p != ObjectClass::kOther)
      ++cr.false_match;  // a named class other than the true one
  }
  return e;
}

std::string row_counts(const std::vector<LabelledFeatures>& rows) {
  int n[kNumClasses] = {};
  for (const auto& r : rows) ++n[class_index(r.cls)];
  return std::to_string(rows.size()) + " rows (" + std::to_string(n[1]) + " pedestrian, " +
         std::to_string(n[2]) + " bike, " + std::to_string(n[0]) + " other)";
}

std::string rates_table(const std::vector<std::pair<std::string, Evaluation>>& sets) {
  std::size_t width = 0;
  for (const auto& set : sets) width = std::max(width, set.first.size() + 2);
  // Each class takes 26 columns: n, correct, false.
  std::string t(width, ' ');
  t += "  pedestrian";
  t.resize(width + 26, ' ');
  t += "  bike";
  t.resize(width + 52, ' ');
  t += "  other\n" + std::string(width, ' ') +
       "     n  correct    false       n  correct    false       n    false\n";
  for (const auto& [name, e] : sets) {
    std::string line = name;
    line.resize(width, ' ');
    for (const ObjectClass c : {ObjectClass::kPedestrian, ObjectClass::kBike}) {
      const auto& r = e[c];
      line += num(r.rows, 6) + "  " + pct(r.correct_pct()) + "  " + pct(r.false_pct()) + "  ";
    }
    const auto& o = e[ObjectClass::kOther];
    t += line + num(o.rows, 6) + "  " + pct(o.false_pct()) + "\n";
  }
  return t;
}

std::string confusion_table(const std::string& name, const Evaluation& e) {
  std::string t = name + ", rows by true class, columns by result:\n" +
                  "              pedestrian      bike     other\n";
  for (const ObjectClass c : {ObjectClass::kPedestrian, ObjectClass::kBike, ObjectClass::kOther}) {
    std::string line = std::string("  ") + to_string(c);
    line.resize(12, ' ');
    for (const ObjectClass p : {ObjectClass::kPedestrian, ObjectClass::kBike, ObjectClass::kOther})
      line += num(e.confusion[class_index(c)][class_index(p)], 10);
    t += line + "\n";
  }
  return t;
}

}  // namespace scw::app
