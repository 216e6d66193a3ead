// SPDX-License-Identifier: Apache-2.0
// Central moments and Hu's seven invariants of an object, from the stage's raw moments.
#pragma once

#include <array>

#include "hls/labelling/labelling_params.hpp"

namespace scw::labelling {

/// The central moments (mu20, mu11, mu02, mu30, mu21, mu12, mu03) of an object, about its
/// centroid (m10 / m00, m01 / m00). Each is the exact rational value m00^-k * N (N an integer
/// combination of raw moments, evaluated in 128-bit integers, k = 1 for order 2 and 2 for
/// order 3), rounded once: an object symmetric about its centroid gives exact zeros, where a
/// double evaluation such as cv::moments leaves cancellation noise. All zero for area 0.
/// Precondition: the moments are those of a pixel set, and area * (largest coordinate + 1)
/// < 2^40 (any object in a frame up to 8192 x 8192); std::overflow_error otherwise.
std::array<double, 7> central_moments(const hls::labelling::Object& o);

/// Hu's seven invariants (thesis eq. 2.7; cv::HuMoments' order h1 .. h7) of the scale-normalised
/// central moments eta_pq = mu_pq / m00^(1 + (p + q) / 2), from the exact central numerators:
/// the sums and differences inside the invariants are exact too, only the products round (in
/// long double). Equals cv::HuMoments(cv::moments(mask, true)) on the object's mask to 1e-9
/// relative wherever OpenCV's own double evaluation carries that many digits. All zero for
/// area 0 (as OpenCV) and for a single pixel. Same precondition as central_moments().
std::array<double, 7> hu_moments(const hls::labelling::Object& o);

}  // namespace scw::labelling
