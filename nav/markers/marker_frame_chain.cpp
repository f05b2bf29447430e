#include "nav/markers/marker_frame_chain.h"

namespace deepnav {

Eigen::Isometry3d isometryOf(const Eigen::Quaterniond& q_a_b, const Eigen::Vector3d& p_b_in_a) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q_a_b.normalized().toRotationMatrix();
  T.translation() = p_b_in_a;
  return T;
}

Eigen::Isometry3d cameraMarkerPose(const MarkerObservation& obs) {
  return isometryOf(obs.q_cam_marker, obs.p_marker_in_cam_m);
}

Eigen::Isometry3d cameraMarkerPoseAlternative(const MarkerObservation& obs) {
  return isometryOf(obs.q_cam_marker_alt, obs.p_marker_in_cam_alt_m);
}

Eigen::Isometry3d panelMarkerPose(const PanelMarker& marker) {
  return isometryOf(marker.q_panel_marker, marker.p_marker_in_panel_m);
}

Eigen::Isometry3d robotPoseFromMarker(const Eigen::Isometry3d& T_odom_panel,
                                      const Eigen::Isometry3d& T_panel_marker,
                                      const Eigen::Isometry3d& T_cam_marker,
                                      const Eigen::Isometry3d& T_robot_cam) {
  return T_odom_panel * T_panel_marker * T_cam_marker.inverse(Eigen::Isometry) *
         T_robot_cam.inverse(Eigen::Isometry);
}

Eigen::Isometry3d panelPoseFromMarker(const Eigen::Isometry3d& T_odom_robot,
                                      const Eigen::Isometry3d& T_robot_cam,
                                      const Eigen::Isometry3d& T_cam_marker,
                                      const Eigen::Isometry3d& T_panel_marker) {
  return T_odom_robot * T_robot_cam * T_cam_marker * T_panel_marker.inverse(Eigen::Isometry);
}

Eigen::Isometry3d predictedCameraMarkerPose(const Eigen::Isometry3d& T_odom_robot,
                                            const Eigen::Isometry3d& T_robot_cam,
                                            const Eigen::Isometry3d& T_odom_panel,
                                            const Eigen::Isometry3d& T_panel_marker) {
  return T_robot_cam.inverse(Eigen::Isometry) * T_odom_robot.inverse(Eigen::Isometry) *
         T_odom_panel * T_panel_marker;
}

}  // namespace deepnav
