#include "tools/sim/render/view_tick.h"

#include "tools/sim/render/panel_faces.h"
#include "tools/sim/rotation.h"

namespace deepnav::sim {

Eigen::Isometry3d panelPoseInOdom(const Scenario& scenario) {
  const PanelGeometry& g = scenario.panel;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(g.front_yaw_deg * kDegToRad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(g.centre_in_odom_m[0], g.centre_in_odom_m[1], scenario.environment.seabedZInOdom_m());
  return T;
}

CameraTick tickFacingFace(const Scenario& scenario, int face, double distance_m, double s_m, double z_m,
                          double yaw_deg, double pitch_deg, TimeUs t_us) {
  const FaceFrame f = panelFaces(scenario.panel)[face];
  // Optical frame looking at the face: x = the face's right, y = down, z = into the face.
  Eigen::Matrix3d R_panel_cam;
  R_panel_cam.col(0) = f.right_in_panel;
  R_panel_cam.col(1) = -Eigen::Vector3d::UnitZ();
  R_panel_cam.col(2) = -f.normal_in_panel;
  R_panel_cam = Eigen::AngleAxisd(yaw_deg * kDegToRad, Eigen::Vector3d::UnitZ()) * R_panel_cam *
                Eigen::AngleAxisd(-pitch_deg * kDegToRad, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d p_left_in_panel = f.pointAt(s_m, z_m, distance_m);
  const Eigen::Isometry3d T_odom_panel = panelPoseInOdom(scenario);
  CameraTick tick;
  tick.t_us = t_us;
  tick.exposure_t_us = t_us;
  tick.q_odom_left_cam = Eigen::Quaterniond(T_odom_panel.linear() * R_panel_cam);
  tick.q_odom_right_cam = tick.q_odom_left_cam;
  tick.p_left_cam_in_odom_m = T_odom_panel * p_left_in_panel;
  tick.p_right_cam_in_odom_m =
      T_odom_panel * (p_left_in_panel + scenario.camera.baseline_m * R_panel_cam.col(0));
  return tick;
}

}  // namespace deepnav::sim
