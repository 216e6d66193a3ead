// SPDX-License-Identifier: Apache-2.0
// `scw vectors labelling`: writes a golden vector set of the labelling stage (Q11.4 disparities
// in, object descriptors and frame status words out), made by the C++ model and checked against
// the flood-fill reference.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/labelling/labelling.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "host/cli/commands.hpp"
#include "host/labelling/run_model.hpp"
#include "host/labelling/second_pass.hpp"
#include "host/reference/labelling_ref.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/frame_beats.hpp"
#include "sim/labelling_model.hpp"
#include "sim/labelling_pack.hpp"
#include "sim/pack.hpp"
#include "sim/stall.hpp"
#include "sim/stream_check.hpp"

namespace scw::cli {
namespace {

using hls::labelling::FrameStatus;
using hls::labelling::LabellingConfig;
using hls::labelling::LabelPacket;
using hls::labelling::Object;

// The golden-vector build of the stage: frames up to 64 x 48, up to 4 x 4 tiles, 16 labels a tile
// (256 a frame), 64 objects a frame. Small tables, so that the overflow preset can exhaust them
// with a readable frame; a replay builds scw_labelling with these parameters.
constexpr int kMaxWidthPx = 64;
constexpr int kMaxHeight = 48;
constexpr int kMaxTilesX = 4;
constexpr int kMaxTilesY = 4;
constexpr int kLabelsPerTile = 16;
constexpr int kMaxObjects = 64;
using VecParams = hls::labelling::LabellingParams<kMaxWidthPx, kMaxHeight, kMaxTilesX, kMaxTilesY,
                                                  kLabelsPerTile, kMaxObjects>;
using InBeat = VecParams::in_beat;
using Model = sim::LabellingModel<VecParams>;
using Layout = sim::BeatLayout<LabelPacket>;

// Every preset streams frames of this size (the build's largest).
constexpr int kW = 64;
constexpr int kH = 48;

struct Options {
  std::string preset;
  std::string out;
  std::string data_dir = "data/tsukuba";
};

/// What the stage must report for a frame.
enum class Expect {
  kClean,           // exactly the reference's objects, no flag
  kTileOverflow,    // a tile runs out of labels: tile_overflow only
  kObjectOverflow,  // more than kMaxObjects objects: object_overflow only, kMaxObjects emitted
};

struct Frame {
  std::string name;
  cv::Mat d;  // CV_16UC1, kW x kH, Q11.4
  Expect expect = Expect::kClean;
};

struct Preset {
  std::vector<Frame> frames;
  LabellingConfig cfg;
  int tiles_x = 1, tiles_y = 1;
  std::string description;
};

cv::Mat blank() { return cv::Mat::zeros(kH, kW, CV_16UC1); }
void put(cv::Mat& m, int x, int y, int d) {
  if (x >= 0 && x < m.cols && y >= 0 && y < m.rows)
    m.at<std::uint16_t>(y, x) = static_cast<std::uint16_t>(d);
}

// ---- shapes: the cases a one-pass labeller gets wrong, each made by a few lines of its own ----

/// A square spiral one pixel wide with one-pixel gaps between its turns, drawn as a turtle path
/// from the top left corner inwards. The disparity rises by 1 every 16 path pixels, so path
/// neighbours always join and the closest point is the centre, which raster order reaches late.
cv::Mat spiral() {
  cv::Mat m = blank();
  static const int kDx[4] = {1, 0, -1, 0}, kDy[4] = {0, 1, 0, -1};
  int x = 0, y = 0, dir = 0, step = 0;
  put(m, x, y, 256);
  // Leg lengths: w-1, h-1, w-1, then every leg 2 shorter than the leg two before it.
  int len[2] = {kW - 1, kH - 1};
  for (int leg = 0;; ++leg) {
    int n = len[leg % 2];
    if (leg >= 3) n = len[leg % 2] -= 2;  // from the fourth leg on, the turns close in
    if (n <= 0) break;
    for (int i = 0; i < n; ++i) {
      x += kDx[dir], y += kDy[dir];
      put(m, x, y, 256 + (++step) / 16);
    }
    dir = (dir + 1) % 4;
  }
  return m;
}

/// Two combs, each with its bar below its teeth, so that every tooth holds a label of its own
/// until the bar row merges them all: 32 teeth on the even columns over a bar on row 22, and 32
/// on the odd columns over a bar on the last row, at disparities that vary per tooth but join
/// the bar.
cv::Mat comb() {
  cv::Mat m = blank();
  for (int x = 0; x < kW; x += 2)
    for (int y = 1; y <= 22; ++y) put(m, x, y, 400);
  for (int x = 0; x < kW; ++x) put(m, x, 22, 400);
  for (int x = 1; x < kW; x += 2)
    for (int y = 25; y < kH; ++y) put(m, x, y, 200 + 4 * (x % 5));
  for (int x = 0; x < kW; ++x) put(m, x, kH - 1, 202);
  return m;
}

/// Twelve nested U shapes open to the top, one pixel apart: each U's two arms meet only in its
/// bottom row, and the inner Us merge later in raster order than the outer ones close.
/// Neighbouring Us alternate near and far disparities.
cv::Mat nested_u() {
  cv::Mat m = blank();
  for (int k = 0; k < 12; ++k) {
    const int d = (k % 2 ? 160 : 480) + 8 * k;
    const int xl = 2 * k, xr = kW - 1 - 2 * k, yb = kH - 1 - 2 * k;
    for (int y = 0; y <= yb; ++y) put(m, xl, y, d), put(m, xr, y, d);
    for (int x = xl; x <= xr; ++x) put(m, x, yb, d);
  }
  return m;
}

/// A staircase of 2-wide, 3-tall steps from the top left corner towards the bottom right, each
/// step sharing an edge with the next (so it crosses tile borders on every row and column of
/// tiles), inside a one-pixel frame on the image border at a disparity that does not join it.
cv::Mat staircase() {
  cv::Mat m = blank();
  for (int i = 0; 2 * i < kH; ++i)
    for (int dy = 0; dy < 3; ++dy)
      for (int dx = 0; dx < 2; ++dx) put(m, 2 * i + dx + 2, 2 * i + dy + 1, 512);
  for (int x = 0; x < kW; ++x) put(m, x, 0, 96), put(m, x, kH - 1, 96);
  for (int y = 0; y < kH; ++y) put(m, 0, y, 96), put(m, kW - 1, y, 96);
  return m;
}

/// Lines on every 8th row and column (one object across every tile border) and a dot in the
/// middle of each cell (48 one-pixel objects at a disparity that does not join the mesh).
cv::Mat mesh() {
  cv::Mat m = blank();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (x % 8 == 0 || y % 8 == 0) put(m, x, y, 256);
      if (x % 8 == 4 && y % 8 == 4) put(m, x, y, 800);
    }
  return m;
}

Preset shapes() {
  Preset p;
  // 3 x 4 tiles of 22 x 13 px, so that neither side divides evenly (the build holds 4 x 4): the
  // last tile column is 20 px wide and the last tile row 9 px tall.
  p.tiles_x = 3;
  p.tiles_y = 4;
  p.cfg = labelling::grid_config(kW, kH, p.tiles_x, p.tiles_y, 0, 1);
  p.cfg.tile_h = 13;
  p.frames = {{"spiral", spiral(), Expect::kClean},
              {"comb", comb(), Expect::kClean},
              {"nested U", nested_u(), Expect::kClean},
              {"staircase", staircase(), Expect::kClean},
              {"mesh", mesh(), Expect::kClean}};
  p.description =
      "scw labelling stage: five 64x48 frames back to back through one stage, 3x4 tiles of "
      "22x13 px (the last column 20 px, the last row 9 px), floor 0, min area 1: a one-pixel "
      "square spiral, two combs merged by their bars, 12 nested U shapes, a staircase inside a "
      "border frame, an 8-px mesh with a dot in each cell";
  return p;
}

// ---- tsukuba: a crop of the bundled ground truth ----

// The crop: regions at three depths (disparity 5, 8 and 14 px) that interlock across the tile
// borders, with thin slivers that the min area of 4 drops (14 components, 11 objects).
constexpr int kCropX = 264;
constexpr int kCropY = 112;

Preset tsukuba(const Options& o) {
  const auto path = std::filesystem::path(o.data_dir) / "truedisp.row3.col3.pgm";
  if (!std::filesystem::exists(path))
    throw std::runtime_error("vectors labelling: no '" + path.string() +
                             "'; the tsukuba set needs data/tsukuba (give --data-dir)");
  const cv::Mat truth = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  if (truth.type() != CV_8UC1 || truth.cols < kCropX + kW || truth.rows < kCropY + kH)
    throw std::runtime_error("vectors labelling: '" + path.string() +
                             "' is not the 8-bit 384x288 Tsukuba ground truth");
  // Middlebury stores disparity x 16 in 8 bits: already the stage's Q11.4.
  cv::Mat d;
  truth(cv::Rect(kCropX, kCropY, kW, kH)).convertTo(d, CV_16UC1);
  Preset p;
  p.tiles_x = 2;
  p.tiles_y = 2;
  p.cfg = labelling::grid_config(kW, kH, p.tiles_x, p.tiles_y, 0, 4);
  p.frames = {{"tsukuba", d, Expect::kClean}};
  std::ostringstream s;
  s << "scw labelling stage: a 64x48 crop (x " << kCropX << " y " << kCropY
    << ") of data/tsukuba truedisp.row3.col3.pgm (8-bit, value = disparity x 16 = Q11.4), "
       "2x2 tiles of 32x24 px, floor 0, min area 4";
  p.description = s.str();
  return p;
}

// ---- overflow: the status flags, and the frame after them ----

/// `cols` x `rows` isolated pixels two pixels apart, the first at (x0, y0): one-pixel objects
/// that never join.
void dots(cv::Mat& m, int x0, int y0, int cols, int rows, int d) {
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) put(m, x0 + 2 * i, y0 + 2 * j, d);
}

