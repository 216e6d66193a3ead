// SPDX-License-Identifier: Apache-2.0
// read_feature_csv() and write_feature_csv() (host/app/feature_csv.hpp).
#include "host/app/feature_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string_view>

namespace scw::app {

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

}  // namespace scw::app
