// Observability of the systematic error states (nav/ekf/systematic_states.h) once absolute poses
// constrain the robot, and the Gauss-Markov bias model's statistics (nav/ekf/bias_gauss_markov.h).
// A vehicle turning on a 3 m circle (a full turn every 47 s, crabbing so that the DVL sees both
// horizontal axes) with a DVL of 1 % scale error and a misalignment, a compass with a residual bias and
// one- and two-cycle deviation, and marker poses at 10 Hz.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/bias_gauss_markov.h"
#include "nav/ekf/ekf.h"
#include "nav/ekf/initial_alignment.h"

namespace deepnav {
namespace {

struct Truth {
  Eigen::Vector3d p, v, a, w;
  Eigen::Matrix3d R;
};

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Circle of radius 3 m at 0.4 m/s, 10 m deep; the heading crabs +-0.5 rad off the track (period 31 s),
// roll and pitch sway a few degrees.
Truth truthAt(double t) {
  const double r = 3.0, speed = 0.4, wc = speed / r;
  Truth x;
  x.p = Eigen::Vector3d(r * std::sin(wc * t), r * (1.0 - std::cos(wc * t)), -10.0);
  x.v = Eigen::Vector3d(speed * std::cos(wc * t), speed * std::sin(wc * t), 0.0);
  x.a = Eigen::Vector3d(-speed * wc * std::sin(wc * t), speed * wc * std::cos(wc * t), 0.0);
  const double fy = kTwoPi / 31.0, fr = kTwoPi / 9.0, fp = kTwoPi / 13.0;
  const double yaw = wc * t + 0.5 * std::sin(fy * t), yaw_d = wc + 0.5 * fy * std::cos(fy * t);
  const double roll = 0.05 * std::sin(fr * t), roll_d = 0.05 * fr * std::cos(fr * t);
  const double pitch = 0.04 * std::sin(fp * t + 0.5), pitch_d = 0.04 * fp * std::cos(fp * t + 0.5);
  x.R = quatFromRollPitchYaw(roll, pitch, yaw).toRotationMatrix();
  const double sr = std::sin(roll), cr = std::cos(roll), sp = std::sin(pitch), cp = std::cos(pitch);
  x.w = Eigen::Vector3d(roll_d - yaw_d * sp, pitch_d * cr + yaw_d * sr * cp, -pitch_d * sr + yaw_d * cr * cp);
  return x;
}

// The errors drawn by "the bench" of this test; the filter knows only their prior sigmas.
struct SystematicTruth {
  double dvl_scale = 0.01;
  Eigen::Vector3d dvl_misalignment_rad{0.004, -0.005, 0.014};
  double heading_bias_rad = 0.012;
  Eigen::Vector4d heading_deviation_rad{0.017, -0.010, 0.007, 0.005};  // B, C, D, E
};

EkfConfig systematicConfig() {
  EkfConfig c;
  c.q_robot_dvl = quatFromRollPitchYaw(0.0, 0.0, std::numbers::pi / 4.0);
  c.p_dvl_in_robot_m = Eigen::Vector3d(-0.2, 0.0, -0.3);
  c.gyro_arw_radps_rthz = 4.4e-5;
  c.gyro_bias_rw_radps2_rthz = 1e-7;
  c.accel_bias_rw_mps3_rthz = 1e-5;
  c.dvl_scale_prior_sigma = 0.01;
  c.dvl_misalignment_prior_sigma_rad = 0.02;
  c.heading_bias_prior_sigma_rad = 0.02;
  c.heading_deviation_prior_sigma_rad = 0.02;
  return c;
}

class Bench {
 public:
  Bench(const EkfConfig& c, const SystematicTruth& sys, bool markers) : c_(c), sys_(sys), markers_(markers) {}