Preset overflow() {
  Preset p;
  p.tiles_x = 2;
  p.tiles_y = 2;
  p.cfg = labelling::grid_config(kW, kH, p.tiles_x, p.tiles_y, 0, 2);
  // 1: 16 two-pixel objects, 288 single dots (a label each, below the minimum area), then 16
  // more objects: the 256 labels of the frame run out before the last 16.
  cv::Mat tile = blank();
  dots(tile, 1, 1, 16, 1, 300), dots(tile, 1, 2, 16, 1, 300);
  dots(tile, 0, 6, 32, 9, 300);
  dots(tile, 1, 42, 16, 1, 300), dots(tile, 1, 43, 16, 1, 300);
  // 2: 40 two-pixel objects in each tile (160 labels) make 160 objects, more than the 64 a
  // frame reports.
  cv::Mat objects = blank();
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      const int d = 320 + 16 * (2 * ty + tx);
      dots(objects, 32 * tx + 4, 24 * ty + 4, 10, 2, d);
      dots(objects, 32 * tx + 4, 24 * ty + 5, 10, 2, d);
      dots(objects, 32 * tx + 4, 24 * ty + 12, 10, 2, d);
      dots(objects, 32 * tx + 4, 24 * ty + 13, 10, 2, d);
    }
  // 3: an ordinary frame: two blocks and a ring across tile borders, which must come out whole.
  cv::Mat normal = blank();
  for (int y = 2; y < 14; ++y)  // across the vertical border; a ramp whose steps all join
    for (int x = 6; x < 40; ++x) put(normal, x, y, 200 + (x - 6) / 4);
  for (int y = 18; y < 44; ++y)  // across the horizontal border
    for (int x = 44; x < 58; ++x) put(normal, x, y, 640);
  for (int a = 0; a < 16; ++a) {  // a 16 x 16 square ring around the tile corner (32, 24)
    put(normal, 20 + a, 18, 360), put(normal, 20 + a, 33, 360);
    put(normal, 20, 18 + a, 360), put(normal, 35, 18 + a, 360);
  }
  p.frames = {{"tile overflow", tile, Expect::kTileOverflow},
              {"object overflow", objects, Expect::kObjectOverflow},
              {"normal", normal, Expect::kClean}};
  p.description =
      "scw labelling stage: three 64x48 frames, 2x2 tiles of 32x24 px, floor 0, min area 2: "
      "16 two-pixel objects, 288 isolated dots, 16 more objects (256 labels a frame: "
      "tile_overflow, the first 16 objects reported), 40 two-pixel objects in each tile (160 "
      "objects, 64 reported: object_overflow), then "
      "an ordinary frame (a ramp, a block, a ring around the tile corner) reported whole with a "
      "clean status";
  return p;
}

