#pragma once
#include <cstdint>

#include <Eigen/Geometry>

#include "nav/ekf/ekf_measurements.h"
#include "nav/types/vo_measurement.h"

namespace deepnav {

// A visual-odometry result of the left camera (optical frames) as the EKF's relative pose of the robot:
//   T_robota_robotb = T_robot_cam T_cama_camb T_robot_cam^-1,
//   p_robotb_in_robota = R_rc t_c + p_cam_in_robot - R_ab p_cam_in_robot.
// Errors (right perturbations, translation first): the rotation error turns with the mounting,
// dr = R_rc dc, and the lever arm turns with it, dp = R_rc dt + R_ab [p_cam_in_robot]x dr, so
// cov_robot = A cov_cam A^T with A = [[R_rc, R_ab [p]x R_rc], [0, R_rc]]. Without translation the
// translation block is not used by the EKF. False when vo is not valid or its covariance not finite.
bool relativePoseFromCamera(const VoMeasurement& vo, const Eigen::Isometry3d& T_robot_cam, TimeUs t_b_us,
                            std::uint32_t clone_id, RelativePoseMeasurement* measurement);

}  // namespace deepnav
