// SPDX-License-Identifier: Apache-2.0
// The tracker's rules (thesis 5.3.3) on synthetic detections, each in mean-speed and Kalman mode.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "host/app/track.hpp"

namespace {

using Eigen::Vector3d;
using scw::app::Detection;
using scw::app::Track;
using scw::app::Tracker;
using scw::app::TrackerParams;
using scw::app::TrackUpdate;

// Classes as the classifier numbers them does not matter to the tracker; these are labels only.
constexpr int kPedestrian = 1;
constexpr int kBike = 2;

/// A pedestrian (Table 5.4's class means) with its cuboid centred at `p`.
Detection pedestrian(const Vector3d& p, int source = 0) {
  return {kPedestrian, {0.326, 0.065, 0.002}, 0.73, 1.80, p, source};
}

/// A person on a bike (Table 5.4's class means): Hu 2 and the width differ from a pedestrian's
/// by far more than their gates.
Detection bike(const Vector3d& p, int source = 0) {
  return {kBike, {0.276, 0.003, 0.016}, 2.03, 1.82, p, source};
}

TrackerParams params_for(bool kalman) {
  TrackerParams p;
  p.use_kalman = kalman;
  return p;
}

// Tolerances: the mean speed is exact arithmetic on exact positions; the Kalman filter's
// two-point start is exact too, then zero innovations keep it so up to rounding in its
// covariance algebra.
double tol(bool kalman) { return kalman ? 1e-6 : 1e-9; }

bool near(const Vector3d& a, const Vector3d& b, double eps) { return (a - b).norm() <= eps; }

/// One frame with a single detection; returns the id it got.
int step(Tracker& tr, const Detection& d) {
  const std::vector<TrackUpdate> u = tr.update({d});
  REQUIRE(u.size() == 1);
  return u[0].track_id;
}

}  // namespace

TEST_CASE("a track's speed appears after its third consecutive match and is the true speed",
          "[app]") {
  const bool kalman = GENERATE(false, true);
  CAPTURE(kalman);
  Tracker tr(params_for(kalman));
  const double dt = tr.params().frame_period_s;
  const Vector3d p0{1.0, 0.9, 15.0};
  const Vector3d v{0.8, 0.0, -12.0};  // crossing slowly while the car closes in at 43 km/h

  const int id = step(tr, pedestrian(p0));
  for (int f = 1; f <= 10; ++f) {
    REQUIRE(step(tr, pedestrian(p0 + f * dt * v)) == id);
    const Track& t = *tr.find(id);
    CAPTURE(f);
    REQUIRE(t.consecutive_matches == f);
    // Frame 0 created the track; frames 1, 2, 3 are its first three matches.
    REQUIRE(t.has_speed == (f >= 3));
    if (!kalman && f < 3) REQUIRE(t.velocity.isZero());
    if (f >= 3) REQUIRE(near(t.velocity, v, tol(kalman)));
    REQUIRE(near(t.position, p0 + f * dt * v, tol(kalman)));
  }

  if (!kalman) {
    // The mean speed follows the latest three matches: after a change of velocity it is the
    // mix of both until three matches at the new one have been seen, then the new one exactly.
    const Vector3d p10 = p0 + 10 * dt * v;
    const Vector3d v2{-1.5, 0.0, -6.0};
    for (int f = 1; f <= 3; ++f) {
      REQUIRE(step(tr, pedestrian(p10 + f * dt * v2)) == id);
      const Vector3d expect = (f * v2 + (3 - f) * v) / 3.0;
      REQUIRE(near(tr.find(id)->velocity, expect, 1e-9));
    }
  }
}

