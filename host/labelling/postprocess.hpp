// SPDX-License-Identifier: Apache-2.0
// Whole-frame post-processing of the labelling stage's output (thesis 3.2): merging object parts
// split by an occluder, convex hulls and occlusion handling (docs/labelling-postprocess.md).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "hls/labelling/labelling_params.hpp"

namespace scw::labelling {

using hls::labelling::LabellingConfig;
using hls::labelling::Object;

/// Labels grouped into final objects ("regions").
struct Grouping {
  /// group_of_label[k] is the group (1..) of label k; group_of_label[0] = 0 (no object).
  std::vector<int> group_of_label;
  /// labels_of_group[g - 1]: the group's labels, ascending.
  std::vector<std::vector<int>> labels_of_group;
  /// objects[g - 1]: the exact descriptor of the group's pixels (hls::labelling::merge).
  std::vector<Object> objects;
  int groups() const { return static_cast<int>(objects.size()); }
};

/// Every label its own group: the grouping without merging.
Grouping identity_grouping(const std::vector<Object>& objects_by_label);

/// Merges object parts split by an occluder (thesis Fig. 3.12). On each row, A's last pixel and
/// a later pixel starting a run of B face each other when every pixel between them is either
/// no data (label 0 and not valid under `cfg`) or valid and closer than both facing pixels
/// (d > both, Q11.4), with at least one such closer pixel. The facing pixels' disparities of
/// each side are collected per pair over all rows where they face; A and B merge when the lower
/// medians mA, mB of the two sides agree by the join rule on the larger one,
/// 10 |mA - mB| < max(mA, mB), on at least `min_rows` rows. Merging is transitive (union-find).
/// Groups are numbered 1.. in ascending order of their smallest label, so in raster order of
/// their first pixel, like the labels.
/// labels16: CV_16UC1 as Segmentation::labels; disp_q4: CV_16UC1 Q11.4 of the same size (the
/// map that was labelled); objects_by_label[k - 1] describes label k. Throws
/// std::invalid_argument for mismatched types, sizes or a label above objects_by_label.size().
Grouping merge_occluded_parts(const cv::Mat& labels16, const cv::Mat& disp_q4,
                              const std::vector<Object>& objects_by_label,
                              const LabellingConfig& cfg, int min_rows = 1);

/// A convex hull: the polygon through pixel centres (image coordinates) and the pixels it
/// covers, edges included.
struct Hull {
  std::vector<cv::Point> polygon;  // cv::convexHull order; 1 or 2 points for a dot or a line
  cv::Rect box;                    // the object's bounding box (the hull lies inside it)
  cv::Mat mask;                    // CV_8UC1 of box.size(): 255 inside the hull, else 0
};

/// The convex hull of each group's pixels: hulls[g - 1] for group g. Built from each row's
/// leftmost and rightmost pixel of the group (the hull of all pixels is the hull of those).
std::vector<Hull> convex_hulls(const cv::Mat& labels16, const Grouping& grouping);

/// One final object after post-processing.
struct Region {
  std::vector<int> labels;     // the labels merged into it, ascending
  Object object;               // exact descriptor of its pixels
  std::uint16_t d_median = 0;  // lower median of its pixels' disparities, Q11.4
  Hull hull;
  /// CV_8UC1 of hull.box.size(): the hull minus the hulls of closer regions (occlusion
  /// handling, Fig. 3.17).
  cv::Mat visible;
};

/// The lower median disparity of each group's pixels: medians[g - 1] (Q11.4).
std::vector<std::uint16_t> median_disparities(const cv::Mat& labels16, const cv::Mat& disp_q4,
                                              const Grouping& grouping);

/// Occlusion handling (Fig. 3.17): each hull mask minus the hull masks of the regions closer to
/// the camera that overlap it. "Closer" compares the median disparities (strictly larger is
/// closer; equal medians cut neither): d_max is one pixel, so a slanted surface's near end or
/// one outlier would decide, where the median follows the bulk of the object. With `groups16`
/// (group_image()), a region's own pixels stay visible whatever hulls cover them: a pixel
/// labelled with the region was seen, and a concave closer object's hull can otherwise swallow
/// a whole farther object (docs/labelling-postprocess.md); without it, the thesis's plain
/// subtraction. Returns visible[g - 1], each of hulls[g - 1].box.size().
std::vector<cv::Mat> occlusion_handling(const std::vector<Hull>& hulls,
                                        const std::vector<std::uint16_t>& medians,
                                        const cv::Mat& groups16 = cv::Mat());

/// The whole of thesis 3.2's post-processing: merge_occluded_parts (when `merge`), then
/// convex_hulls, median_disparities and occlusion_handling (own pixels kept). regions[g - 1] is
/// group g.
std::vector<Region> postprocess(const cv::Mat& labels16, const cv::Mat& disp_q4,
                                const std::vector<Object>& objects_by_label,
                                const LabellingConfig& cfg, bool merge = true);

/// The label image renumbered by group: each pixel's group number (CV_16UC1).
cv::Mat group_image(const cv::Mat& labels16, const Grouping& grouping);

}  // namespace scw::labelling
