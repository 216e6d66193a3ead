// SPDX-License-Identifier: Apache-2.0
// Golden vector sets: SHA-256, the manifest, the writer and the checked readers.
#include "host/vectors/vector_set.hpp"

#include <openssl/evp.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <stdexcept>

#include "host/io/image_file.hpp"

namespace scw::vectors {
namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;
using scw::sim::Bits;

namespace {

constexpr const char* kManifestName = "manifest.json";
// Far above any beat the pipeline carries; stops a corrupt manifest from making every line
// allocate megabytes.
constexpr long long kMaxWidthBits = 65536;
constexpr const char* kRegenerate =
    "regenerate the set with scw, or restore it from version control";

// ---- SHA-256 -----------------------------------------------------------------------------------

class Sha256 {
 public:
  Sha256() : ctx_(EVP_MD_CTX_new(), &EVP_MD_CTX_free) {
    if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("OpenSSL could not start a SHA-256 digest");
  }
  void update(const char* data, std::size_t n) {
    if (EVP_DigestUpdate(ctx_.get(), data, n) != 1)
      throw std::runtime_error("OpenSSL SHA-256 update failed");
  }
  std::string hex_digest() {
    std::array<unsigned char, EVP_MAX_MD_SIZE> md{};
    unsigned int len = 0;
    if (EVP_DigestFinal_ex(ctx_.get(), md.data(), &len) != 1)
      throw std::runtime_error("OpenSSL SHA-256 finalisation failed");
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string s;
    for (unsigned int i = 0; i < len; ++i) {
      s += kDigits[md[i] >> 4];
      s += kDigits[md[i] & 15];
    }
    return s;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx_;
};

// ---- file I/O ----------------------------------------------------------------------------------

std::string read_bytes(const fs::path& path, const std::string& name) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(name + ": cannot be opened for reading");
  std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(name + ": read error");
  return s;
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot be written");
}

// ---- names, roles, kinds -----------------------------------------------------------------------

// Names stay plain and portable so a testbench can pass them to $readmemh unquoted and a set
// can never write outside its directory.
std::string name_problem(const std::string& name) {
  if (name.empty()) return "the file name is empty";
  if (name == kManifestName) return "'manifest.json' is reserved for the manifest";
  const std::string rule =
      "; use letters, digits, '_', '-' and '.' only, not starting with '.' (no directories)";
  if (name.front() == '.') return "file name '" + name + "' starts with '.'" + rule;
  for (char c : name) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    if (!ok) return "file name '" + name + "' contains '" + std::string(1, c) + "'" + rule;
  }
  return "";
}

std::string kind_of_name(const std::string& name) {
  static const std::map<std::string, std::string> kKinds = {
      {".hex", "hex"}, {".png", "png"}, {".pgm", "pgm"}, {".csv", "csv"}};
  const auto it = kKinds.find(fs::path(name).extension().string());
  return it == kKinds.end() ? "" : it->second;
}

bool valid_role(const std::string& role) { return role == "input" || role == "expected"; }

std::string image_type_name(int type) {
  switch (type) {
    case CV_8UC1:
      return "8UC1";
    case CV_16UC1:
      return "16UC1";
    case CV_8UC3:
      return "8UC3";
    default:
      return "";
  }
}

bool is_sha256_hex(const std::string& s) {
  if (s.size() != 64) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

// ---- manifest fields ---------------------------------------------------------------------------

[[noreturn]] void bad_manifest(const std::string& where, const std::string& problem) {
  throw std::runtime_error(where + ": " + problem);
}

const json& field(const json& obj, const char* key, const std::string& where) {
  const auto it = obj.find(key);
  if (it == obj.end()) bad_manifest(where, std::string("missing field '") + key + "'");
  return *it;
}

std::string string_field(const json& obj, const char* key, const std::string& where) {
  const json& v = field(obj, key, where);
  if (!v.is_string())
    bad_manifest(where, std::string("field '") + key + "' must be a string, not " + v.dump());
  return v.get<std::string>();
}

long long int_field(const json& obj, const char* key, long long lo, long long hi,
                    const std::string& where) {
  const json& v = field(obj, key, where);
  const bool in_range =
      v.is_number_integer() &&
      !(v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) &&
      v.get<long long>() >= lo && v.get<long long>() <= hi;
  if (!in_range)
    bad_manifest(where, std::string("field '") + key + "' must be an integer in [" +
                            std::to_string(lo) + ", " + std::to_string(hi) + "], not " + v.dump());
  return v.get<long long>();
}

constexpr long long kMaxCount = 1LL << 40;

void check_meta(const FileEntry& f, const std::string& where) {
  if (!f.meta.is_object()) bad_manifest(where, "field 'meta' must be an object");
  if (f.kind == "hex") {
    int_field(f.meta, "width_bits", 1, kMaxWidthBits, where);
    int_field(f.meta, "beats", 0, kMaxCount, where);
  } else if (f.kind == "csv") {
    int_field(f.meta, "rows", 0, kMaxCount, where);
    int_field(f.meta, "columns", 1, kMaxCount, where);
  } else if (f.kind == "png" || f.kind == "pgm") {
    int_field(f.meta, "width", 1, kMaxCount, where);
    int_field(f.meta, "height", 1, kMaxCount, where);
    const std::string type = string_field(f.meta, "type", where);
    if (type != "8UC1" && type != "16UC1" && (type != "8UC3" || f.kind != "png"))
      bad_manifest(where, "image type '" + type + "' is not one of 8UC1, 16UC1" +
                              (f.kind == "png" ? ", 8UC3" : " (PGM is single channel)"));
  } else {
    bad_manifest(where, "kind '" + f.kind + "' must be one of hex, png, pgm, csv");
  }
}

FileEntry parse_entry(const json& j, const std::string& where0) {
  if (!j.is_object()) bad_manifest(where0, "must be an object");
  FileEntry f;
  f.name = string_field(j, "name", where0);
  const std::string where = where0 + " ('" + f.name + "')";
  if (const std::string p = name_problem(f.name); !p.empty()) bad_manifest(where, p);
  f.role = string_field(j, "role", where);
  if (!valid_role(f.role))
    bad_manifest(where, "role '" + f.role + "' must be \"input\" or \"expected\"");
  f.kind = string_field(j, "kind", where);
  if (f.kind != "hex" && f.kind != "png" && f.kind != "pgm" && f.kind != "csv")
    bad_manifest(where, "kind '" + f.kind + "' must be one of hex, png, pgm, csv");
  if (kind_of_name(f.name) != f.kind)
    bad_manifest(where, "kind '" + f.kind + "' does not match the name's extension");
  f.sha256 = string_field(j, "sha256", where);
  if (!is_sha256_hex(f.sha256))
    bad_manifest(where, "field 'sha256' must be 64 lowercase hex digits, not '" + f.sha256 + "'");
  f.meta = field(j, "meta", where);
  check_meta(f, where);
  return f;
}

// Known meta keys first, in reading order, so a diff of two manifests lines up.
ordered_json meta_json(const FileEntry& f) {
  static const std::map<std::string, std::vector<const char*>> kOrder = {
      {"hex", {"width_bits", "beats", "layout"}},
      {"png", {"width", "height", "type"}},
      {"pgm", {"width", "height", "type"}},
      {"csv", {"rows", "columns"}}};
  ordered_json out = ordered_json::object();
  if (!f.meta.is_object()) return out;
  if (const auto it = kOrder.find(f.kind); it != kOrder.end())
    for (const char* key : it->second)
      if (f.meta.contains(key)) out[key] = f.meta.at(key);
  for (const auto& [key, value] : f.meta.items())
    if (!out.contains(key)) out[key] = value;
  return out;
}

// ---- parsers (shared by verify_file and the readers) -------------------------------------------

std::runtime_error line_error(const FileEntry& f, std::size_t line, const std::string& problem) {
  return std::runtime_error(f.name + " line " + std::to_string(line) + ": " + problem);
}

// Splits at '\n'; a final line without '\n' still counts, the empty piece after a final '\n'
// does not.
std::vector<std::string_view> split_lines(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    lines.emplace_back(text.data() + pos, end - pos);
    pos = end + 1;
  }
  return lines;
}

std::vector<Bits> parse_hex(const std::string& text, const FileEntry& f) {
  const int width = f.meta.at("width_bits").get<int>();
  const auto beats = f.meta.at("beats").get<long long>();
  const std::size_t digits = static_cast<std::size_t>((width + 3) / 4);
  std::vector<Bits> out;
  std::size_t line = 0;
  for (std::string_view s : split_lines(text)) {
    ++line;
    if (!s.empty() && s.back() == '\r')
      throw line_error(f, line, "ends in a carriage return; hex files use '\\n' line endings");
    if (s.empty())
      throw line_error(f, line, "is empty; $readmemh would skip it and shift every later beat");
    if (s.size() != digits)
      throw line_error(f, line,
                       "has " + std::to_string(s.size()) + " characters, expected " +
                           std::to_string(digits) + " hex digits for a " + std::to_string(width) +
                           "-bit beat");
    try {
      out.push_back(Bits::from_hex(s, width));
    } catch (const std::invalid_argument& e) {
      throw line_error(f, line, e.what());
    }
  }
  if (static_cast<long long>(out.size()) != beats)
    throw std::runtime_error(f.name + ": has " + std::to_string(out.size()) +
                             " beats (lines) but the manifest declares " + std::to_string(beats));
  return out;
}

std::vector<std::string> split_csv_line(std::string_view s, const FileEntry& f, std::size_t line) {
  if (!s.empty() && s.back() == '\r')
    throw line_error(f, line, "ends in a carriage return; CSV files use '\\n' line endings");
  if (s.find('"') != std::string_view::npos)
    throw line_error(f, line, "contains a quote; scw CSV values are never quoted");
  std::vector<std::string> values;
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = s.find(',', pos);
    values.emplace_back(s.substr(pos, comma == std::string_view::npos ? s.npos : comma - pos));
    if (comma == std::string_view::npos) break;
    pos = comma + 1;
  }
  return values;
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text, const FileEntry& f,
                                                std::vector<std::string>* header) {
  const auto lines = split_lines(text);
  if (lines.empty()) throw std::runtime_error(f.name + ": is empty; expected a header row");
  std::vector<std::string> head = split_csv_line(lines[0], f, 1);
  const auto columns = f.meta.at("columns").get<long long>();
  if (static_cast<long long>(head.size()) != columns)
    throw line_error(f, 1,
                     "header has " + std::to_string(head.size()) +
                         " columns but the manifest declares " + std::to_string(columns));
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    rows.push_back(split_csv_line(lines[i], f, i + 1));
    if (rows.back().size() != head.size())
      throw line_error(f, i + 1,
                       "has " + std::to_string(rows.back().size()) + " values, the header has " +
                           std::to_string(head.size()));
  }
  const auto declared = f.meta.at("rows").get<long long>();
  if (static_cast<long long>(rows.size()) != declared)
    throw std::runtime_error(f.name + ": has " + std::to_string(rows.size()) +
                             " data rows but the manifest declares " + std::to_string(declared));
  if (header) *header = std::move(head);
  return rows;
}

}  // namespace

