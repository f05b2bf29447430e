#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "base/marker_observation.h"
#include "nav/ekf/ekf_measurements.h"
#include "nav/markers/marker_pose_covariance.h"
#include "nav/markers/panel_description.h"
#include "nav/types/time.h"

namespace deepnav {

// The panel's pose in odom and its isotropic 1-sigma (e.g. PanelPoseEstimator once fixed).
struct PanelPoseInOdom {
  Eigen::Isometry3d T_odom_panel = Eigen::Isometry3d::Identity();
  double sigma_position_m = 0.0;    // >= 0
  double sigma_rotation_rad = 0.0;  // about the odom axes, >= 0
};

// Robot pose in odom from one marker observation (its best IPPE solution), as an EKF
// PoseMeasurement:
//   T_odom_robot = T_odom_panel * T_panel_marker * T_marker_cam * T_cam_robot
//   (marker_frame_chain.h)
// Covariance: diagonal, [x y z roll pitch yaw] with the rotation about the odom axes
// (PoseMeasurement). From the marker model (marker_pose_covariance.h) sigma_pos, sigma_rot, plus
// two first-order terms:
//   - a rotation error dtheta of the camera moves the robot origin by dtheta x (lever from the
//   camera to
//     the robot), bounded by sigma_rot |p_cam_in_robot|;
//   - the panel's own uncertainty: sigma_panel_pos, and its rotation error moves the robot by at
//   most
//     sigma_panel_rot |p_robot - p_panel|;
//   var_pos = sigma_pos^2 + (sigma_rot |p_cam_in_robot|)^2 + sigma_panel_pos^2 + (sigma_panel_rot
//   r)^2, var_rot = sigma_rot^2 + sigma_panel_rot^2,
// each isotropic, hence diagonal in any frame. False (and *out untouched) on a non-finite result.
bool markerPoseMeasurement(TimeUs t_us, const MarkerObservation& obs, const PanelMarker& marker,
                           const PanelPoseInOdom& panel, const Eigen::Isometry3d& T_robot_cam,
                           const MarkerCovarianceConfig& config, PoseMeasurement* out);

}  // namespace deepnav