// ---- running and checking ----

/// One frame's burst as the stage emitted it, and its label image.
struct FrameOut {
  std::vector<Object> objects;  // in output order
  FrameStatus status;
  cv::Mat labels;  // CV_16UC1: the number of the object holding each pixel, else 0
  std::vector<std::uint16_t> label_of;  // objects[i]'s number in `labels`
};

/// The model's second pass on the frame it has just emitted, on the vector build itself, so that
/// in an overflow frame the image shows exactly the objects the stage reported.
void second_pass(const Model::kernel_type& k, const std::vector<std::int32_t>& node_map, FrameOut& f) {
  auto n = labelling::number_objects(f.objects, node_map, kW, kH,
                                     [&k](int node) { return k.root(node); });
  f.labels = n.labels;
  f.label_of = std::move(n.label_of);
}

/// Every frame back to back through one stage, no stalls, from reset.
std::vector<FrameOut> run_model(const Preset& p, const std::vector<InBeat>& beats,
                                std::vector<LabelPacket>& words, std::int64_t& cycles) {
  const auto model = std::make_unique<Model>(p.cfg);  // descriptor RAMs: off the stack
  std::vector<std::int32_t> node_map(static_cast<std::size_t>(kW) * kH, 0);
  model->kernel().set_node_map(&node_map);
  std::vector<FrameOut> frames(1);
  std::size_t next = 0;
  const std::int64_t limit = 64 * static_cast<std::int64_t>(beats.size()) + 64 * VecParams::kNodes;
  for (cycles = 0; frames.size() <= p.frames.size(); ++cycles) {
    if (cycles > limit) throw std::logic_error("vectors labelling: the model did not finish");
    const bool valid = next < beats.size();
    const auto o = model->eval(valid, valid ? beats[next] : InBeat{}, true);
    if (o.out_valid) {
      words.push_back(o.out);
      if (o.out.last != o.out.data.is_status)
        throw std::logic_error("vectors labelling: `last` is not on the status word alone");
      FrameOut& f = frames.back();
      if (!o.out.data.is_status) {
        f.objects.push_back(o.out.data.object);
      } else {
        // The node map and the roots stay this frame's until the next frame's Resolve.
        f.status = o.out.data.status;
        second_pass(model->kernel(), node_map, f);
        frames.emplace_back();
      }
    }
    model->tick();
    if (valid && o.in_ready) ++next;
  }
  frames.pop_back();
  if (next != beats.size()) throw std::logic_error("vectors labelling: input beats left over");
  if (model->kernel().error()) throw std::logic_error("vectors labelling: the stage raised err");
  return frames;
}

