#pragma once
#include <Eigen/Geometry>
#include <cstdint>

#include "nav/ekf/ekf_measurements.h"
#include "nav/types/time.h"
#include "vision/planes/plane_registration.h"

namespace deepnav {

// The plane registration (camera frames) as the EKF's relative pose measurement (robot frames):
//   T_robota_robotb = T_robot_cam T_cama_camb T_robot_cam^-1,
//   p_robotb_in_robota = R_rc t_c + p_cam_in_robot - R_ab p_cam_in_robot,
// rotation error delta_r = R_rc delta_c (both right perturbations), translation covariance
// R_rc C_t R_rc^T + J C_rot J^T with J = R_ab [p_cam_in_robot]x (the lever arm turns with the
// rotation error), cross covariance J C_rot. Order [x y z roll pitch yaw] as in
// RelativePoseMeasurement. Without translation the translation block keeps the registration's
// unobservable variance and has_translation is false. Returns false when the registration is not
// valid (rotation not fully observed).
bool toRelativePoseMeasurement(const PlaneRegistrationResult& registration,
                               const Eigen::Isometry3d& T_robot_cam, TimeUs t_b_us,
                               std::uint32_t clone_id, RelativePoseMeasurement* measurement);

}  // namespace deepnav
