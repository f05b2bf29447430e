#include "nav/metrics/chi_square.h"

#include <cmath>
#include <limits>

namespace deepnav {
namespace {

constexpr double kEps = 1e-14;
constexpr int kMaxIterations = 100000;

// P(a, x) by the series e^-x x^a / Gamma(a + 1) * sum_n x^n / ((a + 1) ... (a + n)), for x < a + 1.
double lowerGammaSeries(double a, double x) {
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * kEps) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) = 1 - P(a, x) by its continued fraction, for x >= a + 1 (modified Lentz's method).
double upperGammaFraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEps) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chiSquareCdf(double x, double k) {
  if (!(x > 0.0)) return 0.0;
  if (!std::isfinite(x)) return 1.0;
  const double a = 0.5 * k;
  const double y = 0.5 * x;
  return y < a + 1.0 ? lowerGammaSeries(a, y) : 1.0 - upperGammaFraction(a, y);
}

double chiSquareQuantile(double p, double k) {
  if (!(p > 0.0)) return 0.0;
  if (!(p < 1.0)) return std::numeric_limits<double>::infinity();
  // The mean is k and the standard deviation sqrt(2k): the quantile lies below k + 40 sqrt(2k) + 40
  // for any p the bands use.
  double lo = 0.0;
  double hi = k + 40.0 * std::sqrt(2.0 * k) + 40.0;
  while (chiSquareCdf(hi, k) < p) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (chiSquareCdf(mid, k) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ChiSquareBand chiSquareBand(double k, double alpha) {
  return {chiSquareQuantile(0.5 * alpha, k), chiSquareQuantile(1.0 - 0.5 * alpha, k)};
}

ChiSquareBand chiSquareMeanBand(double k, double n_samples, double alpha) {
  const ChiSquareBand b = chiSquareBand(k * n_samples, alpha);
  return {b.lo / n_samples, b.hi / n_samples};
}

}  // namespace deepnav