  // Runs [0, duration_s] through the filter (started at the truth), calling probe(t) once per second.
  template <class Probe>
  void run(Ekf* ekf, double duration_s, Probe probe) {
    EkfInitialState init;
    const Truth t0 = truthAt(0.0);
    init.x.p_robot_in_odom_m = t0.p;
    init.x.v_robot_in_odom_mps = t0.v;
    init.x.q_odom_robot = Eigen::Quaterniond(t0.R);
    ASSERT_TRUE(ekf->reset(0, init));
    const int steps = static_cast<int>(std::lround(duration_s * 100.0));
    for (int k = 1; k <= steps; ++k) {
      const double t = k * 0.01;
      ekf->setImu(imu(t));
      if (k % 20 == 0) {
        ekf->fuseDvl(dvl(t));
        ekf->fuseDepth(depth(t));
      }
      if (k % 10 == 0) {
        ekf->fuseHeading(heading(t));
        if (markers_) ekf->fusePose(pose(t));
      }
      if (k % 100 == 0) probe(t);
    }
  }

 private:
  double n() { return gauss_(rng_); }
  Eigen::Vector3d n3() { return Eigen::Vector3d(n(), n(), n()); }

  ImuSample imu(double t) {
    const Truth x = truthAt(t - 0.005);  // the sample averages (t - dt, t]
    ImuSample s;
    s.t_us = sToUs(t);
    s.w_imu_radps = x.w + c_.gyro_arw_radps_rthz * 10.0 * n3();
    s.f_imu_mps2 = x.R.transpose() * (x.a + Eigen::Vector3d(0.0, 0.0, c_.gravity_mps2)) + c_.accel_vrw_mps2_rthz * 10.0 * n3();
    return s;
  }

  DvlSample dvl(double t) {
    const Truth x = truthAt(t);
    DvlSample m;
    m.t_us = sToUs(t);
    m.valid = true;
    const Eigen::Matrix3d R_dr = c_.q_robot_dvl.toRotationMatrix().transpose();
    const Eigen::Vector3d u = x.R.transpose() * x.v + x.w.cross(c_.p_dvl_in_robot_m);
    m.v_dvl_mps = (1.0 + sys_.dvl_scale) * expSo3(-sys_.dvl_misalignment_rad) * R_dr * u + 0.003 * n3();
    m.fom_mps = 0.003;
    return m;
  }

  DepthSample depth(double t) {
    DepthSample m;
    m.t_us = sToUs(t);
    m.depth_m = -truthAt(t).p.z() + 0.01 * n();
    m.sigma_m = 0.01;
    return m;
  }

  HeadingSample heading(double t) {
    const Truth x = truthAt(t);
    const double psi = std::numbers::pi / 2.0 - std::atan2(x.R(1, 0), x.R(0, 0));
    const Eigen::Vector4d basis(std::sin(psi), std::cos(psi), std::sin(2.0 * psi), std::cos(2.0 * psi));
    HeadingSample m;
    m.t_us = sToUs(t);
    m.heading_rad = wrapPi(psi + sys_.heading_bias_rad + sys_.heading_deviation_rad.dot(basis) + 0.002 * n());
    m.sigma_rad = 0.002;
    return m;
  }

  PoseMeasurement pose(double t) {
    const Truth x = truthAt(t);
    PoseMeasurement m;
    m.t_us = sToUs(t);
    m.p_robot_in_odom_m = x.p + 0.02 * n3();
    m.q_odom_robot = Eigen::Quaterniond(expSo3(0.005 * n3()) * x.R);
    m.cov_pose.setZero();
    m.cov_pose.diagonal() << Eigen::Vector3d::Constant(4e-4), Eigen::Vector3d::Constant(2.5e-5);
    return m;
  }

