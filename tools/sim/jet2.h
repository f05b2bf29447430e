#pragma once
#include <cmath>

namespace deepnav::sim {

// A value with its first and second time derivatives (second-order forward-mode differentiation).
// The trajectory is written once in terms of Jet2 so that position, velocity and acceleration come out
// exact to rounding: the IMU truth then integrates back to the path without finite-difference error.
struct Jet2 {
  double v = 0.0;   // value
  double d1 = 0.0;  // d/dt
  double d2 = 0.0;  // d2/dt2

  static Jet2 constant(double c) { return {c, 0.0, 0.0}; }
  static Jet2 variable(double t) { return {t, 1.0, 0.0}; }
};

inline Jet2 operator+(Jet2 a, Jet2 b) { return {a.v + b.v, a.d1 + b.d1, a.d2 + b.d2}; }
inline Jet2 operator-(Jet2 a, Jet2 b) { return {a.v - b.v, a.d1 - b.d1, a.d2 - b.d2}; }
inline Jet2 operator-(Jet2 a) { return {-a.v, -a.d1, -a.d2}; }
inline Jet2 operator*(Jet2 a, Jet2 b) {
  return {a.v * b.v, a.d1 * b.v + a.v * b.d1, a.d2 * b.v + 2.0 * a.d1 * b.d1 + a.v * b.d2};
}
inline Jet2 operator+(Jet2 a, double c) { return {a.v + c, a.d1, a.d2}; }
inline Jet2 operator+(double c, Jet2 a) { return a + c; }
inline Jet2 operator-(Jet2 a, double c) { return {a.v - c, a.d1, a.d2}; }
inline Jet2 operator-(double c, Jet2 a) { return {c - a.v, -a.d1, -a.d2}; }
inline Jet2 operator*(Jet2 a, double c) { return {a.v * c, a.d1 * c, a.d2 * c}; }
inline Jet2 operator*(double c, Jet2 a) { return a * c; }

// Chain rule for y = f(x): y' = f'(x) x', y'' = f''(x) x'^2 + f'(x) x''.
inline Jet2 chain(Jet2 x, double f, double df, double ddf) {
  return {f, df * x.d1, ddf * x.d1 * x.d1 + df * x.d2};
}

inline Jet2 sin(Jet2 x) { return chain(x, std::sin(x.v), std::cos(x.v), -std::sin(x.v)); }
inline Jet2 cos(Jet2 x) { return chain(x, std::cos(x.v), -std::sin(x.v), -std::cos(x.v)); }

// x^p for x > 0.
inline Jet2 pow(Jet2 x, double p) {
  const double f = std::pow(x.v, p);
  return chain(x, f, p * f / x.v, p * (p - 1.0) * f / (x.v * x.v));
}

inline Jet2 operator/(Jet2 a, Jet2 b) { return a * pow(b, -1.0); }

// atan2(y, x) for (x, y) away from the origin.
inline Jet2 atan2(Jet2 y, Jet2 x) {
  const double r2 = x.v * x.v + y.v * y.v;
  const double d1 = (x.v * y.d1 - y.v * x.d1) / r2;
  // d/dt of (x y' - y x') / r2.
  const double num_d1 = x.v * y.d2 - y.v * x.d2;
  const double r2_d1 = 2.0 * (x.v * x.d1 + y.v * y.d1);
  const double d2 = num_d1 / r2 - (x.v * y.d1 - y.v * x.d1) * r2_d1 / (r2 * r2);
  return {std::atan2(y.v, x.v), d1, d2};
}

// The quintic "smootherstep" 6s^5 - 15s^4 + 10s^3 on [0, 1], clamped outside: its first and second
// derivatives vanish at both ends, so blends built from it join rest-to-rest segments with C2 continuity.
inline Jet2 smootherstep(Jet2 s) {
  if (s.v <= 0.0) return Jet2::constant(0.0);
  if (s.v >= 1.0) return Jet2::constant(1.0);
  const double x = s.v;
  const double f = x * x * x * (x * (6.0 * x - 15.0) + 10.0);
  const double df = 30.0 * x * x * (x - 1.0) * (x - 1.0);
  const double ddf = 60.0 * x * (x - 1.0) * (2.0 * x - 1.0);
  return chain(s, f, df, ddf);
}

}  // namespace deepnav::sim
