// SPDX-License-Identifier: Apache-2.0
#include "host/warning/setup.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scw::host::warning {
namespace {

long to_int(double v, double scale, long lo, long hi, const char* what, const char* unit) {
  const double x = std::round(v * scale);
  if (!std::isfinite(v) || x < lo || x > hi)
    throw std::invalid_argument(std::string("warning: ") + what + " " + std::to_string(v) + " " +
                                unit + " does not fit its port (" + std::to_string(lo / scale) +
                                " .. " + std::to_string(hi / scale) + " " + unit + ")");
  return static_cast<long>(x);
}

}  // namespace

hls::warning::WarningConfig to_fixed(const WarningSetup& s) {
  hls::warning::WarningConfig c;
  c.baseline_q8 = static_cast<std::uint32_t>(
      to_int(s.baseline_m, 1000.0 * 256, 1, (1 << 20) - 1, "baseline", "m"));
  c.focal_q4 = static_cast<std::uint16_t>(to_int(s.focal_px, 16, 1, 65535, "focal length", "px"));
  c.cu_q4 = static_cast<std::uint16_t>(to_int(s.cu_px, 16, 0, 65535, "principal point u", "px"));
  c.cv_q4 = static_cast<std::uint16_t>(to_int(s.cv_px, 16, 0, 65535, "principal point v", "px"));
  const Eigen::Vector3d& t = s.vehicle_origin;
  c.veh_x_mm = static_cast<std::int16_t>(to_int(t.x(), 1000, -32768, 32767, "vehicle x", "m"));
  c.veh_y_mm = static_cast<std::int16_t>(to_int(t.y(), 1000, -32768, 32767, "vehicle y", "m"));
  c.veh_z_mm = static_cast<std::int16_t>(to_int(t.z(), 1000, -32768, 32767, "vehicle z", "m"));
  auto mm = [](double v, const char* what) {
    return static_cast<std::uint16_t>(to_int(v, 1000, 0, 65535, what, "m"));
  };
  c.tunnel_half_w_mm = mm(s.tunnel_half_width_m(), "tunnel half width");
  c.tunnel_h_mm = mm(s.tunnel_height_m(), "tunnel height");
  c.high_mm = mm(s.high_m, "high threshold");
  c.medium_mm = mm(s.medium_m, "medium threshold");
  c.near_mm = mm(s.near_m, "near distance");
  c.min_height_mm = mm(s.min_height_m, "minimum height");
  c.d_limit_q4 = static_cast<std::uint16_t>(
      to_int(s.d_limit_px, 16, 16, 32767, "disparity limit", "px"));
  c.rule = s.distance_rule;
  c.spread_q4 = static_cast<std::uint8_t>(to_int(s.spread_k, 16, 0, 255, "spread k", "sd"));
  return c;
}

}  // namespace scw::host::warning