  EkfConfig c_;
  SystematicTruth sys_;
  bool markers_;
  std::mt19937_64 rng_{18};
  std::normal_distribution<double> gauss_{0.0, 1.0};
};

struct Estimate {
  double value = 0.0, sigma = 0.0;
};

Estimate estimateOf(const Ekf& ekf, int rel, int k, double value) {
  const FilterState& s = ekf.state();
  const int i = s.sysIndex(rel) + k;
  return {value, std::sqrt(s.P(i, i))};
}

// The first time (s) after which the state's sigma stayed below the bound, or -1.
struct Convergence {
  double bound = 0.0;
  double since_s = -1.0;
  void note(double t, double sigma) {
    if (sigma >= bound) since_s = -1.0;
    else if (since_s < 0.0) since_s = t;
  }
};

TEST(EkfSystematicStates, MarkersRevealDvlScaleAndMisalignmentWithin30Seconds) {
  // GIVEN a DVL reading 1 % fast and misaligned by [0.23, -0.29, 0.80] deg, markers at 10 Hz
  const EkfConfig c = systematicConfig();
  const SystematicTruth truth;
  Ekf ekf;
  std::string error;
  ASSERT_TRUE(ekf.init(c, &error)) << error;
  Bench bench(c, truth, true);
  Convergence scale{0.001}, yaw_mis{0.002};
  // WHEN 60 s are fused
  bench.run(&ekf, 60.0, [&](double t) {
    const SystematicLayout& l = ekf.state().sys_layout;
    scale.note(t, estimateOf(ekf, l.dvl_scale, 0, 0.0).sigma);
    yaw_mis.note(t, estimateOf(ekf, l.dvl_misalignment, 2, 0.0).sigma);
  });
  // THEN the scale factor's sigma fell below 0.1 % (from 1 %) within 30 s and stayed there, the estimate
  // within 3 sigma of the truth; likewise the misalignment about the DVL's z below 0.11 deg
  const FilterState& s = ekf.state();
  const SystematicLayout& l = s.sys_layout;
  const Estimate est_s = estimateOf(ekf, l.dvl_scale, 0, s.x.sys.dvl_scale);
  std::printf("DVL scale: sigma < 0.1 %% from %.0f s, misalignment z sigma < 0.002 rad from %.0f s; at 60 s %.5f +- %.5f\n",
              scale.since_s, yaw_mis.since_s, est_s.value, est_s.sigma);
  EXPECT_GE(scale.since_s, 0.0);
  EXPECT_LE(scale.since_s, 30.0);
  EXPECT_LT(std::abs(est_s.value - truth.dvl_scale), 3.0 * est_s.sigma) << est_s.value << " +- " << est_s.sigma;
  EXPECT_GE(yaw_mis.since_s, 0.0);
  EXPECT_LE(yaw_mis.since_s, 30.0);
  for (int k = 0; k < 3; ++k) {
    const Estimate e = estimateOf(ekf, l.dvl_misalignment, k, s.x.sys.dvl_misalignment_rad(k));
    EXPECT_LT(std::abs(e.value - truth.dvl_misalignment_rad(k)), 3.0 * e.sigma) << k << ": " << e.value << " +- " << e.sigma;
    EXPECT_LT(e.sigma, 0.005) << k;  // each axis learnt (prior 0.02 rad)
  }
}

TEST(EkfSystematicStates, MarkersRevealCompassBiasAndDeviationWithinOneTurn) {
  // GIVEN a compass with a 0.69 deg residual bias and one- and two-cycle deviation of 0.3-1 deg, turning
  const EkfConfig c = systematicConfig();
  const SystematicTruth truth;
  Ekf ekf;
  std::string error;
  ASSERT_TRUE(ekf.init(c, &error)) << error;
  Bench bench(c, truth, true);
  Convergence bias{0.002}, one_cycle{0.002};
  // WHEN 90 s (nearly two turns) are fused
  bench.run(&ekf, 90.0, [&](double t) {
    const SystematicLayout& l = ekf.state().sys_layout;
    bias.note(t, estimateOf(ekf, l.heading_bias, 0, 0.0).sigma);
    one_cycle.note(t, estimateOf(ekf, l.heading_deviation, 0, 0.0).sigma);
  });
  // THEN bias and the B term fell below 0.11 deg sigma (from 1.15 deg) within one turn (47 s), and every
  // term is within 3 sigma of the truth with sigma below 0.17 deg
  const FilterState& s = ekf.state();
  const SystematicLayout& l = s.sys_layout;
  EXPECT_GE(bias.since_s, 0.0);
  EXPECT_LE(bias.since_s, 47.0);
  EXPECT_GE(one_cycle.since_s, 0.0);
  EXPECT_LE(one_cycle.since_s, 47.0);
  const Estimate b = estimateOf(ekf, l.heading_bias, 0, s.x.sys.heading_bias_rad);
  std::printf("compass: bias sigma < 0.002 rad from %.0f s, B from %.0f s; at 90 s bias %.5f +- %.5f\n", bias.since_s,
              one_cycle.since_s, b.value, b.sigma);
  EXPECT_LT(std::abs(b.value - truth.heading_bias_rad), 3.0 * b.sigma) << b.value << " +- " << b.sigma;
  for (int k = 0; k < 4; ++k) {
    const Estimate e = estimateOf(ekf, l.heading_deviation, k, s.x.sys.heading_deviation_rad(k));
    EXPECT_LT(std::abs(e.value - truth.heading_deviation_rad(k)), 3.0 * e.sigma) << k << ": " << e.value << " +- " << e.sigma;
    EXPECT_LT(e.sigma, 0.003) << k;
  }
}

TEST(EkfSystematicStates, WithoutAbsolutePosesTheStatesAreConsideredNotEstimated) {
  // GIVEN the same dive without markers: nothing but the compass tells the heading
  const EkfConfig c = systematicConfig();
  Ekf ekf;
  std::string error;
  ASSERT_TRUE(ekf.init(c, &error)) << error;
  Bench bench(c, SystematicTruth{}, false);
  // WHEN 60 s are fused
  bench.run(&ekf, 60.0, [](double) {});
  // THEN the systematic states were consider states (Ekf::considerUnaided): never corrected, their sigma
  // exactly the prior, and the yaw's sigma includes the bias's (the compass reads yaw plus bias)
  const FilterState& s = ekf.state();
  const Estimate b = estimateOf(ekf, s.sys_layout.heading_bias, 0, 0.0);
  EXPECT_DOUBLE_EQ(b.sigma, c.heading_bias_prior_sigma_rad);
  EXPECT_EQ(s.x.sys.heading_bias_rad, 0.0);
  EXPECT_EQ(s.x.sys.dvl_scale, 0.0);
  EXPECT_GT(std::sqrt(s.P(es::kTheta + 2, es::kTheta + 2)), 0.9 * c.heading_bias_prior_sigma_rad);
}

TEST(EkfSystematicStates, StatesOffKeepTheFifteenStateLayout) {
  // GIVEN the default config (every prior sigma 0)
  Ekf ekf;
  std::string error;
  ASSERT_TRUE(ekf.init(EkfConfig{}, &error)) << error;
  // THEN the state is the core only, and a negative prior is refused naming its key
  EXPECT_EQ(ekf.state().dim(), es::kCoreDim);
  EXPECT_EQ(ekf.state().sys_layout.dim, 0);
  EkfConfig bad;
  bad.dvl_scale_prior_sigma = -0.01;
  EXPECT_FALSE(ekf.init(bad, &error));
  EXPECT_NE(error.find("dvl_scale_prior_sigma"), std::string::npos);
  bad = EkfConfig{};
  bad.gyro_bias_gm_tau_s = 0.5;
  EXPECT_FALSE(ekf.init(bad, &error));
  EXPECT_NE(error.find("gyro_bias_gm_tau_s"), std::string::npos);
}

TEST(EkfSystematicStates, GaussMarkovBiasVarianceApproachesSigmaSquaredAndEstimateDecays) {
  // GIVEN a gyro bias GM process (tau 10 s, sigma 1e-4 rad/s), an initial bias sigma 5x that, an estimate
  // of 2e-4 rad/s, and a robot at rest with only its IMU (the bias is unobservable)
  EkfConfig c;
  c.gyro_bias_rw_radps2_rthz = 0.0;
  c.gyro_bias_gm_tau_s = 10.0;
  c.gyro_bias_gm_sigma_radps = 1e-4;
  c.init_gyro_bias_sigma_radps = 5e-4;
  Ekf ekf;
  std::string error;
  ASSERT_TRUE(ekf.init(c, &error)) << error;
  EkfInitialState init;
  init.x.b_gyro_radps = Eigen::Vector3d(2e-4, 0.0, 0.0);
  ASSERT_TRUE(ekf.reset(0, init));
  double var_at_tau = 0.0;
  for (int k = 1; k <= 5000; ++k) {
    ImuSample s;
    s.t_us = sToUs(k * 0.01);
    s.f_imu_mps2 = Eigen::Vector3d(0.0, 0.0, c.gravity_mps2);
    ekf.setImu(s);
    if (k == 1000) var_at_tau = ekf.state().P(es::kBg, es::kBg);
  }
  // THEN the variance follows sigma^2 + (P0 - sigma^2) exp(-2t/tau), at 1 tau and at 5 tau (within 0.2 %
  // of sigma^2 there)
  const double s2 = 1e-8, p0 = 25e-8;
  EXPECT_NEAR(var_at_tau, s2 + (p0 - s2) * std::exp(-2.0), 1e-6 * s2);
  EXPECT_NEAR(ekf.state().P(es::kBg, es::kBg), s2 + (p0 - s2) * std::exp(-10.0), 1e-6 * s2);
  EXPECT_NEAR(ekf.state().P(es::kBg, es::kBg), s2, 2e-3 * s2);
  // AND the estimate decays as exp(-t/tau)
  EXPECT_NEAR(ekf.state().x.b_gyro_radps.x(), 2e-4 * std::exp(-5.0), 1e-9);
}

TEST(EkfSystematicStates, GaussMarkovDiscretisationMatchesTheProcessStatistics) {
  // GIVEN 4000 stationary GM paths drawn exactly as the bench draws them (tools/sim/sensors/imu_gauss_markov.h)
  EkfConfig c;
  c.accel_bias_rw_mps3_rthz = 0.0;
  c.accel_bias_gm_tau_s = 30.0;
  c.accel_bias_gm_sigma_mps2 = 5e-4;
  const double dt = 0.01;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  const double decay = std::exp(-dt / 30.0), drive = 5e-4 * std::sqrt(1.0 - decay * decay);
  double sum2 = 0.0, sum_lag = 0.0;
  const int paths = 4000, steps = 1000;
  for (int p = 0; p < paths; ++p) {
    double b = 5e-4 * g(rng);
    const double b0 = b;
    for (int k = 0; k < steps; ++k) b = decay * b + drive * g(rng);
    sum2 += b * b;
    sum_lag += b * b0;
  }
  // WHEN the filter's model propagates the same step
  CoreMatrix Phi = CoreMatrix::Identity(), Q = CoreMatrix::Zero();
  NominalState x;
  applyBiasGaussMarkov(c, dt, &Phi, &Q, &x);
  double P = 25e-8, cross = 25e-8;  // variance, and covariance with the start
  for (int k = 0; k < steps; ++k) {
    P = Phi(es::kBa, es::kBa) * P * Phi(es::kBa, es::kBa) + Q(es::kBa, es::kBa);
    cross *= Phi(es::kBa, es::kBa);
  }
  // THEN the model's variance stays sigma^2 and its autocovariance is sigma^2 exp(-t/tau), both within
  // the sample's 4-sigma spread (relative sd of a variance estimate sqrt(2 / N))
  EXPECT_NEAR(P, 25e-8, 1e-15);
  EXPECT_NEAR(sum2 / paths, P, 4.0 * std::sqrt(2.0 / paths) * P);
  EXPECT_NEAR(sum_lag / paths, cross, 4.0 * std::sqrt(2.0 / paths) * 25e-8);
  EXPECT_NEAR(cross, 25e-8 * std::exp(-10.0 / 30.0), 1e-12);
}

}  // namespace
}  // namespace deepnav
