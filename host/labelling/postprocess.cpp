// SPDX-License-Identifier: Apache-2.0
// Whole-frame post-processing of the labelling stage's output: occluder merging, convex hulls,
// occlusion handling (docs/labelling-postprocess.md).
#include "host/labelling/postprocess.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace scw::labelling {
namespace {

void check_labels(const cv::Mat& labels16, std::size_t count) {
  if (labels16.empty() || labels16.type() != CV_16UC1)
    throw std::invalid_argument("post-processing needs a CV_16UC1 label image (0 = none)");
  double mx = 0;
  cv::minMaxLoc(labels16, nullptr, &mx);
  if (mx > static_cast<double>(count))
    throw std::invalid_argument("the label image holds label " +
                                std::to_string(static_cast<int>(mx)) + " but only " +
                                std::to_string(count) + " objects are described");
}

void check_disparity(const cv::Mat& labels16, const cv::Mat& disp_q4) {
  if (disp_q4.type() != CV_16UC1 || disp_q4.size() != labels16.size())
    throw std::invalid_argument(
        "post-processing needs the CV_16UC1 Q11.4 disparity map that was labelled, of the label "
        "image's size");
}

int find(std::vector<int>& parent, int k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

/// The facing edge disparities of one pair of labels lo < hi, over all rows where they face.
struct Facing {
  std::vector<std::uint16_t> d_lo, d_hi;
  int rows = 0, last_row = -1;
};

std::uint16_t lower_median(std::vector<std::uint16_t>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>((v.size() - 1) / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

Grouping group(const std::vector<Object>& objects_by_label, std::vector<int>& parent) {
  const int n = static_cast<int>(objects_by_label.size());
  Grouping g;
  g.group_of_label.assign(static_cast<std::size_t>(n) + 1, 0);
  // Ascending labels: a root is first met at its group's smallest label, so groups come out in
  // raster order of their first pixel, and each group's labels ascending.
  for (int k = 1; k <= n; ++k) {
    const int root = find(parent, k);
    int& gr = g.group_of_label[static_cast<std::size_t>(root)];
    if (gr == 0) {
      g.labels_of_group.emplace_back();
      g.objects.push_back(objects_by_label[static_cast<std::size_t>(k) - 1]);
      gr = g.groups();
    } else {
      auto& o = g.objects[static_cast<std::size_t>(gr) - 1];
      o = hls::labelling::merge(o, objects_by_label[static_cast<std::size_t>(k) - 1]);
    }
    g.group_of_label[static_cast<std::size_t>(k)] = gr;
    g.labels_of_group[static_cast<std::size_t>(gr) - 1].push_back(k);
  }
  return g;
}

}  // namespace

Grouping identity_grouping(const std::vector<Object>& objects_by_label) {
  std::vector<int> parent(objects_by_label.size() + 1);
  std::iota(parent.begin(), parent.end(), 0);
  return group(objects_by_label, parent);
}

Grouping merge_occluded_parts(const cv::Mat& labels16, const cv::Mat& disp_q4,
                              const std::vector<Object>& objects_by_label,
                              const LabellingConfig& cfg, int min_rows) {
  check_labels(labels16, objects_by_label.size());
  check_disparity(labels16, disp_q4);
  std::unordered_map<std::uint64_t, Facing> facing;
  const int w = labels16.cols;
  for (int y = 0; y < labels16.rows; ++y) {
    const auto* lab = labels16.ptr<std::uint16_t>(y);
    const auto* d = disp_q4.ptr<std::uint16_t>(y);
    for (int x = 0; x < w; ++x) {
      const int a = lab[x];
      if (a == 0 || (x + 1 < w && lab[x + 1] == a)) continue;  // not the end of a run of A
      // Walk right through no data and pixels closer than A's edge; every run start met on the
      // way faces A. The walk stops at A itself (its next run end walks on) or at a pixel no
      // closer than A's edge, which hides whatever lies beyond. Cost: the width of occluders
      // and holes crossed, small in practice.
      const int ea = d[x];
      int gap_min = std::numeric_limits<int>::max();  // smallest valid disparity crossed
      for (int x2 = x + 1; x2 < w; ++x2) {
        const int b = lab[x2];
        if (b == a) break;
        const int db = d[x2];
        if (b != 0 && lab[x2 - 1] != b && gap_min != std::numeric_limits<int>::max() &&
            gap_min > std::max(ea, db)) {
          const int lo = std::min(a, b), hi = std::max(a, b);
          auto& f = facing[(static_cast<std::uint64_t>(lo) << 32) | static_cast<std::uint64_t>(hi)];
          f.d_lo.push_back(static_cast<std::uint16_t>(lo == a ? ea : db));
          f.d_hi.push_back(static_cast<std::uint16_t>(lo == a ? db : ea));
          if (f.last_row != y) ++f.rows, f.last_row = y;
        }
        if (!hls::labelling::is_valid(static_cast<std::uint16_t>(db), cfg)) continue;  // no data
        if (db <= ea) break;
        gap_min = std::min(gap_min, db);
      }
    }
  }
  std::vector<int> parent(objects_by_label.size() + 1);
  std::iota(parent.begin(), parent.end(), 0);
  for (auto& [key, f] : facing) {
    if (f.rows < min_rows) continue;
    const int m_lo = lower_median(f.d_lo), m_hi = lower_median(f.d_hi);
    // The join rule (eq. 3.10) between the two sides' typical edge values, on the larger one:
    // neither side is "later in raster order" here, and the larger bound is the lenient one.
    const int diff = m_lo > m_hi ? m_lo - m_hi : m_hi - m_lo;
    if (10 * diff >= std::max(m_lo, m_hi)) continue;
    const int ra = find(parent, static_cast<int>(key >> 32));
    const int rb = find(parent, static_cast<int>(key & 0xffffffffu));
    parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  }
  return group(objects_by_label, parent);
}

std::vector<Hull> convex_hulls(const cv::Mat& labels16, const Grouping& grouping) {
  check_labels(labels16, grouping.group_of_label.size() - 1);
  const int n = grouping.groups();
  std::vector<std::vector<cv::Point>> extremes(static_cast<std::size_t>(n));
  std::vector<int> lo(static_cast<std::size_t>(n) + 1), hi(lo.size(), -1);
  std::vector<int> touched;
  for (int y = 0; y < labels16.rows; ++y) {
    const auto* lab = labels16.ptr<std::uint16_t>(y);
    for (int x = 0; x < labels16.cols; ++x) {
      if (lab[x] == 0) continue;
      const auto g = static_cast<std::size_t>(grouping.group_of_label[lab[x]]);
      if (hi[g] < 0) lo[g] = x, touched.push_back(static_cast<int>(g));
      hi[g] = x;
    }
    for (const int g : touched) {
      auto& pts = extremes[static_cast<std::size_t>(g) - 1];
      pts.emplace_back(lo[static_cast<std::size_t>(g)], y);
      if (hi[static_cast<std::size_t>(g)] != lo[static_cast<std::size_t>(g)])
        pts.emplace_back(hi[static_cast<std::size_t>(g)], y);
      hi[static_cast<std::size_t>(g)] = -1;
    }
    touched.clear();
  }
  std::vector<Hull> hulls(static_cast<std::size_t>(n));
  for (std::size_t g = 0; g < hulls.size(); ++g) {
    const Object& o = grouping.objects[g];
    Hull& h = hulls[g];
    h.box = cv::Rect(o.x_min, o.y_min, o.x_max - o.x_min + 1, o.y_max - o.y_min + 1);
    h.mask = cv::Mat::zeros(h.box.size(), CV_8UC1);
    if (extremes[g].empty()) continue;
    cv::convexHull(extremes[g], h.polygon);
    std::vector<cv::Point> local(h.polygon);
    for (auto& p : local) p -= h.box.tl();
    // fillConvexPoly covers the edges too, so every pixel of the object is inside its mask; a
    // dot or a straight line has no area and is drawn as a line.
    if (local.size() < 3)
      cv::line(h.mask, local.front(), local.back(), cv::Scalar(255), 1, cv::LINE_8);
    else
      cv::fillConvexPoly(h.mask, local, cv::Scalar(255), cv::LINE_8);
  }
  return hulls;
}

std::vector<std::uint16_t> median_disparities(const cv::Mat& labels16, const cv::Mat& disp_q4,
                                              const Grouping& grouping) {
  check_labels(labels16, grouping.group_of_label.size() - 1);
  check_disparity(labels16, disp_q4);
  std::vector<std::vector<std::uint16_t>> values(static_cast<std::size_t>(grouping.groups()));
  for (std::size_t g = 0; g < values.size(); ++g) values[g].reserve(grouping.objects[g].area);
  for (int y = 0; y < labels16.rows; ++y) {
    const auto* lab = labels16.ptr<std::uint16_t>(y);
    const auto* d = disp_q4.ptr<std::uint16_t>(y);
    for (int x = 0; x < labels16.cols; ++x)
      if (lab[x] != 0)
        values[static_cast<std::size_t>(grouping.group_of_label[lab[x]]) - 1].push_back(d[x]);
  }
  std::vector<std::uint16_t> medians(values.size(), 0);
  for (std::size_t g = 0; g < values.size(); ++g)
    if (!values[g].empty()) medians[g] = lower_median(values[g]);
  return medians;
}

std::vector<cv::Mat> occlusion_handling(const std::vector<Hull>& hulls,
                                        const std::vector<std::uint16_t>& medians,
                                        const cv::Mat& groups16) {
  if (medians.size() != hulls.size())
    throw std::invalid_argument("occlusion handling needs one median disparity per hull");
  if (!groups16.empty() && groups16.type() != CV_16UC1)
    throw std::invalid_argument("occlusion handling keeps own pixels from a CV_16UC1 group image");
  std::vector<cv::Mat> visible(hulls.size());
  for (std::size_t g = 0; g < hulls.size(); ++g) {
    const Hull& mine = hulls[g];
    visible[g] = mine.mask.clone();
    for (std::size_t c = 0; c < hulls.size(); ++c) {
      if (medians[c] <= medians[g]) continue;
      const cv::Rect both = mine.box & hulls[c].box;
      if (both.empty()) continue;
      visible[g](both - mine.box.tl()).setTo(0, hulls[c].mask(both - hulls[c].box.tl()));
    }
    if (groups16.empty()) continue;
    const cv::Rect box = mine.box & cv::Rect(0, 0, groups16.cols, groups16.rows);
    if (box != mine.box)
      throw std::invalid_argument("a hull lies outside the group image given to keep own pixels");
    visible[g].setTo(255, groups16(box) == static_cast<int>(g + 1));
  }
  return visible;
}

std::vector<Region> postprocess(const cv::Mat& labels16, const cv::Mat& disp_q4,
                                const std::vector<Object>& objects_by_label,
                                const LabellingConfig& cfg, bool merge) {
  const Grouping grouping = merge ? merge_occluded_parts(labels16, disp_q4, objects_by_label, cfg)
                                  : identity_grouping(objects_by_label);
  auto hulls = convex_hulls(labels16, grouping);
  const auto medians = median_disparities(labels16, disp_q4, grouping);
  auto visible = occlusion_handling(hulls, medians, group_image(labels16, grouping));
  std::vector<Region> regions(hulls.size());
  for (std::size_t g = 0; g < regions.size(); ++g) {
    regions[g].labels = grouping.labels_of_group[g];
    regions[g].object = grouping.objects[g];
    regions[g].d_median = medians[g];
    regions[g].hull = std::move(hulls[g]);
    regions[g].visible = std::move(visible[g]);
  }
  return regions;
}

cv::Mat group_image(const cv::Mat& labels16, const Grouping& grouping) {
  check_labels(labels16, grouping.group_of_label.size() - 1);
  cv::Mat out(labels16.size(), CV_16UC1);
  for (int y = 0; y < labels16.rows; ++y) {
    const auto* lab = labels16.ptr<std::uint16_t>(y);
    auto* o = out.ptr<std::uint16_t>(y);
    for (int x = 0; x < labels16.cols; ++x)
      o[x] = static_cast<std::uint16_t>(grouping.group_of_label[lab[x]]);
  }
  return out;
}

}  // namespace scw::labelling
