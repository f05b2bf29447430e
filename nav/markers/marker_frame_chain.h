#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "base/marker_observation.h"
#include "nav/markers/panel_description.h"

namespace deepnav {

// The frame chains of marker navigation. T_a_b is the pose of frame b in frame a: x_a = T_a_b *
// x_b. Frames: odom O (ENU), robot R (FLU), camera optical C (z forward, x right, y down), panel P
// and marker M (nav/markers/panel_description.h). T_robot_cam is the camera mounting (board data).

// T from a rotation q_a_b and the origin of b in a.
Eigen::Isometry3d isometryOf(const Eigen::Quaterniond& q_a_b, const Eigen::Vector3d& p_b_in_a);

// T_cam_marker of an observation (its best solution) and of its alternative IPPE solution.
Eigen::Isometry3d cameraMarkerPose(const MarkerObservation& obs);
Eigen::Isometry3d cameraMarkerPoseAlternative(const MarkerObservation& obs);

// T_panel_marker of a marker of the knowledge base.
Eigen::Isometry3d panelMarkerPose(const PanelMarker& marker);

// Robot in odom from a marker whose panel pose is known (stage 2, or stage 1 once the panel is
// fixed):
//   T_odom_robot = T_odom_panel * T_panel_marker * T_marker_cam * T_cam_robot.
Eigen::Isometry3d robotPoseFromMarker(const Eigen::Isometry3d& T_odom_panel,
                                      const Eigen::Isometry3d& T_panel_marker,
                                      const Eigen::Isometry3d& T_cam_marker,
                                      const Eigen::Isometry3d& T_robot_cam);

// Panel in odom from a marker seen by a robot whose pose is known (stage 1, the filter's estimate):
//   T_odom_panel = T_odom_robot * T_robot_cam * T_cam_marker * T_marker_panel.
Eigen::Isometry3d panelPoseFromMarker(const Eigen::Isometry3d& T_odom_robot,
                                      const Eigen::Isometry3d& T_robot_cam,
                                      const Eigen::Isometry3d& T_cam_marker,
                                      const Eigen::Isometry3d& T_panel_marker);

// The marker's pose in the camera predicted from the robot and panel poses (e.g. to choose between
// the two IPPE solutions, marker_ambiguity.h):
//   T_cam_marker = T_cam_robot * T_robot_odom * T_odom_panel * T_panel_marker.
Eigen::Isometry3d predictedCameraMarkerPose(const Eigen::Isometry3d& T_odom_robot,
                                            const Eigen::Isometry3d& T_robot_cam,
                                            const Eigen::Isometry3d& T_odom_panel,
                                            const Eigen::Isometry3d& T_panel_marker);

}  // namespace deepnav
