// SPDX-License-Identifier: Apache-2.0
// compare_sets() (host/vectors/compare_sets.hpp).
#include "host/vectors/compare_sets.hpp"

#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "host/vectors/vector_set.hpp"

namespace scw::vectors {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_json(const fs::path& dir) {
  std::ifstream f(dir / "manifest.json");
  if (!f) throw std::runtime_error("'" + dir.string() + "' holds no manifest.json: give a set");
  try {
    return json::parse(f);
  } catch (const json::exception& e) {
    throw std::runtime_error("'" + (dir / "manifest.json").string() + "': " + e.what());
  }
}

std::string bytes_of(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

/// Empty when `dir`/`entry` is what its manifest says (verify_file()), else why not.
std::string unverified(const fs::path& dir, const json& entry) {
  FileEntry e;
  e.name = entry.at("name").get<std::string>();
  e.role = entry.at("role").get<std::string>();
  e.kind = entry.at("kind").get<std::string>();
  e.sha256 = entry.at("sha256").get<std::string>();
  e.meta = entry.at("meta");
  try {
    verify_file(dir, e);
    return {};
  } catch (const std::exception& ex) {
    return "'" + dir.string() + "': " + ex.what();
  }
}

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream f(p);
  std::vector<std::string> lines;
  for (std::string l; std::getline(f, l);) lines.push_back(l);
  return lines;
}

/// A beat's bits, least significant first, from its hex line (most significant digit first).
std::vector<bool> bits_of(const std::string& hex) {
  std::vector<bool> bits;
  for (auto c = hex.rbegin(); c != hex.rend(); ++c) {
    const int v = std::isdigit(static_cast<unsigned char>(*c)) ? *c - '0' : (*c | 0x20) - 'a' + 10;
    for (int b = 0; b < 4; ++b) bits.push_back((v >> b) & 1);
  }
  return bits;
}

/// A field's value as text that does not depend on its width: binary, most significant bit
/// first, without the leading zeros (unsigned) or the leading copies of the sign bit (signed).
std::string value_of(const std::vector<bool>& bits, int lsb, int width, bool is_signed) {
  std::string v;
  for (int i = lsb + width - 1; i >= lsb; --i)
    v += (static_cast<std::size_t>(i) < bits.size() && bits[static_cast<std::size_t>(i)]) ? '1'
                                                                                          : '0';
  const char pad = is_signed ? v.front() : '0';
  while (v.size() > 1 && v[0] == pad && v[1] == pad) v.erase(0, 1);
  if (!is_signed && v.size() > 1 && v[0] == '0') v.erase(0, 1);
  return v;
}

using Values = std::map<std::string, std::string>;

void add_fields(const json& fields, const std::vector<bool>& bits, int base,
                const std::string& prefix, Values& out) {
  for (const auto& f : fields)
    out[prefix + f.at("name").get<std::string>()] =
        value_of(bits, base + f.at("lsb").get<int>(), f.at("bits").get<int>(),
                 f.value("signed", false));
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
Values values_of(const json& layout, const std::vector<bool>& bits) {
  Values v;
  const json* nested = nullptr;
  if (layout.contains("status_fields") && layout.contains("object_fields")) {
    const int at = data_lsb(layout);
    nested = &layout.at(static_cast<std::size_t>(at) < bits.size() && bits[static_cast<std::size_t>(at)]
                            ? "status_fields"
                            : "object_fields");
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
std::string compare_fields(const fs::path& fa, const json& la, const fs::path& fb, const json& lb) {
  if (!la.contains("fields") || !lb.contains("fields"))
    return "its layout differs and has no field table to compare the values by";
  const auto a = lines_of(fa), b = lines_of(fb);
  if (a.size() != b.size())
    return std::to_string(a.size()) + " beats against " + std::to_string(b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Values va = values_of(la, bits_of(a[k])), vb = values_of(lb, bits_of(b[k]));
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
  const json ma = read_json(a), mb = read_json(b);
  read_manifest(a);  // each a valid manifest, or an error naming the field at fault
  read_manifest(b);
  SetComparison c;
  for (const char* key : {"format", "stage", "description", "config"})
    if (ma.value(key, json()) != mb.value(key, json()))
      c.problems.push_back(std::string("the manifests differ in ") + key);
  const json& files_a = ma.at("files");
  const json& files_b = mb.at("files");
  if (files_a.size() != files_b.size()) {
    c.problems.push_back("the sets list " + std::to_string(files_a.size()) + " and " +
                         std::to_string(files_b.size()) + " files");
    return c;
  }
  for (std::size_t i = 0; i < files_a.size(); ++i) {
    const json &fa = files_a[i], &fb = files_b[i];
    const std::string name = fa.at("name").get<std::string>();
    if (fb.at("name") != name || fb.at("role") != fa.at("role") || fb.at("kind") != fa.at("kind")) {
      c.problems.push_back("file " + std::to_string(i) + ": " + name + " against " +
                           fb.at("name").get<std::string>() + " (name, role or kind)");
      continue;
    }
    bool verified = true;
    for (const auto& [dir, entry] : {std::pair{a, &fa}, std::pair{b, &fb}})
      if (const std::string why = unverified(dir, *entry); !why.empty()) {
        c.problems.push_back(why);
        verified = false;
      }
    if (!verified) continue;
    if (bytes_of(a / name) == bytes_of(b / name) && fa.at("meta") == fb.at("meta")) {
      c.same.push_back(name);
      continue;
    }
    const json &meta_a = fa.at("meta"), &meta_b = fb.at("meta");
    const bool relaid = fa.at("kind") == "hex" &&
                        (meta_a.at("width_bits") != meta_b.at("width_bits") ||
                         meta_a.value("layout", json()) != meta_b.value("layout", json()));
    if (!relaid) {
      c.problems.push_back(name + " differs at the same layout");
      continue;
    }
    std::string why;
    try {
      why = compare_fields(a / name, meta_a.value("layout", json::object()), b / name,
                           meta_b.value("layout", json::object()));
    } catch (const std::exception& e) {  // a layout without a field's name, lsb or bits
      why = std::string("its layout cannot be read (") + e.what() + ")";
    }
    if (why.empty())
      c.repacked.push_back(name);
    else
      c.problems.push_back(name + " (another layout): " + why);
  }
  return c;
}

}  // namespace scw::vectors