TEST_CASE("a missed track coasts on the constant-velocity path for five frames", "[app]") {
  const bool kalman = GENERATE(false, true);
  CAPTURE(kalman);
  Tracker tr(params_for(kalman));
  const double dt = tr.params().frame_period_s;
  const Vector3d p0{-2.0, 0.9, 20.0};
  const Vector3d v{1.4, 0.0, -10.0};
  const int id = step(tr, pedestrian(p0));
  for (int f = 1; f <= 4; ++f) step(tr, pedestrian(p0 + f * dt * v));
  const Track before = *tr.find(id);
  REQUIRE(before.has_speed);

  for (int m = 1; m <= 5; ++m) {
    CAPTURE(m);
    REQUIRE(tr.update({}).empty());
    const Track* t = tr.find(id);
    REQUIRE(t != nullptr);
    REQUIRE(t->missed == m);
    REQUIRE(t->consecutive_matches == 0);
    REQUIRE(t->source_index == -1);
    REQUIRE(near(t->position, p0 + (4 + m) * dt * v, tol(kalman)));
    REQUIRE(near(t->velocity, v, tol(kalman)));
    REQUIRE(t->has_speed);
    // Shape and size are presumed constant while the object is not seen.
    REQUIRE(t->hu == before.hu);
    REQUIRE(t->width_m == before.width_m);
    REQUIRE(t->height_m == before.height_m);
  }

  SECTION("a track without a speed yet coasts at zero velocity") {
    Tracker fresh(params_for(kalman));
    const int id2 = step(fresh, bike({3.0, 0.9, 12.0}));
    for (int m = 1; m <= 5; ++m) {
      fresh.update({});
      REQUIRE(fresh.find(id2)->position == Vector3d(3.0, 0.9, 12.0));
    }
  }
}

TEST_CASE("a track is removed on its sixth consecutive miss, and ids are not reused", "[app]") {
  const bool kalman = GENERATE(false, true);
  CAPTURE(kalman);
  Tracker tr(params_for(kalman));
  const double dt = tr.params().frame_period_s;
  const Vector3d p0{0.5, 0.9, 10.0};
  const Vector3d v{0.0, 0.0, -5.0};
  REQUIRE(tr.mode() == Tracker::Mode::kInitialisation);
  const int id = step(tr, pedestrian(p0));
  REQUIRE(tr.mode() == Tracker::Mode::kTracking);
  for (int f = 1; f <= 3; ++f) step(tr, pedestrian(p0 + f * dt * v));

  for (int m = 1; m <= 5; ++m) tr.update({});
  REQUIRE(tr.find(id) != nullptr);
  REQUIRE(tr.find(id)->missed == 5);
  tr.update({});
  REQUIRE(tr.find(id) == nullptr);
  REQUIRE(tr.tracks().empty());
  REQUIRE(tr.mode() == Tracker::Mode::kInitialisation);

  // Back in initialisation: the same object at its predicted place is a new track, new id.
  const std::vector<TrackUpdate> u = tr.update({pedestrian(p0 + 10 * dt * v, 7)});
  REQUIRE(u.size() == 1);
  REQUIRE(u[0].is_new);
  REQUIRE(u[0].track_id > id);
  REQUIRE(u[0].source_index == 7);
}

TEST_CASE("a re-detection within five misses keeps the track's id", "[app]") {
  const bool kalman = GENERATE(false, true);
  const int misses = GENERATE(1, 4, 5);
  CAPTURE(kalman, misses);
  Tracker tr(params_for(kalman));
  const double dt = tr.params().frame_period_s;
  const Vector3d p0{-1.0, 0.9, 18.0};
  const Vector3d v{0.6, 0.0, -9.0};
  const int id = step(tr, bike(p0));
  for (int f = 1; f <= 3; ++f) step(tr, bike(p0 + f * dt * v));
  for (int m = 1; m <= misses; ++m) tr.update({});

  int f = 3 + misses + 1;
  const std::vector<TrackUpdate> u = tr.update({bike(p0 + f * dt * v, 4)});
  REQUIRE(u[0].track_id == id);
  REQUIRE_FALSE(u[0].is_new);
  const Track* t = tr.find(id);
  REQUIRE(t->missed == 0);
  REQUIRE(t->consecutive_matches == 1);
  REQUIRE(t->source_index == 4);
  REQUIRE(t->has_speed);  // the speed survives the gap
  REQUIRE(near(t->velocity, v, tol(kalman)));
  REQUIRE(tr.tracks().size() == 1);

  // Two more matches: the mean speed now spans the gap (the time does too) and is still exact.
  for (int k = 0; k < 2; ++k) {
    ++f;
    REQUIRE(step(tr, bike(p0 + f * dt * v)) == id);
  }
  REQUIRE(tr.find(id)->consecutive_matches == 3);
  REQUIRE(near(tr.find(id)->velocity, v, tol(kalman)));
}

