// SPDX-License-Identifier: Apache-2.0
// road_reference(): the road stage in doubles.
#include "host/reference/road_ref.hpp"

#include <cmath>
#include <stdexcept>

namespace scw::reference {

RoadFrameRef road_reference(const cv::Mat& q4, const RoadLinePx& road,
                            const hls::road::RoadConfig& cfg) {
  if (q4.empty() || (q4.type() != CV_16UC1 && q4.type() != CV_16SC1))
    throw std::invalid_argument("road reference: a 16-bit map of disparity x 16 is needed");
  const double unit = hls::road::kPxUnit;  const double tol = cfg.tol_q4 / 16.0, tol_rel = cfg.tol_rel_q8 / 256.0;
  const double gate = cfg.gate_q4 / 16.0, gate_rel = cfg.gate_rel_q8 / 256.0;
  RoadFrameRef r;
  r.kept = q4.clone();
  double n = 0, sv = 0, svv = 0, sd = 0, svd = 0;
  for (int v = 0; v < q4.rows; ++v) {
    const double dr = road.a * v + road.b;
    if (dr < 1.0) continue;
    for (int u = 0; u < q4.cols; ++u) {
      const int code = static_cast<std::int16_t>(q4.at<std::uint16_t>(v, u));
      if (code <= 0) continue;
      const double d = code / 16.0, e = std::abs(d - dr);
      if (cfg.enable && e <= tol + tol_rel * dr) r.kept.at<std::uint16_t>(v, u) = 0;
      if (e <= gate + gate_rel * dr) {
        n += 1, sv += v, svv += double(v) * v, sd += d, svd += v * d;
      }
    }
  }
  r.pixels = n;
  r.next = road;
  const double den = n * svv - sv * sv;
  if (n < cfg.min_count || den <= 0) return r;
  const double a = (n * svd - sv * sd) / den, b = (sd - a * sv) / n;
  if (!(a > 0) || a < cfg.a_min / unit || a > cfg.a_max / unit) return r;
  const double horizon = -b / a;
  if (horizon < cfg.h_min || horizon > cfg.h_max) return r;
  r.next = {a, b};
  r.fitted = true;
  return r;
}

}  // namespace scw::reference
