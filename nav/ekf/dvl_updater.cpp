#include "nav/ekf/dvl_updater.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "base/so3.h"
#include "nav/ekf/ekf_config.h"

namespace deepnav {

bool isValidDvl(const DvlSample& m) {
  if (!m.valid || !m.v_dvl_mps.allFinite() || !m.cov_v_dvl_mps2.allFinite()) return false;
  if (!std::isfinite(m.fom_mps) || m.fom_mps < 0.0) return false;
  const Eigen::Matrix3d& C = m.cov_v_dvl_mps2;
  if ((C.diagonal().array() < 0.0).any()) return false;
  // A covariance that will be used (all variances > 0, linearizeDvl) must be one: symmetric and
  // positive definite. An indefinite R can make S look fine and break P in the update.
  if ((C.diagonal().array() > 0.0).all()) {
    return C.isApprox(C.transpose(), 1e-9) && Eigen::LLT<Eigen::Matrix3d>(C).info() == Eigen::Success;
  }
  return true;
}

namespace {

// The DVL's systematic errors (systematic_states.h), when estimated: with y = R_dr u the velocity in the
// nominal DVL axes and M = (1 + s) Exp(-alpha), the prediction becomes M y and every Jacobian block
// M times the one without them, plus
//   H_s = Exp(-alpha) y,  H_alpha = (1 + s) Exp(-alpha) [y]x Jr(-alpha)   (Exp(-alpha - d) ~= Exp(-alpha) (I - [Jr(-alpha) d]x)).
void addDvlScaleAndMisalignment(const FilterState& s, const Eigen::Vector3d& y, Linearization* out) {
  const SystematicLayout& l = s.sys_layout;
  const double scale = 1.0 + s.x.sys.dvl_scale;
  const Eigen::Vector3d& alpha = s.x.sys.dvl_misalignment_rad;
  const Eigen::Matrix3d E = expSo3(-alpha);
  const Eigen::Matrix3d M = scale * E;
  out->H.block(0, 0, 3, s.dim()) = (M * out->H.block(0, 0, 3, s.dim())).eval();
  out->residual.head<3>() += y - M * y;  // the residual was taken against y
  if (l.dvl_scale >= 0) out->H.block<3, 1>(0, s.sysIndex(l.dvl_scale)) = E * y;
  if (l.dvl_misalignment >= 0) {
    out->H.block<3, 3>(0, s.sysIndex(l.dvl_misalignment)) = scale * E * skew(y) * rightJacobianSo3(-alpha);
  }
}

// A velocity bias b in the DVL axes adds to the prediction: H_b = I.
void addDvlBias(const FilterState& s, Linearization* out) {
  out->residual.head<3>() -= s.x.sys.dvl_bias_mps;
  out->H.block<3, 3>(0, s.sysIndex(s.sys_layout.dvl_bias)).setIdentity();
}

}  // namespace

bool linearizeDvl(const FilterState& s, const DvlSample& m, const EkfConfig& c, Linearization* out) {
  const Eigen::Matrix3d R_dvl_robot = c.q_robot_dvl.toRotationMatrix().transpose();
  const Eigen::Matrix3d Rt = s.x.q_odom_robot.toRotationMatrix().transpose();
  const Eigen::Vector3d& v = s.x.v_robot_in_odom_mps;
  const Eigen::Vector3d& r = c.p_dvl_in_robot_m;
  const Eigen::Vector3d w = s.w_robot_meas_radps - s.x.b_gyro_radps;
  const Eigen::Vector3d v_pred = R_dvl_robot * (Rt * v + w.cross(r));
  out->reset(3, s.dim());
  out->residual = m.v_dvl_mps - v_pred;
  out->H.block<3, 3>(0, es::kV) = R_dvl_robot * Rt;
  out->H.block<3, 3>(0, es::kTheta) = R_dvl_robot * Rt * skew(v);
  out->H.block<3, 3>(0, es::kBg) = R_dvl_robot * skew(r);
  if (s.sys_layout.dvl_scale >= 0 || s.sys_layout.dvl_misalignment >= 0) addDvlScaleAndMisalignment(s, v_pred, out);
  if (s.sys_layout.dvl_bias >= 0) addDvlBias(s, out);
  if (m.cov_v_dvl_mps2.diagonal().minCoeff() > 0.0) {
    out->R = m.cov_v_dvl_mps2;
  } else {
    const double sigma = m.fom_mps > 0.0 ? m.fom_mps : c.dvl_sigma_mps;
    out->R = MeasMatrix::Identity(3, 3) * (sigma * sigma);
  }
  return true;
}

}  // namespace deepnav