std::vector<cv::Mat> crop_maps(const std::vector<fs::path>& maps, cv::Rect& roi,
                               const std::string& what) {
  std::vector<cv::Mat> out;
  for (const auto& path : maps) {
    const cv::Mat m = host::io::read_disparity_q4(path);
    if (roi.area() == 0) roi = cv::Rect(0, 0, m.cols, m.rows);
    if ((roi & cv::Rect(0, 0, m.cols, m.rows)) != roi)
      throw std::invalid_argument(what + ": the crop " + crop_text(roi) + " must lie inside the " +
                                  std::to_string(m.cols) + "x" + std::to_string(m.rows) + " map " +
                                  path.filename().string() + ": give --roi X Y W H");
    out.push_back(m(roi).clone());
  }
  return out;
}

cv::Mat stacked_frames(const std::vector<cv::Mat>& frames) {
  cv::Mat all;
  cv::vconcat(frames, all);
  return all;
}

std::string crop_text(const cv::Rect& roi) {
  return "x " + std::to_string(roi.x) + " y " + std::to_string(roi.y) + " " +
         std::to_string(roi.width) + "x" + std::to_string(roi.height);
}

CsvTable read_csv_file(const fs::path& path) {
  FileEntry f;
  f.name = path.string();
  f.kind = "csv";
  if (!fs::is_regular_file(path)) throw std::runtime_error(f.name + ": no such file");
  const std::string text = read_bytes(path, f.name);
  const auto lines = split_lines(text);
  if (lines.empty()) throw std::runtime_error(f.name + ": is empty; expected a header row");
  CsvTable t;
  t.header = split_csv_line(lines[0], f, 1);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    t.rows.push_back(split_csv_line(lines[i], f, i + 1));
    t.lines.push_back(i + 1);
    if (t.rows.back().size() != t.header.size())
      throw line_error(f, i + 1,
                       "has " + std::to_string(t.rows.back().size()) + " values, the header has " +
                           std::to_string(t.header.size()));
  }
  return t;
}

