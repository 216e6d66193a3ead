// SPDX-License-Identifier: Apache-2.0
// The application layer's tracker of pedestrians and bikes (thesis 5.3.3), docs/tracking.md.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

namespace scw::app {

/// One object of a frame that the classifier called pedestrian or bike.
struct Detection {
  int cls = 0;                           // the classifier's class, carried through to the track
  std::array<double, 3> hu{};            // Hu 1, Hu 2, Hu 3 (thesis eq. 2.7, Table 5.4 scale)
  double width_m = 0.0, height_m = 0.0;  // 3D size
  /// Centre of the bounding cuboid in vehicle coordinates, m (x right, y up, z ahead).
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  int source_index = -1;  // the caller's index of the object (not read by the tracker)
};

/// One tracked object after Tracker::update().
struct Track {
  int id = 0;   // unique over the tracker's life: ids increase and are never reused
  int cls = 0;  // the class of the latest matching detection
  /// Shape and size of the latest matching detection: kept unchanged while the track misses.
  std::array<double, 3> hu{};
  double width_m = 0.0, height_m = 0.0;
  /// Position, m: the latest detection's centre (mean-speed mode), the filtered estimate
  /// (Kalman mode), or the prediction when this frame had no match.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Velocity, m/s, vehicle axes. Mean-speed mode: zero until has_speed. Kalman mode: the
  /// filter's estimate (non-zero from the first match on, but trust it only with has_speed).
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  /// Set after the third consecutive match (a track's first detection is not a match); stays
  /// set for the rest of the track's life, the speed kept through misses.
  bool has_speed = false;
  int consecutive_matches = 0;  // matches since creation or the last miss
  int missed = 0;               // consecutive frames without a match (0 when matched)
  int age = 0;                  // frames since creation (0 in the frame that created it)
  int source_index = -1;        // the matching detection's source_index this frame, else -1
};

/// Tracker parameters. Every gate is a strict upper bound on an absolute difference between a
/// detection and a track; the defaults are argued in docs/tracking.md.
struct TrackerParams {
  /// Hu 1..3 gates: the larger of the pedestrian and bike standard deviations of Table 5.4.
  std::array<double, 3> hu_gate{0.066, 0.030, 0.017};
  double width_gate_m = 0.15;   // Table 5.4: bike width std. dev.
  double height_gate_m = 0.10;  // Table 5.4: pedestrian height std. dev.
  /// Position gate per axis (x, y, z) against the track's predicted position, m. z is wider:
  /// stereo depth error grows with distance squared.
  Eigen::Vector3d position_gate_m{0.5, 0.5, 1.0};
  double frame_period_s = 0.01;  // 100 Hz, the thesis's camera rate
  int speed_matches = 3;         // consecutive matches before the speed is known (thesis: 3)
  int max_missed = 5;            // frames predicted without a match; removed on the next miss

  /// Kalman mode: a constant-velocity cv::KalmanFilter per track gives prediction, position
  /// and velocity instead of the latest detection and the mean speed.
  bool use_kalman = false;
  double kalman_accel_sigma = 2.0;   // process noise: white acceleration, m/s^2 (1 sigma)
  double kalman_meas_sigma_m = 0.1;  // measurement noise of the cuboid centre, m (1 sigma)
};

/// What update() did with one detection.
struct TrackUpdate {
  int track_id = 0;       // the track the detection updated or started
  bool is_new = false;    // true when it started a new track
  int source_index = -1;  // copied from the detection
};

/// Nearest-neighbour tracker after thesis 5.3.3. Per frame: every track is predicted one frame
/// ahead; detection-track pairs inside all gates are taken greedily by increasing normalised
/// distance (each detection and each track used once); matched tracks take the detection,
/// unmatched detections start tracks, unmatched tracks coast on their prediction and are
/// removed after max_missed coasting frames. With no track (initialisation mode) every
/// detection starts a track.
class Tracker {
 public:
  enum class Mode { kInitialisation, kTracking };

  /// Throws std::invalid_argument naming a parameter that is not positive (gates, frame period,
  /// noise) or not at least 1 (speed_matches) or 0 (max_missed).
  explicit Tracker(const TrackerParams& params = {});
  ~Tracker();
  Tracker(Tracker&&) noexcept;
  Tracker& operator=(Tracker&&) noexcept;

  /// Processes one frame. Returns one entry per detection, in the same order. Throws
  /// std::invalid_argument for a detection with a non-finite value or a negative size.
  std::vector<TrackUpdate> update(const std::vector<Detection>& detections);

  /// The live tracks after the latest update(), in order of creation.
  const std::vector<Track>& tracks() const { return tracks_; }
  /// The track with this id, or nullptr when it is not (or no longer) tracked.
  const Track* find(int id) const;
  /// Initialisation while nothing is tracked, tracking otherwise.
  Mode mode() const { return tracks_.empty() ? Mode::kInitialisation : Mode::kTracking; }
  const TrackerParams& params() const { return params_; }

  /// The normalised distance of a detection to a track's prediction: the sum over Hu 1..3,
  /// width, height and x, y, z of (difference / gate)^2. Every term of a matching pair is
  /// below 1. Exposed for tests and diagnostics.
  double distance(const Detection& d, const Track& t, const Eigen::Vector3d& predicted) const;
  /// Whether every difference is inside its gate.
  bool gates(const Detection& d, const Track& t, const Eigen::Vector3d& predicted) const;

 private:
  struct Motion;  // per-track motion state: measurement history or Kalman filter

  Eigen::Vector3d predict(std::size_t i);
  void start(const Detection& d);
  void match(std::size_t i, const Detection& d);

  TrackerParams params_;
  std::vector<Track> tracks_;
  std::vector<std::unique_ptr<Motion>> motion_;  // motion_[i] belongs to tracks_[i]
  long frame_ = 0;                               // frames processed
  int next_id_ = 1;
};

}  // namespace scw::app
