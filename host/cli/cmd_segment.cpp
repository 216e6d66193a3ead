// SPDX-License-Identifier: Apache-2.0
// `scw segment`: labels a disparity map into objects with the labelling stage's streaming model;
// writes the label image, the object table and pictures, optionally after thesis 3.2's
// post-processing (docs/labelling-postprocess.md).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "host/cli/commands.hpp"
#include "host/io/image_file.hpp"
#include "host/labelling/hu_moments.hpp"
#include "host/labelling/picture.hpp"
#include "host/labelling/postprocess.hpp"
#include "host/labelling/run_model.hpp"

namespace scw::cli {
namespace {

using hls::labelling::Object;

struct Options {
  std::string disparity;
  int min_area = 1;
  std::string tiles = "4x4";  // speckled street maps need more labels than one tile holds
  double scale = 16.0;
  double floor = 0.0;
  bool post = false;
  std::string out_dir;
  bool scale_given = false;
};

/// A disparity map as the stage takes it, and how it was read.
struct Input {
  cv::Mat q4;  // CV_16UC1, Q11.4
  std::string kind;
  long negatives = 0;  // 16-bit values with the int16 sign bit set, read as no data
};

const char* const kSupported =
    "scw segment reads a single-channel disparity map: a 16-bit PNG of disparity x 16 (Q11.4, "
    "what `scw disparity --out16` writes) or an 8-bit image of disparity x S (--scale S, "
    "default 16 as Middlebury's ground truth)";

Input read_disparity(const Options& o) {
  const cv::Mat img = cv::imread(o.disparity, cv::IMREAD_UNCHANGED);
  if (img.empty())
    throw std::runtime_error("cannot read '" + o.disparity + "' as an image; " + kSupported);
  Input in;
  if (img.type() == CV_16UC1 || img.type() == CV_16SC1) {
    if (o.scale_given)
      throw std::runtime_error("'" + o.disparity +
                               "' is 16-bit, already disparity x 16 (Q11.4); --scale applies to "
                               "8-bit maps only, drop it");
    // `scw disparity --out16` stores int16 bit patterns: a negative invalid code (opencv mode)
    // reads as >= 0x8000 in a 16-bit PNG; both are no data.
    img.convertTo(in.q4, CV_16UC1);  // a no-op copy for 16U; CV_16S negatives saturate to 0
    if (img.type() == CV_16SC1) in.negatives = cv::countNonZero(img < 0);
    for (int y = 0; y < in.q4.rows; ++y)
      for (int x = 0; x < in.q4.cols; ++x) {
        auto& d = in.q4.at<std::uint16_t>(y, x);
        if (d >= 0x8000) d = 0, ++in.negatives;
      }
    in.kind = "16-bit Q11.4";
    return in;
  }
  if (img.type() == CV_8UC1) {
    if (!(o.scale > 0) || 255.0 * 16.0 / o.scale > 32767.0)
      throw std::runtime_error("--scale " + std::to_string(o.scale) +
                               " cannot be used: 8-bit values are disparity x S with S > 0 and "
                               "255 / S at most 2047 px (the stage's Q11.4 range)");
    in.q4.create(img.size(), CV_16UC1);
    for (int y = 0; y < img.rows; ++y)
      for (int x = 0; x < img.cols; ++x)
        in.q4.at<std::uint16_t>(y, x) =
            static_cast<std::uint16_t>(std::lround(img.at<std::uint8_t>(y, x) * 16.0 / o.scale));
    std::ostringstream kind;
    kind << "8-bit, disparity = value / " << o.scale;
    in.kind = kind.str();
    return in;
  }
  throw std::runtime_error("'" + o.disparity + "' has " + std::to_string(img.channels()) +
                           " channel(s) of " + std::to_string(8 * img.elemSize1()) +
                           "-bit values; " + kSupported);
}

/// A Q11.4 value as disparity in pixels, exactly (at most 4 decimals).
std::string px(int q4) {
  std::string s = std::to_string(q4 / 16);
  if (const int frac = q4 % 16; frac != 0) {
    std::string digits = std::to_string(10000 + frac * 625).substr(1);
    while (digits.back() == '0') digits.pop_back();
    s += "." + digits;
  }
  return s;
}

using host::io::write_image;

std::ofstream open_csv(const std::filesystem::path& p) {
  std::ofstream f(p);
  if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
  f.precision(12);  // Hu invariants span many decades: significant digits, not decimals
  return f;
}

void write_objects_csv(const std::filesystem::path& p, const std::vector<Object>& objects) {
  std::ofstream f = open_csv(p);
  f << "label,area,x_min,x_max,y_min,y_max,d_min,d_max,d_min_q4,d_max_q4,closest_x,closest_y,"
       "first_x,first_y,m10,m01,m20,m11,m02,m30,m21,m12,m03,hu1,hu2,hu3,hu4,hu5,hu6,hu7\n";
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const Object& o = objects[k];
    f << k + 1 << ',' << o.area << ',' << o.x_min << ',' << o.x_max << ',' << o.y_min << ','
      << o.y_max << ',' << px(o.d_min) << ',' << px(o.d_max) << ',' << o.d_min << ',' << o.d_max
      << ',' << o.closest_x << ',' << o.closest_y << ',' << o.first_x << ',' << o.first_y << ','
      << o.m10 << ',' << o.m01 << ',' << o.m20 << ',' << o.m11 << ',' << o.m02 << ',' << o.m30
      << ',' << o.m21 << ',' << o.m12 << ',' << o.m03;
    for (const double h : labelling::hu_moments(o)) f << ',' << h;
    f << '\n';
  }
  if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
}

void write_regions_csv(const std::filesystem::path& p,
                       const std::vector<labelling::Region>& regions) {
  std::ofstream f = open_csv(p);
  f << "region,labels,area,x_min,x_max,y_min,y_max,d_min,d_max,d_median,closest_x,closest_y,"
       "hull_px,visible_px,hull\n";
  for (std::size_t g = 0; g < regions.size(); ++g) {
    const auto& r = regions[g];
    const Object& o = r.object;
    std::string labels, hull;
    for (const int k : r.labels) labels += (labels.empty() ? "" : " ") + std::to_string(k);
    for (const auto& q : r.hull.polygon)
      hull += (hull.empty() ? "" : " ") + std::to_string(q.x) + ":" + std::to_string(q.y);
    f << g + 1 << ',' << labels << ',' << o.area << ',' << o.x_min << ',' << o.x_max << ','
      << o.y_min << ',' << o.y_max << ',' << px(o.d_min) << ',' << px(o.d_max) << ','
      << px(r.d_median) << ',' << o.closest_x << ',' << o.closest_y << ','
      << cv::countNonZero(r.hull.mask) << ',' << cv::countNonZero(r.visible) << ',' << hull << '\n';
  }
  if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
}

std::string status_text(const labelling::FrameStatus& s) {
  std::string t;
  for (const auto& [flag, name] :
       {std::pair{s.tile_overflow, "tile_overflow"},
        std::pair{s.object_overflow, "object_overflow"}, std::pair{s.stream_error, "stream_error"}})
    if (flag) t += (t.empty() ? "" : " ") + std::string(name);
  return t.empty() ? "ok" : t;
}

void run(const Options& o) {
  const auto [tiles_x, tiles_y] = labelling::parse_tiles(o.tiles);
  if (!(o.floor >= 0.0) || o.floor * 16.0 > 32767.0)
    throw std::runtime_error("--floor " + std::to_string(o.floor) +
                             " is outside 0 .. 2047 px of disparity");
  const int floor_q4 = static_cast<int>(std::lround(o.floor * 16.0));
  const Input in = read_disparity(o);
  const auto cfg =
      labelling::grid_config(in.q4.cols, in.q4.rows, tiles_x, tiles_y, floor_q4, o.min_area);
  std::cerr << "segment: '" << o.disparity << "' " << in.q4.cols << " x " << in.q4.rows << " px, "
            << in.kind << "; tiles " << tiles_x << " x " << tiles_y << " of " << cfg.tile_w << " x "
            << cfg.tile_h << " px, floor " << px(floor_q4) << " px, min area " << o.min_area
            << " px\n";
  if (in.negatives > 0)
    std::cerr << "  " << in.negatives << " pixels hold a negative (invalid) code: no data\n";

  const labelling::Segmentation seg = labelling::segment(in.q4, cfg);
  const std::filesystem::path dir(o.out_dir);
  std::filesystem::create_directories(dir);
  write_image(dir / "labels.png", seg.labels);
  write_objects_csv(dir / "objects.csv", seg.objects_by_label);
  write_image(dir / "labels_color.png", labelling::colour_labels(seg.labels));
  std::string wrote = "labels.png, objects.csv, labels_color.png";
  std::string regions_text;
  if (o.post) {
    const auto regions = labelling::postprocess(seg.labels, in.q4, seg.objects_by_label, cfg);
    std::vector<labelling::OverlayItem> items;
    for (std::size_t g = 0; g < regions.size(); ++g)
      items.push_back({static_cast<int>(g) + 1, regions[g].hull.box, regions[g].hull.polygon,
                       regions[g].visible});
    write_image(dir / "regions.png",
              labelling::draw_overlay(labelling::disparity_picture(in.q4), items));
    write_regions_csv(dir / "regions.csv", regions);
    wrote += ", regions.png, regions.csv";
    regions_text = ", " + std::to_string(regions.size()) + " regions after merging";
  }
  if (seg.status.tile_overflow)
    std::cerr << "segment: warning: a tile ran out of its " << labelling::kHostLabelsPerTile
              << " labels, so objects are missing or wrong; use smaller tiles (more of them "
                 "with --tiles, up to "
              << labelling::kHostMaxTiles << "x" << labelling::kHostMaxTiles << ")\n";
  if (seg.status.object_overflow)
    std::cerr << "segment: warning: more than " << labelling::kHostMaxObjects
              << " objects reached the minimum area, the rest are not reported; raise "
                 "--min-area\n";
  std::cout << "segment: " << seg.objects_by_label.size() << " objects, status "
            << status_text(seg.status) << ", " << seg.cycles << " cycles" << regions_text
            << "; wrote " << wrote << " in " << dir.string() << "\n";
}

}  // namespace

