// SPDX-License-Identifier: Apache-2.0
// Table 5.5 / 5.6's rates: a classifier's results counted over a set of rows, and the tables
// `scw train` prints.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "host/app/classifiers.hpp"

namespace scw::app {

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

/// "600 rows (200 pedestrian, 200 bike, 200 other)".
std::string row_counts(const std::vector<LabelledFeatures>& rows);

/// Table 5.6's columns, one line per named set (such as training and test), with each class's
/// row count since two sets differ: correct = classified as its class; false = a pedestrian
/// taken for a bike or the reverse; other's false = taken for a pedestrian or a bike.
std::string rates_table(const std::vector<std::pair<std::string, Evaluation>>& sets);

/// The set's confusion matrix, rows by true class, columns by result, headed by `name`.
std::string confusion_table(const std::string& name, const Evaluation& e);

}  // namespace scw::app
