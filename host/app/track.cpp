// SPDX-License-Identifier: Apache-2.0
// The application layer's tracker of pedestrians and bikes (thesis 5.3.3), docs/tracking.md.
#include "host/app/track.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <opencv2/video/tracking.hpp>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace scw::app {

namespace {

void require_positive(double v, const char* name) {
  // Written as !(v > 0) so that NaN is refused too.
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw std::invalid_argument(std::string("TrackerParams::") + name +
                                " must be positive and "
                                "finite, is " +
                                std::to_string(v));
  }
}

void check(const Detection& d, std::size_t k) {
  bool ok = std::isfinite(d.width_m) && std::isfinite(d.height_m) && d.width_m >= 0.0 &&
            d.height_m >= 0.0 && d.centre_m.allFinite();
  for (double h : d.hu) ok = ok && std::isfinite(h);
  if (!ok) {
    throw std::invalid_argument("Tracker::update: detection " + std::to_string(k) +
                                " (source_index " + std::to_string(d.source_index) +
                                ") has a non-finite value or a negative size");
  }
}

Eigen::Vector3d to_eigen(const cv::Mat& state, int row0) {
  return {state.at<double>(row0, 0), state.at<double>(row0 + 1, 0), state.at<double>(row0 + 2, 0)};
}

}  // namespace

// Per-track motion state, kept beside the public Track so Track stays a plain value.
struct Tracker::Motion {
  /// The measured centres (frame, position) of the latest observations: the creating detection
  /// and later matches, at most speed_matches + 1 of them. The mean speed spans them.
  std::deque<std::pair<long, Eigen::Vector3d>> seen;
  /// Kalman mode: created at the track's first match (two-point initialisation), else null.
  std::unique_ptr<cv::KalmanFilter> kf;
};

Tracker::Tracker(const TrackerParams& params) : params_(params) {
  const char* hu_names[3] = {"hu_gate[0]", "hu_gate[1]", "hu_gate[2]"};
  for (int k = 0; k < 3; ++k) require_positive(params_.hu_gate[k], hu_names[k]);
  require_positive(params_.width_gate_m, "width_gate_m");
  require_positive(params_.height_gate_m, "height_gate_m");
  const char* pos_names[3] = {"position_gate_m.x", "position_gate_m.y", "position_gate_m.z"};
  for (int k = 0; k < 3; ++k) require_positive(params_.position_gate_m[k], pos_names[k]);
  require_positive(params_.frame_period_s, "frame_period_s");
  require_positive(params_.kalman_accel_sigma, "kalman_accel_sigma");
  require_positive(params_.kalman_meas_sigma_m, "kalman_meas_sigma_m");
  if (params_.speed_matches < 1) {
    throw std::invalid_argument("TrackerParams::speed_matches must be at least 1, is " +
                                std::to_string(params_.speed_matches));
  }
  if (params_.max_missed < 0) {
    throw std::invalid_argument("TrackerParams::max_missed must not be negative, is " +
                                std::to_string(params_.max_missed));
  }
}

Tracker::~Tracker() = default;
Tracker::Tracker(Tracker&&) noexcept = default;
Tracker& Tracker::operator=(Tracker&&) noexcept = default;

const Track* Tracker::find(int id) const {
  for (const Track& t : tracks_) {
    if (t.id == id) return &t;
  }
  return nullptr;
}

bool Tracker::gates(const Detection& d, const Track& t, const Eigen::Vector3d& predicted) const {
  for (int k = 0; k < 3; ++k) {
    if (!(std::abs(d.hu[k] - t.hu[k]) < params_.hu_gate[k])) return false;
  }
  if (!(std::abs(d.width_m - t.width_m) < params_.width_gate_m)) return false;
  if (!(std::abs(d.height_m - t.height_m) < params_.height_gate_m)) return false;
  const Eigen::Vector3d dp = (d.centre_m - predicted).cwiseAbs();
  return (dp.array() < params_.position_gate_m.array()).all();
}

