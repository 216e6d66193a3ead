// SPDX-License-Identifier: Apache-2.0
// Rectify stage golden vectors: the presets, the model (and a caller's RTL) run and their checks
// against the integer reference, the files.
#include "host/vectors/rectify_set.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "hls/pipeline/pipeline_params.hpp"
#include "hls/rectify/map_taps.hpp"
#include "host/io/image_file.hpp"
#include "host/rectify/calibration.hpp"
#include "host/rectify/test_maps.hpp"
#include "host/reference/rectify_ref.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/join.hpp"
#include "sim/models/rectify_model.hpp"
#include "sim/words/pack.hpp"

namespace scw::vectors {
namespace {

using hls::rectify::MapPoint;

constexpr int kFracBits = RectifyRtlParams::kFracBits;
constexpr int kRtlPpc = kRectifyVecRtlPpc;

// Synthetic sets: a small frame; the chessboard sets: a crop of the bundled 640 x 480 pair
// (rectify_preset's size), or all of it.
constexpr int kSynthWidth = 64;
constexpr int kSynthHeight = 32;

/// A 64 x 32 grey test card: 8 x 8 checks, a slow gradient and a fixed integer hash for
/// texture, so every output pixel's four taps differ and the rounding is exercised.
cv::Mat pattern_image(int w, int h) {
  cv::Mat img(h, w, CV_8UC1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint32_t n =
          static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u;
      n = (n ^ (n >> 13)) * 0x5bd1e995u;
      n ^= n >> 15;
      const int check = ((x >> 3) + (y >> 3)) & 1 ? 170 : 40;
      const int v = check + (x + 2 * y) / 2 + static_cast<int>(n & 31u);
      img.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(std::min(v, 255));
    }
  return img;
}

rectify::FixedMap as_fixed(const std::vector<MapPoint>& m, int w, int h) {
  rectify::FixedMap f;
  f.width = w;
  f.height = h;
  f.frac_bits = kFracBits;
  f.points = m;
  return f;
}

RectifyFrame synthetic(const std::string& preset) {
  constexpr int w = kSynthWidth, h = kSynthHeight;
  RectifyFrame f;
  f.raw = {pattern_image(w, h)};
  std::ostringstream d;
  d << "scw_rectify: " << w << "x" << h << " test card (8x8 checks, gradient, hashed texture) ";
  if (preset == "shift") {
    f.map = rectify::shift_map(w, h, kFracBits, 4.3, 2.6);
    d << "shifted: output (u, v) samples raw (u + 4.3, v + 2.6); the right columns and bottom "
         "rows sample outside the image (zeros)";
  } else if (preset == "rotation") {
    f.map = rectify::rotation_map(w, h, kFracBits, 12.0, (w - 1) / 2.0, (h - 1) / 2.0);
    d << "turned by 12 degrees about its centre";
  } else {
    f.map = rectify::barrel_map(w, h, kFracBits, -0.3);
    d << "with strong barrel distortion undone (k1 = -0.3, r = 1 at the corners)";
  }
  f.windows = {rectify::row_window(as_fixed(f.map, w, h))};
  f.description = d.str();
  return f;
}

/// One camera of a calibrated pair, cropped: the map of the output ROI expressed relative to
/// a raw crop of the same size that holds every tap the ROI reads.
struct Crop {
  cv::Mat raw;                         // the raw crop
  std::vector<MapPoint> map;           // relative to the crop, clamped as the host does
  cv::Point origin;                    // crop's top-left in the raw image
  std::vector<std::uint8_t> full_ref;  // the ROI rectified from the whole raw image
};

Crop crop_camera(const cv::Mat& raw, const rectify::FixedMap& full, cv::Rect roi,
                 const std::string& name) {
  constexpr int s = 1 << kFracBits;
  std::vector<MapPoint> m;
  m.reserve(static_cast<std::size_t>(roi.area()));
  int x_lo = full.width, x_hi = -1, y_lo = full.height, y_hi = -1;
  for (int v = roi.y; v < roi.y + roi.height; ++v)
    for (int u = roi.x; u < roi.x + roi.width; ++u) {
      const MapPoint p = full.at(u, v);
      m.push_back(p);
      const auto t = hls::rectify::decode_taps<kFracBits>(p, full.width, full.height);
      // A tap is read when its column and its row both carry weight inside the image.
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          if ((dy ? t.row1 : t.row0) && (dx ? t.col1 : t.col0)) {
            x_lo = std::min(x_lo, t.x0 + dx);
            x_hi = std::max(x_hi, t.x0 + dx);
            y_lo = std::min(y_lo, t.y0 + dy);
            y_hi = std::max(y_hi, t.y0 + dy);
          }
    }
  if (x_hi < 0) throw std::runtime_error(name + ": the ROI samples no raw pixel at all");
  const auto fit = [&](int lo, int hi, int size, int limit, const char* axis) {
    if (hi - lo + 1 > size)
      throw std::runtime_error(name + ": the ROI's taps span raw " + axis + " " +
                               std::to_string(lo) + " .. " + std::to_string(hi) +
                               ", more than the " + std::to_string(size) +
                               "-px crop; pick another --roi");
    return std::clamp((lo + hi + 1) / 2 - size / 2, 0, limit - size);  // centred on the taps
  };
  Crop c;
  c.origin = {fit(x_lo, x_hi, roi.width, full.width, "columns"),
              fit(y_lo, y_hi, roi.height, full.height, "rows")};
  c.raw = raw(cv::Rect(c.origin, roi.size())).clone();
  // Shifting by whole pixels is exact; positions the host clamped outside the full image stay
  // outside the crop, and clamping again to the crop's range changes no sample.
  c.map = m;
  for (auto& p : c.map) {
    p.x -= c.origin.x * s;
    p.y -= c.origin.y * s;
    p = rectify::clamp_point(p, roi.width, roi.height, kFracBits);
  }
  const cv::Mat whole = raw.isContinuous() ? raw : raw.clone();
  c.full_ref = reference::rectify_reference(whole.ptr<std::uint8_t>(), whole.cols, whole.rows,
                                            m.data(), roi.width, roi.height, kFracBits);
  const auto crop_ref =
      reference::rectify_reference(c.raw.ptr<std::uint8_t>(), roi.width, roi.height, c.map.data(),
                                   roi.width, roi.height, kFracBits);
  if (crop_ref != c.full_ref)
    throw std::logic_error(name +
                           ": the ROI rectified from the crop differs from the ROI "
                           "rectified from the whole image; the crop misses taps");
  return c;
}

/// One camera of calibrated raw pairs: the output ROI at `roi_at` of `size` (empty: the whole
/// image), rectified with the pairs' calibration (both cameras' maps plan the one lead), a frame
/// a pair. `source` names the camera's images in the description.
RectifyFrame calibrated(const UserCalibratedPair& u, cv::Point roi_at, cv::Size size,
                        const std::string& source) {
  if (u.left.empty() || u.left.size() != u.right.size())
    throw std::invalid_argument("vectors rectify: give as many --right images as --left (" +
                                std::to_string(u.left.size()) + " and " +
                                std::to_string(u.right.size()) + ")");
  const bool right = u.right_camera;
  std::vector<cv::Mat> left_raw, right_raw;
  for (std::size_t i = 0; i < u.left.size(); ++i) {
    left_raw.push_back(host::io::read_grey_image(u.left[i]));
    right_raw.push_back(host::io::read_grey_image(u.right[i]));
  }
  const auto calib = rectify::load_stereo_calibration(u.calib.string(), left_raw[0].size());
  for (std::size_t i = 0; i < u.left.size(); ++i)
    for (const bool r : {false, true}) {
      const cv::Mat& img = r ? right_raw[i] : left_raw[i];
      if (img.size() != calib.image_size)
        throw std::runtime_error("vectors rectify: " + (r ? u.right : u.left)[i].string() + " is " +
                                 std::to_string(img.cols) + "x" + std::to_string(img.rows) +
                                 ", the calibration " + u.calib.string() + " is for " +
                                 std::to_string(calib.image_size.width) + "x" +
                                 std::to_string(calib.image_size.height) + " images");
    }
  const auto rect = rectify::rectify_calibration(calib);
  const auto full_l = rectify::quantise_map(rect.map1_x, rect.map1_y, kFracBits);
  const auto full_r = rectify::quantise_map(rect.map2_x, rect.map2_y, kFracBits);
  if (size.area() == 0) size = {full_l.width, full_l.height};
  const cv::Rect roi(roi_at, size);
  if ((roi & cv::Rect(0, 0, full_l.width, full_l.height)) != roi)
    throw std::runtime_error("--roi " + std::to_string(roi.x) + " " + std::to_string(roi.y) +
                             ": the " + std::to_string(roi.width) + " x " +
                             std::to_string(roi.height) + " ROI must lie inside the " +
                             std::to_string(full_l.width) + " x " + std::to_string(full_l.height) +
                             " rectified image");
  RectifyFrame f;
  cv::Point origin;
  for (std::size_t i = 0; i < u.left.size(); ++i) {
    const Crop cl = crop_camera(left_raw[i], full_l, roi, u.left[i].filename().string());
    const Crop cr = crop_camera(right_raw[i], full_r, roi, u.right[i].filename().string());
    const Crop& c = right ? cr : cl;
    f.raw.push_back(c.raw);
    if (i > 0) continue;  // the maps, and so the crop, are every frame's
    f.map = c.map;
    origin = c.origin;
    // Left and right share one lead, as the host runs a stereo pair, so both sets have one
    // config.
    f.windows = {rectify::row_window(as_fixed(cl.map, roi.width, roi.height)),
                 rectify::row_window(as_fixed(cr.map, roi.width, roi.height))};
  }
  std::ostringstream d;
  d << "scw_rectify: " << source << " rectified with " << u.calib.filename().string()
    << " (stereoRectify alpha " << rect.alpha << ", CALIB_ZERO_DISPARITY): output ROI x " << roi.x
    << " y " << roi.y << " " << roi.width << "x" << roi.height << " of the " << full_l.width << "x"
    << full_l.height << " rectified image; raw input = the crop at x " << origin.x << " y "
    << origin.y << ", map shifted to it (equal to rectifying the whole image)";
  f.description = d.str();
  return f;
}

/// The bundled chessboard pair: its files must be in `dir`.
RectifyFrame chessboard(const std::filesystem::path& dir, cv::Point roi_at, cv::Size size,
                        bool right) {
  const UserCalibratedPair u{{dir / "left01.jpg"},
                             {dir / "right01.jpg"},
                             dir / "derived_stereo_calibration_helper.yml",
                             right};
  for (const auto& p : {u.left[0], u.right[0], u.calib})
    if (!std::filesystem::exists(p))
      throw std::runtime_error("no '" + p.string() +
                               "'; the chessboard sets need data/chessboard (give --data-dir)");
  return calibrated(u, roi_at, size,
                    std::string("data/chessboard/") + (right ? "right01.jpg" : "left01.jpg"));
}

nlohmann::json map_beat_layout(int p, int coord_bits) {
  nlohmann::json fields = nlohmann::json::array();
  for (int i = 0; i < p; ++i) {
    fields.push_back(
        {{"name", "x" + std::to_string(i)}, {"lsb", 2 * i * coord_bits}, {"bits", coord_bits}});
    fields.push_back({{"name", "y" + std::to_string(i)},
                      {"lsb", (2 * i + 1) * coord_bits},
                      {"bits", coord_bits}});
  }
  const int flags = 2 * p * coord_bits;
  fields.push_back({{"name", "sof"}, {"lsb", flags}, {"bits", 1}});
  fields.push_back({{"name", "eol"}, {"lsb", flags + 1}, {"bits", 1}});
  return {{"pixels_per_beat", p},
          {"coord_bits", coord_bits},
          {"frac_bits", kFracBits},
          {"signed", true},
          {"fields", fields}};
}

/// Checks one engine's run: handshake rules kept, no time-out, no error bits, and every beat
/// equal to the reference; throws naming the engine and the first wrong beat otherwise.
template <typename Out>
void check_run(const std::string& engine, const sim::RunResult<Out>& r, std::uint8_t err,
               const std::vector<Out>& expect, int cols) {
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error("vectors rectify: " + engine + ": " + what);
  };
  if (r.timed_out) fail("timed out after " + std::to_string(r.cycles) + " cycles");
  if (!r.violations.empty()) fail("handshake rule broken: " + r.violations.front());
  if (err != 0) fail("error bits " + std::to_string(err) + " set on a well-formed frame");
  if (r.out.size() != expect.size())
    fail(std::to_string(r.out.size()) + " output beats, expected " + std::to_string(expect.size()));
  for (std::size_t i = 0; i < expect.size(); ++i)
    if (r.out[i] != expect[i])
      fail("beat " + std::to_string(i) + " (row " + std::to_string(i / cols) + ", beat " +
           std::to_string(i % cols) + ") is " + sim::pack(r.out[i]).hex() +
           ", the integer reference gives " + sim::pack(expect[i]).hex());
}

/// The RTL on the same beats: every beat equal to the reference, and cycle for cycle what the
/// C++ model did.
void check_rtl(const RectifyRtl& rtl, const hls::rectify::RectifyConfig& cfg,
               const std::vector<RectifyRtlParams::pixel_beat>& raw_beats,
               const std::vector<RectifyRtlParams::map_beat>& map_beats,
               const sim::StallPattern& pattern,
               const std::vector<RectifyRtlParams::pixel_beat>& expect,
               const std::vector<sim::CycleRecord>& cpp_trace, RectifySetSummary& sum) {
  const RectifyRtlRun rr = rtl(cfg, raw_beats, map_beats, pattern, expect.size());
  check_run("RTL", rr.run, rr.err, expect, cfg.width / kRtlPpc);
  const std::string diff = sim::first_difference(cpp_trace, rr.run.trace, "C++ model", "RTL");
  if (!diff.empty()) throw std::runtime_error("vectors rectify: cycle traces differ: " + diff);
  sum.rtl = true;
  sum.rtl_beats = rr.run.out.size();
}

template <typename Params>
void write_files(const std::filesystem::path& dir, const RectifyFrame& f, int lead_rows,
                 const std::vector<typename Params::pixel_beat>& raw_beats,
                 const std::vector<typename Params::map_beat>& map_beats,
                 const std::vector<typename Params::pixel_beat>& expect,
                 const std::vector<std::uint8_t>& ref) {
  constexpr int P = Params::kPpc;
  const int w = f.raw[0].cols, h = f.raw[0].rows;
  nlohmann::json config = {{"width", w},
                           {"height", h},
                           {"frames", f.raw.size()},
                           {"ppc", P},
                           {"frac_bits", Params::kFracBits},
                           {"coord_bits", Params::kCoordBits},
                           {"rows", Params::kRows},
                           {"lead_rows", lead_rows},
                           {"latency", Params::kLatency},
                           {"max_width_px", Params::kMaxWidthPx},
                           {"max_height", Params::kMaxHeight}};
  VectorWriter vw(dir, "rectify", config, f.description);
  cv::Mat raws;
  cv::vconcat(f.raw, raws);
  vw.add_image("input.png", "input", raws);
  vw.add_hex("input.hex", "input", sim::pack_all(raw_beats), pixel_beat_layout(P, 8));
  vw.add_hex("map.hex", "input", sim::pack_all(map_beats),
             map_beat_layout(P, Params::kCoordBits));
  vw.add_hex("expected.hex", "expected", sim::pack_all(expect), pixel_beat_layout(P, 8));
  cv::Mat out_img(h * static_cast<int>(f.raw.size()), w, CV_8UC1);
  std::copy(ref.begin(), ref.end(), out_img.data);
  vw.add_image("expected.png", "expected", out_img);
  vw.finish();
}

template <typename Params>
RectifySetSummary run(const RectifyFrame& f, const std::string& preset,
                      const sim::StallPattern& pattern, const RectifyRtl& rtl,
                      const std::filesystem::path& dir) {
  constexpr int P = Params::kPpc;
  using PixelBeat = typename Params::pixel_beat;
  using MapBeat = typename Params::map_beat;
  const int w = f.raw[0].cols, h = f.raw[0].rows;
  if (w > Params::kMaxWidthPx || h > Params::kMaxHeight || w % P != 0 || w / P < 2)
    throw std::invalid_argument("vectors rectify: a " + std::to_string(w) + "x" +
                                std::to_string(h) + " frame does not fit the build (up to " +
                                std::to_string(Params::kMaxWidthPx) + "x" +
                                std::to_string(Params::kMaxHeight) + ")");
  const auto plan = rectify::plan_for_stage(f.windows, Params::kRows, "vectors rectify " + preset);
  const hls::rectify::RectifyConfig cfg{w, h, plan.lead_rows};

  // Frames back to back, each with the one map.
  std::vector<PixelBeat> raw_beats, expect;
  std::vector<MapBeat> map_beats;
  std::vector<std::uint8_t> ref;
  const auto frame_map = sim::frame_beats_of<MapBeat>(f.map.data(), w, h);
  for (const cv::Mat& m : f.raw) {
    if (m.size() != f.raw[0].size())
      throw std::logic_error("vectors rectify: the frames are not one size");
    const cv::Mat raw = m.isContinuous() ? m : m.clone();
    const auto rb = sim::frame_beats_of<PixelBeat>(raw.ptr<std::uint8_t>(), w, h);
    const auto fr = reference::rectify_reference(raw.ptr<std::uint8_t>(), w, h, f.map.data(), w, h,
                                                 Params::kFracBits);
    const auto eb = sim::frame_beats_of<PixelBeat>(fr.data(), w, h);
    raw_beats.insert(raw_beats.end(), rb.begin(), rb.end());
    map_beats.insert(map_beats.end(), frame_map.begin(), frame_map.end());
    ref.insert(ref.end(), fr.begin(), fr.end());
    expect.insert(expect.end(), eb.begin(), eb.end());
  }

  // The C++ model always runs; the RTL when the caller brings one (at P = 2 only).
  auto cpp = std::make_unique<sim::RectifyModel<Params>>(cfg);
  const auto rc = sim::run_join(*cpp, raw_beats, map_beats, pattern, expect.size());
  check_run("C++ model", rc, cpp->kernel().error(), expect, w / P);
  RectifySetSummary sum;
  if (rtl) {
    if constexpr (std::is_same_v<Params, RectifyRtlParams>)
      check_rtl(rtl, cfg, raw_beats, map_beats, pattern, expect, rc.trace, sum);
    else
      check_rectify_rtl_ppc(P, "vectors");
  }
  write_files<Params>(dir, f, plan.lead_rows, raw_beats, map_beats, expect, ref);
  sum.width = w;
  sum.height = h;
  sum.frames = static_cast<int>(f.raw.size());
  sum.ppc = P;
  sum.beats = rc.out.size();
  sum.cycles = rc.cycles;
  sum.stalls = pattern.name();
  sum.lead_rows = plan.lead_rows;
  sum.rows_needed = plan.rows_needed;
  sum.rows = Params::kRows;
  return sum;
}

}  // namespace

