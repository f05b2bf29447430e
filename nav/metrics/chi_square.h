#pragma once

namespace deepnav {

// Chi-square distribution with k degrees of freedom (k > 0, real): the consistency bands of the NEES.
// CDF: F(x; k) = P(k/2, x/2), P the regularized lower incomplete gamma function, evaluated by its power
// series for x < a + 1 and by its continued fraction (modified Lentz) otherwise (Abramowitz & Stegun
// 6.5.29 and 6.5.31), both to relative 1e-14.
double chiSquareCdf(double x, double k);

// Quantile: the x with F(x; k) = p, p in (0, 1), by bisection on the CDF to relative 1e-12.
double chiSquareQuantile(double p, double k);

// Two-sided (1 - alpha) probability band of a chi-square variable with k dof: [q(alpha/2), q(1 - alpha/2)].
// With alpha = 0.05: k = 1 gives [0.00098, 5.02], k = 3 gives [0.216, 9.35].
struct ChiSquareBand {
  double lo = 0.0;
  double hi = 0.0;
};
ChiSquareBand chiSquareBand(double k, double alpha);

// Band of the time-average of N independent NEES samples of k dof each: N * mean is chi-square with N k
// dof, so the band is that of N k dof divided by N (Bar-Shalom, Li, Kirubarajan 2001, sec. 5.4.2).
ChiSquareBand chiSquareMeanBand(double k, double n_samples, double alpha);

}  // namespace deepnav
