// SPDX-License-Identifier: Apache-2.0
// Thesis 3.2's post-processing on synthetic maps (occluder merging, Fig. 3.12; convex hulls;
// occlusion handling, Fig. 3.17), the label pictures, and a check of what `scw segment` wrote.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "host/labelling/picture.hpp"
#include "host/labelling/postprocess.hpp"
#include "host/reference/labelling_ref.hpp"

namespace {

using namespace scw;
using hls::labelling::LabellingConfig;
using hls::labelling::Object;

constexpr std::uint16_t q4(int px) { return static_cast<std::uint16_t>(16 * px); }

/// A map and what the labelling stage makes of it (the flood-fill reference stands in for the
/// streaming model: same objects, same numbering).
struct Labelled {
  cv::Mat disp;    // CV_16UC1 Q11.4
  cv::Mat labels;  // CV_16UC1
  std::vector<Object> objects;
  LabellingConfig cfg;
};

Labelled label(const cv::Mat& disp) {
  Labelled l{disp, cv::Mat(), {}, LabellingConfig{}};
  l.cfg.width = disp.cols, l.cfg.height = disp.rows;
  l.cfg.tile_w = disp.cols, l.cfg.tile_h = disp.rows;
  const auto ref =
      reference::labelling_reference(disp.ptr<std::uint16_t>(), disp.cols, disp.rows, l.cfg);
  l.labels = cv::Mat(disp.size(), CV_16UC1);
  std::copy(ref.labels.begin(), ref.labels.end(), l.labels.ptr<std::uint16_t>());
  l.objects = ref.objects;
  return l;
}

void fill(cv::Mat& m, int x0, int y0, int x1, int y1, std::uint16_t d) {  // inclusive corners
  m(cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1)).setTo(d);
}

int label_at(const Labelled& l, int x, int y) { return l.labels.at<std::uint16_t>(y, x); }

labelling::Grouping merged(const Labelled& l) {
  return labelling::merge_occluded_parts(l.labels, l.disp, l.objects, l.cfg);
}

/// Fig. 3.12: a plane at d = 20 cut in two by a vertical occluder at d = 40.
cv::Mat split_plane() {
  cv::Mat m(40, 60, CV_16UC1, cv::Scalar(0));
  fill(m, 0, 5, 59, 34, q4(20));
  fill(m, 25, 0, 34, 39, q4(40));
  return m;
}

}  // namespace

TEST_CASE("a plane split by a closer occluder is merged into one object (Fig. 3.12)",
          "[labelling][post]") {
  cv::Mat m = split_plane();
  SECTION("plain") {}
  SECTION("with no data between the occluder and the right part (an occlusion halo)") {
    fill(m, 35, 5, 37, 34, 0);
  }
  SECTION("with a slanted plane whose sides agree by the join rule") {
    for (int x = 0; x < 60; ++x) fill(m, x, 5, x, 34, static_cast<std::uint16_t>(320 + x / 2));
    fill(m, 25, 0, 34, 39, q4(40));
  }
  const Labelled l = label(m);
  REQUIRE(l.objects.size() == 3);  // occluder (first pixel in row 0), left part, right part
  const int occ = label_at(l, 30, 0), left = label_at(l, 0, 5), right = label_at(l, 59, 5);
  REQUIRE(left != right);
  const auto g = merged(l);
  CHECK(g.groups() == 2);
  CHECK(g.group_of_label[static_cast<std::size_t>(left)] ==
        g.group_of_label[static_cast<std::size_t>(right)]);
  CHECK(g.group_of_label[static_cast<std::size_t>(occ)] !=
        g.group_of_label[static_cast<std::size_t>(left)]);
  // Groups are numbered in raster order of their first pixel; the descriptor is exact.
  CHECK(g.group_of_label[static_cast<std::size_t>(occ)] == 1);
  const auto& plane = g.objects[static_cast<std::size_t>(g.group_of_label[left]) - 1];
  CHECK(plane == hls::labelling::merge(l.objects[static_cast<std::size_t>(left) - 1],
                                       l.objects[static_cast<std::size_t>(right) - 1]));
  CHECK(g.labels_of_group[static_cast<std::size_t>(g.group_of_label[left]) - 1] ==
        std::vector<int>{left, right});
}

