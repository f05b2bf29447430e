// Allan deviation of a static simulated IMU of each grade against the grade's configured figures.
//
// Model of the Allan variance of one axis (independent terms add):
//   AVAR(tau) = N^2 / tau                      white noise, N = ARW or VRW density [unit/sqrt(s)]
//             + gm(tau)^2                      Gauss-Markov bias (imu_gauss_markov.h): peak B at 1.89 T_c
//             + K^2 tau / 3                    rate random walk, K [unit/s/sqrt(s)]
// The turn-on bias, scale factor and misalignment are constant at rest and do not enter.
// Each term is checked where it dominates (its share of the model variance is asserted > 1/2):
// N at tau = 1 s (short run, 100 Hz, 1 h), B at tau = 1.89 T_c and K at tau = 30 T_c (long run,
// 1000 T_c at a lower rate so that it stays ~1.2 M samples: the white term is still white).
// Tolerance: the estimate from n independent differences of tau-averages has relative standard error
// about 1 / sqrt(2 n) (chi-square with n degrees of freedom); n = 3 axes x (T / tau - 1) non-overlapping
// clusters (the overlapping estimator used here is at least as good). Bound: 3 standard errors.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_stats.h"
#include "tools/sim/sensors/imu_gauss_markov.h"
#include "tools/sim/sensors/imu_grades.h"

