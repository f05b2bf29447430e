#pragma once
#include <cmath>

namespace deepnav::sim {

// The classic compass deviation series (Bowditch, The American Practical Navigator, NGA Pub. 9, ch. 6
// "Magnetic compass adjustment"; Admiralty Manual of Navigation vol. 1, "the deviation formula"):
//   delta(psi) = A + B sin psi + C cos psi + D sin 2psi + E cos 2psi,
// psi the magnetic heading the compass would read without the vehicle's own iron. A: constant
// (asymmetric soft iron, lubber-line misalignment); B, C: one-cycle (hard iron, the vehicle's permanent
// magnetism, plus vertical soft iron); D, E: two-cycle (horizontal soft iron induced by the Earth's field).
// Here delta is the error ADDED to the reading (reading = psi + delta), the sign of CompassConfig::bias_deg;
// a navigator's "easterly deviation" is -delta.
struct CompassDeviation {
  double a_deg = 0.0;
  double b_deg = 0.0;
  double c_deg = 0.0;
  double d_deg = 0.0;
  double e_deg = 0.0;

  bool isZero() const { return a_deg == 0.0 && b_deg == 0.0 && c_deg == 0.0 && d_deg == 0.0 && e_deg == 0.0; }
  double at_deg(double psi_rad) const {
    return a_deg + b_deg * std::sin(psi_rad) + c_deg * std::cos(psi_rad) + d_deg * std::sin(2.0 * psi_rad) +
           e_deg * std::cos(2.0 * psi_rad);
  }
  bool operator==(const CompassDeviation&) const = default;
};

}  // namespace deepnav::sim