const std::vector<std::string>& rectify_presets() {
  static const std::vector<std::string> kNames = {"shift", "rotation", "barrel", "chessboard_left",
                                                  "chessboard_right"};
  return kNames;
}

RectifyFrame rectify_preset(const std::string& name, const std::filesystem::path& data_dir,
                            cv::Point roi, cv::Size size) {
  if (name == "shift" || name == "rotation" || name == "barrel") return synthetic(name);
  if (name == "chessboard_left" || name == "chessboard_right")
    return chessboard(data_dir, roi, size, name == "chessboard_right");
  throw std::invalid_argument("vectors rectify: no preset '" + name +
                              "' (there are: shift, rotation, barrel, chessboard_left, "
                              "chessboard_right)");
}

RectifyFrame rectify_frame(const UserCalibratedPair& pair, cv::Point roi, cv::Size size) {
  std::string source;
  for (const auto& image : pair.right_camera ? pair.right : pair.left)
    source += (source.empty() ? "" : ", ") + image.filename().string();
  return calibrated(pair, roi, size,
                    source + (pair.right_camera ? " (right" : " (left") + " camera, " +
                        std::to_string(pair.left.size()) + " frame(s) back to back)");
}

void check_rectify_rtl_ppc(int ppc, const std::string& build) {
  if (build != "vectors")
    throw std::runtime_error(
        "vectors rectify: the CLI Verilates scw_rectify at the vectors build "
        "only; use --engine cpp for the " +
        build + " build");
  if (ppc != kRtlPpc)
    throw std::runtime_error(
        "vectors rectify: the CLI Verilates scw_rectify at P = " + std::to_string(kRtlPpc) +
        " only; use --engine cpp for P = " + std::to_string(ppc));
}