namespace {

cv::Mat load_image(const fs::path& path, const FileEntry& f) {
  cv::Mat img = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  if (img.empty()) throw std::runtime_error(f.name + ": cannot be decoded as " + f.kind);
  const std::string type = image_type_name(img.type());
  const auto w = f.meta.at("width").get<long long>();
  const auto h = f.meta.at("height").get<long long>();
  const std::string want = f.meta.at("type").get<std::string>();
  if (img.cols != w || img.rows != h || type != want)
    throw std::runtime_error(f.name + ": is " + std::to_string(img.cols) + "x" +
                             std::to_string(img.rows) + " " + cv::typeToString(img.type()) +
                             " but the manifest declares " + std::to_string(w) + "x" +
                             std::to_string(h) + " " + want);
  return img;
}

}  // namespace

// ---- public free functions ---------------------------------------------------------------------

std::string sha256_bytes(std::string_view bytes) {
  Sha256 sha;
  sha.update(bytes.data(), bytes.size());
  return sha.hex_digest();
}

std::string sha256_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be opened for reading");
  Sha256 sha;
  std::array<char, 1 << 16> buf{};
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    sha.update(buf.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw std::runtime_error(path.string() + ": read error");
  return sha.hex_digest();
}

json pixel_beat_layout(int pixels_per_beat, int pixel_bits) {
  json fields = json::array();
  for (int i = 0; i < pixels_per_beat; ++i)
    fields.push_back(
        {{"name", "px" + std::to_string(i)}, {"lsb", i * pixel_bits}, {"bits", pixel_bits}});
  const int flags = pixels_per_beat * pixel_bits;
  fields.push_back({{"name", "sof"}, {"lsb", flags}, {"bits", 1}});
  fields.push_back({{"name", "eol"}, {"lsb", flags + 1}, {"bits", 1}});
  return {{"pixels_per_beat", pixels_per_beat}, {"pixel_bits", pixel_bits}, {"fields", fields}};
}