TEST_CASE("crossing objects keep their identities when their features differ", "[app]") {
  const bool kalman = GENERATE(false, true);
  CAPTURE(kalman);
  // A pedestrian walks right in front of a cyclist riding left, 2 m/s each, seen at 10 Hz: from
  // the first frame to the next they swap sides, so each detection is nearest to the other's
  // track. Position alone would swap the identities; Hu 2 and the width keep them.
  TrackerParams p = params_for(kalman);
  p.frame_period_s = 0.1;
  TrackerParams position_only = p;
  position_only.hu_gate = {1e9, 1e9, 1e9};
  position_only.width_gate_m = position_only.height_gate_m = 1e9;

  Tracker with_features(p), by_position(position_only);
  auto frame = [](int f) {
    return std::vector<Detection>{pedestrian({-0.1 + 0.2 * f, 0.90, 10.0}, 0),
                                  bike({0.1 - 0.2 * f, 0.91, 10.2}, 1)};
  };
  const std::vector<TrackUpdate> first = with_features.update(frame(0));
  const std::vector<TrackUpdate> first_pos = by_position.update(frame(0));
  for (int f = 1; f <= 8; ++f) {
    CAPTURE(f);
    const std::vector<TrackUpdate> u = with_features.update(frame(f));
    REQUIRE(u[0].track_id == first[0].track_id);
    REQUIRE(u[1].track_id == first[1].track_id);
    REQUIRE_FALSE(u[0].is_new);
    REQUIRE_FALSE(u[1].is_new);
    if (f == 1) {
      // The swap the features prevent (what position-only matching does afterwards is moot).
      const std::vector<TrackUpdate> w = by_position.update(frame(f));
      REQUIRE(w[0].track_id == first_pos[1].track_id);
      REQUIRE(w[1].track_id == first_pos[0].track_id);
    }
  }
  REQUIRE(with_features.tracks().size() == 2);
  const Track& ped = *with_features.find(first[0].track_id);
  REQUIRE(ped.cls == kPedestrian);
  REQUIRE(near(ped.velocity, {2.0, 0.0, 0.0}, tol(kalman)));
  REQUIRE(near(with_features.find(first[1].track_id)->velocity, {-2.0, 0.0, 0.0}, tol(kalman)));
}

TEST_CASE("a detection that matches no track starts a track with a new id", "[app]") {
  const bool kalman = GENERATE(false, true);
  CAPTURE(kalman);
  Tracker tr(params_for(kalman));
  // Empty frames leave the tracker in initialisation; the first frame with objects adds all.
  REQUIRE(tr.update({}).empty());
  const std::vector<TrackUpdate> init =
      tr.update({pedestrian({0.0, 0.9, 10.0}, 0), pedestrian({3.0, 0.9, 10.0}, 1)});
  REQUIRE(init[0].is_new);
  REQUIRE(init[1].is_new);
  REQUIRE(init[1].track_id > init[0].track_id);
  REQUIRE(tr.tracks().size() == 2);

  // Same two objects, plus one out of every position gate, plus a bike where the first
  // pedestrian is (inside its position gate, outside its shape gates).
  const std::vector<TrackUpdate> u =
      tr.update({pedestrian({0.0, 0.9, 10.0}, 0), pedestrian({3.0, 0.9, 10.0}, 1),
                 pedestrian({-4.0, 0.9, 25.0}, 2), bike({0.05, 0.9, 10.2}, 3)});
  REQUIRE(u[0].track_id == init[0].track_id);
  REQUIRE(u[1].track_id == init[1].track_id);
  REQUIRE(u[2].is_new);
  REQUIRE(u[3].is_new);
  REQUIRE(u[2].track_id > init[1].track_id);
  REQUIRE(u[3].track_id == u[2].track_id + 1);
  REQUIRE(u[3].source_index == 3);
  REQUIRE(tr.tracks().size() == 4);
  REQUIRE(tr.find(u[3].track_id)->cls == kBike);
}

