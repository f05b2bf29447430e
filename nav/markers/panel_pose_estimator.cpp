#include "nav/markers/panel_pose_estimator.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/fail.h"
#include "base/so3.h"
#include "nav/markers/marker_frame_chain.h"

namespace deepnav {
namespace {

double largestEigenvalue(const Eigen::Matrix3d& m) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues()(2);
}

// Angle of the rotation between two orientations, [0, pi].
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return std::min(a.angularDistance(b), std::numbers::pi);
}

Eigen::Matrix3d fromRowMajor(const std::array<double, 9>& a) {
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = a[3 * r + c];
  }
  return m;
}

std::array<double, 9> toRowMajor(const Eigen::Matrix3d& m) {
  std::array<double, 9> a{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) a[3 * r + c] = m(r, c);
  }
  return a;
}

bool isCovariance(const Eigen::Matrix3d& m) {
  if (!m.allFinite() || !m.isApprox(m.transpose(), 1e-9)) return false;
  const Eigen::Vector3d ev =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues();
  return ev(0) >= -1e-12 * std::max(1.0, ev(2));
}

}  // namespace

Eigen::Isometry3d PanelPoseEstimate::T_odom_panel() const {
  return isometryOf(q_odom_panel, p_panel_in_odom_m);
}

PanelPoseInOdom PanelPoseEstimate::inOdom() const {
  PanelPoseInOdom p;
  p.T_odom_panel = T_odom_panel();
  p.sigma_position_m = std::sqrt(std::max(0.0, largestEigenvalue(cov_position_m2)));
  p.sigma_rotation_rad = std::sqrt(std::max(0.0, largestEigenvalue(cov_rotation_rad2)));
  return p;
}

bool PanelPoseEstimator::init(const PanelPoseConfig& config, std::string* error) {
  initialised_ = false;
  if (!validatePanelPoseConfig(config, error)) return false;
  config_ = config;
  reset();
  initialised_ = true;
  return true;
}

void PanelPoseEstimator::reset() {
  clearAccumulators();
  estimate_ = PanelPoseEstimate{};
  counters_ = PanelPoseCounters{};
}

void PanelPoseEstimator::clearAccumulators() {
  n_ = 0;
  mean_p_.setZero();
  m2_p_.setZero();
  rotations_.clear();
  seen_ids_.reset();
  consecutive_outliers_ = 0;
}

bool PanelPoseEstimator::passesQuality(const MarkerObservation& obs) const {
  return obs.distance_m <= config_.max_distance_m &&
         obs.obliqueness_rad <= config_.max_obliqueness_rad &&
         obs.reprojection_error_px <= config_.max_reprojection_px;
}

bool PanelPoseEstimator::insideGate(const Eigen::Isometry3d& T_odom_panel) const {
  // gate = max(floor, k * RMS scatter); RMS of |p - mean| is sqrt(trace(scatter)).
  const double k = config_.outlier_gate_sigma;
  const double gate_m =
      std::max(config_.outlier_floor_m, k * std::sqrt(estimate_.scatter_position_m2.trace()));
  const double gate_rad =
      std::max(config_.outlier_floor_rad, k * std::sqrt(estimate_.scatter_rotation_rad2.trace()));
  const double dp_m = (T_odom_panel.translation() - estimate_.p_panel_in_odom_m).norm();
  const double dtheta_rad =
      angleBetween(Eigen::Quaterniond(T_odom_panel.linear()), estimate_.q_odom_panel);
  return dp_m <= gate_m && dtheta_rad <= gate_rad;
}

