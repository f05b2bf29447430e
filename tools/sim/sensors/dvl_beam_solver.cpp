#include "tools/sim/sensors/dvl_beam_solver.h"

#include <cmath>

#include <Eigen/LU>

namespace deepnav::sim {

bool solveDvlBeams(const std::array<Eigen::Vector3d, kDvlBeams>& beams, const std::array<double, kDvlBeams>& u_mps,
                   const std::array<double, kDvlBeams>& sigma_mps, std::uint8_t mask, Eigen::Vector3d* v_mps,
                   Eigen::Matrix3d* cov_mps2) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();  // B^T B
  Eigen::Matrix3d weighted = Eigen::Matrix3d::Zero();  // B^T S B
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();  // B^T u
  int count = 0;
  for (int i = 0; i < kDvlBeams; ++i) {
    if (!(mask & (1u << i))) continue;
    const Eigen::Matrix3d outer = beams[i] * beams[i].transpose();
    normal += outer;
    weighted += sigma_mps[i] * sigma_mps[i] * outer;
    rhs += u_mps[i] * beams[i];
    ++count;
  }
  // Three unit beams at a sane tilt give det(B^T B) of order 0.1; coplanar ones give 0.
  if (count < 3 || !(std::abs(normal.determinant()) > 1e-9)) return false;
  const Eigen::Matrix3d inverse = normal.inverse();
  *v_mps = inverse * rhs;
  *cov_mps2 = inverse * weighted * inverse;
  return true;
}

}  // namespace deepnav::sim
