// SPDX-License-Identifier: Apache-2.0
// `scw segment`: labels a disparity map into objects with the labelling stage's streaming model;
// writes the label image, the object table and pictures, optionally after thesis 3.2's
// post-processing (docs/labelling-postprocess.md).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "host/cli/commands.hpp"
#include "host/cli/value_checks.hpp"
#include "host/io/image_file.hpp"
#include "host/labelling/picture.hpp"
#include "host/labelling/postprocess.hpp"
#include "host/labelling/run_model.hpp"
#include "host/labelling/segment_files.hpp"

namespace scw::cli {
namespace {

using hls::labelling::Object;

struct SegmentOptions {
  std::string disparity;
  int min_area = 1;
  std::string tiles = "4x4";  // speckled street maps need more labels than one tile holds
  double scale = 16.0;
  double floor = 0.0;
  bool post = false;
  std::string out_dir;
  bool scale_given = false;
};

using host::io::write_image;

void run_segment(const SegmentOptions& o) {
  const auto [tiles_x, tiles_y] = labelling::parse_tiles(o.tiles);
  if (!(o.floor >= 0.0) || o.floor * 16.0 > 32767.0)
    throw std::runtime_error("--floor " + std::to_string(o.floor) +
                             " is outside 0 .. 2047 px of disparity");
  const int floor_q4 = static_cast<int>(std::lround(o.floor * 16.0));
  const labelling::DisparityInput in =
      labelling::read_disparity_map(o.disparity, o.scale, o.scale_given);
  const auto cfg =
      labelling::grid_config(in.q4.cols, in.q4.rows, tiles_x, tiles_y, floor_q4, o.min_area);
  std::cerr << "segment: '" << o.disparity << "' " << in.q4.cols << " x " << in.q4.rows << " px, "
            << in.kind << "; tiles " << tiles_x << " x " << tiles_y << " of " << cfg.tile_w << " x "
            << cfg.tile_h << " px, floor " << labelling::px_text(floor_q4) << " px, min area " << o.min_area
            << " px\n";
  if (in.negatives > 0)
    std::cerr << "  " << in.negatives << " pixels hold a negative (invalid) code: no data\n";

  const labelling::Segmentation seg = labelling::segment(in.q4, cfg);
  const std::filesystem::path dir(o.out_dir);
  std::filesystem::create_directories(dir);
  write_image(dir / "labels.png", seg.labels);
  labelling::write_objects_csv(dir / "objects.csv", seg.objects_by_label);
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
    labelling::write_regions_csv(dir / "regions.csv", regions);
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
            << labelling::status_flags(seg.status) << ", " << seg.cycles << " cycles" << regions_text
            << "; wrote " << wrote << " in " << dir.string() << "\n";
}

}  // namespace

void add_segment_command(CLI::App& app) {
  auto o = std::make_shared<SegmentOptions>();
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
      ->check(positive("px", "50"));
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
    run_segment(*o);
  });
}

}  // namespace scw::cli