TEST_CASE("each feature's gate alone makes a detection a new object", "[app]") {
  const bool kalman = GENERATE(false, true);
  // One feature just outside its gate, everything else equal, alone in the frame: no other
  // detection competes for the track, so only the gate can refuse the pair.
  const int feature = GENERATE(range(0, 8));
  CAPTURE(kalman, feature);
  Tracker tr(params_for(kalman));
  const TrackerParams& p = tr.params();
  const Detection d0 = pedestrian({0.0, 0.9, 10.0});
  const int id = step(tr, d0);
  Detection d = d0;
  if (feature < 3) d.hu[feature] += 1.01 * p.hu_gate[feature];
  if (feature == 3) d.width_m += 1.01 * p.width_gate_m;
  if (feature == 4) d.height_m -= 1.01 * p.height_gate_m;
  if (feature >= 5) d.centre_m[feature - 5] += 1.01 * p.position_gate_m[feature - 5];
  const std::vector<TrackUpdate> u = tr.update({d});
  REQUIRE(u[0].is_new);
  REQUIRE(u[0].track_id > id);
  REQUIRE(tr.find(id)->missed == 1);

  // Just inside the gate it is the same object.
  Tracker tr2(params_for(kalman));
  const int id2 = step(tr2, d0);
  Detection e = d0;
  if (feature < 3) e.hu[feature] += 0.99 * p.hu_gate[feature];
  if (feature == 3) e.width_m += 0.99 * p.width_gate_m;
  if (feature == 4) e.height_m -= 0.99 * p.height_gate_m;
  if (feature >= 5) e.centre_m[feature - 5] += 0.99 * p.position_gate_m[feature - 5];
  REQUIRE(step(tr2, e) == id2);
}

TEST_CASE("the most likely correspondence wins and no detection feeds two tracks", "[app]") {
  const bool kalman = GENERATE(false, true);
  CAPTURE(kalman);
  Tracker tr(params_for(kalman));
  const std::vector<TrackUpdate> init =
      tr.update({pedestrian({0.0, 0.9, 10.0}), pedestrian({0.4, 0.9, 10.0})});

  SECTION("two detections in one track's gates: the nearer updates it, the other is new") {
    // Both are inside the first track's gate; the second track's gate holds only the nearer.
    Detection a = pedestrian({0.05, 0.9, 10.0}, 0);
    Detection b = pedestrian({-0.2, 0.9, 10.0}, 1);
    const std::vector<TrackUpdate> u = tr.update({b, a});
    REQUIRE(u[1].track_id == init[0].track_id);
    REQUIRE(u[0].is_new);  // b: the first track is taken, b is outside the second's gate
    REQUIRE(tr.find(init[1].track_id)->missed == 1);
  }
  SECTION("one detection in two tracks' gates goes to the nearer track only") {
    const std::vector<TrackUpdate> u = tr.update({pedestrian({0.3, 0.9, 10.0})});
    REQUIRE(u[0].track_id == init[1].track_id);
    REQUIRE(tr.find(init[0].track_id)->missed == 1);
  }
  SECTION("features count in the distance, not only the position") {
    // At the same distance from both tracks, the detection whose shape is closer wins.
    Detection d = pedestrian({0.2, 0.9, 10.0});
    Tracker tr2(params_for(kalman));
    Detection t0 = pedestrian({0.0, 0.9, 10.0});
    Detection t1 = pedestrian({0.4, 0.9, 10.0});
    t1.hu[0] += 0.03;
    const std::vector<TrackUpdate> i2 = tr2.update({t0, t1});
    REQUIRE(tr2.update({d})[0].track_id == i2[0].track_id);
  }
}

