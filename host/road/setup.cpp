// SPDX-License-Identifier: Apache-2.0
// to_fixed(): the road stage's configuration from the rig.
#include "host/road/setup.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scw::road {
namespace {

constexpr double kUnit = hls::road::kPxUnit;

void positive(double v, const char* name) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string("road: ") + name + " = " + std::to_string(v) +
                                " must be a positive number");
}

std::uint16_t q4(double px, const char* name) {
  if (!(px >= 0.0) || px * 16.0 > 0x7fff)
    throw std::invalid_argument(std::string("road: ") + name + " = " + std::to_string(px) +
                                " px outside 0 .. 2047");
  return static_cast<std::uint16_t>(std::lround(px * 16.0));
}

std::uint8_t q8(double rel, const char* name) {
  if (!(rel >= 0.0) || rel * 256.0 > 255.0)
    throw std::invalid_argument(std::string("road: ") + name + " = " + std::to_string(rel) +
                                " outside 0 .. 0.996");
  return static_cast<std::uint8_t>(std::lround(rel * 256.0));
}

}  // namespace

RoadSetup rig_setup(double baseline_m, double focal_px, double cv_px, double camera_height_m,
                    double camera_pitch_deg) {
  RoadSetup s;
  s.baseline_m = baseline_m;
  s.focal_px = focal_px;
  s.cv_px = cv_px;
  s.camera_height_m = camera_height_m;
  s.camera_pitch_deg = camera_pitch_deg;
  return s;
}

RoadConfig to_fixed(const RoadSetup& s) {
  positive(s.baseline_m, "baseline");
  positive(s.camera_height_m, "camera height");
  positive(s.focal_px, "focal length");
  positive(s.cv_px, "principal point row");
  if (!(s.height_ratio >= 1.0))
    throw std::invalid_argument("road: height ratio " + std::to_string(s.height_ratio) +
                                " must be at least 1");
  if (!(std::abs(s.camera_pitch_deg) <= s.max_pitch_deg))
    throw std::invalid_argument("road: camera pitch " + std::to_string(s.camera_pitch_deg) +
                                " degrees outside the plausible +-" +
                                std::to_string(s.max_pitch_deg) + " (down is positive)");
  // The flat road seen by a camera at height H pitched down by t: d(v) = (b cos t / H)
  // (v - cv + f tan t) px; the plausible slopes stay about the level camera's b / H.
  constexpr double kRad = 3.14159265358979323846 / 180.0;
  const double slope = s.baseline_m / s.camera_height_m;
  const double pitch = s.camera_pitch_deg * kRad;
  const double nominal = slope * std::cos(pitch);
  RoadConfig c;
  c.enable = s.enable;
  c.nominal.a = static_cast<std::int32_t>(std::lround(nominal * kUnit));
  c.nominal.b = static_cast<std::int32_t>(
      std::lround(-nominal * (s.cv_px - s.focal_px * std::tan(pitch)) * kUnit));
  c.a_min = static_cast<std::int32_t>(std::lround(slope / s.height_ratio * kUnit));
  c.a_max = static_cast<std::int32_t>(std::lround(slope * s.height_ratio * kUnit));
  const double shift = s.focal_px * std::tan(s.max_pitch_deg * kRad);
  c.h_min = static_cast<std::uint16_t>(std::max(0.0, std::floor(s.cv_px - shift)));
  c.h_max = static_cast<std::uint16_t>(std::min(1023.0, std::ceil(s.cv_px + shift)));
  c.tol_q4 = q4(s.tol_px, "tolerance");
  c.tol_rel_q8 = q8(s.tol_rel, "relative tolerance");
  c.gate_q4 = q4(s.gate_px, "gate");
  c.gate_rel_q8 = q8(s.gate_rel, "relative gate");
  if (s.min_count < 1 || s.min_count >= (1 << 20))
    throw std::invalid_argument("road: min count " + std::to_string(s.min_count) +
                                " outside 1 .. 1048575");
  c.min_count = static_cast<std::uint32_t>(s.min_count);
  hls::road::check_config(c);
  return c;
}

}  // namespace scw::road