std::string status_text(const FrameStatus& s) {
  std::ostringstream t;
  t << s.objects << " objects, tile_overflow " << s.tile_overflow << ", object_overflow "
    << s.object_overflow << ", stream_error " << s.stream_error;
  return t.str();
}

/// Throws unless the model's frame is what the reference says it must be.
void check_frame(const Preset& p, const Frame& in, const FrameOut& got) {
  const std::string at = "vectors labelling: frame '" + in.name + "': ";
  const auto ref = reference::labelling_reference(in.d.ptr<std::uint16_t>(), kW, kH, p.cfg);
  if (got.status.objects != got.objects.size() || got.status.stream_error)
    throw std::runtime_error(at + "status " + status_text(got.status) + " for " +
                             std::to_string(got.objects.size()) + " objects emitted");
  const auto in_ref = [&](const Object& o) {
    return std::find(ref.objects.begin(), ref.objects.end(), o) != ref.objects.end();
  };
  switch (in.expect) {
    case Expect::kClean: {
      if (got.status.tile_overflow || got.status.object_overflow ||
          got.objects.size() != ref.objects.size())
        throw std::runtime_error(at + "the model gives " + status_text(got.status) +
                                 ", the reference finds " + std::to_string(ref.objects.size()) +
                                 " objects and no overflow");
      const auto sorted = labelling::raster_sorted(got.objects);
      for (std::size_t i = 0; i < sorted.size(); ++i)
        if (sorted[i] != ref.objects[i])
          throw std::runtime_error(
              at + "object " + std::to_string(i + 1) + " in raster order (first pixel x " +
              std::to_string(sorted[i].first_x) + " y " + std::to_string(sorted[i].first_y) +
              ") differs from the reference's");
      if (!std::equal(ref.labels.begin(), ref.labels.end(), got.labels.begin<std::uint16_t>()))
        throw std::runtime_error(at + "the label image differs from the reference's");
      // And the host's segment() (its own, larger build) labels the frame the same way.
      const auto host = labelling::segment(in.d, p.cfg);
      if (host.objects_by_label != ref.objects ||
          cv::norm(host.labels, got.labels, cv::NORM_INF) != 0)
        throw std::runtime_error(at + "segment() at the host's build differs");
      break;
    }
    case Expect::kTileOverflow:
    case Expect::kObjectOverflow: {
      const bool tile = in.expect == Expect::kTileOverflow;
      if (got.status.tile_overflow != tile || got.status.object_overflow == tile)
        throw std::runtime_error(at + "expected " +
                                 (tile ? "tile_overflow alone" : "object_overflow alone") +
                                 ", the model gives " + status_text(got.status));
      if (!tile && got.objects.size() != static_cast<std::size_t>(kMaxObjects))
        throw std::runtime_error(at + "an object overflow must report " +
                                 std::to_string(kMaxObjects) + " objects");
      // The objects never join, so every one reported is whole: one of the reference's.
      for (const Object& o : got.objects)
        if (!in_ref(o))
          throw std::runtime_error(at + "the object at x " + std::to_string(o.first_x) + " y " +
                                   std::to_string(o.first_y) + " is not one of the reference's");
      if (got.objects.size() >= ref.objects.size())
        throw std::runtime_error(at + "nothing was dropped: not an overflow");
      break;
    }
  }
}

