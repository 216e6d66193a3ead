// SPDX-License-Identifier: Apache-2.0
// Ray casting a frame through the rig: road, sky and textured boxes, supersampled, with camera
// noise, into the raw 8-bit pair a real rig would deliver (docs/scene.md).
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "host/scene/rays.hpp"
#include "host/scene/rig.hpp"
#include "host/scene/scene.hpp"

namespace scw::host::scene {

/// Noise and texture seed of a rendering.
struct RenderOptions {
  double noise_sigma = 1.0;  // grey levels, Gaussian, independent per pixel and camera
  std::uint32_t seed = 1;    // the road's texture and the noise (with the frame index)
  /// The road's grain and markings. Markings are off in the thesis presets: far dashes merge
  /// into one marking whose box passes the warning stage's minimum height (docs/scene.md).
  GroundLook ground;
};

struct StereoImages {
  cv::Mat left, right;  // CV_8UC1, raw (distorted, unrectified)
};

/// What one ray sees first: the grey level there and the distance along the ray.
struct Hit {
  double grey = 0.0;
  double distance_m = 0.0;  // infinity for the sky
  int object = -1;          // index into the objects, -1 for road or sky
};

/// Casts one ray (origin and direction in vehicle coordinates; the direction need not be unit):
/// the nearest of the boxes and the road wins, else the sky. `pixel_rad`: the angle a pixel
/// subtends, for the textures' footprints; `subsamples`: samples per pixel and axis.
Hit cast_ray(const cv::Vec3d& origin, const cv::Vec3d& direction,
             const std::vector<SceneObject>& objects, double pixel_rad, int subsamples,
             std::uint32_t ground_seed, const GroundLook& ground = {});

/// The renderer of one rig: its two ray tables, built once (about a second each).
class Renderer {
 public:
  /// Rays per pixel and axis of every scene docs/scene.md measured (`scw scene --subsamples`).
  static constexpr int kDefaultSubsamples = 3;
  explicit Renderer(const StereoRig& rig, int subsamples = kDefaultSubsamples);

  const StereoRig& rig() const { return rig_; }
  const RayTable& rays(Side s) const { return s == Side::left ? left_ : right_; }

  /// The camera's image before noise and quantisation: the mean of each pixel's sub-samples,
  /// CV_32FC1.
  cv::Mat render_clean(Side s, const std::vector<SceneObject>& objects,
                       std::uint32_t ground_seed, const GroundLook& ground = {}) const;
  /// The raw 8-bit image of one camera: render_clean plus noise seeded by (seed, frame index,
  /// camera), rounded and clamped, so a frame renders the same on every run.
  cv::Mat render(Side s, const SceneFrame& frame, const RenderOptions& options) const;
  StereoImages render_pair(const SceneFrame& frame, const RenderOptions& options) const;

 private:
  StereoRig rig_;
  RayTable left_, right_;
};

}  // namespace scw::host::scene
