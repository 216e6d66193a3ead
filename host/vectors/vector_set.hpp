// SPDX-License-Identifier: Apache-2.0
// Golden vector sets: a manifest plus hex, image and CSV files that any HDL simulator can replay.
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "sim/words/bits.hpp"
#include "sim/words/fields.hpp"

namespace scw::vectors {

/// Lowercase hex SHA-256 of a file's bytes; throws std::runtime_error if it cannot be read.
std::string sha256_file(const std::filesystem::path& path);
/// Lowercase hex SHA-256 of a byte string.
std::string sha256_bytes(std::string_view bytes);

/// One file of a set, as listed in the manifest.
struct FileEntry {
  std::string name;    ///< plain file name inside the set directory, e.g. "in_left.hex"
  std::string role;    ///< "input" (drive the DUT) or "expected" (compare the DUT's output)
  std::string kind;    ///< "hex", "png", "pgm" or "csv"; must match the name's extension
  std::string sha256;  ///< 64 lowercase hex digits of the file's bytes
  /// hex: width_bits, beats, optional layout; png/pgm: width, height, type ("8UC1", "16UC1",
  /// "8UC3"); csv: rows (without the header), columns.
  nlohmann::json meta;
};

/// The contents of manifest.json.
struct Manifest {
  /// Bumped whenever a reader of the previous version would misread a set (docs/vectors.md).
  static constexpr const char* kFormat = "scw-vectors/1";
  std::string stage;        ///< "rectify", "disparity", "labelling", "warning", ...
  std::string description;  ///< free text for a human
  nlohmann::json config;    ///< the stage parameters the set was generated with (an object)
  std::vector<FileEntry> files;
};

/// `frames` as `k` frames back to back (`scw vectors <stage> --frames K`): the first k, or all of
/// them in order, again and again, up to k. Throws std::invalid_argument for k < 1 or no frame.
template <typename T>
void repeat_frames(std::vector<T>& frames, int k) {
  if (k < 1 || frames.empty())
    throw std::invalid_argument("--frames " + std::to_string(k) + ": give at least 1, and a frame");
  const std::size_t n = frames.size();
  frames.resize(static_cast<std::size_t>(k), frames.front());
  for (std::size_t i = n; i < frames.size(); ++i) frames[i] = frames[i % n];
}

/// Frames [r.begin, r.end) of `frames` (a segment of a set split by --segments or --shard).
template <typename T, typename Range>
std::vector<T> frames_in(const std::vector<T>& frames, const Range& r) {
  return {frames.begin() + static_cast<std::ptrdiff_t>(r.begin),
          frames.begin() + static_cast<std::ptrdiff_t>(r.end)};
}

/// The frames one above the other, in order: how a set's PNG holds frames back to back.
cv::Mat stacked_frames(const std::vector<cv::Mat>& frames);

/// Maps of the user's cropped alike: the crop `roi` (empty: the first map's whole size) of each
/// 16-bit Q11.4 map (host::io::read_disparity_q4), in order, and `roi` set to the crop used.
/// `what` names the command in errors. Throws std::invalid_argument naming the map a crop does
/// not lie inside, and std::runtime_error for a file that is not a 16-bit map.
std::vector<cv::Mat> crop_maps(const std::vector<std::filesystem::path>& maps, cv::Rect& roi,
                               const std::string& what);
/// "x X y Y WxH": a crop for the descriptions.
std::string crop_text(const cv::Rect& roi);

/// Layout description of a pixel beat `{eol, sof, px[P-1], ..., px[0]}` for add_hex().
nlohmann::json pixel_beat_layout(int pixels_per_beat, int pixel_bits);
/// Layout description of a non-image beat `{last, data}` for add_hex().
nlohmann::json stream_beat_layout(int data_bits);

/// A word's field table (sim/words/fields.hpp) as layout entries `{name, lsb, bits[, signed]}`,
/// the fields from bit `lsb` up, appended to `entries` (fields below them, written by hand).
template <typename Table>
nlohmann::json field_layout(const Table& table, int lsb = 0,
                            nlohmann::json entries = nlohmann::json::array()) {
  sim::words::for_each(table, [&](const auto& f) {
    nlohmann::json e = {{"name", f.name}, {"lsb", lsb}, {"bits", f.bits}};
    if (f.kSigned) e["signed"] = true;
    entries.push_back(std::move(e));
    lsb += f.bits;
  });
  return entries;
}

/// A word's values as `{name: value}` (an enum as its code), beside its
/// field_layout() for a human reading the manifest.
template <typename Table, typename S>
nlohmann::json field_values(const Table& table, const S& s) {
  nlohmann::json v = nlohmann::json::object();
  sim::words::for_each(table, [&](const auto& f) {
    using F = std::remove_cv_t<std::remove_reference_t<decltype(f)>>;
    if constexpr (std::is_enum_v<typename F::value_type>)
      v[f.name] = static_cast<long long>(f.get(s));
    else
      v[f.name] = f.get(s);
  });
  return v;
}

/// The exact text finish() writes: 2-space indent, fixed key order, trailing newline.
std::string manifest_text(const Manifest& manifest);
/// Parses and validates `dir`/manifest.json (format string, fields, file names) without
/// reading the files it lists; throws std::runtime_error naming the field at fault.
Manifest read_manifest(const std::filesystem::path& dir);
/// Checks one listed file: it exists, its SHA-256 matches, and its contents agree with `meta`
/// (hex line count and digits, image size and type, CSV shape). Throws std::runtime_error
/// whose message starts with the file name.
void verify_file(const std::filesystem::path& dir, const FileEntry& entry);

/// Writes a set: each add_*() writes its file at once, finish() writes manifest.json last, so a
/// set whose generation failed has no manifest and cannot be mistaken for a good one. Output is
/// byte-for-byte reproducible: no timestamps, no absolute paths, names in the caller's order.
class VectorWriter {
 public:
  /// Creates `dir` if missing; `config` must be a JSON object (or null for none).
  VectorWriter(std::filesystem::path dir, std::string stage, nlohmann::json config,
               std::string description = "");