json stream_beat_layout(int data_bits) {
  return {{"data_bits", data_bits},
          {"fields", json::array({{{"name", "data"}, {"lsb", 0}, {"bits", data_bits}},
                                  {{"name", "last"}, {"lsb", data_bits}, {"bits", 1}}})}};
}

std::string manifest_text(const Manifest& m) {
  ordered_json files = ordered_json::array();
  for (const FileEntry& f : m.files) {
    ordered_json e;
    e["name"] = f.name;
    e["role"] = f.role;
    e["kind"] = f.kind;
    e["sha256"] = f.sha256;
    e["meta"] = meta_json(f);
    files.push_back(std::move(e));
  }
  ordered_json top;
  top["format"] = Manifest::kFormat;
  top["stage"] = m.stage;
  top["description"] = m.description;
  top["config"] = m.config.is_null() ? ordered_json::object() : ordered_json(m.config);
  top["files"] = std::move(files);
  return top.dump(2) + "\n";
}

namespace {
Manifest parse_manifest(const fs::path& dir) {
  const fs::path path = dir / kManifestName;
  const std::string where = path.string();
  if (!fs::is_regular_file(path))
    throw std::runtime_error(where +
                             ": not found; a vector set is a directory holding manifest.json, "
                             "which scw writes last, so its absence may mean generation failed");
  json j;
  try {
    j = json::parse(read_bytes(path, where));
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number too large
    bad_manifest(where, std::string("not valid JSON (") + e.what() + ")");
  }
  if (!j.is_object()) bad_manifest(where, "the top level must be a JSON object");
  const std::string format = string_field(j, "format", where);
  if (format != Manifest::kFormat) {
    const bool ours = format.rfind("scw-vectors/", 0) == 0;
    bad_manifest(where, "format is '" + format + "' but this scw reads '" + Manifest::kFormat +
                            "'" + (ours ? " (use the scw version that wrote the set)" : ""));
  }
  Manifest m;
  m.stage = string_field(j, "stage", where);
  if (m.stage.empty()) bad_manifest(where, "field 'stage' is empty");
  m.description = string_field(j, "description", where);
  m.config = field(j, "config", where);
  if (!m.config.is_object()) bad_manifest(where, "field 'config' must be an object");
  const json& files = field(j, "files", where);
  if (!files.is_array()) bad_manifest(where, "field 'files' must be an array");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < files.size(); ++i) {
    FileEntry f = parse_entry(files[i], where + ": files[" + std::to_string(i) + "]");
    if (!seen.insert(f.name).second) bad_manifest(where, "file '" + f.name + "' is listed twice");
    m.files.push_back(std::move(f));
  }
  return m;
}
}  // namespace