TEST_CASE("three parts behind two occluders merge transitively", "[labelling][post]") {
  cv::Mat m(20, 70, CV_16UC1, cv::Scalar(0));
  fill(m, 0, 2, 69, 17, q4(20));
  fill(m, 20, 0, 24, 19, q4(40));
  fill(m, 45, 0, 49, 19, q4(60));
  const Labelled l = label(m);
  REQUIRE(l.objects.size() == 5);
  const auto g = merged(l);
  CHECK(g.groups() == 3);
  const int a = label_at(l, 0, 2), b = label_at(l, 30, 2), c = label_at(l, 69, 2);
  CHECK(g.group_of_label[a] == g.group_of_label[b]);
  CHECK(g.group_of_label[b] == g.group_of_label[c]);
  CHECK(g.objects[static_cast<std::size_t>(g.group_of_label[a]) - 1].area == 70 * 16 - 10 * 16);
}

TEST_CASE("parts are not merged without the evidence of Fig. 3.12", "[labelling][post]") {
  cv::Mat m(40, 60, CV_16UC1, cv::Scalar(0));
  cv::Point a(0, 5), b(59, 5);  // a pixel of each part
  SECTION("two objects at clearly different disparities behind one occluder") {
    fill(m, 0, 5, 24, 34, q4(20));
    fill(m, 35, 5, 59, 34, q4(30));  // 10 |20 - 30| >= 30
    fill(m, 25, 0, 34, 39, q4(40));
  }
  SECTION("a gap of background (no data) between parts at the same disparity") {
    fill(m, 0, 5, 24, 34, q4(20));
    fill(m, 35, 5, 59, 34, q4(20));
  }
  SECTION("parts on different rows, the occluder between them in columns") {
    fill(m, 0, 0, 24, 14, q4(20));
    fill(m, 35, 20, 59, 39, q4(20));
    fill(m, 25, 0, 34, 39, q4(40));
    a = {0, 0}, b = {59, 39};
  }
  SECTION("farther background between the parts shows they stand apart") {
    fill(m, 0, 0, 59, 39, q4(8));  // joins neither part: 10 |20 - 8| >= 20
    fill(m, 0, 5, 24, 34, q4(20));
    fill(m, 35, 5, 59, 34, q4(20));
    fill(m, 28, 0, 31, 39, q4(40));  // an occluder, but background on both of its sides
    // ... which it splits, and whose two halves it does merge.
    const Labelled l = label(m);
    const auto g = merged(l);
    CHECK(g.group_of_label[label_at(l, 0, 0)] == g.group_of_label[label_at(l, 59, 0)]);
  }
  SECTION("an occluder farther than one of the parts") {
    fill(m, 0, 5, 24, 34, q4(20));
    fill(m, 35, 5, 59, 34, q4(21));
    fill(m, 25, 0, 34, 39, q4(40));
    fill(m, 25, 5, 34, 34, q4(10));  // the pixels between are farther: nothing was hidden
  }
  const Labelled l = label(m);
  const auto g = merged(l);
  REQUIRE(label_at(l, a.x, a.y) != label_at(l, b.x, b.y));
  CHECK(g.group_of_label[label_at(l, a.x, a.y)] != g.group_of_label[label_at(l, b.x, b.y)]);
}