const std::vector<std::string>& rectify_builds() {
  static const std::vector<std::string> kNames = {"vectors", "thesis"};
  return kNames;
}

RectifySetSummary write_rectify_set(const RectifyFrame& f, const std::string& preset, int ppc,
                                    const sim::StallPattern& stalls, const RectifyRtl& rtl,
                                    const std::filesystem::path& dir, const std::string& build) {
  if (rtl) check_rectify_rtl_ppc(ppc, build);
  if (build == "thesis") {
    switch (ppc) {
      case 1:
        return run<hls::pipeline::ThesisPipeline<1>::rectify>(f, preset, stalls, rtl, dir);
      case 2:
        return run<hls::pipeline::ThesisPipeline<2>::rectify>(f, preset, stalls, rtl, dir);
      case 4:
        return run<hls::pipeline::ThesisPipeline<4>::rectify>(f, preset, stalls, rtl, dir);
      default:
        break;
    }
  } else if (build != "vectors") {
    throw std::invalid_argument("vectors rectify: no build '" + build + "' (vectors, thesis)");
  }
  switch (ppc) {
    case 1:
      return run<RectifyVecParams<1>>(f, preset, stalls, rtl, dir);
    case 2:
      return run<RectifyVecParams<2>>(f, preset, stalls, rtl, dir);
    case 4:
      return run<RectifyVecParams<4>>(f, preset, stalls, rtl, dir);
    default:
      throw std::invalid_argument("vectors rectify: P = " + std::to_string(ppc) +
                                  "; the sets are built for 1, 2 or 4 pixels a beat");
  }
}

}  // namespace scw::vectors