Manifest read_manifest(const fs::path& dir) {
  try {
    return parse_manifest(dir);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(e.what()) + "; " + kRegenerate);
  }
}

void verify_file(const fs::path& dir, const FileEntry& f) {
  // Callers may build entries by hand: keep them inside `dir`, and the parsers rely on meta.
  if (const std::string p = name_problem(f.name); !p.empty()) throw std::runtime_error(p);
  check_meta(f, f.name + ": manifest entry");
  const fs::path path = dir / f.name;
  if (!fs::is_regular_file(path))
    throw std::runtime_error(f.name +
                             ": missing; the manifest lists it but the directory has "
                             "no such file");
  const std::string actual = sha256_file(path);
  if (actual != f.sha256)
    throw std::runtime_error(f.name + ": SHA-256 mismatch: the manifest records " + f.sha256 +
                             " but the file hashes to " + actual +
                             ", so the file changed after the set was written");
  if (f.kind == "hex") {
    parse_hex(read_bytes(path, f.name), f);
  } else if (f.kind == "csv") {
    parse_csv(read_bytes(path, f.name), f, nullptr);
  } else {
    load_image(path, f);
  }
}

// ---- VectorWriter ------------------------------------------------------------------------------

VectorWriter::VectorWriter(fs::path dir, std::string stage, json config, std::string description)
    : dir_(std::move(dir)) {
  if (stage.empty()) throw std::invalid_argument("vector set: the stage name is empty");
  if (config.is_null()) config = json::object();
  if (!config.is_object())
    throw std::invalid_argument("vector set: config must be a JSON object, not " + config.dump());
  manifest_.stage = std::move(stage);
  manifest_.description = std::move(description);
  manifest_.config = std::move(config);
  fs::create_directories(dir_);
}

