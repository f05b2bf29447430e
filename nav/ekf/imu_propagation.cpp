#include "nav/ekf/imu_propagation.h"

#include "base/so3.h"
#include "nav/ekf/ekf_config.h"

namespace deepnav {

NominalState propagateNominal(const NominalState& x, const RobotImu& u, double dt_s, double gravity_mps2) {
  const Eigen::Vector3d theta = (u.w_robot_radps - x.b_gyro_radps) * dt_s;
  const Eigen::Matrix3d R = x.q_odom_robot.toRotationMatrix();
  const Eigen::Matrix3d Rm = R * expSo3(0.5 * theta);
  const Eigen::Vector3d a = Rm * (u.f_robot_mps2 - x.b_accel_mps2) + Eigen::Vector3d(0.0, 0.0, -gravity_mps2);
  NominalState out = x;
  out.p_robot_in_odom_m += x.v_robot_in_odom_mps * dt_s + 0.5 * dt_s * dt_s * a;
  out.v_robot_in_odom_mps += a * dt_s;
  out.q_odom_robot = (x.q_odom_robot * expSo3Quat(theta)).normalized();
  return out;
}

CoreMatrix propagationJacobian(const NominalState& x, const RobotImu& u, double dt_s) {
  const Eigen::Vector3d theta = (u.w_robot_radps - x.b_gyro_radps) * dt_s;
  const Eigen::Matrix3d R = x.q_odom_robot.toRotationMatrix();
  const Eigen::Matrix3d Rm = R * expSo3(0.5 * theta);
  const Eigen::Matrix3d R_next = R * expSo3(theta);
  const Eigen::Vector3d f = u.f_robot_mps2 - x.b_accel_mps2;
  const Eigen::Matrix3d A_theta = -skew(Rm * f);
  const Eigen::Matrix3d A_bg = Rm * skew(f) * rightJacobianSo3(0.5 * theta) * (0.5 * dt_s);
  const Eigen::Matrix3d A_ba = -Rm;
  const double h = 0.5 * dt_s * dt_s;
  CoreMatrix F = CoreMatrix::Identity();
  F.block<3, 3>(es::kP, es::kV).diagonal().setConstant(dt_s);
  F.block<3, 3>(es::kP, es::kTheta) = h * A_theta;
  F.block<3, 3>(es::kP, es::kBg) = h * A_bg;
  F.block<3, 3>(es::kP, es::kBa) = h * A_ba;
  F.block<3, 3>(es::kV, es::kTheta) = dt_s * A_theta;
  F.block<3, 3>(es::kV, es::kBg) = dt_s * A_bg;
  F.block<3, 3>(es::kV, es::kBa) = dt_s * A_ba;
  F.block<3, 3>(es::kTheta, es::kBg) = -R_next * rightJacobianSo3(theta) * dt_s;
  return F;
}

CoreMatrix propagationNoise(const EkfConfig& c, double dt_s) {
  const double qa = c.accel_vrw_mps2_rthz * c.accel_vrw_mps2_rthz;
  const double qg = c.gyro_arw_radps_rthz * c.gyro_arw_radps_rthz;
  const double qbg = c.gyro_bias_rw_radps2_rthz * c.gyro_bias_rw_radps2_rthz;
  const double qba = c.accel_bias_rw_mps3_rthz * c.accel_bias_rw_mps3_rthz;
  CoreMatrix Q = CoreMatrix::Zero();
  Q.block<3, 3>(es::kP, es::kP).diagonal().setConstant(qa * dt_s * dt_s * dt_s / 4.0);
  Q.block<3, 3>(es::kP, es::kV).diagonal().setConstant(qa * dt_s * dt_s / 2.0);
  Q.block<3, 3>(es::kV, es::kP).diagonal().setConstant(qa * dt_s * dt_s / 2.0);
  Q.block<3, 3>(es::kV, es::kV).diagonal().setConstant(qa * dt_s);
  Q.block<3, 3>(es::kTheta, es::kTheta).diagonal().setConstant(qg * dt_s);
  Q.block<3, 3>(es::kBg, es::kBg).diagonal().setConstant(qbg * dt_s);
  Q.block<3, 3>(es::kBa, es::kBa).diagonal().setConstant(qba * dt_s);
  return Q;
}

void propagateCovariance(const CoreMatrix& Phi, const CoreMatrix& Q, FilterState* s) {
  // Coefficient-based (lazy) products: at 15 x 15 they beat Eigen's blocked GEMM path.
  const CoreMatrix Pcc = s->P.topLeftCorner<es::kCoreDim, es::kCoreDim>();
  const CoreMatrix PhiP = Phi.lazyProduct(Pcc);
  s->P.topLeftCorner<es::kCoreDim, es::kCoreDim>() = PhiP.lazyProduct(Phi.transpose());
  s->P.topLeftCorner<es::kCoreDim, es::kCoreDim>() += Q;
  const int nc = s->dim() - es::kCoreDim;
  if (nc == 0) return;
  using CrossBlock = Eigen::Matrix<double, es::kCoreDim, Eigen::Dynamic, 0, es::kCoreDim, es::kMaxDim - es::kCoreDim>;
  CrossBlock X(es::kCoreDim, nc);
  X = Phi.lazyProduct(s->P.block(0, es::kCoreDim, es::kCoreDim, nc));
  s->P.block(0, es::kCoreDim, es::kCoreDim, nc) = X;
  s->P.block(es::kCoreDim, 0, nc, es::kCoreDim) = X.transpose();
}

}  // namespace deepnav