/// Frames stacked top to bottom in stream order: one image a set.
cv::Mat stacked(const std::vector<cv::Mat>& frames) {
  cv::Mat all;
  cv::vconcat(frames, all);
  return all;
}

nlohmann::json word_layout() {
  // The generic {last, data} description, plus the two shapes the 897-bit data takes
  // (sim/labelling_pack.hpp): bit 0 tells them apart.
  nlohmann::json l = vectors::stream_beat_layout(Layout::kPayloadBits);
  nlohmann::json obj = nlohmann::json::array();
  obj.push_back({{"name", "is_status"}, {"lsb", 0}, {"bits", 1}});
  obj.push_back({{"name", "area"}, {"lsb", 1}, {"bits", 32}});
  int at = 33;
  for (const char* n : {"x_min", "x_max", "y_min", "y_max", "d_min", "d_max", "closest_x",
                        "closest_y", "first_x", "first_y"}) {
    obj.push_back({{"name", n}, {"lsb", at}, {"bits", 16}});
    at += 16;
  }
  for (const char* n :
       {"m10", "m01", "m20", "m11", "m02", "m30", "m21", "m12", "m03", "sum_d", "sum_dd"}) {
    obj.push_back({{"name", n}, {"lsb", at}, {"bits", 64}});
    at += 64;
  }
  l["object_fields"] = obj;
  l["status_fields"] =
      nlohmann::json::array({{{"name", "is_status"}, {"lsb", 0}, {"bits", 1}},
                             {{"name", "objects"}, {"lsb", 1}, {"bits", 32}},
                             {{"name", "tile_overflow"}, {"lsb", 33}, {"bits", 1}},
                             {{"name", "object_overflow"}, {"lsb", 34}, {"bits", 1}},
                             {{"name", "stream_error"}, {"lsb", 35}, {"bits", 1}}});
  return l;
}