void VectorWriter::add_entry(FileEntry entry) {
  entry.sha256 = sha256_file(path_of(entry.name));
  manifest_.files.push_back(std::move(entry));
}

namespace {
// Everything the writer can reject is checked before a byte is written.
void check_new_file(const Manifest& m, bool finished, const std::string& name,
                    const std::string& role, const std::string& kind) {
  if (finished) throw std::logic_error(name + ": the vector set was already finished");
  if (const std::string p = name_problem(name); !p.empty()) throw std::invalid_argument(p);
  if (!valid_role(role))
    throw std::invalid_argument(name + ": role '" + role + "' must be \"input\" or \"expected\"");
  if (kind_of_name(name) != kind)
    throw std::invalid_argument(name + ": a " + kind + " file must be named *." + kind);
  for (const FileEntry& f : m.files)
    if (f.name == name) throw std::invalid_argument(name + ": already added to this vector set");
}

void check_csv_value(const std::string& name, const std::string& v, std::size_t row,
                     const std::string& column) {
  if (v.find_first_of(",\"\r\n") == std::string::npos) return;
  const std::string at = row == 0 ? "header" : "row " + std::to_string(row);
  throw std::invalid_argument(name + ": " + at + ", column '" + column + "': value '" + v +
                              "' contains a comma, quote or line break, which scw CSV files "
                              "never quote; encode the value without them");
}
}  // namespace

void VectorWriter::add_hex(const std::string& name, const std::string& role,
                           const std::vector<Bits>& beats, json layout) {
  check_new_file(manifest_, finished_, name, role, "hex");
  if (beats.empty())
    throw std::invalid_argument(name + ": no beats; $readmemh needs at least one line");
  const int width = beats.front().width();
  if (width < 1 || width > kMaxWidthBits)
    throw std::invalid_argument(name + ": beat width " + std::to_string(width) + " is outside 1.." +
                                std::to_string(kMaxWidthBits));
  std::string text;
  text.reserve(beats.size() * static_cast<std::size_t>((width + 3) / 4 + 1));
  for (std::size_t i = 0; i < beats.size(); ++i) {
    if (beats[i].width() != width)
      throw std::invalid_argument(name + ": beat " + std::to_string(i) + " is " +
                                  std::to_string(beats[i].width()) + " bits wide, beat 0 is " +
                                  std::to_string(width));
    text += beats[i].hex();
    text += '\n';
  }
  write_bytes(path_of(name), text);
  json meta = {{"width_bits", width}, {"beats", beats.size()}};
  if (!layout.is_null()) meta["layout"] = std::move(layout);
  add_entry({name, role, "hex", "", std::move(meta)});
}

void VectorWriter::add_image(const std::string& name, const std::string& role, const cv::Mat& img) {
  const std::string kind = kind_of_name(name);
  if (kind != "png" && kind != "pgm")
    throw std::invalid_argument(name + ": an image file must be named *.png or *.pgm");
  check_new_file(manifest_, finished_, name, role, kind);
  const std::string type = image_type_name(img.type());
  if (img.empty() || type.empty() || (kind == "pgm" && type == "8UC3"))
    throw std::invalid_argument(name + ": cannot store a " + std::to_string(img.cols) + "x" +
                                std::to_string(img.rows) + " " + cv::typeToString(img.type()) +
                                " image as " + kind + "; use 8UC1 or 16UC1" +
                                (kind == "png" ? " or 8UC3" : ""));
  // Explicit encoder settings: OpenCV's defaults have changed between releases, and the bytes
  // (hence the SHA-256) must not.
  const std::vector<int> params =
      kind == "png" ? std::vector<int>{cv::IMWRITE_PNG_COMPRESSION, 6, cv::IMWRITE_PNG_STRATEGY,
                                       cv::IMWRITE_PNG_STRATEGY_DEFAULT}
                    : std::vector<int>{cv::IMWRITE_PXM_BINARY, 1};
  if (!cv::imwrite(path_of(name).string(), img, params))
    throw std::runtime_error(path_of(name).string() + ": OpenCV could not write the image");
  add_entry({name, role, kind, "", {{"width", img.cols}, {"height", img.rows}, {"type", type}}});
}

