#pragma once
#include <span>

#include <Eigen/Core>

namespace deepnav {

// Smoothness m_A of a filtered trajectory (the paper's measure): the lag-one autocorrelation coefficient
// of successive position increments, averaged over the three axes.
//
// For axis j with positions p_0 .. p_N (N + 1 epochs, equally spaced in time), the increments are
//   d_k = p_{k+1,j} - p_{k,j},  k = 0 .. N-1,     dbar = (1/N) sum_k d_k
// and the coefficient is (Box & Jenkins' r_1)
//   r_j = sum_{k=0}^{N-2} (d_k - dbar)(d_{k+1} - dbar)  /  sum_{k=0}^{N-1} (d_k - dbar)^2
//   m_A = (1 / |J|) sum_{j in J} r_j
// J is the set of axes with a non-zero denominator (an axis whose increments are all equal, e.g. a
// constant depth, carries no information and is left out). r_j is in [-1, 1]: close to 1 for a smooth
// trajectory (increments change slowly), about -0.5 for white jitter on the positions.
struct Smoothness {
  double m_a = 0.0;
  int axes_used = 0;  // |J|; 0 when fewer than 3 positions or all axes constant (m_a is then 0)
};

Smoothness smoothnessMa(std::span<const Eigen::Vector3d> positions_m);

// r_j of one axis' increment series; false when it is undefined (fewer than 2 increments or constant).
bool lagOneAutocorrelation(std::span<const double> increments, double* r1);

}  // namespace deepnav