TEST_CASE("the convex hull of an L shape fills the notch", "[labelling][post]") {
  cv::Mat m(24, 24, CV_16UC1, cv::Scalar(0));
  fill(m, 2, 2, 6, 21, q4(30));    // upright, x 2..6
  fill(m, 2, 17, 21, 21, q4(30));  // foot, y 17..21
  const Labelled l = label(m);
  REQUIRE(l.objects.size() == 1);
  const auto hulls = labelling::convex_hulls(l.labels, labelling::identity_grouping(l.objects));
  REQUIRE(hulls.size() == 1);
  const auto& h = hulls[0];
  CHECK(h.box == cv::Rect(2, 2, 20, 20));
  CHECK(h.polygon.size() == 5);  // (2,2) (6,2) (21,17) (21,21) (2,21)
  const auto in_hull = [&](int x, int y) { return h.mask.at<std::uint8_t>(y - 2, x - 2) != 0; };
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
      if (l.labels.at<std::uint16_t>(y, x) != 0) REQUIRE(in_hull(x, y));
  CHECK(in_hull(12, 12));  // in the notch, under the edge (6,2)-(21,17): y >= x - 4
  CHECK(in_hull(14, 10));  // on that edge
  CHECK(!in_hull(16, 8));  // above it
  CHECK(!in_hull(21, 2));  // the far corner of the box
  // The filled hull is the polygon's area plus its edge pixels, far above the L's 160 pixels.
  CHECK(cv::countNonZero(h.mask) > 160 + 80);
}

TEST_CASE("hulls of a dot and of a line are their pixels", "[labelling][post]") {
  cv::Mat m(10, 10, CV_16UC1, cv::Scalar(0));
  fill(m, 1, 1, 1, 1, q4(30));
  fill(m, 3, 5, 8, 5, q4(30));
  const Labelled l = label(m);
  const auto hulls = labelling::convex_hulls(l.labels, labelling::identity_grouping(l.objects));
  REQUIRE(hulls.size() == 2);
  CHECK(cv::countNonZero(hulls[0].mask) == 1);
  CHECK(cv::countNonZero(hulls[1].mask) == 6);
}

TEST_CASE("occlusion handling removes closer objects' hulls from a farther one (Fig. 3.17)",
          "[labelling][post]") {
  // A box at d = 20 with a closer bottle (d = 60) standing in front of it, inside its outline,
  // and a farther wall (d = 10) to the side whose hull the box overlaps.
  cv::Mat m(40, 60, CV_16UC1, cv::Scalar(0));
  fill(m, 10, 5, 39, 34, q4(20));
  fill(m, 18, 12, 25, 26, q4(60));
  fill(m, 40, 0, 59, 39, q4(10));
  const Labelled l = label(m);
  REQUIRE(l.objects.size() == 3);
  const auto regions = labelling::postprocess(l.labels, l.disp, l.objects, l.cfg);
  REQUIRE(regions.size() == 3);
  const auto region_of = [&](int x, int y) -> const labelling::Region& {
    const int k = label_at(l, x, y);
    for (const auto& r : regions)
      for (const int lab : r.labels)
        if (lab == k) return r;
    FAIL("no region holds label " << k);
    return regions[0];
  };
  const auto& box = region_of(10, 5);
  const auto& bottle = region_of(18, 12);
  const auto& wall = region_of(40, 0);
  CHECK(box.d_median == q4(20));
  CHECK(bottle.d_median == q4(60));
  const auto inside = [](const cv::Mat& mask, const cv::Rect& b, int x, int y) {
    return b.contains({x, y}) && mask.at<std::uint8_t>(y - b.y, x - b.x) != 0;
  };
  // The box's hull covers the bottle; after occlusion handling the bottle's pixels are gone.
  CHECK(inside(box.hull.mask, box.hull.box, 20, 20));
  CHECK(!inside(box.visible, box.hull.box, 20, 20));
  CHECK(cv::countNonZero(box.visible) == 30 * 30 - 8 * 15);
  // Nothing is closer than the bottle; the wall loses nothing to the box, which does not
  // overlap its hull, and the box loses nothing to the farther wall.
  CHECK(cv::countNonZero(bottle.visible) == cv::countNonZero(bottle.hull.mask));
  CHECK(cv::countNonZero(wall.visible) == 20 * 40);
}

