// SPDX-License-Identifier: Apache-2.0
// Whole-image disparity reference: straight loops over every window and candidate.
#include "host/reference/disparity_ref.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace scw::reference {
namespace {

std::size_t at(int width, int x, int y) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
         static_cast<std::size_t>(x);
}

// floor(a / b) for b > 0 (C++ division truncates toward zero).
std::int32_t floor_div(std::int32_t a, std::int32_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

}  // namespace

std::vector<std::uint8_t> prefilter_xsobel_reference(const std::uint8_t* in, int width, int height,
                                                     int cap) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                static_cast<std::uint8_t>(cap));
  // Rows y with a partner row in OpenCV's pairwise loop: all of them when H is even, all but the
  // last when H is odd. A single-row image stays all `cap` too.
  const int filtered_rows = height - (height % 2);
  const auto reflect = [height](int y) { return y < 0 ? 1 : y >= height ? height - 2 : y; };
  const auto g = [&](int x, int y) {
    const int yy = reflect(y);
    return int{in[at(width, x + 1, yy)]} - int{in[at(width, x - 1, yy)]};
  };
  for (int y = 0; y < filtered_rows; ++y)
    for (int x = 1; x < width - 1; ++x) {
      const int s = g(x, y - 1) + 2 * g(x, y) + g(x, y + 1);
      out[at(width, x, y)] = static_cast<std::uint8_t>(std::clamp(s, -cap, cap) + cap);
    }
  return out;
}

int sad_reference(const std::uint8_t* l, const std::uint8_t* r, int width, int u, int v, int d,
                  int window_n) {
  const int rad = window_n / 2;
  int sum = 0;
  for (int j = -rad; j <= rad; ++j)
    for (int i = -rad; i <= rad; ++i)
      sum += std::abs(int{l[at(width, u + i, v + j)]} - int{r[at(width, u + i - d, v + j)]});
  return sum;
}

std::int32_t subpixel_reference(int d, int prev, int best, int next) {
  const int den = prev + next - 2 * best + std::abs(prev - next);
  const int frac = den != 0 ? (prev - next) * 256 / den : 0;
  return floor_div(d * 256 + frac + 15, 16);
}

std::vector<std::uint16_t> disparity_reference(const std::uint8_t* left, const std::uint8_t* right,
                                               int width, int height, int window_n, int num_disp,
                                               const hls::disparity::DisparityConfig& cfg) {
  if (window_n < 1 || window_n % 2 == 0)
    throw std::invalid_argument("disparity_reference: the window N must be odd, got " +
                                std::to_string(window_n));
  if (num_disp < 1) throw std::invalid_argument("disparity_reference: num_disp must be >= 1");
  if (cfg.prefilter && (cfg.prefilter_cap < 1 || cfg.prefilter_cap > 63))
    throw std::invalid_argument("disparity_reference: prefilter_cap must be 1 .. 63");

  const std::uint16_t invalid = hls::disparity::invalid_code(cfg);
  std::vector<std::uint16_t> out(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                 invalid);

  std::vector<std::uint8_t> pl, pr;
  const std::uint8_t* l = left;
  const std::uint8_t* r = right;
  if (cfg.prefilter) {
    pl = prefilter_xsobel_reference(left, width, height, cfg.prefilter_cap);
    pr = prefilter_xsobel_reference(right, width, height, cfg.prefilter_cap);
    l = pl.data();
    r = pr.data();
  }

  const int rad = window_n / 2;
  const int dmin = cfg.dmin;
  // The left edge: column u is decided among the candidates whose window lies inside the right
  // image, d <= u - rad, when there are at least `fewest` of them (all num_disp by default).
  const int fewest =
      cfg.edge_candidates > 0 && cfg.edge_candidates < num_disp ? cfg.edge_candidates : num_disp;
  const int u_begin = rad + std::max(dmin + fewest - 1, 0), u_end = width - rad + std::min(dmin, 0);
  const int v_begin = rad, v_end = height - rad;
  std::vector<int> sad(static_cast<std::size_t>(num_disp));
  for (int v = v_begin; v < v_end; ++v)
    for (int u = u_begin; u < u_end; ++u) {
      const int n = std::min(num_disp, u - rad - dmin + 1);  // the candidates that fit
      int best = 0;  // candidate index k, d = dmin + k
      for (int k = 0; k < n; ++k) {
        sad[k] = sad_reference(l, r, width, u, v, dmin + k, window_n);
        if (sad[k] <= sad[best]) best = k;
      }
      const int min_sad = sad[best];

      if (cfg.texture_threshold > 0) {
        int texture = 0;
        for (int j = -rad; j <= rad; ++j)
          for (int i = -rad; i <= rad; ++i)
            texture += std::abs(int{l[at(width, u + i, v + j)]} - cfg.prefilter_cap);
        if (texture < cfg.texture_threshold) continue;
      }
      if (cfg.uniqueness_ratio > 0) {
        const int thresh = min_sad + min_sad * cfg.uniqueness_ratio / 100;
        bool unique = true;
        for (int k = 0; k < n; ++k)
          if (std::abs(k - best) > 1 && sad[k] <= thresh) unique = false;
        if (!unique) continue;
      }
      if (cfg.sad_limit > 0 && min_sad > cfg.sad_limit) continue;

      const int d = dmin + best;
      std::int32_t value = d * 16;
      if (cfg.subpixel && best > 0 && best < n - 1)
        value = subpixel_reference(d, sad[best - 1], min_sad, sad[best + 1]);
      out[at(width, u, v)] = static_cast<std::uint16_t>(static_cast<std::int16_t>(value));
    }
  return out;
}

}  // namespace scw::reference