  /// One beat per line, ceil(width/4) lowercase digits; all beats must have the same width.
  void add_hex(const std::string& name, const std::string& role,
               const std::vector<scw::sim::Bits>& beats, nlohmann::json layout = {});
  /// ".png" (8UC1, 16UC1, 8UC3 in OpenCV's BGR order) or ".pgm" (8UC1, 16UC1; binary P5).
  void add_image(const std::string& name, const std::string& role, const cv::Mat& img);
  /// Header row first; values must not contain commas, quotes or line breaks.
  void add_csv(const std::string& name, const std::string& role,
               const std::vector<std::string>& header,
               const std::vector<std::vector<std::string>>& rows);
  /// Writes manifest.json; the writer accepts nothing afterwards.
  void finish();

 private:
  void add_entry(FileEntry entry);
  std::filesystem::path path_of(const std::string& name) const { return dir_ / name; }

  std::filesystem::path dir_;
  Manifest manifest_;
  bool finished_ = false;
};

/// A stage's configuration word (sim/words/*_cfg.hpp) as a one-line input file `name`, its layout
/// the table's fields and, with `with_values`, their values read back from the word (sets whose
/// config already lists them leave that out).
template <typename S, typename Table>
void add_config_hex(VectorWriter& vw, const std::string& name, const sim::Bits& word,
                    const Table& table, bool with_values) {
  nlohmann::json layout = {{"fields", field_layout(table)}};
  if (with_values) layout["values"] = field_values(table, sim::words::unpack_word<S>(word, table));
  vw.add_hex(name, "input", {word}, layout);
}

/// A CSV file of the user's, in the sets' dialect (a header row, comma-separated unquoted values,
/// '\n' line endings; blank lines skipped).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as wide as the header
  std::vector<std::size_t> lines;              // each row's line number in the file, from 1
};
/// Reads `path`; throws std::runtime_error naming the file and line of the first problem.
CsvTable read_csv_file(const std::filesystem::path& path);

/// A set opened for reading; every file was verified by open().
class VectorSet {
 public:
  /// Parses the manifest and runs verify_file() on every file; throws std::runtime_error
  /// naming the first problem.
  static VectorSet open(const std::filesystem::path& dir);

  const Manifest& manifest() const { return manifest_; }
  const std::filesystem::path& dir() const { return dir_; }
  /// The entry called `name`; throws std::runtime_error if the set has none.
  const FileEntry& file(const std::string& name) const;

  /// The beats of a hex file, checked against width_bits and beats.
  std::vector<scw::sim::Bits> read_hex(const std::string& name) const;
  /// The image as stored (cv::IMREAD_UNCHANGED), checked against width, height and type.
  cv::Mat read_image(const std::string& name) const;
  /// The data rows of a CSV file; the header row goes to `*header` if given.
  std::vector<std::vector<std::string>> read_csv(const std::string& name,
                                                 std::vector<std::string>* header = nullptr) const;

 private:
  VectorSet(std::filesystem::path dir, Manifest manifest)
      : dir_(std::move(dir)), manifest_(std::move(manifest)) {}
  const FileEntry& file_of_kind(const std::string& name, const char* kind1,
                                const char* kind2 = nullptr) const;

  std::filesystem::path dir_;
  Manifest manifest_;
};

}  // namespace scw::vectors