TEST_CASE("the Kalman velocity converges to the true one on a noisy track", "[app]") {
  // 3 s at 100 Hz of a constant-velocity object whose cuboid centre jitters by 5 cm (1 sigma)
  // on each axis. Differencing positions 3 frames apart turns that into about 2.4 m/s of speed
  // noise per axis; the filter averages it down.
  const Vector3d p0{-3.0, 0.9, 30.0};
  const Vector3d v{1.2, 0.0, -8.0};
  const double sigma = 0.05;
  std::mt19937 rng(20240611);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Vector3d> measured;
  for (int f = 0; f < 300; ++f) {
    // One draw a statement: a call's arguments are evaluated in an unspecified order.
    const double nz = noise(rng), ny = noise(rng), nx = noise(rng);
    measured.push_back(p0 + f * 0.01 * v + Vector3d(nx, ny, nz));
  }

  TrackerParams kp;
  kp.use_kalman = true;
  Tracker kalman(kp), mean{TrackerParams{}};
  int id_k = 0, id_m = 0;
  double sq_k = 0.0, sq_m = 0.0, pos_sq_k = 0.0, pos_sq_raw = 0.0, early_sq_k = 0.0;
  int n = 0;
  for (int f = 0; f < 300; ++f) {
    const int ik = step(kalman, pedestrian(measured[f]));
    const int im = step(mean, pedestrian(measured[f]));
    if (f == 0) id_k = ik, id_m = im;
    REQUIRE(ik == id_k);  // the noise never breaks the track
    REQUIRE(im == id_m);
    if (f >= 3 && f < 23) early_sq_k += (kalman.find(id_k)->velocity - v).squaredNorm();
    if (f >= 200) {  // the last second
      const Vector3d truth = p0 + f * 0.01 * v;
      sq_k += (kalman.find(id_k)->velocity - v).squaredNorm();
      sq_m += (mean.find(id_m)->velocity - v).squaredNorm();
      pos_sq_k += (kalman.find(id_k)->position - truth).squaredNorm();
      pos_sq_raw += (measured[f] - truth).squaredNorm();
      ++n;
    }
  }
  const double rms_k = std::sqrt(sq_k / n), rms_m = std::sqrt(sq_m / n);
  const double pos_rms_k = std::sqrt(pos_sq_k / n), pos_rms_raw = std::sqrt(pos_sq_raw / n);
  // Printed on every run: the numbers docs/tracking.md quotes.
  const double early_rms_k = std::sqrt(early_sq_k / 20);
  WARN("velocity RMS error, frames 3..22: Kalman "
       << early_rms_k << " m/s; last second: Kalman " << rms_k << " m/s, mean speed " << rms_m
       << " m/s; position RMS: Kalman " << pos_rms_k << " m, raw " << pos_rms_raw << " m");
  CHECK(rms_k < 0.2);
  CHECK(rms_k < early_rms_k / 5.0);  // it converges
  CHECK(rms_k < rms_m / 5.0);
  CHECK(pos_rms_k < pos_rms_raw / 2.0);  // the smoothing of the position
  CHECK(near(kalman.find(id_k)->velocity, v, 0.5));
}

TEST_CASE("bad parameters and detections are refused by name", "[app]") {
  TrackerParams p;
  p.position_gate_m.z() = 0.0;
  REQUIRE_THROWS_WITH(Tracker(p), Catch::Contains("position_gate_m.z"));
  p = TrackerParams{};
  p.frame_period_s = std::nan("");
  REQUIRE_THROWS_WITH(Tracker(p), Catch::Contains("frame_period_s"));
  p = TrackerParams{};
  p.max_missed = -1;
  REQUIRE_THROWS_WITH(Tracker(p), Catch::Contains("max_missed"));

  Tracker tr;
  Detection d = pedestrian({0.0, 0.9, std::nan("")}, 9);
  REQUIRE_THROWS_WITH(tr.update({d}), Catch::Contains("source_index 9"));
  REQUIRE(tr.tracks().empty());  // a refused frame changes nothing
}
