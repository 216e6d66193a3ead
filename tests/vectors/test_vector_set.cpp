// SPDX-License-Identifier: Apache-2.0
// Golden vector sets: round trips, checksums, reproducibility and clear errors on bad input.
#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <opencv2/core.hpp>
#include <random>
#include <string>
#include <vector>

#include "host/vectors/compare_sets.hpp"
#include "host/vectors/vector_set.hpp"

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using nlohmann::json;
using scw::sim::Bits;
using scw::vectors::FileEntry;
using scw::vectors::Manifest;
using scw::vectors::VectorSet;
using scw::vectors::VectorWriter;

// A fresh directory per test, removed afterwards even when the test fails.
class TempDir {
 public:
  TempDir() {
    static std::atomic<unsigned> counter{0};
    std::random_device rd;
    do {
      path_ = fs::temp_directory_path() /
              ("scw_vectors_test_" + std::to_string(rd()) + "_" + std::to_string(counter++));
    } while (!fs::create_directory(path_));
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void spit(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << bytes;
}

// {eol, sof, px[P-1], ..., px[0]}, the RTL FIFO word.
Bits pixel_beat(const std::vector<std::uint64_t>& px, int bits, bool sof, bool eol) {
  const int p = static_cast<int>(px.size());
  Bits b(p * bits + 2);
  for (int i = 0; i < p; ++i) b.set(i * bits, bits, px[static_cast<std::size_t>(i)]);
  b.set(p * bits, 1, sof);
  b.set(p * bits + 1, 1, eol);
  return b;
}

// A 4x2 frame of 8-bit pixels, two per beat: 4 beats of 18 bits.
std::vector<Bits> frame_beats() {
  return {pixel_beat({0x12, 0xab}, 8, true, false), pixel_beat({0x00, 0xff}, 8, false, true),
          pixel_beat({0x7f, 0x80}, 8, false, false), pixel_beat({0x01, 0x02}, 8, false, true)};
}

cv::Mat random_image(int rows, int cols, int type, unsigned seed) {
  cv::Mat m(rows, cols, type);
  cv::theRNG().state = seed;
  cv::randu(m, cv::Scalar::all(0), cv::Scalar::all(type == CV_16UC1 ? 65536 : 256));
  return m;
}

bool same_image(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

const json kConfig = {{"width", 4}, {"height", 2}, {"pixels_per_beat", 2}, {"window", 5}};

// Every kind of file, so tampering and reproducibility are checked across all of them.
void write_sample_set(const fs::path& dir) {
  VectorWriter w(dir, "rectify", kConfig, "sample set for tests");
  w.add_hex("in.hex", "input", frame_beats(), scw::vectors::pixel_beat_layout(2, 8));
  std::vector<Bits> objects;
  for (std::uint64_t i = 0; i < 3; ++i) {
    Bits b(17);
    b.set(0, 16, 0x1000 * i + 7);
    b.set(16, 1, i == 2);
    objects.push_back(b);
  }
  w.add_hex("out.hex", "expected", objects, scw::vectors::stream_beat_layout(16));
  w.add_image("left.png", "input", random_image(5, 7, CV_8UC1, 1));
  w.add_image("depth.png", "expected", random_image(5, 7, CV_16UC1, 2));
  w.add_image("overlay.png", "expected", random_image(5, 7, CV_8UC3, 3));
  w.add_image("right.pgm", "input", random_image(5, 7, CV_8UC1, 4));
  w.add_image("disp.pgm", "expected", random_image(5, 7, CV_16UC1, 5));
  w.add_csv("objects.csv", "expected", {"id", "x", "y", "severity"},
            {{"0", "12", "3", "high"}, {"1", "40", "17", ""}});
  w.finish();
}

// Edits manifest.json as JSON, for tests that need a manifest scw would never write.
void edit_manifest(const fs::path& dir, const std::function<void(json&)>& edit) {
  json j = json::parse(slurp(dir / "manifest.json"));
  edit(j);
  spit(dir / "manifest.json", j.dump(2) + "\n");
}

// Replaces a file and records its new checksum, so the check after the checksum is reached.
void replace_and_rehash(const fs::path& dir, const std::string& name, const std::string& bytes) {
  spit(dir / name, bytes);
  const std::string sha = scw::vectors::sha256_file(dir / name);
  edit_manifest(dir, [&](json& j) {
    for (auto& f : j["files"])
      if (f["name"] == name) f["sha256"] = sha;
  });
}

}  // namespace

TEST_CASE("SHA-256 matches the published FIPS 180-2 test vectors", "[vectors]") {
  using scw::vectors::sha256_bytes;
  CHECK(sha256_bytes("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_bytes("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_bytes("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");

  TempDir tmp;
  spit(tmp.path() / "abc.bin", "abc");
  CHECK(scw::vectors::sha256_file(tmp.path() / "abc.bin") ==
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // One million 'a': larger than the reader's buffer, so chunking is exercised.
  spit(tmp.path() / "million.bin", std::string(1000000, 'a'));
  CHECK(scw::vectors::sha256_file(tmp.path() / "million.bin") ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  CHECK_THROWS_WITH(scw::vectors::sha256_file(tmp.path() / "absent.bin"), Contains("absent.bin"));
}

TEST_CASE("hex files round trip as plain $readmemh text", "[vectors]") {
  TempDir tmp;
  std::vector<Bits> wide;
  for (std::uint64_t i = 0; i < 5; ++i) {
    Bits b(70);  // spans three 32-bit words, top digit holds 2 bits
    b.set(0, 64, 0x0123456789abcdefULL * (i + 1));
    b.set(64, 6, 0x3f - i);
    wide.push_back(b);
  }
  std::vector<Bits> single;
  for (int i = 0; i < 4; ++i) {
    Bits b(1);
    b.set(0, 1, static_cast<std::uint64_t>(i & 1));
    single.push_back(b);
  }
  {
    VectorWriter w(tmp.path(), "disparity", kConfig);
    w.add_hex("frame.hex", "input", frame_beats(), scw::vectors::pixel_beat_layout(2, 8));
    w.add_hex("wide.hex", "expected", wide);
    w.add_hex("single.hex", "expected", single);
    w.finish();
  }
  // px0 = 0x12 at [7:0], px1 = 0xab at [15:8], sof at 16, eol at 17.
  CHECK(slurp(tmp.path() / "frame.hex") == "1ab12\n2ff00\n0807f\n20201\n");
  CHECK(slurp(tmp.path() / "single.hex") == "0\n1\n0\n1\n");

  const VectorSet set = VectorSet::open(tmp.path());
  CHECK(set.read_hex("frame.hex") == frame_beats());
  CHECK(set.read_hex("wide.hex") == wide);
  CHECK(set.read_hex("single.hex") == single);
  const FileEntry& f = set.file("frame.hex");
  CHECK(f.role == "input");
  CHECK(f.kind == "hex");
  CHECK(f.meta.at("width_bits") == 18);
  CHECK(f.meta.at("beats") == 4);
  CHECK(f.meta.at("layout") == scw::vectors::pixel_beat_layout(2, 8));
  CHECK_FALSE(set.file("wide.hex").meta.contains("layout"));
  CHECK(set.file("wide.hex").meta.at("width_bits") == 70);
  CHECK(set.manifest().stage == "disparity");
  CHECK(set.manifest().config == kConfig);
}

TEST_CASE("beat layouts describe {eol, sof, pixels} and {last, data}", "[vectors]") {
  const json px = scw::vectors::pixel_beat_layout(4, 8);
  REQUIRE(px.at("fields").size() == 6);
  CHECK(px.at("fields")[3] == json({{"name", "px3"}, {"lsb", 24}, {"bits", 8}}));
  CHECK(px.at("fields")[4] == json({{"name", "sof"}, {"lsb", 32}, {"bits", 1}}));
  CHECK(px.at("fields")[5] == json({{"name", "eol"}, {"lsb", 33}, {"bits", 1}}));
  const json st = scw::vectors::stream_beat_layout(40);
  CHECK(st.at("fields")[1] == json({{"name", "last"}, {"lsb", 40}, {"bits", 1}}));
}

TEST_CASE("images round trip through PNG and PGM", "[vectors]") {
  TempDir tmp;
  const cv::Mat g8 = random_image(6, 9, CV_8UC1, 11);
  const cv::Mat g16 = random_image(6, 9, CV_16UC1, 12);
  const cv::Mat bgr = random_image(6, 9, CV_8UC3, 13);
  {
    VectorWriter w(tmp.path(), "rectify", kConfig);
    w.add_image("g8.png", "input", g8);
    w.add_image("g16.png", "input", g16);
    w.add_image("bgr.png", "expected", bgr);
    w.add_image("g8.pgm", "input", g8);
    w.add_image("g16.pgm", "expected", g16);
    w.finish();
  }
  const VectorSet set = VectorSet::open(tmp.path());
  CHECK(same_image(set.read_image("g8.png"), g8));
  CHECK(same_image(set.read_image("g16.png"), g16));
  CHECK(same_image(set.read_image("bgr.png"), bgr));
  CHECK(same_image(set.read_image("g8.pgm"), g8));
  CHECK(same_image(set.read_image("g16.pgm"), g16));
  CHECK(set.file("g16.pgm").meta == json({{"width", 9}, {"height", 6}, {"type", "16UC1"}}));
  CHECK(set.file("bgr.png").meta.at("type") == "8UC3");
  // Binary PGM with a plain header, readable by any tool.
  CHECK(slurp(tmp.path() / "g8.pgm").rfind("P5\n9 6\n255\n", 0) == 0);
}

TEST_CASE("CSV tables round trip with their header", "[vectors]") {
  TempDir tmp;
  const std::vector<std::string> header = {"id", "x", "label"};
  const std::vector<std::vector<std::string>> rows = {
      {"0", "-3", "pedestrian"}, {"1", "", "cyclist"}, {"2", "4.5", ""}};
  {
    VectorWriter w(tmp.path(), "labelling", kConfig);
    w.add_csv("objects.csv", "expected", header, rows);
    w.add_csv("one_column.csv", "expected", {"v"}, {{"a"}, {""}, {"b"}});
    w.add_csv("no_rows.csv", "expected", {"a", "b"}, {});
    w.finish();
  }
  CHECK(slurp(tmp.path() / "objects.csv") == "id,x,label\n0,-3,pedestrian\n1,,cyclist\n2,4.5,\n");
  const VectorSet set = VectorSet::open(tmp.path());
  std::vector<std::string> got_header;
  CHECK(set.read_csv("objects.csv", &got_header) == rows);
  CHECK(got_header == header);
  CHECK(set.read_csv("one_column.csv") ==
        std::vector<std::vector<std::string>>{{"a"}, {""}, {"b"}});
  CHECK(set.read_csv("no_rows.csv").empty());
  CHECK(set.file("objects.csv").meta == json({{"rows", 3}, {"columns", 3}}));
}

TEST_CASE("a set is byte-for-byte reproducible and holds no paths", "[vectors]") {
  TempDir a;
  TempDir b;
  write_sample_set(a.path());
  write_sample_set(b.path());
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(a.path())) {
    const std::string name = entry.path().filename().string();
    CAPTURE(name);
    CHECK(slurp(entry.path()) == slurp(b.path() / name));
    ++files;
  }
  CHECK(files == 9);  // eight data files and the manifest

  const std::string text = slurp(a.path() / "manifest.json");
  CHECK(text.find(a.path().string()) == std::string::npos);
  CHECK(text.find(fs::temp_directory_path().string()) == std::string::npos);
  CHECK(text.rfind("{\n  \"format\": \"scw-vectors/1\",\n  \"stage\": \"rectify\",", 0) == 0);
  CHECK(text.back() == '\n');
  // Reading and re-serialising gives the same bytes: the key order is part of the format.
  CHECK(scw::vectors::manifest_text(scw::vectors::read_manifest(a.path())) == text);

  const VectorSet set = VectorSet::open(a.path());
  REQUIRE(set.manifest().files.size() == 8);
  CHECK(set.manifest().files[0].name == "in.hex");  // caller's order is kept
  CHECK(set.manifest().description == "sample set for tests");
  for (const FileEntry& f : set.manifest().files)
    CHECK(f.sha256 == scw::vectors::sha256_file(a.path() / f.name));
}

TEST_CASE("a changed or missing file fails verification, naming the file", "[vectors]") {
  TempDir tmp;
  write_sample_set(tmp.path());
  REQUIRE_NOTHROW(VectorSet::open(tmp.path()));

  SECTION("one flipped digit in a hex file") {
    std::string text = slurp(tmp.path() / "out.hex");
    text[0] = text[0] == '0' ? '1' : '0';
    spit(tmp.path() / "out.hex", text);
    CHECK_THROWS_AS(VectorSet::open(tmp.path()), std::runtime_error);
    CHECK_THROWS_WITH(VectorSet::open(tmp.path()), Contains("out.hex") &&
                                                       Contains("SHA-256 mismatch") &&
                                                       Contains("regenerate"));
    const Manifest m = scw::vectors::read_manifest(tmp.path());
    CHECK_NOTHROW(scw::vectors::verify_file(tmp.path(), m.files[0]));
    CHECK_THROWS_WITH(scw::vectors::verify_file(tmp.path(), m.files[1]), Contains("out.hex"));
  }
  SECTION("an image rewritten with the same pixels but different bytes") {
    std::string bytes = slurp(tmp.path() / "right.pgm");
    bytes.insert(2, " ");  // still a valid PGM header, but not the file that was recorded
    spit(tmp.path() / "right.pgm", bytes);
    CHECK_THROWS_WITH(VectorSet::open(tmp.path()), Contains("right.pgm") && Contains("SHA-256"));
  }
  SECTION("a missing file") {
    fs::remove(tmp.path() / "objects.csv");
    CHECK_THROWS_WITH(VectorSet::open(tmp.path()), Contains("objects.csv") && Contains("missing"));
  }
}

TEST_CASE("malformed manifests give clear errors, never a crash", "[vectors]") {
  TempDir tmp;
  write_sample_set(tmp.path());
  const fs::path dir = tmp.path();
  auto open_error = [&]() -> std::string {
    try {
      VectorSet::open(dir);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    FAIL("VectorSet::open accepted a malformed set");
    return "";
  };

  SECTION("no manifest") {
    fs::remove(dir / "manifest.json");
    CHECK_THAT(open_error(), Contains("manifest.json") && Contains("not found"));
  }
  SECTION("not JSON") {
    spit(dir / "manifest.json", "{\"format\": \"scw-vectors/1\",\n  \"stage\": ");
    CHECK_THAT(open_error(), Contains("manifest.json") && Contains("not valid JSON"));
  }
  SECTION("top level is not an object") {
    spit(dir / "manifest.json", "[1, 2]\n");
    CHECK_THAT(open_error(), Contains("JSON object"));
  }
  SECTION("missing field") {
    edit_manifest(dir, [](json& j) { j.erase("stage"); });
    CHECK_THAT(open_error(), Contains("missing field 'stage'"));
  }
  SECTION("a future format version") {
    edit_manifest(dir, [](json& j) { j["format"] = "scw-vectors/2"; });
    CHECK_THAT(open_error(), Contains("'scw-vectors/2'") && Contains("'scw-vectors/1'"));
  }
  SECTION("not a vector set format at all") {
    edit_manifest(dir, [](json& j) { j["format"] = 1; });
    CHECK_THAT(open_error(), Contains("'format' must be a string"));
  }
  SECTION("config is not an object") {
    edit_manifest(dir, [](json& j) { j["config"] = "64x32"; });
    CHECK_THAT(open_error(), Contains("'config' must be an object"));
  }
  SECTION("files is not an array") {
    edit_manifest(dir, [](json& j) { j["files"] = json::object(); });
    CHECK_THAT(open_error(), Contains("'files' must be an array"));
  }
  SECTION("a file entry without a checksum") {
    edit_manifest(dir, [](json& j) { j["files"][1].erase("sha256"); });
    CHECK_THAT(open_error(),
               Contains("files[1] ('out.hex')") && Contains("missing field 'sha256'"));
  }
  SECTION("a checksum that is not 64 lowercase hex digits") {
    edit_manifest(dir, [](json& j) { j["files"][0]["sha256"] = "ABC"; });
    CHECK_THAT(open_error(), Contains("in.hex") && Contains("64 lowercase hex digits"));
  }
  SECTION("an unknown role") {
    edit_manifest(dir, [](json& j) { j["files"][0]["role"] = "golden"; });
    CHECK_THAT(open_error(), Contains("role 'golden'"));
  }
  SECTION("a kind that contradicts the extension") {
    edit_manifest(dir, [](json& j) { j["files"][0]["kind"] = "csv"; });
    CHECK_THAT(open_error(), Contains("in.hex") && Contains("extension"));
  }
  SECTION("a name that leaves the directory") {
    edit_manifest(dir, [](json& j) { j["files"][0]["name"] = "../in.hex"; });
    CHECK_THAT(open_error(), Contains("'../in.hex'") && Contains("no directories"));
  }
  SECTION("a file listed twice") {
    edit_manifest(dir, [](json& j) { j["files"].push_back(j["files"][0]); });
    CHECK_THAT(open_error(), Contains("'in.hex' is listed twice"));
  }
  SECTION("a negative width") {
    edit_manifest(dir, [](json& j) { j["files"][0]["meta"]["width_bits"] = -3; });
    CHECK_THAT(open_error(), Contains("in.hex") && Contains("'width_bits' must be an integer"));
  }
  SECTION("a width given as text") {
    edit_manifest(dir, [](json& j) { j["files"][0]["meta"]["width_bits"] = "18"; });
    CHECK_THAT(open_error(), Contains("'width_bits' must be an integer"));
  }
  SECTION("a three-channel PGM") {
    edit_manifest(dir, [](json& j) { j["files"][5]["meta"]["type"] = "8UC3"; });
    CHECK_THAT(open_error(), Contains("right.pgm") && Contains("single channel"));
  }
  SECTION("declared image size differs from the file") {
    edit_manifest(dir, [](json& j) { j["files"][2]["meta"]["width"] = 8; });
    CHECK_THAT(open_error(), Contains("left.png: is 7x5 CV_8UC1 but the manifest declares 8x5"));
  }
}

TEST_CASE("bad hex lines are reported with file and line", "[vectors]") {
  TempDir tmp;
  write_sample_set(tmp.path());  // in.hex: 4 beats of 18 bits = 5 digits, top digit <= 3
  auto error_for = [&](const std::string& text) -> std::string {
    replace_and_rehash(tmp.path(), "in.hex", text);
    try {
      VectorSet::open(tmp.path());
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    FAIL("VectorSet::open accepted a bad hex file");
    return "";
  };
  CHECK_THAT(error_for("1ab12\n4ff00\n0807f\n20201\n"),
             Contains("in.hex line 2") && Contains("wider than 18 bits"));
  CHECK_THAT(error_for("1ab12\n2ff00\n08g7f\n20201\n"),
             Contains("in.hex line 3") && Contains("bad hex digit 'g'"));
  CHECK_THAT(error_for("1ab12\n002ff00\n0807f\n20201\n"),
             Contains("in.hex line 2") && Contains("has 7 characters, expected 5 hex digits"));
  CHECK_THAT(error_for("1ab12\n2ff00\n807f\n20201\n"),
             Contains("in.hex line 3") && Contains("has 4 characters"));
  CHECK_THAT(error_for("1ab12\n\n2ff00\n0807f\n20201\n"),
             Contains("in.hex line 2") && Contains("is empty"));
  CHECK_THAT(error_for("1ab12\r\n2ff00\r\n0807f\r\n20201\r\n"),
             Contains("in.hex line 1") && Contains("carriage return"));
  CHECK_THAT(error_for("1ab12\n2ff00\n0807f\n20201\n00000\n"),
             Contains("in.hex: has 5 beats (lines) but the manifest declares 4"));
  CHECK_THAT(error_for("// a comment\n"), Contains("in.hex line 1"));
  // A last line without '\n' is still one beat, as $readmemh reads it.
  replace_and_rehash(tmp.path(), "in.hex", "1ab12\n2ff00\n0807f\n20201");
  CHECK(VectorSet::open(tmp.path()).read_hex("in.hex") == frame_beats());
}

TEST_CASE("bad CSV content is reported with file and line", "[vectors]") {
  TempDir tmp;
  write_sample_set(tmp.path());
  auto error_for = [&](const std::string& text) -> std::string {
    replace_and_rehash(tmp.path(), "objects.csv", text);
    try {
      VectorSet::open(tmp.path());
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    FAIL("VectorSet::open accepted a bad CSV file");
    return "";
  };
  CHECK_THAT(error_for("id,x,y,severity\n0,12,3\n1,40,17,\n"),
             Contains("objects.csv line 2") && Contains("has 3 values, the header has 4"));
  CHECK_THAT(error_for("id,x,y,severity\n0,12,3,\"high\"\n1,40,17,\n"),
             Contains("objects.csv line 2") && Contains("quote"));
  CHECK_THAT(error_for("id,x,y\n0,12,3\n1,40,17\n"),
             Contains("objects.csv line 1") && Contains("header has 3 columns"));
  CHECK_THAT(error_for("id,x,y,severity\n0,12,3,high\n"),
             Contains("objects.csv: has 1 data rows but the manifest declares 2"));
  CHECK_THAT(error_for(""), Contains("objects.csv: is empty"));
}

TEST_CASE("a corrupt image is reported, not crashed on", "[vectors]") {
  TempDir tmp;
  write_sample_set(tmp.path());
  replace_and_rehash(tmp.path(), "left.png", "not a png at all");
  CHECK_THROWS_WITH(VectorSet::open(tmp.path()), Contains("left.png: cannot be decoded as png"));
}

TEST_CASE("the writer rejects what it cannot write faithfully", "[vectors]") {
  TempDir tmp;
  VectorWriter w(tmp.path(), "warning", kConfig);
  const std::vector<std::string> header = {"id", "label"};

  CHECK_THROWS_WITH(w.add_csv("t.csv", "expected", header, {{"0", "a,b"}}),
                    Contains("t.csv: row 1, column 'label'") && Contains("comma"));
  CHECK_THROWS_WITH(w.add_csv("t.csv", "expected", header, {{"0", "say \"hi\""}}),
                    Contains("t.csv"));
  CHECK_THROWS_WITH(w.add_csv("t.csv", "expected", header, {{"0", "two\nlines"}}),
                    Contains("t.csv"));
  CHECK_THROWS_WITH(w.add_csv("t.csv", "expected", {"id", "a,b"}, {}), Contains("header"));
  CHECK_THROWS_WITH(w.add_csv("t.csv", "expected", header, {{"0"}}),
                    Contains("row 1 has 1 values, the header has 2"));
  CHECK_FALSE(fs::exists(tmp.path() / "t.csv"));  // nothing half-written

  CHECK_THROWS_AS(w.add_hex("x.hex", "input", {}), std::invalid_argument);
  CHECK_THROWS_WITH(w.add_hex("x.hex", "input", {Bits(8), Bits(9)}),
                    Contains("beat 1 is 9 bits wide, beat 0 is 8"));
  CHECK_THROWS_WITH(w.add_hex("sub/x.hex", "input", {Bits(8)}), Contains("no directories"));
  CHECK_THROWS_WITH(w.add_hex("x.txt", "input", {Bits(8)}), Contains("*.hex"));
  CHECK_THROWS_WITH(w.add_hex("manifest.json", "input", {Bits(8)}), Contains("reserved"));
  CHECK_THROWS_WITH(w.add_hex("x.hex", "output", {Bits(8)}), Contains("role 'output'"));
  CHECK_THROWS_WITH(w.add_image("x.jpg", "input", random_image(2, 2, CV_8UC1, 1)),
                    Contains("*.png or *.pgm"));
  CHECK_THROWS_WITH(w.add_image("x.png", "input", cv::Mat(2, 2, CV_32FC1, cv::Scalar(0))),
                    Contains("x.png") && Contains("CV_32FC1"));
  CHECK_THROWS_WITH(w.add_image("x.pgm", "input", random_image(2, 2, CV_8UC3, 1)),
                    Contains("x.pgm") && Contains("8UC1 or 16UC1"));
  CHECK_THROWS_AS(w.add_image("x.png", "input", cv::Mat()), std::invalid_argument);

  w.add_hex("x.hex", "input", {Bits(8)});
  CHECK_THROWS_WITH(w.add_hex("x.hex", "input", {Bits(8)}), Contains("already added"));
  w.finish();
  CHECK_THROWS_AS(w.add_hex("y.hex", "input", {Bits(8)}), std::logic_error);
  CHECK_THROWS_AS(w.finish(), std::logic_error);
  CHECK_THROWS_AS(VectorWriter(tmp.path(), "", kConfig), std::invalid_argument);
  CHECK_THROWS_AS(VectorWriter(tmp.path(), "warning", json::array()), std::invalid_argument);
}

TEST_CASE("reader lookups name what is missing or mismatched", "[vectors]") {
  TempDir tmp;
  write_sample_set(tmp.path());
  const VectorSet set = VectorSet::open(tmp.path());
  CHECK_THROWS_WITH(set.file("nope.hex"), Contains("no file 'nope.hex'") && Contains("in.hex"));
  CHECK_THROWS_WITH(set.read_hex("left.png"), Contains("left.png: is a png file, not hex"));
  CHECK_THROWS_WITH(set.read_image("in.hex"), Contains("not png or pgm"));
  CHECK_THROWS_WITH(set.read_csv("in.hex"), Contains("not csv"));
}

namespace {

// A set of one hex file of `values` (a, b, c per beat), packed as {c, b, a} from bit 0 with a of
// `a_bits` bits (unsigned), b of 8 and c of 4 (signed).
void write_packed_set(const fs::path& dir, int a_bits,
                      const std::vector<std::array<std::int64_t, 3>>& values) {
  std::vector<Bits> beats;
  for (const auto& v : values) {
    Bits b(a_bits + 12);
    b.set(0, a_bits, static_cast<std::uint64_t>(v[0]));
    b.set(a_bits, 8, static_cast<std::uint64_t>(v[1]));
    b.set(a_bits + 8, 4, static_cast<std::uint64_t>(v[2]) & 0xf);
    beats.push_back(b);
  }
  const json layout = {{"fields",
                        {{{"name", "a"}, {"lsb", 0}, {"bits", a_bits}},
                         {{"name", "b"}, {"lsb", a_bits}, {"bits", 8}},
                         {{"name", "c"}, {"lsb", a_bits + 8}, {"bits", 4}, {"signed", true}}}}};
  VectorWriter w(dir, "warning", kConfig);
  w.add_hex("words.hex", "expected", beats, layout);
  w.finish();
}

}  // namespace

TEST_CASE("compare_sets: equal bytes, or equal fields at another packing, and values must agree",
          "[vectors]") {
  using scw::vectors::compare_sets;
  TempDir tmp;
  const fs::path a = tmp.path() / "a", wider = tmp.path() / "wider", same = tmp.path() / "same",
                 changed = tmp.path() / "changed", other = tmp.path() / "other";
  const std::vector<std::array<std::int64_t, 3>> values = {{5, 200, -1}, {0, 7, 3}};
  write_packed_set(a, 6, values);
  write_packed_set(same, 6, values);
  write_packed_set(wider, 10, values);  // field a 4 bits wider: b and c move up
  auto edited = values;
  edited[1][2] = -2;
  write_packed_set(changed, 10, edited);
  write_packed_set(other, 6, edited);

  const auto s = compare_sets(a, same);
  CHECK(s.problems.empty());
  CHECK(s.same == std::vector<std::string>{"words.hex"});
  const auto w = compare_sets(a, wider);
  CHECK(w.problems.empty());
  CHECK(w.repacked == std::vector<std::string>{"words.hex"});
  // A value that differs is named by beat and field (c, signed: -1 in 4 bits is 0b1, -2 0b10).
  const auto c = compare_sets(a, changed);
  REQUIRE(c.problems.size() == 1);
  CHECK_THAT(c.problems[0], Contains("beat 1, field 'c'"));
  // At the same layout, any other byte is a difference: no field by field fallback.
  const auto o = compare_sets(a, other);
  REQUIRE(o.problems.size() == 1);
  CHECK_THAT(o.problems[0], Contains("differs at the same layout"));
  // A file changed after its set was written is named, whatever the other set holds.
  spit(same / "words.hex", slurp(other / "words.hex"));
  CHECK_THROWS_WITH(compare_sets(a, same), Contains("SHA-256 mismatch"));
  CHECK_THROWS_WITH(compare_sets(a, tmp.path() / "none"), Contains("manifest.json"));
}
