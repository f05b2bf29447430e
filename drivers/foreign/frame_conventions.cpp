#include "drivers/foreign/frame_conventions.h"

namespace deepnav::foreign {

const Eigen::Matrix3d& rotationFluFromFrd() {
  static const Eigen::Matrix3d R = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  return R;
}

const Eigen::Matrix3d& rotationEnuFromNed() {
  static const Eigen::Matrix3d R = (Eigen::Matrix3d() << 0, 1, 0, 1, 0, 0, 0, 0, -1).finished();
  return R;
}

Eigen::Vector3d bodyVectorToFlu(const Eigen::Vector3d& v, FrameConvention convention) {
  return convention == FrameConvention::kNedFrd ? Eigen::Vector3d(rotationFluFromFrd() * v) : v;
}

Eigen::Matrix3d bodyCovarianceToFlu(const Eigen::Matrix3d& c, FrameConvention convention) {
  if (convention != FrameConvention::kNedFrd) return c;
  const Eigen::Matrix3d& R = rotationFluFromFrd();
  return R * c * R.transpose();
}

Eigen::Quaterniond orientationToEnuFlu(const Eigen::Quaterniond& q, FrameConvention convention) {
  if (convention != FrameConvention::kNedFrd) return q;
  const Eigen::Quaterniond q_enu_ned(rotationEnuFromNed());
  const Eigen::Quaterniond q_frd_flu(rotationFluFromFrd().transpose());
  return (q_enu_ned * q * q_frd_flu).normalized();
}

}  // namespace deepnav::foreign