void run(const Options& o, const Preset& p) {
  hls::labelling::check_config<VecParams>(p.cfg);
  std::vector<InBeat> beats;
  std::vector<cv::Mat> images;
  for (const Frame& f : p.frames) {
    if (f.d.type() != CV_16UC1 || f.d.cols != kW || f.d.rows != kH || !f.d.isContinuous())
      throw std::logic_error("vectors labelling: a frame is not 64x48 16-bit");
    const auto b = sim::frame_beats_of<InBeat>(f.d.ptr<std::uint16_t>(), kW, kH);
    beats.insert(beats.end(), b.begin(), b.end());
    images.push_back(f.d);
  }
  std::vector<LabelPacket> words;
  std::int64_t cycles = 0;
  const auto frames = run_model(p, beats, words, cycles);
  if (frames.size() != p.frames.size())
    throw std::logic_error("vectors labelling: the model closed another number of frames");
  for (std::size_t i = 0; i < frames.size(); ++i) check_frame(p, p.frames[i], frames[i]);
  {
    // A replay stalls both sides; the words it must see cannot depend on that.
    const auto m = std::make_unique<Model>(p.cfg);
    const auto r = sim::run_stream(*m, beats, sim::StallPattern{sim::StallKind::kBoth, 0},
                                   words.size(), 4'000'000);
    if (r.timed_out || !r.violations.empty() || r.out != words)
      throw std::logic_error("vectors labelling: the model's words change under stalls");
  }
  std::cout << "C++ model: " << frames.size() << " frames, " << words.size()
            << " words, checked against the flood-fill reference (" << cycles << " cycles)\n";

  const LabellingConfig& c = p.cfg;
  const nlohmann::json config = {{"max_width_px", kMaxWidthPx},
                                 {"max_height", kMaxHeight},
                                 {"max_tiles_x", kMaxTilesX},
                                 {"max_tiles_y", kMaxTilesY},
                                 {"labels_per_tile", kLabelsPerTile},
                                 {"max_objects", kMaxObjects},
                                 {"width", c.width},
                                 {"height", c.height},
                                 {"tile_w", c.tile_w},
                                 {"tile_h", c.tile_h},
                                 {"tiles_x", p.tiles_x},
                                 {"tiles_y", p.tiles_y},
                                 {"floor", c.floor},
                                 {"min_area", c.min_area},
                                 {"frames", frames.size()},
                                 {"beats_in", beats.size()},
                                 {"words_out", words.size()}};

  std::vector<sim::Bits> in_words, out_words;
  for (const auto& b : beats) in_words.push_back(sim::pack(b));
  for (const auto& w : words) out_words.push_back(sim::pack(w));

  // One row per object word, in stream order; `word` is its line in expected.hex (from 0),
  // `label` its number in labels.png.
  std::vector<std::vector<std::string>> obj_rows, status_rows;
  std::vector<cv::Mat> label_images;
  std::size_t line = 0;
  for (std::size_t fi = 0; fi < frames.size(); ++fi) {
    const FrameOut& f = frames[fi];
    for (std::size_t i = 0; i < f.objects.size(); ++i, ++line) {
      const Object& b = f.objects[i];
      std::vector<std::string> r = {std::to_string(fi), std::to_string(line),
                                    std::to_string(f.label_of[i]), std::to_string(b.area)};
      for (std::uint16_t v : {b.x_min, b.x_max, b.y_min, b.y_max, b.d_min, b.d_max, b.closest_x,
                              b.closest_y, b.first_x, b.first_y})
        r.push_back(std::to_string(v));
      for (std::uint64_t v :
           {b.m10, b.m01, b.m20, b.m11, b.m02, b.m30, b.m21, b.m12, b.m03, b.sum_d, b.sum_dd})
        r.push_back(std::to_string(v));
      obj_rows.push_back(std::move(r));
    }
    status_rows.push_back({std::to_string(fi), std::to_string(line),
                           std::to_string(f.status.objects),
                           std::to_string(f.status.tile_overflow ? 1 : 0),
                           std::to_string(f.status.object_overflow ? 1 : 0),
                           std::to_string(f.status.stream_error ? 1 : 0)});
    ++line;
    label_images.push_back(f.labels);
  }

  vectors::VectorWriter vw(o.out, "labelling", config, p.description);
  vw.add_hex("in.hex", "input", in_words, vectors::pixel_beat_layout(1, 16));
  vw.add_image("in.png", "input", stacked(images));
  vw.add_hex("expected.hex", "expected", out_words, word_layout());
  vw.add_csv(
      "expected_objects.csv", "expected",
      {"frame", "word",      "label",     "area",    "x_min",   "x_max", "y_min", "y_max", "d_min",
       "d_max", "closest_x", "closest_y", "first_x", "first_y", "m10",   "m01",   "m20",   "m11",
       "m02",   "m30",       "m21",       "m12",     "m03",     "sum_d", "sum_dd"},
      obj_rows);
  vw.add_csv("expected_status.csv", "expected",
             {"frame", "word", "objects", "tile_overflow", "object_overflow", "stream_error"},
             status_rows);
  vw.add_image("labels.png", "expected", stacked(label_images));
  vw.finish();
  std::cout << "wrote " << o.out << "/ (" << frames.size() << " frames of " << kW << "x" << kH
            << ", " << p.tiles_x << "x" << p.tiles_y << " tiles, " << obj_rows.size()
            << " objects, " << words.size() << " words)\n";
}

}  // namespace

void add_vectors_labelling_command(CLI::App& vectors) {
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "labelling", "Write a labelling golden vector set (disparities in, object words out)");
  cmd->add_option("--preset", o->preset,
                  "shapes (five 64x48 adversarial shapes, 3x4 tiles), tsukuba (64x48 crop of "
                  "the bundled ground truth, 2x2 tiles, min area 4) or overflow (a tile and an "
                  "object overflow, then a normal frame)")
      ->required()
      ->check(CLI::IsMember({"shapes", "tsukuba", "overflow"}));
  cmd->add_option("--out", o->out, "Vector set directory to write")->required();
  cmd->add_option("--data-dir", o->data_dir, "Folder with truedisp.row3.col3.pgm");
  cmd->callback([o] {
    if (o->preset == "shapes")
      run(*o, shapes());
    else if (o->preset == "tsukuba")
      run(*o, tsukuba(*o));
    else
      run(*o, overflow());
  });
}

}  // namespace scw::cli
