// SPDX-License-Identifier: Apache-2.0
// Value noise and the surfaces built from it (host/scene/texture.hpp).
#include "host/scene/texture.hpp"

#include <algorithm>
#include <cmath>

namespace scw::host::scene {
namespace {

/// A 32-bit integer mixer (Wellons' lowbias32): every input bit moves about half the output.
std::uint32_t mix(std::uint32_t h) {
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

double lattice(std::int64_t ix, std::int64_t iy, std::uint32_t seed) {
  const std::uint32_t h = mix(mix(mix(seed) ^ static_cast<std::uint32_t>(ix)) ^
                              static_cast<std::uint32_t>(iy));
  return h * (2.0 / 4294967295.0) - 1.0;
}

double smooth(double t) { return t * t * (3.0 - 2.0 * t); }
double smooth_integral(double t) { return t * t * t * (1.0 - 0.5 * t); }  // of smooth, from 0

/// Value noise along y at lattice column pair (ix, ix + 1), blended by sx: row k's value.
double row_value(std::int64_t ix, double sx, std::int64_t k, std::uint32_t seed) {
  const double a = lattice(ix, k, seed);
  return a + sx * (lattice(ix + 1, k, seed) - a);
}

/// Octave weight for a footprint: full from 1.5 footprints per cell down to none at 0.5.
double resolved(double cell_m, double footprint_m) {
  return std::clamp(cell_m / footprint_m - 0.5, 0.0, 1.0);
}

// Value noise's standard deviation (measured over 4 million samples: 0.430). Octave sums are
// divided by it, so a surface's contrast is two standard deviations of its texture, whatever
// its octaves.
constexpr double kValueNoiseSd = 0.43;

double unit_scale(const Octave* octaves, int count) {
  double w2 = 0.0;
  for (int i = 0; i < count; ++i) w2 += octaves[i].weight * octaves[i].weight;
  return 1.0 / (kValueNoiseSd * std::sqrt(w2));
}

// A band of more cells than this is averaged nearly flat (its deviation falls as one over the
// root of the count): the octave fades out between half of it and all of it, which bounds the
// work for far road.
constexpr double kMaxBandCells = 32.0;

// Road: asphalt grain from 2 to 20 cm, equal weights, by default faint (+- 3 grey levels, as worn
// asphalt looks from a car, GroundLook): block matching then leaves the road mostly invalid, as on
// the Karlsruhe street. A strongly grained road (+- 25 and more) is matched in patches that neither the ground
// filter nor the minimum height removes, and the patches decide the warning (docs/scene.md).
constexpr Octave kAsphalt[] = {{0.02, 1.0}, {0.05, 1.0}, {0.10, 1.0}, {0.20, 1.0}};
constexpr double kAsphaltMean = 110.0;
constexpr double kPaint = 215.0;  // marking grey level

// Lane markings: dashed lines between the lanes, no solid edge lines. A long solid line is one
// connected marking from the bottom of the image to the horizon; its bounding box, which the
// warning stage sizes objects by, is metres tall and wide, so it would pass for an obstacle beside
// the tunnel (docs/scene.md). Dashes are short enough to stay flat.
constexpr double kLineWidth = 0.12;
constexpr double kDashedX[] = {-1.75, 1.75};
constexpr double kDash = 3.0, kGap = 6.0;

// Objects: 4, 8 and 16 cm cells, so a pixel at 31 m (2.3 cm) still resolves the finest one
// with 3 x 3 sub-samples and the block matcher has texture at every preset distance.
constexpr Octave kSkin[] = {{0.04, 1.0}, {0.08, 1.0}, {0.16, 1.0}};
// Faces facing sideways are a little darker, the top lighter: light from above, a hint of
// shape for the eye; the matcher does not need it.
constexpr double kFaceShade[] = {-12.0, -12.0, -6.0, 10.0, 0.0, 0.0};

/// Dash length between z = 0 and z (the integral of the dash indicator): the difference of two
/// gives the dashed part of any interval, hence the markings' box filter along the road.
double dash_length_below(double z) {
  const double period = kDash + kGap;
  const double n = std::floor(z / period);
  return n * kDash + std::min(z - n * period, kDash);
}

/// Fraction of [c - w/2, c + w/2] (the sample's footprint) covered by [lo, hi].
double overlap(double c, double w, double lo, double hi) {
  const double a = std::max(c - 0.5 * w, lo), b = std::min(c + 0.5 * w, hi);
  return std::clamp((b - a) / w, 0.0, 1.0);
}

}  // namespace

double value_noise(double x, double y, std::uint32_t seed) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const double sx = smooth(x - fx), sy = smooth(y - fy);
  const double v00 = lattice(ix, iy, seed), v10 = lattice(ix + 1, iy, seed);
  const double v01 = lattice(ix, iy + 1, seed), v11 = lattice(ix + 1, iy + 1, seed);
  const double top = v00 + sx * (v10 - v00), bottom = v01 + sx * (v11 - v01);
  return top + sy * (bottom - top);
}

double value_noise_band(double x, double y0, double y1, std::uint32_t seed) {
  if (!(y1 - y0 > 1e-9)) return value_noise(x, 0.5 * (y0 + y1), seed);
  const double fx = std::floor(x);
  const auto ix = static_cast<std::int64_t>(fx);
  const double sx = smooth(x - fx);
  const auto k0 = static_cast<std::int64_t>(std::floor(y0));
  const auto k1 = static_cast<std::int64_t>(std::floor(y1));
  double sum = 0.0;
  double a = row_value(ix, sx, k0, seed);
  for (std::int64_t k = k0; k <= k1; ++k) {
    const double b = row_value(ix, sx, k + 1, seed);
    // The part of cell k inside the band, in cell units: the value there is a + smooth(t) (b - a).
    const double t0 = std::max(y0 - static_cast<double>(k), 0.0);
    const double t1 = std::min(y1 - static_cast<double>(k), 1.0);
    sum += a * (t1 - t0) + (b - a) * (smooth_integral(t1) - smooth_integral(t0));
    a = b;
  }
  return sum / (y1 - y0);
}

double fractal_noise(double x, double y, std::uint32_t seed, const Octave* octaves, int count,
                     double footprint_m) {
  double sum = 0.0;
  for (int i = 0; i < count; ++i) {
    const Octave& o = octaves[i];
    const double w = o.weight * resolved(o.cell_m, footprint_m);
    if (w > 0.0)
      sum += w * value_noise(x / o.cell_m, y / o.cell_m, seed + 0x9e3779b9U * (i + 1U));
  }
  return sum * unit_scale(octaves, count);
}

double ground_grey(double x, double z, double footprint_x_m, double footprint_z_m,
                   std::uint32_t seed, const GroundLook& look) {
  // Grain: each octave fades by the footprint across and is averaged over the one along.
  double grain = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Octave& o = kAsphalt[i];
    const double cells = footprint_z_m / o.cell_m;
    const double w = o.weight * resolved(o.cell_m, footprint_x_m) *
                     std::clamp(2.0 - 2.0 * cells / kMaxBandCells, 0.0, 1.0);
    if (w > 0.0)
      grain += w * value_noise_band(x / o.cell_m, (z - 0.5 * footprint_z_m) / o.cell_m,
                                    (z + 0.5 * footprint_z_m) / o.cell_m,
                                    seed + 0x9e3779b9U * (i + 1U));
  }
  const double asphalt =
      kAsphaltMean + 0.5 * look.grain_contrast * grain * unit_scale(kAsphalt, 4);
  if (!look.markings) return asphalt;
  double paint = 0.0;
  const double along =
      (dash_length_below(z + 0.5 * footprint_z_m) - dash_length_below(z - 0.5 * footprint_z_m)) /
      footprint_z_m;
  for (double c : kDashedX)
    paint += along * overlap(x, footprint_x_m, c - kLineWidth / 2, c + kLineWidth / 2);
  paint = std::min(paint, 1.0);
  return asphalt + paint * (kPaint - asphalt);
}

double object_grey(const SurfaceLook& look, int face, double a, double b, double footprint_m) {
  const std::uint32_t seed =
      look.seed * 0x2545f491U + static_cast<std::uint32_t>(face) * 0x68e31da4U;
  return look.base + kFaceShade[face] +
         0.5 * look.contrast * fractal_noise(a, b, seed, kSkin, 3, footprint_m);
}

}  // namespace scw::host::scene
