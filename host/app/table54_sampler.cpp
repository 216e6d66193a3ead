// SPDX-License-Identifier: Apache-2.0
// synthesize_table54() and its samplers (host/app/table54_sampler.hpp).
#include "host/app/table54_sampler.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>

namespace scw::app {

namespace {

/// Samplers on std::mt19937, whose sequence the standard fixes (unlike std::*_distribution's),
/// so a seed gives the same rows with any standard library.
class Sampler {
 public:
  explicit Sampler(unsigned seed) : mt_(seed) {}

  double uniform() {  // in (0, 1), 53 bits
    const std::uint64_t a = mt_() >> 5, b = mt_() >> 6;
    return (static_cast<double>((a << 26) + b) + 0.5) / 9007199254740992.0;
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double normal() {  // Marsaglia's polar method, one value per pair kept for simplicity
    for (;;) {
      const double u = 2 * uniform() - 1, v = 2 * uniform() - 1, q = u * u + v * v;
      if (q > 0 && q < 1) return u * std::sqrt(-2 * std::log(q) / q);
    }
  }
  double exponential(double mean) { return -mean * std::log(uniform()); }
  /// Gamma with shape k and scale 1 (Marsaglia and Tsang 2000; k < 1 by the k + 1 boost).
  double gamma(double k) {
    if (k < 1) return gamma(k + 1) * std::pow(uniform(), 1 / k);
    const double d = k - 1.0 / 3, c = 1 / std::sqrt(9 * d);
    for (;;) {
      double x = 0, v = 0;
      do {
        x = normal();
        v = 1 + c * x;
      } while (v <= 0);
      v = v * v * v;
      const double u = uniform();
      if (u < 1 - 0.0331 * x * x * x * x) return d * v;
      if (std::log(u) < 0.5 * x * x + d * (1 - v + std::log(v))) return d * v;
    }
  }
  /// The gamma distribution with this mean and standard deviation (shape (m / sd)^2, scale
  /// sd^2 / m): non-negative, and near the normal when m / sd is large.
  double gamma_ms(double mean, double sd) {
    const double k = (mean / sd) * (mean / sd);
    return sd * sd / mean * gamma(k);
  }

 private:
  std::mt19937 mt_;
};

Features draw(Sampler& g, const ClassStats& st, double widen) {
  const auto m = to_array(st.mean), sd = to_array(st.sigma);
  std::array<double, kNumFeatures> a{};
  for (std::size_t i = 0; i < kNumFeatures; ++i) a[i] = g.gamma_ms(m[i], widen * sd[i]);
  return from_array(a);
}

/// Trees, bushes, poles and signs as the labelling stage segments them: anything from a
/// compact blob (hu1 near its minimum 1 / 2 pi, a disc) to a thin pole, up to 4 m each way.
Features clutter(Sampler& g) {
  Features f;
  f.hu1 = g.uniform(0.16, 0.60);
  f.hu2 = g.uniform(0, f.hu1 * f.hu1);  // hu1^2 - hu2 = 4 (eta20 eta02 - eta11^2) >= 0
  f.hu3 = g.exponential(0.02);
  f.width_m = g.uniform(0.2, 4.0);
  f.height_m = g.uniform(0.3, 4.0);
  return f;
}

}  // namespace

std::vector<LabelledFeatures> synthesize_table54(int per_class, unsigned seed) {
  if (per_class < 0) throw std::invalid_argument("synthesize_table54: per_class must be >= 0");
  Sampler g(seed);
  std::vector<LabelledFeatures> rows;
  rows.reserve(3 * static_cast<std::size_t>(per_class));
  for (int i = 0; i < per_class; ++i)
    rows.push_back({ObjectClass::kPedestrian, draw(g, kTable54Pedestrian, 1)});
  for (int i = 0; i < per_class; ++i)
    rows.push_back({ObjectClass::kBike, draw(g, kTable54Bike, 1)});
  for (int i = 0; i < per_class; ++i) {
    const double u = g.uniform();
    // Half clutter; half look-alikes (a bush the size of a person, a fence as wide as a bike):
    // a class's distribution at twice its spread, so some fall inside the class's box, as
    // Table 5.5's "other" column shows real trees and bushes do.
    const Features f = u < 0.5    ? clutter(g)
                       : u < 0.75 ? draw(g, kTable54Pedestrian, 2)
                                  : draw(g, kTable54Bike, 2);
    rows.push_back({ObjectClass::kOther, f});
  }
  return rows;
}

}  // namespace scw::app
