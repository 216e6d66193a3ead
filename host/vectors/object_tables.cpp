// SPDX-License-Identifier: Apache-2.0
// CSV object tables: each column found by its field's name in the word's one field table
// (sim/words/labelling_pack.hpp), each value checked against the field's width.
#include "host/vectors/object_tables.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "host/vectors/vector_set.hpp"
#include "sim/words/labelling_pack.hpp"

namespace scw::vectors {
namespace {

/// The columns of one file, found by name.
class Columns {
 public:
  Columns(const CsvTable& t, std::filesystem::path file) : t_(t), file_(std::move(file)) {}

  std::size_t index(const std::string& name) const {
    const auto it = std::find(t_.header.begin(), t_.header.end(), name);
    if (it == t_.header.end())
      throw std::runtime_error(file_.string() + ": no column '" + name +
                               "' (a labelling set's expected_objects.csv and "
                               "expected_status.csv have the columns this reads)");
    return static_cast<std::size_t>(it - t_.header.begin());
  }

  /// Row r's value in column `name`: a whole number of at most `bits` bits.
  std::uint64_t value(std::size_t r, const std::string& name, int bits) const {
    const std::string& v = t_.rows[r][index(name)];
    const auto where = [&] {
      return file_.string() + ":" + std::to_string(t_.lines[r]) + ": " + name + " '" + v + "' ";
    };
    if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos || v.size() > 20)
      throw std::runtime_error(where() + "is not a whole number >= 0");
    const unsigned long long x = std::stoull(v);
    if (bits < 64 && x >> bits)
      throw std::runtime_error(where() + "does not fit the field's " + std::to_string(bits) +
                               " bits");
    return x;
  }

 private:
  const CsvTable& t_;
  std::filesystem::path file_;
};

/// Makes `tables` hold frame `f`, refusing a frame number beyond any sensible sequence.
ObjectTable& frame_of(std::vector<ObjectTable>& tables, std::uint64_t f,
                      const std::filesystem::path& file) {
  constexpr std::uint64_t kMaxFrames = 1u << 20;
  if (f >= kMaxFrames)
    throw std::runtime_error(file.string() + ": frame " + std::to_string(f) + " is past " +
                             std::to_string(kMaxFrames) + " frames; frames count from 0");
  if (tables.size() <= f) tables.resize(f + 1);
  return tables[f];
}

}  // namespace

std::vector<ObjectTable> read_object_tables(const std::filesystem::path& objects,
                                            const std::filesystem::path& status) {
  std::vector<ObjectTable> tables;
  const CsvTable ot = read_csv_file(objects);
  const Columns oc(ot, objects);
  for (std::size_t r = 0; r < ot.rows.size(); ++r) {
    hls::labelling::Object o;
    sim::words::for_each(sim::labelling_word::kObjectFields, [&](const auto& f) {
      using T = typename std::remove_reference_t<decltype(f)>::value_type;
      o.*f.member = static_cast<T>(oc.value(r, f.name, f.bits));
    });
    frame_of(tables, oc.value(r, "frame", 32), objects).objects.push_back(o);
  }
  if (status.empty()) return tables;
  const CsvTable st = read_csv_file(status);
  const Columns sc(st, status);
  std::vector<bool> seen;
  for (std::size_t r = 0; r < st.rows.size(); ++r) {
    const std::uint64_t f = sc.value(r, "frame", 32);
    ObjectTable& t = frame_of(tables, f, status);
    if (seen.size() <= f) seen.resize(f + 1);
    if (seen[f])
      throw std::runtime_error(status.string() + ":" + std::to_string(st.lines[r]) +
                               ": a second status row for frame " + std::to_string(f));
    seen[f] = true;
    t.flags.tile_overflow = sc.value(r, "tile_overflow", 1) != 0;
    t.flags.object_overflow = sc.value(r, "object_overflow", 1) != 0;
    t.flags.stream_error = sc.value(r, "stream_error", 1) != 0;
  }
  return tables;
}

}  // namespace scw::vectors