void VectorWriter::add_csv(const std::string& name, const std::string& role,
                           const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows) {
  check_new_file(manifest_, finished_, name, role, "csv");
  if (header.empty()) throw std::invalid_argument(name + ": the header has no columns");
  std::string text;
  auto append = [&](const std::vector<std::string>& values, std::size_t row) {
    for (std::size_t c = 0; c < values.size(); ++c) {
      check_csv_value(name, values[c], row, header[c]);
      if (c) text += ',';
      text += values[c];
    }
    text += '\n';
  };
  for (const std::string& h : header)
    if (h.empty()) throw std::invalid_argument(name + ": a header column name is empty");
  append(header, 0);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].size() != header.size())
      throw std::invalid_argument(name + ": row " + std::to_string(r + 1) + " has " +
                                  std::to_string(rows[r].size()) + " values, the header has " +
                                  std::to_string(header.size()));
    append(rows[r], r + 1);
  }
  write_bytes(path_of(name), text);
  add_entry({name, role, "csv", "", {{"rows", rows.size()}, {"columns", header.size()}}});
}

void VectorWriter::finish() {
  if (finished_) throw std::logic_error("vector set: finish() called twice");
  write_bytes(dir_ / kManifestName, manifest_text(manifest_));
  finished_ = true;
}

// ---- VectorSet ---------------------------------------------------------------------------------

VectorSet VectorSet::open(const fs::path& dir) {
  Manifest m = read_manifest(dir);
  for (const FileEntry& f : m.files) {
    try {
      verify_file(dir, f);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("vector set '" + dir.string() + "': " + e.what() + "; " +
                               kRegenerate);
    }
  }
  return VectorSet(dir, std::move(m));
}

const FileEntry& VectorSet::file(const std::string& name) const {
  std::string names;
  for (const FileEntry& f : manifest_.files) {
    if (f.name == name) return f;
    names += (names.empty() ? "" : ", ") + f.name;
  }
  throw std::runtime_error("vector set '" + dir_.string() + "' has no file '" + name +
                           "' (it has: " + (names.empty() ? "none" : names) + ")");
}

const FileEntry& VectorSet::file_of_kind(const std::string& name, const char* kind1,
                                         const char* kind2) const {
  const FileEntry& f = file(name);
  if (f.kind != kind1 && (kind2 == nullptr || f.kind != kind2))
    throw std::runtime_error(name + ": is a " + f.kind + " file, not " + kind1 +
                             (kind2 ? std::string(" or ") + kind2 : std::string()));
  return f;
}

std::vector<Bits> VectorSet::read_hex(const std::string& name) const {
  const FileEntry& f = file_of_kind(name, "hex");
  return parse_hex(read_bytes(dir_ / f.name, f.name), f);
}

cv::Mat VectorSet::read_image(const std::string& name) const {
  const FileEntry& f = file_of_kind(name, "png", "pgm");
  return load_image(dir_ / f.name, f);
}

std::vector<std::vector<std::string>> VectorSet::read_csv(const std::string& name,
                                                          std::vector<std::string>* header) const {
  const FileEntry& f = file_of_kind(name, "csv");
  return parse_csv(read_bytes(dir_ / f.name, f.name), f, header);
}

}  // namespace scw::vectors