TEST_CASE("occlusion handling keeps a farther object's own pixels inside a closer one's hull",
          "[labelling][post]") {
  // A closer U (d = 60) and a farther post (d = 20) standing in its notch: the U's hull covers
  // the post, yet the post's pixels were seen.
  cv::Mat m(30, 30, CV_16UC1, cv::Scalar(0));
  fill(m, 2, 2, 6, 27, q4(60));
  fill(m, 23, 2, 27, 27, q4(60));
  fill(m, 2, 23, 27, 27, q4(60));
  fill(m, 12, 5, 17, 19, q4(20));
  const Labelled l = label(m);
  REQUIRE(l.objects.size() == 2);
  const auto grouping = labelling::identity_grouping(l.objects);
  const auto hulls = labelling::convex_hulls(l.labels, grouping);
  const auto medians = labelling::median_disparities(l.labels, l.disp, grouping);
  const std::size_t post = static_cast<std::size_t>(label_at(l, 12, 5)) - 1;
  // The thesis's plain subtraction leaves nothing of the post; keeping own pixels leaves them.
  CHECK(cv::countNonZero(labelling::occlusion_handling(hulls, medians)[post]) == 0);
  const auto kept =
      labelling::occlusion_handling(hulls, medians, labelling::group_image(l.labels, grouping));
  CHECK(cv::countNonZero(kept[post]) == 6 * 15);
  CHECK(cv::countNonZero(kept[1 - post]) == 26 * 26);
}

TEST_CASE("postprocess merges, fits hulls and handles occlusion on Fig. 3.12",
          "[labelling][post]") {
  const Labelled l = label(split_plane());
  const auto regions = labelling::postprocess(l.labels, l.disp, l.objects, l.cfg);
  REQUIRE(regions.size() == 2);
  const auto& plane = regions[1];  // the occluder's first pixel is in row 0
  CHECK(plane.labels.size() == 2);
  CHECK(plane.hull.box == cv::Rect(0, 5, 60, 30));
  CHECK(cv::countNonZero(plane.hull.mask) == 60 * 30);  // the hull spans the occluder
  CHECK(cv::countNonZero(plane.visible) == 50 * 30);    // whose hull is then cut out
  const auto unmerged = labelling::postprocess(l.labels, l.disp, l.objects, l.cfg, false);
  CHECK(unmerged.size() == 3);
  const cv::Mat groups = labelling::group_image(l.labels, merged(l));
  CHECK(groups.at<std::uint16_t>(0, 30) == 1);
  CHECK(groups.at<std::uint16_t>(5, 0) == 2);
  CHECK(groups.at<std::uint16_t>(5, 59) == 2);
  CHECK(groups.at<std::uint16_t>(0, 0) == 0);
}

TEST_CASE("post-processing refuses images it cannot read, saying what it needs",
          "[labelling][post][errors]") {
  const Labelled l = label(split_plane());
  using Catch::Matchers::Contains;
  cv::Mat labels8;
  l.labels.convertTo(labels8, CV_8UC1);
  CHECK_THROWS_WITH(labelling::merge_occluded_parts(labels8, l.disp, l.objects, l.cfg),
                    Contains("CV_16UC1 label image"));
  CHECK_THROWS_WITH(
      labelling::merge_occluded_parts(l.labels, l.disp(cv::Rect(0, 0, 10, 10)), l.objects, l.cfg),
      Contains("of the label image's size"));
  const std::vector<Object> fewer(l.objects.begin(), l.objects.end() - 1);
  CHECK_THROWS_WITH(labelling::merge_occluded_parts(l.labels, l.disp, fewer, l.cfg),
                    Contains("holds label 3 but only 2 objects"));
}