PanelObservationVerdict PanelPoseEstimator::addObservation(TimeUs t_us,
                                                           const MarkerObservation& obs,
                                                           const PanelMarker& marker,
                                                           const Eigen::Isometry3d& T_odom_robot,
                                                           const Eigen::Isometry3d& T_robot_cam) {
  if (estimate_.fixed) {
    ++counters_.ignored_fixed;
    return PanelObservationVerdict::kIgnoredFixed;
  }
  const bool finite = obs.p_marker_in_cam_m.allFinite() && obs.q_cam_marker.coeffs().allFinite() &&
                      obs.p_marker_in_cam_alt_m.allFinite() &&
                      obs.q_cam_marker_alt.coeffs().allFinite() &&
                      T_odom_robot.matrix().allFinite() && T_robot_cam.matrix().allFinite() &&
                      std::isfinite(obs.distance_m) && std::isfinite(obs.obliqueness_rad) &&
                      std::isfinite(obs.reprojection_error_px);
  if (!initialised_ || !finite || obs.id < 0 || obs.id >= kMaxMarkerId || marker.id != obs.id) {
    ++counters_.rejected_invalid;
    return PanelObservationVerdict::kRejectedInvalid;
  }
  if (!passesQuality(obs)) {
    ++counters_.rejected_quality;
    return PanelObservationVerdict::kRejectedQuality;
  }
  const Eigen::Isometry3d T_panel_marker = panelMarkerPose(marker);
  Eigen::Isometry3d T_odom_panel =
      panelPoseFromMarker(T_odom_robot, T_robot_cam, cameraMarkerPose(obs), T_panel_marker);
  if (obs.ambiguous) {
    if (!config_.use_ambiguous || n_ == 0) {
      ++counters_.rejected_ambiguous;
      return PanelObservationVerdict::kRejectedAmbiguous;
    }
    // The planar ambiguity flips the marker's tilt: keep the solution closer to the running mean.
    const Eigen::Isometry3d T_alt = panelPoseFromMarker(
        T_odom_robot, T_robot_cam, cameraMarkerPoseAlternative(obs), T_panel_marker);
    if (angleBetween(Eigen::Quaterniond(T_alt.linear()), estimate_.q_odom_panel) <
        angleBetween(Eigen::Quaterniond(T_odom_panel.linear()), estimate_.q_odom_panel)) {
      T_odom_panel = T_alt;
    }
  }
  if (n_ > 0 && !insideGate(T_odom_panel)) {
    if (++consecutive_outliers_ < config_.restart_after_rejections) {
      ++counters_.rejected_outlier;
      return PanelObservationVerdict::kRejectedOutlier;
    }
    // Everything disagrees with the mean: the mean is the odd one out. Start again from here.
    clearAccumulators();
    ++counters_.restarts;
  }
  if (obs.ambiguous) ++counters_.ambiguous_resolved;
  accumulate(t_us, obs.id, T_odom_panel);
  return PanelObservationVerdict::kAccepted;
}

int PanelPoseEstimator::addFrame(TimeUs t_us, const MarkerObservations& observations,
                                 const PanelDescription& panel,
                                 const Eigen::Isometry3d& T_odom_robot,
                                 const Eigen::Isometry3d& T_robot_cam) {
  int accepted = 0;
  for (int i = 0; i < observations.count; ++i) {
    const MarkerObservation& obs = observations.items[i];
    const PanelMarker* marker = panel.marker(obs.id);
    if (marker == nullptr) {
      ++counters_.unknown_markers;
      continue;
    }
    if (addObservation(t_us, obs, *marker, T_odom_robot, T_robot_cam) ==
        PanelObservationVerdict::kAccepted) {
      ++accepted;
    }
  }
  return accepted;
}

void PanelPoseEstimator::accumulate(TimeUs t_us, int marker_id,
                                    const Eigen::Isometry3d& T_odom_panel) {
  // Welford's update of the mean and of the sum of squared deviations.
  ++n_;
  const Eigen::Vector3d p = T_odom_panel.translation();
  const Eigen::Vector3d delta = p - mean_p_;
  mean_p_ += delta / n_;
  m2_p_.noalias() += delta * (p - mean_p_).transpose();
  rotations_.add(Eigen::Quaterniond(T_odom_panel.linear()));
  seen_ids_.set(static_cast<size_t>(marker_id));
  consecutive_outliers_ = 0;
  ++counters_.accepted;
  updateEstimate();
  if (thresholdsMet()) {
    estimate_.fixed = true;
    estimate_.t_fixed_us = t_us;
  }
}

