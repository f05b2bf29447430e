#include "vision/planes/plane_vo_measurement.h"

#include "nav/pipeline/camera_relative_pose.h"

namespace deepnav {

bool toRelativePoseMeasurement(const PlaneRegistrationResult& registration,
                               const Eigen::Isometry3d& T_robot_cam, TimeUs t_b_us,
                               std::uint32_t clone_id, RelativePoseMeasurement* measurement) {
  if (!registration.valid) return false;
  VoMeasurement vo;
  vo.valid = true;
  vo.source = VoSource::kPlanes;
  vo.q_cama_camb = registration.q_cama_camb;
  vo.p_camb_in_cama_m = registration.p_camb_in_cama_m;
  vo.has_translation = registration.has_translation;
  vo.cov = registration.cov;
  vo.support = registration.matched_planes;
  return relativePoseFromCamera(vo, T_robot_cam, t_b_us, clone_id, measurement);
}

}  // namespace deepnav