double Tracker::distance(const Detection& d, const Track& t,
                         const Eigen::Vector3d& predicted) const {
  // Each difference in units of its gate, so no feature dominates by its scale and "inside the
  // gates" means every term is below 1.
  double s = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double r = (d.hu[k] - t.hu[k]) / params_.hu_gate[k];
    s += r * r;
  }
  const double rw = (d.width_m - t.width_m) / params_.width_gate_m;
  const double rh = (d.height_m - t.height_m) / params_.height_gate_m;
  s += rw * rw + rh * rh;
  s += (d.centre_m - predicted).cwiseQuotient(params_.position_gate_m).squaredNorm();
  return s;
}

Eigen::Vector3d Tracker::predict(std::size_t i) {
  Track& t = tracks_[i];
  Motion& m = *motion_[i];
  if (m.kf) {
    // cv::KalmanFilter::predict also copies the prediction into statePost / errorCovPost, so a
    // frame without a match leaves the filter coasting on its prediction.
    return to_eigen(m.kf->predict(), 0);
  }
  // Mean-speed mode, or Kalman mode before the first match: constant velocity, which is zero
  // until the track has a speed.
  return t.position + t.velocity * params_.frame_period_s;
}

void Tracker::start(const Detection& d) {
  Track t;
  t.id = next_id_++;
  t.cls = d.cls;
  t.hu = d.hu;
  t.width_m = d.width_m;
  t.height_m = d.height_m;
  t.position = d.centre_m;
  t.source_index = d.source_index;
  auto m = std::make_unique<Motion>();
  m->seen.emplace_back(frame_, d.centre_m);
  tracks_.push_back(t);
  motion_.push_back(std::move(m));
}

void Tracker::match(std::size_t i, const Detection& d) {
  Track& t = tracks_[i];
  Motion& m = *motion_[i];
  const double dt = params_.frame_period_s;
  t.cls = d.cls;
  t.hu = d.hu;
  t.width_m = d.width_m;
  t.height_m = d.height_m;
  t.source_index = d.source_index;
  t.missed = 0;
  ++t.consecutive_matches;
  if (t.consecutive_matches >= params_.speed_matches) t.has_speed = true;

  if (params_.use_kalman) {
    if (!m.kf) {
      // Two-point initialisation (Bar-Shalom): position from this match, velocity from the
      // difference to the previous observation, covariances from the measurement noise. It is
      // the limit of an uninformative velocity prior, so a noise-free constant-velocity object
      // is estimated exactly from its first match on, with no guessed prior speed.
      const auto& [f0, p0] = m.seen.back();
      const double T = static_cast<double>(frame_ - f0) * dt;
      const double r = params_.kalman_meas_sigma_m * params_.kalman_meas_sigma_m;
      const double q = params_.kalman_accel_sigma * params_.kalman_accel_sigma;
      m.kf = std::make_unique<cv::KalmanFilter>(6, 3, 0, CV_64F);
      cv::KalmanFilter& kf = *m.kf;
      // State (x, y, z, vx, vy, vz), one frame per step; measurement (x, y, z).
      cv::setIdentity(kf.transitionMatrix);
      for (int k = 0; k < 3; ++k) kf.transitionMatrix.at<double>(k, k + 3) = dt;
      kf.measurementMatrix = cv::Mat::zeros(3, 6, CV_64F);
      for (int k = 0; k < 3; ++k) kf.measurementMatrix.at<double>(k, k) = 1.0;
      // Discrete white-noise acceleration: an unknown acceleration of variance q, constant
      // over a frame, moves position by a dt^2 / 2 and velocity by a dt.
      kf.processNoiseCov = cv::Mat::zeros(6, 6, CV_64F);
      for (int k = 0; k < 3; ++k) {
        kf.processNoiseCov.at<double>(k, k) = q * dt * dt * dt * dt / 4.0;
        kf.processNoiseCov.at<double>(k, k + 3) = q * dt * dt * dt / 2.0;
        kf.processNoiseCov.at<double>(k + 3, k) = q * dt * dt * dt / 2.0;
        kf.processNoiseCov.at<double>(k + 3, k + 3) = q * dt * dt;
      }
      cv::setIdentity(kf.measurementNoiseCov, cv::Scalar(r));
      kf.errorCovPost = cv::Mat::zeros(6, 6, CV_64F);
      for (int k = 0; k < 3; ++k) {
        kf.statePost.at<double>(k, 0) = d.centre_m[k];
        kf.statePost.at<double>(k + 3, 0) = (d.centre_m[k] - p0[k]) / T;
        kf.errorCovPost.at<double>(k, k) = r;
        kf.errorCovPost.at<double>(k, k + 3) = r / T;
        kf.errorCovPost.at<double>(k + 3, k) = r / T;
        kf.errorCovPost.at<double>(k + 3, k + 3) = 2.0 * r / (T * T);
      }
    } else {
      const cv::Mat z = (cv::Mat_<double>(3, 1) << d.centre_m.x(), d.centre_m.y(), d.centre_m.z());
      m.kf->correct(z);
    }
    t.position = to_eigen(m.kf->statePost, 0);
    t.velocity = to_eigen(m.kf->statePost, 3);
  } else {
    t.position = d.centre_m;
  }

  m.seen.emplace_back(frame_, d.centre_m);
  while (static_cast<int>(m.seen.size()) > params_.speed_matches + 1) m.seen.pop_front();
  if (!params_.use_kalman && t.consecutive_matches >= params_.speed_matches) {
    // The mean speed over the last speed_matches matches: total displacement over total time
    // (the oldest kept observation may lie before a gap of misses, then the time covers it).
    const auto& [f0, p0] = m.seen.front();
    t.velocity = (d.centre_m - p0) / (static_cast<double>(frame_ - f0) * dt);
  }
}

