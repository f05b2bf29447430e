#pragma once
#include <Eigen/Geometry>

#include "nav/types/nav_solution.h"

namespace deepnav {

// Smooths the pose the vehicle receives, in the spirit of PX4 EKF2's output predictor: the published
// pose is propagated tick to tick with the filter's own velocity and angular rate, and pulled towards the
// filter's pose by a first-order correction of time constant tau:
//   p_pred = p_out + v dt,          q_pred = q_out Exp(w dt)
//   alpha  = dt / (tau + dt),       p_out = p_pred + alpha (p_ekf - p_pred),  q_out = slerp(q_pred, q_ekf, alpha)
// The EKF's corrections (a depth fix every 100 ms, a marker pose, a VO update) would otherwise appear as
// millimetre steps at the loop rate; a manipulator on a floating base wants them spread over tau. In
// steady motion the feed-forward leaves no lag; a correction is followed with time constant tau.
// Velocity, rates and covariances pass through. tau = 0 publishes the filter's pose unchanged.
class OutputSmoother {
 public:
  // Gaps longer than this (or backwards time) restart from the filter's pose.
  static constexpr double kMaxGapS = 0.5;

  void init(double tau_s) {
    tau_s_ = tau_s;
    started_ = false;
  }
  void apply(NavSolution* solution);

 private:
  double tau_s_ = 0.0;
  bool started_ = false;
  TimeUs last_us_ = 0;
  Eigen::Vector3d p_out_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_out_ = Eigen::Quaterniond::Identity();
};

}  // namespace deepnav
