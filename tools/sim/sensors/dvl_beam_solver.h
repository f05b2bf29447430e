#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Core>

namespace deepnav::sim {

constexpr int kDvlBeams = 4;

// The velocity v of a Janus DVL from the radial velocities u_i = b_i . v of its locked beams (bit i of
// mask), by least squares over those beams: v = (B^T B)^-1 B^T u, B the rows b_i^T. With four beams the
// system is overdetermined (the instrument's 4-beam solution); with three it is square (the 3-beam
// solution, exact, no redundancy left to check). For independent beam errors of 1-sigma sigma_i the
// covariance is (B^T B)^-1 B^T S B (B^T B)^-1, S = diag(sigma_i^2): for four beams at tilt a with equal
// sigma it is diag(sigma^2 / (2 sin^2 a), same, sigma^2 / (4 cos^2 a)). False with fewer than three
// beams or beams that do not span 3-D. Allocates nothing.
bool solveDvlBeams(const std::array<Eigen::Vector3d, kDvlBeams>& beams, const std::array<double, kDvlBeams>& u_mps,
                   const std::array<double, kDvlBeams>& sigma_mps, std::uint8_t mask, Eigen::Vector3d* v_mps,
                   Eigen::Matrix3d* cov_mps2);

}  // namespace deepnav::sim
