#include "nav/markers/marker_pose_measurement.h"

#include "nav/markers/marker_frame_chain.h"

namespace deepnav {

bool markerPoseMeasurement(TimeUs t_us, const MarkerObservation& obs, const PanelMarker& marker,
                           const PanelPoseInOdom& panel, const Eigen::Isometry3d& T_robot_cam,
                           const MarkerCovarianceConfig& config, PoseMeasurement* out) {
  const Eigen::Isometry3d T_odom_robot = robotPoseFromMarker(
      panel.T_odom_panel, panelMarkerPose(marker), cameraMarkerPose(obs), T_robot_cam);
  const MarkerPoseSigmas s = markerPoseSigmas(obs, config);
  const double lever_cam_m = T_robot_cam.translation().norm();
  const double lever_panel_m =
      (T_odom_robot.translation() - panel.T_odom_panel.translation()).norm();
  const double rot_lever = s.rotation_rad * lever_cam_m;
  const double panel_lever = panel.sigma_rotation_rad * lever_panel_m;
  const double var_pos = s.position_m * s.position_m + rot_lever * rot_lever +
                         panel.sigma_position_m * panel.sigma_position_m +
                         panel_lever * panel_lever;
  const double var_rot =
      s.rotation_rad * s.rotation_rad + panel.sigma_rotation_rad * panel.sigma_rotation_rad;

  PoseMeasurement m;
  m.t_us = t_us;
  m.p_robot_in_odom_m = T_odom_robot.translation();
  m.q_odom_robot = Eigen::Quaterniond(T_odom_robot.linear()).normalized();
  m.cov_pose.setZero();
  m.cov_pose.diagonal() << var_pos, var_pos, var_pos, var_rot, var_rot, var_rot;
  m.source = kSrcMarkers;
  if (!m.p_robot_in_odom_m.allFinite() || !m.q_odom_robot.coeffs().allFinite() ||
      !m.cov_pose.allFinite() || !(var_pos > 0.0) || !(var_rot > 0.0)) {
    return false;
  }
  *out = m;
  return true;
}

}  // namespace deepnav