std::vector<TrackUpdate> Tracker::update(const std::vector<Detection>& detections) {
  for (std::size_t k = 0; k < detections.size(); ++k) check(detections[k], k);
  ++frame_;

  // Phase 1: track existing objects. Predict every track one frame ahead, then take the gated
  // pairs greedily by increasing distance, so the most likely correspondence wins and neither
  // a track nor a detection is used twice.
  std::vector<Eigen::Vector3d> predicted(tracks_.size());
  for (std::size_t i = 0; i < tracks_.size(); ++i) predicted[i] = predict(i);

  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    for (std::size_t k = 0; k < detections.size(); ++k) {
      if (gates(detections[k], tracks_[i], predicted[i])) {
        pairs.emplace_back(distance(detections[k], tracks_[i], predicted[i]), i, k);
      }
    }
  }
  // Ties fall to the older track, then the earlier detection: deterministic.
  std::sort(pairs.begin(), pairs.end());

  std::vector<TrackUpdate> out(detections.size());
  std::vector<int> track_of(detections.size(), -1);
  std::vector<bool> matched(tracks_.size(), false);
  for (const auto& [dist, i, k] : pairs) {
    (void)dist;
    if (matched[i] || track_of[k] >= 0) continue;
    matched[i] = true;
    track_of[k] = static_cast<int>(i);
  }

  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    ++tracks_[i].age;
    if (matched[i]) continue;
    // No correspondence: shape and size stay, the position coasts on the prediction.
    Track& t = tracks_[i];
    t.position = predicted[i];
    if (motion_[i]->kf) t.velocity = to_eigen(motion_[i]->kf->statePost, 3);
    t.source_index = -1;
    t.consecutive_matches = 0;
    ++t.missed;
  }
  for (std::size_t k = 0; k < detections.size(); ++k) {
    if (track_of[k] < 0) continue;
    const auto i = static_cast<std::size_t>(track_of[k]);
    match(i, detections[k]);
    out[k] = {tracks_[i].id, false, detections[k].source_index};
  }

  // Phase 3 (done before 2, which only appends tracks with no miss): remove tracks that missed
  // more than max_missed frames in a row.
  std::size_t w = 0;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    if (tracks_[i].missed > params_.max_missed) continue;
    if (w != i) {
      tracks_[w] = std::move(tracks_[i]);
      motion_[w] = std::move(motion_[i]);
    }
    ++w;
  }
  tracks_.resize(w);
  motion_.resize(w);

  // Phase 2: every detection without a correspondence starts a track. In initialisation mode
  // (no tracks) that is every detection of the frame.
  for (std::size_t k = 0; k < detections.size(); ++k) {
    if (track_of[k] >= 0) continue;
    start(detections[k]);
    out[k] = {tracks_.back().id, true, detections[k].source_index};
  }
  return out;
}

}  // namespace scw::app
