#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav {

// Mean rotation of many unit quaternions, and their scatter about it, from one 4x4 accumulator.
//
// Mean: Markley, Cheng, Crassidis & Oshman, "Averaging Quaternions", J. Guidance, Control, and
// Dynamics 30(4), 2007: the average maximising sum_i w_i (q_i . q)^2 is the eigenvector of the
// largest eigenvalue of
//   M = sum_i w_i q_i q_i^T.
// It is insensitive to the sign of each q_i and to the order of the samples. (The DexROV paper
// averages incrementally with Slerp; that result depends on the order, this one does not, and for
// the small scatter of marker observations the two agree to second order in the angles.)
//
// Scatter: with q_i = Exp(d_i) (x) q_mean (a rotation error d_i about the odom axes, the convention
// of PoseMeasurement), q_i = cos(|d_i|/2) q_mean + sin(|d_i|/2) B u_i, where the columns of the 4x3
// matrix B are [0, e_k] (x) q_mean (orthonormal, and orthogonal to q_mean). Hence B^T q_i =
// sin(|d_i|/2) u_i and
//   E[d d^T] ~= 4 B^T (M / sum w) B,
// exact up to sin(x) ~ x: the scatter needs no stored samples.
class QuaternionAverage {
 public:
  void clear();
  void add(const Eigen::Quaterniond& q, double weight = 1.0);

  int count() const { return count_; }
  double weightSum() const { return weight_sum_; }
  // Identity when empty. The sign is chosen with w >= 0.
  Eigen::Quaterniond mean() const;
  // Weighted scatter E[d d^T] about mean() (biased, 1/sum w), rad^2; zero when empty.
  Eigen::Matrix3d scatter() const;

 private:
  Eigen::Matrix4d M_ = Eigen::Matrix4d::Zero();  // in Eigen's coeffs() order (x, y, z, w)
  double weight_sum_ = 0.0;
  int count_ = 0;
};

}  // namespace deepnav
