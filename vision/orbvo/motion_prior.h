#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vision/orbvo/pose_refiner.h"
#include "vision/orbvo/relative_camera_pose.h"
#include "vision/orbvo/stereo_rig.h"

namespace deepnav {

// The navigation's prediction of the camera motion between two pairs, as an arbiter of the ORB VO's
// inliers. Scene points that move coherently (marine snow lit by the lamps and drifting with the
// current: the sea-trial bench draws 150-500 particles per m^3 drifting at 0.13 m/s) can outnumber the
// static features of a murky image; RANSAC and the robust refinement then follow them and the
// translation is pulled by a fraction of their drift (measured on sea-trial-murky seed 1: the ORB
// results the EKF refused were off by 12 mm median, along minus the current, rotation unaffected).
// The prediction (IMU and DVL dead reckoning over 0.1 s: millimetres) tells the static points from the
// drifting ones. It only selects inliers: the pose and its covariance still come from the images alone.
struct OrbMotionPriorConfig {
  bool enabled = false;
  double translation_sigma_m = 0.002;  // 1-sigma of the predicted camera translation between two pairs
                                       // (DVL-aided dead reckoning over 0.1 s: about 1 mm, and the
                                       // filter's corrections in between)
  double rotation_sigma_deg = 0.1;     // and of its rotation (per axis)
  double consistency_chi2 = 22.46;     // VO vs prediction, 6 dof: 99.9 % (a disagreement triggers the
                                       // re-selection; the re-selected pose must pass it too)
  double gate_chi2 = 9.21;             // a point's left pixel against its predicted projection, 2 dof 99 %
};

// T_cam_world of frame b predicted from frame a's and the relative motion T_a_b.
CameraPoseEstimate predictCameraPose(const CameraPoseEstimate& a, const Eigen::Isometry3d& T_a_b);

// NEES of the VO relative pose against the prediction, with the covariance cov_vo + cov_prior.
double priorDisagreement(const RelativeCameraPose& vo, const Eigen::Isometry3d& T_a_b_prior,
                         const OrbMotionPriorConfig& config);

// True when the point's left pixel lies within the gate around its projection by the predicted pose:
// the pixel noise sigma_px and the prediction's error (f sigma_t / z, f sigma_r) add in quadrature.
bool withinPriorGate(const StereoRig& rig, const CameraPoseEstimate& predicted, const Eigen::Vector3d& p_in_world_m,
                     const Eigen::Vector2d& uv_px, double sigma_px, const OrbMotionPriorConfig& config);

}  // namespace deepnav