void add_segment_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "segment",
      "Connected-component labelling of a disparity map into objects with the labelling "
      "stage's streaming model (thesis eq. 3.10), optionally with thesis 3.2's post-processing");
  cmd->add_option("--disparity", o->disparity,
                  "Disparity map: 16-bit PNG of disparity x 16 (scw disparity --out16; values "
                  ">= 0x8000, negative codes, are no data) or 8-bit of disparity x --scale")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--min-area", o->min_area,
                  "Objects with fewer pixels are not reported (noise removal); 1 keeps every "
                  "object, as fits noise-free maps such as ground truth")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  const std::string max_tiles =
      std::to_string(labelling::kHostMaxTiles) + "x" + std::to_string(labelling::kHostMaxTiles);
  cmd->add_option("--tiles", o->tiles,
                  "Tile grid CxR (columns x rows, e.g. 4x2; at most " + max_tiles +
                      "); the objects do not depend on it, only the labels each tile needs")
      ->capture_default_str();
  auto* scale = cmd->add_option("--scale", o->scale,
                                "8-bit maps only: disparity = value / S (16: Middlebury truth)")
                    ->capture_default_str();
  cmd->add_option("--floor", o->floor,
                  "Background: pixels with disparity <= F px are not objects (rounded to 1/16 "
                  "px; 0: only 0 is no data)")
      ->capture_default_str();
  cmd->add_flag("--post", o->post,
                "Also merge parts split by an occluder, fit convex hulls and remove closer "
                "objects' hulls (regions.png, regions.csv)");
  cmd->add_option("--out-dir", o->out_dir,
                  "Writes labels.png (16-bit, 0 none, objects 1.. in raster order of their first "
                  "pixel), objects.csv, labels_color.png")
      ->required();
  cmd->callback([o, scale] {
    o->scale_given = scale->count() > 0;
    run(*o);
  });
}

}  // namespace scw::cli
