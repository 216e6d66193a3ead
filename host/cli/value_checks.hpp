// SPDX-License-Identifier: Apache-2.0
// CLI11 checks for numeric options whose errors say what is wrong with the value given and what a
// good one looks like ("--camera-height: -1 is not positive; give a positive number of m, e.g.
// 1.2"), before the value reaches a stage whose own check can only name its internal parameter.
// CLI11 puts the option's name in front of each message. Also the trimming of a comma list's items.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <string>

namespace scw::cli {

namespace detail {

/// The value as a finite double, or false (not a number, nan, inf).
inline bool finite_value(const std::string& s, double& v) {
  try {
    std::size_t used = 0;
    v = std::stod(s, &used);
    return used == s.size() && std::isfinite(v);
  } catch (const std::exception&) {
    return false;
  }
}

/// A check that passes finite values with ok(v) and otherwise says "<value> <wrong>; give <want>,
/// e.g. <eg>".
template <typename Ok>
CLI::Validator number_check(Ok ok, const std::string& wrong, const std::string& want,
                            const std::string& eg) {
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        double v = 0;
        if (!finite_value(s, v)) return s + " is not a number; give " + want + ", e.g. " + eg;
        if (ok(v)) return {};
        return s + " " + wrong + "; give " + want + ", e.g. " + eg;
      },
      want, want);
}

}  // namespace detail

/// Greater than zero and finite (lengths, focal lengths, periods).
inline CLI::Validator positive(const std::string& unit, const std::string& eg) {
  return detail::number_check([](double v) { return v > 0; }, "is not positive",
                              unit.empty() ? "a positive number" : "a positive number of " + unit, eg);
}

/// Zero or more and finite (areas, heights, margins).
inline CLI::Validator non_negative(const std::string& unit, const std::string& eg) {
  return detail::number_check([](double v) { return v >= 0; }, "is negative",
                              unit.empty() ? "a number >= 0" : "a number of " + unit + " >= 0", eg);
}

/// A block-matching window: an odd whole number of pixels, at least 3 (N x N around the pixel).
inline CLI::Validator odd_window() {
  return detail::number_check(
      [](double v) { return v >= 3 && v == std::floor(v) && static_cast<long>(v) % 2 == 1; },
      "is not a window size (N x N around the pixel)", "an odd number of px, at least 3",
      "9 or 21");
}

/// For a comma list split by CLI11 (`delimiter(',')`): the blanks around each item go, so
/// "labelling, warning" names two items as "labelling,warning" does.
inline CLI::Validator trimmed() {
  return CLI::Validator(
      [](std::string& s) {
        s.erase(0, s.find_first_not_of(" \t"));
        s.erase(s.find_last_not_of(" \t") + 1);
        return std::string{};
      },
      "");
}

}  // namespace scw::cli
