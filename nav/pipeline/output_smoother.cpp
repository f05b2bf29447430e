#include "nav/pipeline/output_smoother.h"

namespace deepnav {

void OutputSmoother::apply(NavSolution* s) {
  const double dt_s = usToS(s->t_us - last_us_);
  const bool restart = !started_ || !(tau_s_ > 0.0) || s->stage == NavStage::kInit || !(dt_s > 0.0) ||
                       dt_s > kMaxGapS;
  last_us_ = s->t_us;
  if (restart) {
    started_ = tau_s_ > 0.0 && s->stage != NavStage::kInit;
    p_out_ = s->p_robot_in_odom_m;
    q_out_ = s->q_odom_robot;
    return;
  }
  const Eigen::Vector3d p_pred = p_out_ + s->v_robot_in_odom_mps * dt_s;
  const Eigen::Vector3d rotation = s->w_robot_radps * dt_s;
  const double angle = rotation.norm();
  const Eigen::Quaterniond dq = angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation / angle))
                                            : Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond q_pred = (q_out_ * dq).normalized();
  const double alpha = dt_s / (tau_s_ + dt_s);
  p_out_ = p_pred + alpha * (s->p_robot_in_odom_m - p_pred);
  q_out_ = q_pred.slerp(alpha, s->q_odom_robot).normalized();
  if (!p_out_.allFinite() || !q_out_.coeffs().allFinite()) {
    p_out_ = s->p_robot_in_odom_m;  // never publish a non-finite pose: fall back to the filter's
    q_out_ = s->q_odom_robot;
  }
  s->p_robot_in_odom_m = p_out_;
  s->q_odom_robot = q_out_;
}

}  // namespace deepnav
