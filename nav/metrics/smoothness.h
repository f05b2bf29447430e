#pragma once
#include <span>

#include <Eigen/Core>

namespace deepnav {

// Smoothness m_A of a filtered trajectory (the paper's measure): the lag-one autocorrelation coefficient
// of successive position increments, pooled over the three axes.
//
// For axis j with positions p_0 .. p_N (N + 1 epochs, equally spaced in time), the increments are
//   d_k = p_{k+1,j} - p_{k,j},  k = 0 .. N-1,     dbar_j = (1/N) sum_k d_k
//   num_j = sum_{k=0}^{N-2} (d_k - dbar_j)(d_{k+1} - dbar_j),   den_j = sum_{k=0}^{N-1} (d_k - dbar_j)^2
// Per axis r_j = num_j / den_j (Box & Jenkins' r_1), and
//   m_A = sum_j num_j / sum_j den_j,
// i.e. the mean of the r_j weighted by each axis' increment variance. Why pooled rather than the plain
// mean of the r_j: an ROV circling a panel at constant depth moves metres in x and y but a few
// millimetres in z, where the increments are the depth sensor's corrections; the plain mean would count
// that noise axis as a third of the score (0.70 instead of 0.99 on the default dive). m_A is in
// [-1, 1]: close to 1 for a smooth trajectory, about -0.5 for white jitter on the positions. Axes whose
// increments are all equal carry nothing and are left out.
struct Smoothness {
  double m_a = 0.0;
  int axes_used = 0;  // axes with den_j > 0; 0 when fewer than 3 positions or all axes constant (m_a is then 0)
  Eigen::Vector3d r_axis = Eigen::Vector3d::Zero();  // r_j per axis (0 when left out)
};

Smoothness smoothnessMa(std::span<const Eigen::Vector3d> positions_m);

// r_j of one axis' increment series; false when it is undefined (fewer than 2 increments or constant).
bool lagOneAutocorrelation(std::span<const double> increments, double* r1);
// The same with its numerator and denominator (for pooling).
bool lagOneAutocorrelation(std::span<const double> increments, double* num, double* den);

}  // namespace deepnav