namespace deepnav::sim {
namespace {

constexpr double kDegPerHToRadPerS = std::numbers::pi / 180.0 / 3600.0;

struct Channel {
  double white_density;     // unit/sqrt(s)
  double bias_instability;  // unit (Allan floor)
  double correlation_time_s;
  double rate_random_walk;  // unit/s/sqrt(s)
};

Channel gyroChannel(const ImuConfig& c) {
  return {c.gyro_noise_deg_per_sqrt_h * std::numbers::pi / 180.0 / 60.0,
          c.gyro_bias_instability_deg_per_h * kDegPerHToRadPerS, c.gyro_bias_correlation_time_s,
          c.gyro_bias_rw_deg_per_h_per_sqrt_h * kDegPerHToRadPerS / 60.0};
}

Channel accelChannel(const ImuConfig& c) {
  return {c.accel_noise_mps_per_sqrt_h / 60.0, c.accel_bias_instability_mps2, c.accel_bias_correlation_time_s,
          c.accel_bias_rw_mps2_per_sqrt_h / 60.0};
}

struct AvarTerms {
  double white, gauss_markov, rate_random_walk;
  double total() const { return white + gauss_markov + rate_random_walk; }
};

AvarTerms modelAvar(const Channel& c, double tau_s) {
  const double sigma_gm = c.bias_instability / kGaussMarkovAdevPeakOverSigma;
  const double gm = gaussMarkovAllanDeviation(sigma_gm, c.correlation_time_s, tau_s);
  return {c.white_density * c.white_density / tau_s, gm * gm,
          c.rate_random_walk * c.rate_random_walk * tau_s / 3.0};
}

// Static IMU samples: [channel 0..5][k], gyro x y z then accel x y z, gravity removed by the mean.
std::vector<std::vector<double>> staticSamples(ImuConfig config, double rate_hz, double duration_s,
                                               std::uint64_t seed) {
  config.rate_hz = rate_hz;
  ImuModel imu;
  std::string error;
  EXPECT_TRUE(imu.init(config, seed, &error)) << error;
  const KinematicState rest = test::restingState();
  const auto n = static_cast<std::size_t>(duration_s * rate_hz);
  std::vector<std::vector<double>> y(6, std::vector<double>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const ImuSample s = imu.measure(rest, static_cast<TimeUs>(std::llround(k * 1e6 / rate_hz)));
    for (int i = 0; i < 3; ++i) {
      y[i][k] = s.w_imu_radps[i];
      y[3 + i][k] = s.f_imu_mps2[i];
    }
  }
  return y;
}

// Overlapping Allan variance at tau = m dt from the integral x_k = dt sum_{i<k} (y_i - mean):
//   AVAR = sum_k (x_{k+2m} - 2 x_{k+m} + x_k)^2 / (2 tau^2 (N + 1 - 2m)).
double overlappingAvar(const std::vector<double>& y, double dt_s, std::size_t m) {
  const double mean = test::mean(y);
  std::vector<long double> x(y.size() + 1, 0.0L);
  for (std::size_t k = 0; k < y.size(); ++k) x[k + 1] = x[k] + static_cast<long double>(y[k] - mean) * dt_s;
  long double sum = 0.0L;
  const std::size_t terms = x.size() - 2 * m;
  for (std::size_t k = 0; k < terms; ++k) {
    const long double d = x[k + 2 * m] - 2.0L * x[k + m] + x[k];
    sum += d * d;
  }
  const double tau_s = static_cast<double>(m) * dt_s;
  return static_cast<double>(sum / (2.0L * tau_s * tau_s * static_cast<long double>(terms)));
}

// Allan variance at tau averaged over three axes (channels first..first+2).
double meanAvar(const std::vector<std::vector<double>>& y, int first, double dt_s, double tau_s) {
  const auto m = static_cast<std::size_t>(std::llround(tau_s / dt_s));
  double sum = 0.0;
  for (int i = first; i < first + 3; ++i) sum += overlappingAvar(y[i], dt_s, m);
  return sum / 3.0;
}

double tolerance(double duration_s, double tau_s) {
  const double n = 3.0 * (std::floor(duration_s / tau_s) - 1.0);
  return 3.0 / std::sqrt(2.0 * n);
}

enum class Term { kWhite, kGaussMarkov, kRateRandomWalk };

void expectAdevMatches(const std::vector<std::vector<double>>& y, int first, const Channel& c, double dt_s,
                       double duration_s, double tau_s, Term term, const char* what) {
  const AvarTerms model = modelAvar(c, tau_s);
  const double share = term == Term::kWhite         ? model.white / model.total()
                       : term == Term::kGaussMarkov ? model.gauss_markov / model.total()
                                                    : model.rate_random_walk / model.total();
  EXPECT_GT(share, 0.5) << what << ": the term does not dominate at tau = " << tau_s << " s";
  const double measured = std::sqrt(meanAvar(y, first, dt_s, tau_s));
  const double expected = std::sqrt(model.total());
  const double tol = tolerance(duration_s, tau_s);
  EXPECT_NEAR(measured / expected, 1.0, tol) << what << " at tau = " << tau_s << " s: measured " << measured
                                             << ", model " << expected << " (share " << share << ")";
  std::printf("[allan] %-28s tau %9.1f s  adev %.4e  model %.4e  ratio %.3f  tol %.3f  share %.2f\n", what, tau_s,
              measured, expected, measured / expected, tol, share);
}

void checkGrade(ImuGrade grade, const char* name, std::uint64_t seed) {
  ImuConfig config;
  applyImuGrade(grade, &config);
  const Channel channels[2] = {gyroChannel(config), accelChannel(config)};
  const std::string label[2] = {std::string(name) + " gyro", std::string(name) + " accel"};

  // White noise: 1 h at 100 Hz, tau = 1 s, where sigma(1 s) = N.
  const double short_s = 3600.0;
  const auto short_run = staticSamples(config, 100.0, short_s, seed);
  for (int t = 0; t < 2; ++t)
    expectAdevMatches(short_run, 3 * t, channels[t], 0.01, short_s, 1.0, Term::kWhite, (label[t] + " N").c_str());

  // Bias instability and rate random walk: 1000 correlation times, ~1.2 M samples.
  const double T_c = config.gyro_bias_correlation_time_s;
  EXPECT_EQ(T_c, config.accel_bias_correlation_time_s);
  const double long_s = 1000.0 * T_c;
  const double rate_hz = 1.2e6 / long_s;
  const auto long_run = staticSamples(config, rate_hz, long_s, seed + 1);
  for (int t = 0; t < 2; ++t) {
    expectAdevMatches(long_run, 3 * t, channels[t], 1.0 / rate_hz, long_s, kGaussMarkovAdevPeakTauOverT * T_c,
                      Term::kGaussMarkov, (label[t] + " B").c_str());
    expectAdevMatches(long_run, 3 * t, channels[t], 1.0 / rate_hz, long_s, 30.0 * T_c, Term::kRateRandomWalk,
                      (label[t] + " K").c_str());
  }
}

TEST(SimImuAllan, GaussMarkovAllanDeviationPeaksAtTheStatedPoint) {
  // The closed form against its stated maximum: 0.6174 sigma at tau = 1.8926 T.
  const double peak = gaussMarkovAllanDeviation(1.0, 1.0, kGaussMarkovAdevPeakTauOverT);
  EXPECT_NEAR(peak, kGaussMarkovAdevPeakOverSigma, 1e-7);
  EXPECT_LT(gaussMarkovAllanDeviation(1.0, 1.0, 1.7), peak);
  EXPECT_LT(gaussMarkovAllanDeviation(1.0, 1.0, 2.1), peak);
  // Limits (bracket expanded in x): short tau, bracket ~ 2 x^3 / 3, ADEV ~ sigma sqrt(2 tau / (3 T)), the
  // rate random walk K^2 tau / 3 of the driving noise K^2 = 2 sigma^2 / T; long tau, bracket ~ 2 x,
  // ADEV ~ sigma sqrt(2 T / tau), white noise of density sigma sqrt(2 T).
  EXPECT_NEAR(gaussMarkovAllanDeviation(1.0, 1.0, 1e-3) / std::sqrt(2.0 * 1e-3 / 3.0), 1.0, 1e-3);
  EXPECT_NEAR(gaussMarkovAllanDeviation(1.0, 1.0, 1e4) / std::sqrt(2.0 / 1e4), 1.0, 1e-3);
}

TEST(SimImuAllan, MemsGradeMatchesItsFigures) { checkGrade(ImuGrade::kMems, "mems", 101); }
TEST(SimImuAllan, TacticalGradeMatchesItsFigures) { checkGrade(ImuGrade::kTactical, "tactical", 201); }
TEST(SimImuAllan, NavigationGradeMatchesItsFigures) { checkGrade(ImuGrade::kNavigation, "navigation", 301); }

}  // namespace
}  // namespace deepnav::sim
