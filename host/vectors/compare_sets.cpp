// SPDX-License-Identifier: Apache-2.0
// compare_sets() (host/vectors/compare_sets.hpp).
#include "host/vectors/compare_sets.hpp"

#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "host/vectors/vector_set.hpp"

namespace scw::vectors {

namespace fs = std::filesystem;
using nlohmann::json;
using scw::sim::Bits;

namespace {

/// A field's value as text that does not depend on its width: binary, most significant bit
/// first, without the leading zeros (unsigned) or the leading copies of the sign bit (signed).
std::string value_of(const Bits& bits, int lsb, int width, bool is_signed) {
  std::string v;
  for (int i = lsb + width - 1; i >= lsb; --i) v += bits.get(i, 1) ? '1' : '0';
  const char pad = is_signed ? v.front() : '0';
  while (v.size() > 1 && v[0] == pad && v[1] == pad) v.erase(0, 1);
  if (!is_signed && v.size() > 1 && v[0] == '0') v.erase(0, 1);
  return v;
}

using Values = std::map<std::string, std::string>;

void add_fields(const json& fields, const Bits& bits, int base, const std::string& prefix,
                Values& out) {
  for (const auto& f : fields)
    out[prefix + f.at("name").get<std::string>()] = value_of(
        bits, base + f.at("lsb").get<int>(), f.at("bits").get<int>(), f.value("signed", false));
}

/// The field a nested table of a stream word starts at: its "data" field's lsb.
int data_lsb(const json& layout) {
  for (const auto& f : layout.at("fields"))
    if (f.at("name") == "data") return f.at("lsb").get<int>();
  throw std::runtime_error("a nested field table without a \"data\" field");
}

/// Every field of a beat by name: the layout's fields and, for a stream word, the fields of the
/// table its data holds (a labelling word: the status table when its is_status bit is set, else
/// the object table; a warning result: the result table), in place of the data field itself.
Values values_of(const json& layout, const Bits& bits) {
  Values v;
  const json* nested = nullptr;
  if (layout.contains("status_fields") && layout.contains("object_fields")) {
    nested = &layout.at(bits.get(data_lsb(layout), 1) ? "status_fields" : "object_fields");
  } else if (layout.contains("result_fields")) {
    nested = &layout.at("result_fields");
  }
  for (const auto& f : layout.at("fields")) {
    const std::string name = f.at("name").get<std::string>();
    if (nested && name == "data")
      add_fields(*nested, bits, f.at("lsb").get<int>(), "data.", v);
    else
      add_fields(json::array({f}), bits, 0, "", v);
  }
  return v;
}

/// Empty when every beat of `fa` and `fb` holds the same field values, else the first difference.
std::string compare_fields(const std::vector<Bits>& a, const json& la, const std::vector<Bits>& b,
                           const json& lb) {
  if (!la.contains("fields") || !lb.contains("fields"))
    return "its layout differs and has no field table to compare the values by";
  if (a.size() != b.size())
    return std::to_string(a.size()) + " beats against " + std::to_string(b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Values va = values_of(la, a[k]), vb = values_of(lb, b[k]);
    for (const auto& [name, value] : va) {
      const auto it = vb.find(name);
      if (it == vb.end()) return "beat " + std::to_string(k) + ": no field '" + name + "'";
      if (it->second != value)
        return "beat " + std::to_string(k) + ", field '" + name + "': 0b" + value + " against 0b" +
               it->second;
    }
    if (va.size() != vb.size()) return "beat " + std::to_string(k) + ": other fields";
  }
  return {};
}

}  // namespace

SetComparison compare_sets(const fs::path& a, const fs::path& b) {
  // Each set as its manifest says, every file verified (its SHA-256 and shape): so equal
  // checksums are equal bytes.
  const VectorSet sa = VectorSet::open(a), sb = VectorSet::open(b);
  const Manifest &ma = sa.manifest(), &mb = sb.manifest();
  SetComparison c;
  if (ma.stage != mb.stage) c.problems.push_back("the manifests differ in stage");
  if (ma.description != mb.description) c.problems.push_back("the manifests differ in description");
  if (ma.config != mb.config) c.problems.push_back("the manifests differ in config");
  if (ma.files.size() != mb.files.size()) {
    c.problems.push_back("the sets list " + std::to_string(ma.files.size()) + " and " +
                         std::to_string(mb.files.size()) + " files");
    return c;
  }
  for (std::size_t i = 0; i < ma.files.size(); ++i) {
    const FileEntry &fa = ma.files[i], &fb = mb.files[i];
    if (fb.name != fa.name || fb.role != fa.role || fb.kind != fa.kind) {
      c.problems.push_back("file " + std::to_string(i) + ": " + fa.name + " against " + fb.name +
                           " (name, role or kind)");
      continue;
    }
    if (fa.sha256 == fb.sha256 && fa.meta == fb.meta) {
      c.same.push_back(fa.name);
      continue;
    }
    const bool relaid =
        fa.kind == "hex" && (fa.meta.at("width_bits") != fb.meta.at("width_bits") ||
                             fa.meta.value("layout", json()) != fb.meta.value("layout", json()));
    if (!relaid) {
      c.problems.push_back(fa.name + " differs at the same layout");
      continue;
    }
    std::string why;
    try {
      why = compare_fields(sa.read_hex(fa.name), fa.meta.value("layout", json::object()),
                           sb.read_hex(fb.name), fb.meta.value("layout", json::object()));
    } catch (const std::exception& e) {  // a field without a name, lsb or bits, or past the word
      why = std::string("its layout cannot be read (") + e.what() + ")";
    }
    if (why.empty())
      c.repacked.push_back(fa.name);
    else
      c.problems.push_back(fa.name + " (another layout): " + why);
  }
  return c;
}

}  // namespace scw::vectors
