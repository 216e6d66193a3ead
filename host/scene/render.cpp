// SPDX-License-Identifier: Apache-2.0
// The ray caster (host/scene/render.hpp).
#include "host/scene/render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core/utility.hpp>

#include "host/scene/texture.hpp"

namespace scw::host::scene {
namespace {

// The sky has no texture, only a gentle gradient: block matching finds nothing there, as on a
// real overcast sky.
constexpr double kSkyHorizon = 200.0, kSkyTop = 170.0;
constexpr double kSkyTopRad = 0.17;  // about the elevation of the image's top row

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Entry distance (in units of the direction) of a ray into a box and the face it enters by
/// (0..5: -x, +x, -y, +y, -z, +z); false when it misses or starts inside.
bool enter_box(const cv::Vec3d& o, const cv::Vec3d& d, const SceneObject& b, double& t,
               int& face) {
  double t_in = -kInf, t_out = kInf;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < b.box_min[a] || o[a] > b.box_max[a]) return false;
      continue;
    }
    double t0 = (b.box_min[a] - o[a]) / d[a], t1 = (b.box_max[a] - o[a]) / d[a];
    // A ray going +a enters by the box's minimum face.
    const int f = 2 * a + (d[a] > 0.0 ? 0 : 1);
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_in) {
      t_in = t0;
      face = f;
    }
    t_out = std::min(t_out, t1);
  }
  if (t_in > t_out || t_in <= 0.0) return false;
  t = t_in;
  return true;
}

/// One 64-bit hash step (splitmix64): the noise of every pixel is a function of its key alone.
std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// A standard normal number from a key (Box-Muller on two hashed uniforms), the same with every
/// compiler and library, unlike std::normal_distribution.
double gaussian(std::uint64_t key) {
  const std::uint64_t a = splitmix(key), b = splitmix(a ^ 0x5851f42d4c957f2dULL);
  const double u1 = (static_cast<double>(a >> 11) + 0.5) * 0x1.0p-53;
  const double u2 = static_cast<double>(b >> 11) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

}  // namespace

Hit cast_ray(const cv::Vec3d& origin, const cv::Vec3d& direction,
             const std::vector<SceneObject>& objects, double pixel_rad, int subsamples,
             std::uint32_t ground_seed, const GroundLook& ground) {
  const double len = cv::norm(direction);
  const cv::Vec3d unit = direction / len;
  double best_t = kInf;
  int best_face = -1, best_obj = -1;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    double t = 0.0;
    int face = -1;
    if (enter_box(origin, direction, objects[i], t, face) && t < best_t) {
      best_t = t;
      best_face = face;
      best_obj = static_cast<int>(i);
    }
  }
  const double t_ground = direction[1] < 0.0 ? -origin[1] / direction[1] : kInf;

  Hit h;
  if (best_obj >= 0 && best_t <= t_ground) {
    const SceneObject& o = objects[static_cast<std::size_t>(best_obj)];
    const cv::Vec3d local = origin + best_t * direction - o.texture_origin;
    const int axis = best_face / 2;
    // The two axes in the face: x faces use (z, y), y faces (x, z), z faces (x, y).
    const double a = axis == 0 ? local[2] : local[0];
    const double b = axis == 1 ? local[2] : local[1];
    h.distance_m = best_t * len;
    const double cos_incidence = std::max(std::abs(unit[axis]), 1e-3);
    h.grey = object_grey(o.look, best_face, a, b, h.distance_m * pixel_rad / cos_incidence);
    h.object = best_obj;
  } else if (t_ground < kInf) {
    const cv::Vec3d p = origin + t_ground * direction;
    h.distance_m = t_ground * len;
    // Across the road a sample spans its angle times the distance; along it, that stretched by
    // the grazing angle.
    const double across = h.distance_m * pixel_rad / subsamples;
    const double along = across / std::max(-unit[1], 1e-9);
    h.grey = ground_grey(p[0], p[2], across, along, ground_seed, ground);
  } else {
    const double elevation = std::atan2(unit[1], std::hypot(unit[0], unit[2]));
    h.distance_m = kInf;
    h.grey = kSkyHorizon + (kSkyTop - kSkyHorizon) * std::clamp(elevation / kSkyTopRad, 0.0, 1.0);
  }
  return h;
}

Renderer::Renderer(const StereoRig& rig, int subsamples)
    : rig_(rig), left_(rig, Side::left, subsamples), right_(rig, Side::right, subsamples) {}

cv::Mat Renderer::render_clean(Side s, const std::vector<SceneObject>& objects,
                               std::uint32_t ground_seed, const GroundLook& ground) const {
  const RayTable& rays = this->rays(s);
  const int n = rays.subsamples();
  const double pixel_rad = 1.0 / rays.focal_px();
  const cv::Size size = rays.image_size();
  cv::Mat out(size, CV_32FC1);
  const double norm = 1.0 / (n * n);
  // Rows on OpenCV's threads: a pixel depends on nothing but its rays, so the image is the same
  // byte for byte with any number of threads; a preset renders in half the time on two cores.
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      auto* row = out.ptr<float>(v);
      for (int u = 0; u < size.width; ++u) {
        double sum = 0.0;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            sum += cast_ray(rays.origin(), rays.direction(u * n + i, v * n + j), objects, pixel_rad,
                            n, ground_seed, ground)
                       .grey;
        row[u] = static_cast<float>(sum * norm);
      }
    }
  });
  return out;
}

cv::Mat Renderer::render(Side s, const SceneFrame& frame, const RenderOptions& options) const {
  const cv::Mat clean = render_clean(s, frame.objects, options.seed, options.ground);
  cv::Mat out(clean.size(), CV_8UC1);
  // Key: seed, frame, camera, pixel; each field in its own bits so no two pixels share a key.
  const std::uint64_t base = (static_cast<std::uint64_t>(options.seed) << 32) ^
                             (static_cast<std::uint64_t>(static_cast<std::uint32_t>(frame.index))
                              << 1) ^
                             (s == Side::left ? 0U : 1U);
  for (int v = 0; v < clean.rows; ++v) {
    const float* in = clean.ptr<float>(v);
    auto* row = out.ptr<std::uint8_t>(v);
    for (int u = 0; u < clean.cols; ++u) {
      const std::uint64_t pixel = static_cast<std::uint64_t>(v) * clean.cols + u;
      const double g = in[u] + options.noise_sigma * gaussian(splitmix(base) ^ pixel);
      row[u] = static_cast<std::uint8_t>(std::clamp(std::lround(g), 0L, 255L));
    }
  }
  return out;
}

StereoImages Renderer::render_pair(const SceneFrame& frame, const RenderOptions& options) const {
  return {render(Side::left, frame, options), render(Side::right, frame, options)};
}

}  // namespace scw::host::scene
