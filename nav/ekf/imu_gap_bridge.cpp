#include "nav/ekf/imu_gap_bridge.h"

#include <algorithm>

#include "nav/ekf/ekf_config.h"
#include "nav/ekf/systematic_states.h"

namespace deepnav {

void bridgeImuGap(double dt_s, const EkfConfig& c, FilterState* s) {
  relocateSystematic(es::kCoreDim, s);  // the clones are dropped
  s->n_clones = 0;
  CoreMatrix Phi = CoreMatrix::Identity();
  Phi.block<3, 3>(es::kP, es::kV) = Eigen::Matrix3d::Identity() * dt_s;
  const int ns = s->sys_layout.dim;
  if (ns > 0) {
    using Cross = Eigen::Matrix<double, es::kCoreDim, Eigen::Dynamic, 0, es::kCoreDim, es::kMaxSysDim>;
    const Cross X = Phi * s->P.block(0, es::kCoreDim, es::kCoreDim, ns);
    s->P.block(0, es::kCoreDim, es::kCoreDim, ns) = X;
    s->P.block(es::kCoreDim, 0, ns, es::kCoreDim) = X.transpose();
  }
  CoreMatrix P = s->P.topLeftCorner<es::kCoreDim, es::kCoreDim>();
  P = (Phi * P * Phi.transpose()).eval();
  const double a2 = c.coast_accel_noise_mps2_rthz * c.coast_accel_noise_mps2_rthz;
  const double dt2 = dt_s * dt_s;
  for (int i = 0; i < 3; ++i) {
    P(es::kP + i, es::kP + i) += a2 * dt2 * dt_s / 3.0;
    P(es::kP + i, es::kV + i) += a2 * dt2 / 2.0;
    P(es::kV + i, es::kP + i) += a2 * dt2 / 2.0;
    P(es::kV + i, es::kV + i) += a2 * dt_s;
  }
  const double rp2 = c.init_roll_pitch_sigma_rad * c.init_roll_pitch_sigma_rad;
  const double yaw2 = c.init_yaw_sigma_rad * c.init_yaw_sigma_rad;
  P(es::kTheta + 0, es::kTheta + 0) = std::max(P(es::kTheta + 0, es::kTheta + 0), rp2);
  P(es::kTheta + 1, es::kTheta + 1) = std::max(P(es::kTheta + 1, es::kTheta + 1), rp2);
  P(es::kTheta + 2, es::kTheta + 2) = std::max(P(es::kTheta + 2, es::kTheta + 2), yaw2);
  s->P.topLeftCorner<es::kCoreDim, es::kCoreDim>() = P;
  s->x.p_robot_in_odom_m += dt_s * s->x.v_robot_in_odom_mps;
}

}  // namespace deepnav
