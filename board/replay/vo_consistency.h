#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "nav/metrics/nees.h"
#include "nav/pipeline/vo_fusion.h"
#include "nav/types/vo_measurement.h"

namespace deepnav {

// Consistency of the visual odometry against the simulator's per-pair truth (/truth/frame): each VO
// relative pose offered to the filter in stage 2, its error against the true relative pose of the left
// camera between its two pairs, and its NEES against its own covariance (6 dof, or 3 for a rotation-only
// result). A consistent VO puts ~95 % of its NEES inside the chi-square band, mean ~dof.

// A VO result as the filter was offered it, with what became of it.
struct VoOffer {
  TimeUs t_us = 0;  // capture time of pair b
  VoMeasurement vo;
  VoOutcome outcome = VoOutcome::kNone;
};

// The true left-camera pose of one stereo pair (odometry frame, optical camera frame).
struct FrameTruthPose {
  TimeUs t_us = 0;
  Eigen::Isometry3d T_odom_cam = Eigen::Isometry3d::Identity();
};

// One VO result scored. error = [dp; n] in the VoMeasurement convention: dp = p_meas - p_true in camera
// a (m), n = Log(R_true^T R_meas) about camera b's axes (rad).
struct VoConsistencyRow {
  TimeUs t_us = 0, t_reference_us = 0;
  VoSource source = VoSource::kNone;
  VoOutcome outcome = VoOutcome::kNone;
  int dof = 6;
  double nees = 0.0;  // NaN when the covariance is not positive definite
  Eigen::Matrix<double, 6, 1> error = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> sigma = Eigen::Matrix<double, 6, 1>::Zero();  // sqrt of cov's diagonal
};

// Per modality: every scored result, and those the filter fused.
struct VoModalityConsistency {
  std::size_t offered = 0;      // stage-2 results offered
  std::size_t without_truth = 0;  // no truth for one of the two pairs
  NeesSummary nees;             // all scored results
  NeesSummary nees_fused;       // fused (accepted or queued) ones
  NeesSummary nees_rejected;    // refused by the gate
  double translation_rms_m = 0.0, rotation_rms_deg = 0.0;
  std::array<double, 6> z_rms{};  // per axis RMS of error / sigma (1 if the axis' variance is right)
};

struct VoConsistency {
  std::vector<VoConsistencyRow> rows;
  VoModalityConsistency orb, planes;
};

// Scores the offers against the truth (truth sorted by time; matched by exact capture time).
VoConsistency computeVoConsistency(const std::vector<VoOffer>& offers, const std::vector<FrameTruthPose>& truth);

// One row's error and NEES against the true relative pose T_a_b (exposed for the tests).
VoConsistencyRow scoreVoResult(const VoMeasurement& vo, const Eigen::Isometry3d& T_a_b_true);

// vo_consistency.csv and the summary.json object {"orb": {...}, "planes": {...}}.
bool writeVoConsistencyCsv(const std::string& path, const VoConsistency& c, std::string* error);
std::string voConsistencyJson(const VoConsistency& c);

}  // namespace deepnav
