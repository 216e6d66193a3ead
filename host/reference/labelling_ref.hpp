// SPDX-License-Identifier: Apache-2.0
// Whole-image reference for the labelling stage: a plain flood fill over the join rule and
// descriptors summed from each object's pixel list, so the tiled streaming model can be checked
// against it object for object.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/labelling/labelling_params.hpp"

namespace scw::reference {

/// What the reference finds in one disparity map.
struct LabellingReference {
  /// The objects of at least cfg.min_area pixels, in raster order of their first pixel;
  /// objects[k - 1] is the object labelled k.
  std::vector<hls::labelling::Object> objects;
  /// width * height, row-major: the object's number 1 .. K, or 0 (background or dropped).
  std::vector<std::uint16_t> labels;
  /// Connected components before the min_area filter.
  int components = 0;
};

/// Labels a row-major `width` x `height` map of Q11.4 disparities (architecture 4.3):
///  - a pixel is valid when hls::labelling::is_valid(d, cfg);
///  - two valid 4-neighbours p (earlier in raster order) and q (later) are joined when
///    joins(d_q, d_p), i.e. 10 |d_q - d_p| < d_q: the later pixel's disparity is the reference,
///    so the relation is symmetric as a graph edge but not in its arguments;
///  - objects are the connected components of that graph (iterative flood fill, no union-find,
///    no code shared with hls::labelling beyond is_valid and joins); those below cfg.min_area
///    are dropped;
///  - descriptors (area, inclusive bbox, d_min/d_max, closest point = first pixel in raster
///    order holding d_max, first pixel, raw moments m_pq = sum x^p y^q, p + q <= 3, x = column,
///    y = row) are summed from each object's pixel list with loops of its own, not with
///    pixel_object()/merge().
/// cfg.width, cfg.height and the tile size are not read: `width` and `height` govern.
/// Throws std::invalid_argument for a null map or a size outside 1 .. 65535, and
/// std::overflow_error when more than 65535 objects survive (labels are 16-bit).
LabellingReference labelling_reference(const std::uint16_t* disp, int width, int height,
                                       const hls::labelling::LabellingConfig& cfg);

}  // namespace scw::reference