void PanelPoseEstimator::updateEstimate() {
  estimate_.p_panel_in_odom_m = mean_p_;
  estimate_.q_odom_panel = rotations_.mean();
  estimate_.observations = n_;
  estimate_.distinct_markers = static_cast<std::int32_t>(seen_ids_.count());
  if (n_ < 2) {
    estimate_.scatter_position_m2.setZero();
    estimate_.scatter_rotation_rad2.setZero();
  } else {
    // Unbiased sample covariances (n - 1); the rotation scatter of QuaternionAverage is over n.
    const Eigen::Matrix3d s = m2_p_ / (n_ - 1);
    estimate_.scatter_position_m2 = 0.5 * (s + s.transpose());
    estimate_.scatter_rotation_rad2 = rotations_.scatter() * (static_cast<double>(n_) / (n_ - 1));
  }
  estimate_.cov_position_m2 = estimate_.scatter_position_m2 / std::max(1, n_);
  estimate_.cov_rotation_rad2 = estimate_.scatter_rotation_rad2 / std::max(1, n_);
}

bool PanelPoseEstimator::thresholdsMet() const {
  if (estimate_.observations < config_.min_observations) return false;
  if (estimate_.distinct_markers < config_.min_distinct_markers) return false;
  if (n_ < 2) return false;  // no scatter from a single observation
  const double pos_std_m =
      std::sqrt(std::max(0.0, largestEigenvalue(estimate_.scatter_position_m2)));
  const double angle_std_rad =
      std::sqrt(std::max(0.0, largestEigenvalue(estimate_.scatter_rotation_rad2)));
  return pos_std_m <= config_.max_position_std_m && angle_std_rad <= config_.max_angle_std_rad;
}

bool PanelPoseEstimator::record(PanelPoseRecord* out) const {
  if (!estimate_.fixed) return false;
  PanelPoseRecord r;
  for (int i = 0; i < 3; ++i) r.p_panel_in_odom_m[i] = estimate_.p_panel_in_odom_m(i);
  for (int i = 0; i < 4; ++i) r.q_odom_panel_xyzw[i] = estimate_.q_odom_panel.coeffs()(i);
  r.cov_position_m2 = toRowMajor(estimate_.cov_position_m2);
  r.cov_rotation_rad2 = toRowMajor(estimate_.cov_rotation_rad2);
  r.observations = estimate_.observations;
  r.distinct_markers = estimate_.distinct_markers;
  r.t_fixed_us = estimate_.t_fixed_us;
  *out = r;
  return true;
}

bool PanelPoseEstimator::restore(const PanelPoseRecord& r, std::string* error) {
  if (!initialised_) return fail(error, "panel pose estimator: not initialised");
  const Eigen::Vector3d p(r.p_panel_in_odom_m[0], r.p_panel_in_odom_m[1], r.p_panel_in_odom_m[2]);
  const Eigen::Quaterniond q(r.q_odom_panel_xyzw[3], r.q_odom_panel_xyzw[0], r.q_odom_panel_xyzw[1],
                             r.q_odom_panel_xyzw[2]);
  if (!p.allFinite()) return fail(error, "p_panel_in_odom_m: not finite");
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-6) {
    return fail(error, "q_odom_panel_xyzw: not a unit quaternion");
  }
  const Eigen::Matrix3d cov_p = fromRowMajor(r.cov_position_m2);
  const Eigen::Matrix3d cov_r = fromRowMajor(r.cov_rotation_rad2);
  if (!isCovariance(cov_p)) return fail(error, "cov_position_m2: not a symmetric PSD matrix");
  if (!isCovariance(cov_r)) return fail(error, "cov_rotation_rad2: not a symmetric PSD matrix");
  if (r.observations < 0 || r.distinct_markers < 0)
    return fail(error, "observations: negative count");
  clearAccumulators();
  estimate_ = PanelPoseEstimate{};
  estimate_.p_panel_in_odom_m = p;
  estimate_.q_odom_panel = q.normalized();
  estimate_.cov_position_m2 = cov_p;
  estimate_.cov_rotation_rad2 = cov_r;
  estimate_.scatter_position_m2 = cov_p * std::max(1, r.observations);
  estimate_.scatter_rotation_rad2 = cov_r * std::max(1, r.observations);
  estimate_.observations = r.observations;
  estimate_.distinct_markers = r.distinct_markers;
  estimate_.fixed = true;
  estimate_.t_fixed_us = r.t_fixed_us;
  return true;
}

}  // namespace deepnav
