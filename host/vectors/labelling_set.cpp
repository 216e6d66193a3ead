// SPDX-License-Identifier: Apache-2.0
// Labelling stage golden vectors: the presets, the model run and its checks against the flood-fill
// reference, the files.
#include "host/vectors/labelling_set.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "hls/labelling/labelling.hpp"
#include "hls/pipeline/pipeline_params.hpp"
#include "host/io/tsukuba.hpp"
#include "host/labelling/run_model.hpp"
#include "host/labelling/second_pass.hpp"
#include "host/labelling/segment_files.hpp"
#include "host/reference/labelling_ref.hpp"
#include "host/vectors/labelling_maps.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/stall.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/labelling_model.hpp"
#include "sim/words/labelling_cfg.hpp"
#include "sim/words/labelling_pack.hpp"
#include "sim/words/pack.hpp"

namespace scw::vectors {
namespace {

using hls::labelling::FrameStatus;
using hls::labelling::LabellingConfig;
using hls::labelling::LabelPacket;
using hls::labelling::Object;

using VecParams = LabellingVecParams;
using Layout = sim::BeatLayout<LabelPacket>;
using Expect = LabellingExpect;
using Preset = LabellingPreset;
constexpr int kMaxObjects = VecParams::kMaxObjects;

// Every preset streams frames of this size (the build's largest).
constexpr int kW = VecParams::kMaxWidthPx;
constexpr int kH = VecParams::kMaxHeight;

cv::Mat blank() { return cv::Mat::zeros(kH, kW, CV_16UC1); }
void put(cv::Mat& m, int x, int y, int d) {
  if (x >= 0 && x < m.cols && y >= 0 && y < m.rows)
    m.at<std::uint16_t>(y, x) = static_cast<std::uint16_t>(d);
}

cv::Mat as_mat(const fixtures::DispMap& m) {
  return cv::Mat(m.h, m.w, CV_16UC1, const_cast<std::uint16_t*>(m.d.data())).clone();
}

// ---- shapes: the cases a one-pass labeller gets wrong (host/vectors/labelling_maps.hpp) ----

/// A square spiral one pixel wide, drawn as a turtle path from the top left corner inwards. The
/// disparity rises by 1 every 16 path pixels, so path neighbours always join and the closest point
/// is the centre, which raster order reaches late. Not fixtures::spiral_map: at 64 x 48 its last
/// leg runs beside the turn before it, and the committed set must keep that centre.
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

Preset shapes() {
  Preset p;
  // 3 x 4 tiles of 22 x 13 px, so that neither side divides evenly (the build holds 4 x 4): the
  // last tile column is 20 px wide and the last tile row 9 px tall.
  p.tiles_x = 3;
  p.tiles_y = 4;
  p.cfg = labelling::grid_config(kW, kH, p.tiles_x, p.tiles_y, 0, 1);
  p.cfg.tile_h = 13;
  // Two combs merged by their bars (a row of margin around them), 12 nested Us whose disparity
  // also steps by 8, a staircase from (2, 1) inside the border frame, an 8-px mesh with dots.
  p.frames = {{"spiral", spiral(), Expect::kClean},
              {"comb", as_mat(fixtures::comb_map(kW, kH, 1)), Expect::kClean},
              {"nested U", as_mat(fixtures::nested_u_map(kW, kH, 12, 8)), Expect::kClean},
              {"staircase", as_mat(fixtures::staircase_map(kW, kH, 2, 1)), Expect::kClean},
              {"mesh", as_mat(fixtures::mesh_map(kW, kH, 8)), Expect::kClean}};
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

Preset tsukuba_preset(const std::filesystem::path& data_dir) {
  // Middlebury stores disparity x 16 in 8 bits: already the stage's Q11.4.
  const cv::Mat d =
      host::io::read_tsukuba_truth(data_dir, CV_16UC1)(cv::Rect(kCropX, kCropY, kW, kH)).clone();
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
template <typename Kernel>
void second_pass(const Kernel& k, const std::vector<std::int32_t>& node_map,
                 const LabellingConfig& cfg, FrameOut& f) {
  auto n = labelling::number_objects(f.objects, node_map, cfg.width, cfg.height,
                                     [&k](int node) { return k.root(node); });
  f.labels = n.labels;
  f.label_of = std::move(n.label_of);
}

/// Every frame back to back through one stage, no stalls, from reset.
template <typename Params>
std::vector<FrameOut> run_model(const Preset& p, const std::vector<typename Params::in_beat>& beats,
                                std::vector<LabelPacket>& words, std::int64_t& cycles) {
  using InBeat = typename Params::in_beat;
  // descriptor RAMs: off the stack
  const auto model = std::make_unique<sim::LabellingModel<Params>>(p.cfg);
  std::vector<std::int32_t> node_map(static_cast<std::size_t>(p.cfg.width) * p.cfg.height, 0);
  model->kernel().set_node_map(&node_map);
  std::vector<FrameOut> frames(1);
  std::size_t next = 0;
  const std::int64_t limit = 64 * static_cast<std::int64_t>(beats.size()) + 64 * Params::kNodes;
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
        second_pass(model->kernel(), node_map, p.cfg, f);
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
  return std::to_string(s.objects) + " objects, " + labelling::status_flags(s);
}

/// Throws unless the model's frame is what the reference says it must be.
template <typename Params>
void check_frame(const Preset& p, const LabellingFrame& in, const FrameOut& got) {
  const std::string at = "vectors labelling: frame '" + in.name + "': ";
  const auto ref =
      reference::labelling_reference(in.d.ptr<std::uint16_t>(), in.d.cols, in.d.rows, p.cfg);
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
        throw std::runtime_error(
            at + "the model gives " + status_text(got.status) + ", the reference finds " +
            std::to_string(ref.objects.size()) +
            " objects and no overflow; a frame must fit the build's tables (" +
            std::to_string(Params::kLabelsPerTile) + " labels a tile, " +
            std::to_string(Params::kMaxObjects) +
            " objects): raise --floor, use more --tiles, or filter the map's speckle");
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
      if (!tile && got.objects.size() != static_cast<std::size_t>(Params::kMaxObjects))
        throw std::runtime_error(at + "an object overflow must report " +
                                 std::to_string(Params::kMaxObjects) + " objects");
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

/// Every frame's beats back to back; `images` gets the frames for in.png.
template <typename InBeat>
std::vector<InBeat> stream_beats(const Preset& p, std::vector<cv::Mat>& images) {
  std::vector<InBeat> beats;
  const int w = p.cfg.width, h = p.cfg.height;
  for (const LabellingFrame& f : p.frames) {
    if (f.d.type() != CV_16UC1 || f.d.cols != w || f.d.rows != h || !f.d.isContinuous())
      throw std::logic_error("vectors labelling: a frame is not the configured " +
                             std::to_string(w) + "x" + std::to_string(h) + " 16-bit");
    const auto b = sim::frame_beats_of<InBeat>(f.d.ptr<std::uint16_t>(), w, h);
    beats.insert(beats.end(), b.begin(), b.end());
    images.push_back(f.d);
  }
  return beats;
}

/// The model's frames, each checked against the reference, and its words the same under stalls.
template <typename Params>
std::vector<FrameOut> checked_frames(const Preset& p,
                                     const std::vector<typename Params::in_beat>& beats,
                                     std::vector<LabelPacket>& words, std::int64_t& cycles) {
  const auto frames = run_model<Params>(p, beats, words, cycles);
  if (frames.size() != p.frames.size())
    throw std::logic_error("vectors labelling: the model closed another number of frames");
  for (std::size_t i = 0; i < frames.size(); ++i) check_frame<Params>(p, p.frames[i], frames[i]);
  // A replay stalls both sides; the words it must see cannot depend on that.
  const auto m = std::make_unique<sim::LabellingModel<Params>>(p.cfg);
  const auto r = sim::run_stream(*m, beats, sim::StallPattern{sim::StallKind::kBoth, 0},
                                 words.size(), 4'000'000);
  if (r.timed_out || !r.violations.empty() || r.out != words)
    throw std::logic_error("vectors labelling: the model's words change under stalls");
  return frames;
}

template <typename Params>
nlohmann::json config_json(const Preset& p, std::size_t frames, std::size_t beats,
                           std::size_t words) {
  const LabellingConfig& c = p.cfg;
  return {{"build", p.build},
          {"max_width_px", Params::kMaxWidthPx},
          {"max_height", Params::kMaxHeight},
          {"max_tiles_x", Params::kMaxTilesX},
          {"max_tiles_y", Params::kMaxTilesY},
          {"labels_per_tile", Params::kLabelsPerTile},
          {"max_objects", Params::kMaxObjects},
          {"width", c.width},
          {"height", c.height},
          {"tile_w", c.tile_w},
          {"tile_h", c.tile_h},
          {"tiles_x", p.tiles_x},
          {"tiles_y", p.tiles_y},
          {"floor", c.floor},
          {"min_area", c.min_area},
          {"frames", frames},
          {"beats_in", beats},
          {"words_out", words}};
}

using Rows = std::vector<std::vector<std::string>>;

/// One expected_objects.csv row: the descriptor, its line in expected.hex and its number in
/// labels.png.
std::vector<std::string> object_row(std::size_t frame, std::size_t line, std::uint16_t label,
                                    const Object& b) {
  std::vector<std::string> r = {std::to_string(frame), std::to_string(line), std::to_string(label)};
  sim::words::for_each(sim::labelling_word::kObjectFields,
                       [&](const auto& f) { r.push_back(std::to_string(b.*f.member)); });
  return r;
}

/// One expected_status.csv row: the frame, its status word's line in expected.hex, its fields.
std::vector<std::string> status_row(std::size_t frame, std::size_t line, const FrameStatus& s) {
  std::vector<std::string> r = {std::to_string(frame), std::to_string(line)};
  sim::words::for_each(sim::labelling_word::kStatusFields,
                       [&](const auto& f) { r.push_back(std::to_string(s.*f.member)); });
  return r;
}

template <typename InBeat>
void write_files(const std::filesystem::path& dir, const Preset& p, const nlohmann::json& config,
                 const std::vector<InBeat>& beats, const std::vector<LabelPacket>& words,
                 const std::vector<cv::Mat>& images, const std::vector<cv::Mat>& label_images,
                 const Rows& obj_rows, const Rows& status_rows) {
  const auto in_words = sim::pack_all(beats);
  const auto out_words = sim::pack_all(words);
  VectorWriter vw(dir, "labelling", config, p.description);
  // The configuration word the testbench puts on cfg_labelling_i (its values in the config).
  add_config_hex<LabellingConfig>(vw, "cfg.hex",
                                  sim::words::pack_word(sim::labelling_cfg::port_config(p.cfg),
                                                        sim::labelling_cfg::kConfigFields),
                                  sim::labelling_cfg::kConfigFields, false);
  vw.add_hex("in.hex", "input", in_words, pixel_beat_layout(1, 16));
  vw.add_image("in.png", "input", stacked_frames(images));
  vw.add_hex("expected.hex", "expected", out_words, labelling_word_layout());
  using sim::words::column_names;
  vw.add_csv("expected_objects.csv", "expected",
             column_names({"frame", "word", "label"}, sim::labelling_word::kObjectFields),
             obj_rows);
  vw.add_csv("expected_status.csv", "expected",
             column_names({"frame", "word"}, sim::labelling_word::kStatusFields), status_rows);
  vw.add_image("labels.png", "expected", stacked_frames(label_images));
  vw.finish();
}

}  // namespace

const std::vector<std::string>& labelling_presets() {
  static const std::vector<std::string> kNames = {"shapes", "tsukuba", "overflow"};
  return kNames;
}

LabellingPreset labelling_preset(const std::string& name, const std::filesystem::path& data_dir) {
  if (name == "shapes") return shapes();
  if (name == "tsukuba") return tsukuba_preset(data_dir);
  if (name == "overflow") return overflow();
  throw std::invalid_argument("vectors labelling: no preset '" + name +
                              "' (there are: shapes, tsukuba, overflow)");
}

LabellingPreset labelling_frames(const UserMap& u) {
  if (u.disparity.empty()) throw std::invalid_argument("vectors labelling: give a map");
  Preset p;
  cv::Rect roi = u.roi;
  const auto maps = crop_maps(u.disparity, roi, "vectors labelling");
  for (std::size_t i = 0; i < maps.size(); ++i)
    p.frames.push_back({u.disparity[i].filename().string(), maps[i], Expect::kClean});
  p.tiles_x = u.tiles_x;
  p.tiles_y = u.tiles_y;
  p.build = u.build;
  p.cfg = labelling::grid_config(roi.width, roi.height, u.tiles_x, u.tiles_y, u.floor, u.min_area);
  std::ostringstream s;
  s << "scw labelling stage (" << u.build << " build): " << p.frames.size()
    << " frame(s) back to back, the crop " << crop_text(roi) << " of";
  for (const auto& path : u.disparity) s << " " << path.filename().string();
  s << " (Q11.4), " << u.tiles_x << "x" << u.tiles_y << " tiles, floor " << u.floor << ", min area "
    << u.min_area;
  p.description = s.str();
  return p;
}

namespace {

template <typename Params>
LabellingSetSummary write_set(const LabellingPreset& p, const std::filesystem::path& dir) {
  using InBeat = typename Params::in_beat;
  if (p.cfg.width > Params::kMaxWidthPx || p.cfg.height > Params::kMaxHeight)
    throw std::invalid_argument("vectors labelling: a " + std::to_string(p.cfg.width) + "x" +
                                std::to_string(p.cfg.height) + " frame does not fit the " +
                                p.build + " build (up to " + std::to_string(Params::kMaxWidthPx) +
                                "x" + std::to_string(Params::kMaxHeight) + "): give --roi X Y W H");
  hls::labelling::check_config<Params>(p.cfg);
  std::vector<cv::Mat> images;
  const std::vector<InBeat> beats = stream_beats<InBeat>(p, images);
  std::vector<LabelPacket> words;
  LabellingSetSummary sum;
  const auto frames = checked_frames<Params>(p, beats, words, sum.cycles);
  // One row per object word, in stream order; `word` is its line in expected.hex (from 0),
  // `label` its number in labels.png.
  Rows obj_rows, status_rows;
  std::vector<cv::Mat> label_images;
  std::size_t line = 0;
  for (std::size_t fi = 0; fi < frames.size(); ++fi) {
    const FrameOut& f = frames[fi];
    for (std::size_t i = 0; i < f.objects.size(); ++i, ++line)
      obj_rows.push_back(object_row(fi, line, f.label_of[i], f.objects[i]));
    status_rows.push_back(status_row(fi, line, f.status));
    ++line;
    label_images.push_back(f.labels);
  }
  write_files(dir, p, config_json<Params>(p, frames.size(), beats.size(), words.size()), beats,
              words, images, label_images, obj_rows, status_rows);
  sum.frames = frames.size();
  sum.words = words.size();
  sum.objects = obj_rows.size();
  sum.width = p.cfg.width;
  sum.height = p.cfg.height;
  sum.tiles_x = p.tiles_x;
  sum.tiles_y = p.tiles_y;
  return sum;
}

}  // namespace

const std::vector<std::string>& labelling_builds() {
  static const std::vector<std::string> kNames = {"vectors", "small", "tsukuba", "thesis"};
  return kNames;
}

LabellingSetSummary write_labelling_set(const LabellingPreset& p,
                                        const std::filesystem::path& dir) {
  // The pipeline builds' stage at P = 1: one disparity a beat, as the replay testbench sends.
  if (p.build == "vectors") return write_set<VecParams>(p, dir);
  if (p.build == "small") return write_set<hls::pipeline::SmallPipeline<1>::labelling>(p, dir);
  if (p.build == "tsukuba") return write_set<hls::pipeline::TsukubaPipeline<1>::labelling>(p, dir);
  if (p.build == "thesis") return write_set<hls::pipeline::ThesisPipeline<1>::labelling>(p, dir);
  throw std::invalid_argument("vectors labelling: no build '" + p.build +
                              "' (vectors, small, tsukuba, thesis)");
}

nlohmann::json labelling_word_layout() {
  nlohmann::json l = stream_beat_layout(Layout::kPayloadBits);
  const nlohmann::json is_status =
      nlohmann::json::array({{{"name", "is_status"}, {"lsb", 0}, {"bits", 1}}});
  l["object_fields"] = field_layout(sim::labelling_word::kObjectFields, 1, is_status);
  l["status_fields"] = field_layout(sim::labelling_word::kStatusFields, 1, is_status);
  return l;
}

}  // namespace scw::vectors