TEST_CASE("label colours are stable, distinct and never black", "[labelling][picture]") {
  std::set<std::vector<int>> seen;
  for (int k = 1; k <= 64; ++k) {
    const cv::Vec3b c = labelling::label_colour(k);
    CHECK(c == labelling::label_colour(k));
    CHECK(std::max({c[0], c[1], c[2]}) >= 150);
    seen.insert({c[0], c[1], c[2]});
  }
  CHECK(seen.size() == 64);
  const Labelled l = label(split_plane());
  const cv::Mat colour = labelling::colour_labels(l.labels);
  REQUIRE(colour.type() == CV_8UC3);
  CHECK(colour.at<cv::Vec3b>(0, 0) == cv::Vec3b(0, 0, 0));
  CHECK(colour.at<cv::Vec3b>(0, 30) == labelling::label_colour(label_at(l, 30, 0)));
  CHECK(colour.at<cv::Vec3b>(20, 59) == labelling::label_colour(label_at(l, 59, 20)));
  // The overlay keeps the picture's size and draws in the items' colours.
  const auto regions = labelling::postprocess(l.labels, l.disp, l.objects, l.cfg);
  std::vector<labelling::OverlayItem> items;
  for (std::size_t g = 0; g < regions.size(); ++g)
    items.push_back({static_cast<int>(g) + 1, regions[g].hull.box, regions[g].hull.polygon,
                     regions[g].visible});
  const cv::Mat view = labelling::draw_overlay(labelling::disparity_picture(l.disp), items);
  CHECK(view.size() == l.disp.size());
  CHECK(view.type() == CV_8UC3);
}

namespace {

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream f(path);
  REQUIRE(f);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(f, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace

// Hidden: run by tests/labelling/cli.cmake on the directory `scw segment` wrote, named by the
// environment variable SCW_SEGMENT_OUT.
TEST_CASE("what scw segment wrote is consistent", "[.segment-output]") {
  const char* dir_env = std::getenv("SCW_SEGMENT_OUT");
  REQUIRE(dir_env != nullptr);
  const std::string dir = dir_env;
  const cv::Mat labels = cv::imread(dir + "/labels.png", cv::IMREAD_UNCHANGED);
  REQUIRE(labels.type() == CV_16UC1);
  const auto csv = read_csv(dir + "/objects.csv");
  REQUIRE(csv.size() >= 2);
  REQUIRE(csv[0].front() == "label");
  const std::size_t objects = csv.size() - 1;
  double mx = 0;
  cv::minMaxLoc(labels, nullptr, &mx);
  CHECK(static_cast<std::size_t>(mx) == objects);
  // Each row: its label, its area counted in labels.png, its first pixel where the label first
  // appears in raster order (so labels are numbered in that order).
  std::vector<long> area(objects + 1, 0);
  std::vector<cv::Point> first(objects + 1, {-1, -1});
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x) {
      const int k = labels.at<std::uint16_t>(y, x);
      if (k == 0) continue;
      if (area[static_cast<std::size_t>(k)]++ == 0) first[static_cast<std::size_t>(k)] = {x, y};
    }
  for (std::size_t k = 1; k <= objects; ++k) {
    const auto& row = csv[k];
    INFO("objects.csv row " << k);
    REQUIRE(row.size() == csv[0].size());
    CHECK(std::stoul(row[0]) == k);
    CHECK(std::stol(row[1]) == area[k]);
    CHECK(std::stoi(row[12]) == first[k].x);
    CHECK(std::stoi(row[13]) == first[k].y);
    if (k > 1)
      CHECK(first[k - 1].y * labels.cols + first[k - 1].x < first[k].y * labels.cols + first[k].x);
  }
  const cv::Mat colour = cv::imread(dir + "/labels_color.png", cv::IMREAD_UNCHANGED);
  CHECK(colour.type() == CV_8UC3);
  CHECK(colour.size() == labels.size());
}
