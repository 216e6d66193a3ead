// SPDX-License-Identifier: Apache-2.0
// Procedural, deterministic surface textures: hash-based value noise, the road with its markings
// and the objects' skins (docs/scene.md).
#pragma once

#include <cstdint>

namespace scw::host::scene {

/// Smooth value noise in [-1, 1]: hashed lattice values at integer (x, y), blended with a
/// smoothstep, so the same (x, y, seed) gives the same value on every machine.
double value_noise(double x, double y, std::uint32_t seed);

/// One octave: lattice spacing in metres and its weight in the sum.
struct Octave {
  double cell_m;
  double weight;
};

/// Octaves of value noise summed and scaled to a standard deviation of 1 (before fading). An
/// octave whose cell is smaller than about one `footprint_m` (the surface length one pixel
/// covers) fades out: a camera averages it away, and left and right samples would otherwise
/// alias it differently, leaving texture that does not match between the views.
double fractal_noise(double x, double y, std::uint32_t seed, const Octave* octaves, int count,
                     double footprint_m);

/// value_noise averaged over y from y0 to y1 at one x, exactly (the smoothstep integrates in
/// closed form): a box filter along one axis, as a pixel averages a surface seen at a slant.
double value_noise_band(double x, double y0, double y1, std::uint32_t seed);

/// How the road looks: its grain's contrast (two standard deviations, grey levels) and whether
/// dashed lane markings are painted on it.
struct GroundLook {
  bool markings = false;
  /// +-3: worn asphalt, as block matching sees the Karlsruhe street (mostly invalid); the street
  /// presets use +-25 and +-60, a road the matcher finds in patches (docs/scene.md).
  double grain_contrast = 3.0;
};

/// The road at world (x, z) (vehicle coordinates, metres): asphalt grain around 110 and the
/// lane markings. `footprint_x_m`, `footprint_z_m`: the ground one sample covers across and
/// along the road. Seen at a grazing angle a sample covers far more road along than across
/// (30 m ahead: 2.3 cm across a pixel, 60 cm along it), so grain and markings are box-filtered
/// over that footprint: the grain across the road stays sharp, as in a real camera, and nothing
/// aliases into texture that differs between the two views.
double ground_grey(double x, double z, double footprint_x_m, double footprint_z_m,
                   std::uint32_t seed, const GroundLook& look);

/// How an object's surface looks: its noise seed, mean grey level and amplitude (two standard
/// deviations of its texture).
struct SurfaceLook {
  std::uint32_t seed = 1;
  double base = 100.0;
  double contrast = 40.0;
};

/// An object's grey level on face `face` (0..5: -x, +x, -y, +y, -z, +z) at in-face coordinates
/// (a, b) in metres from the box's minimum corner, so the texture moves with the object.
double object_grey(const SurfaceLook& look, int face, double a, double b, double footprint_m);

}  // namespace scw::host::scene
