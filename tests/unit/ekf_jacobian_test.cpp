// Every analytic Jacobian of the error-state EKF against central differences of the nominal model,
// perturbing through the error-state retraction (manif test/common_tester.h style).
#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/attitude_updater.h"
#include "nav/ekf/bias_gauss_markov.h"
#include "nav/ekf/depth_updater.h"
#include "nav/ekf/dvl_updater.h"
#include "nav/ekf/ekf_config.h"
#include "nav/ekf/heading_updater.h"
#include "nav/ekf/imu_propagation.h"
#include "nav/ekf/initial_alignment.h"
#include "nav/ekf/innovation_gate.h"
#include "nav/ekf/pose_updater.h"
#include "nav/ekf/relative_pose_updater.h"
#include "nav/ekf/stochastic_clone.h"
#include "nav/ekf/systematic_states.h"

namespace deepnav {
namespace {

using Vec15 = Eigen::Matrix<double, es::kCoreDim, 1>;
constexpr double kEps = 1e-6;

// Error between two nominal states, the inverse of retractNominal: (a [-] b).
Vec15 boxMinus(const NominalState& a, const NominalState& b) {
  Vec15 d;
  d.segment<3>(es::kP) = a.p_robot_in_odom_m - b.p_robot_in_odom_m;
  d.segment<3>(es::kV) = a.v_robot_in_odom_mps - b.v_robot_in_odom_mps;
  d.segment<3>(es::kTheta) = logSo3(a.q_odom_robot.toRotationMatrix() * b.q_odom_robot.toRotationMatrix().transpose());
  d.segment<3>(es::kBg) = a.b_gyro_radps - b.b_gyro_radps;
  d.segment<3>(es::kBa) = a.b_accel_mps2 - b.b_accel_mps2;
  return d;
}

NominalState randomNominal(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  NominalState x;
  x.p_robot_in_odom_m = Eigen::Vector3d(n(rng), n(rng), -10.0 + n(rng));
  x.v_robot_in_odom_mps = 0.5 * Eigen::Vector3d(n(rng), n(rng), n(rng));
  x.q_odom_robot = quatFromRollPitchYaw(0.3 * n(rng), 0.3 * n(rng), 2.0 * n(rng));
  x.b_gyro_radps = 0.01 * Eigen::Vector3d(n(rng), n(rng), n(rng));
  x.b_accel_mps2 = 0.1 * Eigen::Vector3d(n(rng), n(rng), n(rng));
  return x;
}

// A state with two clones and a random (symmetric PD) covariance.
FilterState randomFilterState(std::mt19937_64& rng) {
  FilterState s;
  s.x = randomNominal(rng);
  s.w_robot_meas_radps = Eigen::Vector3d(0.2, -0.3, 0.5);
  for (std::uint32_t id : {7u, 9u}) {
    EXPECT_EQ(augmentClone(id, es::kMaxClones, &s), CloneStatus::kOk);
    const NominalState other = randomNominal(rng);
    s.clones[static_cast<std::size_t>(s.n_clones - 1)].p_robot_in_odom_m = other.p_robot_in_odom_m;
    s.clones[static_cast<std::size_t>(s.n_clones - 1)].q_odom_robot = other.q_odom_robot;
  }
  const int n = s.dim();
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
  s.P.topLeftCorner(n, n) = A * A.transpose() + Eigen::MatrixXd::Identity(n, n);
  return s;
}

EkfConfig mountedConfig() {
  EkfConfig c;
  c.q_robot_dvl = quatFromRollPitchYaw(0.1, -0.2, 0.7);
  c.p_dvl_in_robot_m = Eigen::Vector3d(0.4, -0.1, -0.3);
  c.p_depth_in_robot_m = Eigen::Vector3d(-0.2, 0.15, 0.25);
  c.magnetic_declination_rad = 0.05;
  c.heading_bias_rad = -0.02;
  return c;
}

using Linearize = std::function<bool(const FilterState&, Linearization*)>;

// H_num(:, j) = -(r(x [+] eps e_j) - r(x [-] eps e_j)) / (2 eps), since r ~= r0 - H dx.
void expectJacobianMatches(const FilterState& s, const Linearize& linearize, double tol) {
  Linearization lin;
  ASSERT_TRUE(linearize(s, &lin));
  const int n = s.dim();
  ASSERT_EQ(lin.H.cols(), n);
  for (int j = 0; j < n; ++j) {
    ErrorVector dx = ErrorVector::Zero(n);
    dx(j) = kEps;
    FilterState plus = s, minus = s;
    injectErrorState(dx, &plus);
    injectErrorState(-dx, &minus);
    Linearization lp, lm;
    ASSERT_TRUE(linearize(plus, &lp));
    ASSERT_TRUE(linearize(minus, &lm));
    MeasVector col(lin.m);
    for (int i = 0; i < lin.m; ++i) col(i) = -wrapPi(lp.residual(i) - lm.residual(i)) / (2.0 * kEps);
    for (int i = 0; i < lin.m; ++i) {
      EXPECT_NEAR(lin.H(i, j), col(i), tol) << "row " << i << " col " << j;
    }
  }
}

TEST(EkfJacobian, PropagationMatchesNumericDifferentiation) {
  // GIVEN random states and IMU inputs, with long steps so that every second-order term shows
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 5; ++trial) {
    const NominalState x = randomNominal(rng);
    RobotImu u;
    u.w_robot_radps = Eigen::Vector3d(0.3, -0.5, 0.8);
    u.f_robot_mps2 = Eigen::Vector3d(0.4, -0.2, 9.9);
    for (double dt : {0.01, 0.5}) {
      // WHEN the analytic Phi is computed
      const CoreMatrix F = propagationJacobian(x, u, dt);
      // THEN each column equals the central difference of the propagated error
      for (int j = 0; j < es::kCoreDim; ++j) {
        Vec15 d = Vec15::Zero();
        d(j) = kEps;
        const NominalState base = propagateNominal(x, u, dt, 9.80665);
        const Vec15 ep = boxMinus(propagateNominal(retractNominal(x, d), u, dt, 9.80665), base);
        const Vec15 em = boxMinus(propagateNominal(retractNominal(x, -d), u, dt, 9.80665), base);
        const Vec15 col = (ep - em) / (2.0 * kEps);
        for (int i = 0; i < es::kCoreDim; ++i) EXPECT_NEAR(F(i, j), col(i), 1e-6) << i << "," << j << " dt " << dt;
      }
    }
  }
}

TEST(EkfJacobian, DvlMatchesNumericDifferentiation) {
  // GIVEN a DVL with a mounting rotation and lever arm, a moving and rotating robot
  std::mt19937_64 rng(2);
  const EkfConfig c = mountedConfig();
  DvlSample m;
  m.valid = true;
  m.v_dvl_mps = Eigen::Vector3d(0.3, 0.1, -0.05);
  // WHEN / THEN the analytic H matches the numeric one
  for (int trial = 0; trial < 3; ++trial) {
    expectJacobianMatches(randomFilterState(rng),
                          [&](const FilterState& s, Linearization* l) { return linearizeDvl(s, m, c, l); }, 1e-6);
  }
}

TEST(EkfJacobian, DepthMatchesNumericDifferentiation) {
  // GIVEN a pressure port off the robot origin
  std::mt19937_64 rng(3);
  const EkfConfig c = mountedConfig();
  DepthSample m;
  m.depth_m = 11.0;
  for (int trial = 0; trial < 3; ++trial) {
    expectJacobianMatches(randomFilterState(rng),
                          [&](const FilterState& s, Linearization* l) { return linearizeDepth(s, m, c, l); }, 1e-6);
  }
}

TEST(EkfJacobian, HeadingMatchesNumericDifferentiation) {
  // GIVEN tilted attitudes (the heading Jacobian couples roll/pitch errors when tilted)
  std::mt19937_64 rng(4);
  const EkfConfig c = mountedConfig();
  HeadingSample m;
  m.heading_rad = 1.0;
  for (int trial = 0; trial < 3; ++trial) {
    expectJacobianMatches(randomFilterState(rng),
                          [&](const FilterState& s, Linearization* l) { return linearizeHeading(s, m, c, l); },
                          1e-6);
  }
}

TEST(EkfJacobian, AttitudeMatchesNumericDifferentiation) {
  std::mt19937_64 rng(5);
  const EkfConfig c = mountedConfig();
  AttitudeSample m;
  m.roll_rad = 0.1;
  m.pitch_rad = -0.05;
  for (int trial = 0; trial < 3; ++trial) {
    expectJacobianMatches(randomFilterState(rng),
                          [&](const FilterState& s, Linearization* l) { return linearizeAttitude(s, m, c, l); },
                          1e-6);
  }
}

TEST(EkfJacobian, PoseMatchesNumericDifferentiation) {
  // GIVEN a measured pose 0.4 rad away from the estimate (so Jr^-1 differs from I)
  std::mt19937_64 rng(6);
  for (int trial = 0; trial < 3; ++trial) {
    const FilterState s = randomFilterState(rng);
    PoseMeasurement m;
    m.p_robot_in_odom_m = s.x.p_robot_in_odom_m + Eigen::Vector3d(0.5, -0.2, 0.1);
    m.q_odom_robot = expSo3Quat(Eigen::Vector3d(0.2, -0.3, 0.1)) * s.x.q_odom_robot;
    expectJacobianMatches(s, [&](const FilterState& st, Linearization* l) { return linearizePose(st, m, l); }, 1e-6);
  }
}

TEST(EkfJacobian, RelativePoseMatchesNumericDifferentiation) {
  // GIVEN a relative pose between clone 9 (slot 1) and the current state, with and without translation
  std::mt19937_64 rng(7);
  for (bool with_translation : {true, false}) {
    const FilterState s = randomFilterState(rng);
    RelativePoseMeasurement m;
    m.clone_id = 9;
    m.has_translation = with_translation;
    m.q_robota_robotb = quatFromRollPitchYaw(0.1, 0.2, -0.3);
    m.p_robotb_in_robota_m = Eigen::Vector3d(0.3, -0.4, 0.2);
    expectJacobianMatches(
        s, [&](const FilterState& st, Linearization* l) { return linearizeRelativePose(st, m, l); }, 1e-6);
  }
}

TEST(EkfJacobian, CloneAugmentationIsJPJtAndMarginalisationUndoesIt) {
  // GIVEN a state with two clones
  std::mt19937_64 rng(8);
  FilterState s = randomFilterState(rng);
  const int n = s.dim();
  const Eigen::MatrixXd P0 = s.P.topLeftCorner(n, n);
  // WHEN a third clone is added
  ASSERT_EQ(augmentClone(11, es::kMaxClones, &s), CloneStatus::kOk);
  // THEN P_aug = J P J^T with J = [I; select(dp, dtheta)]
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + 6, n);
  J.topRows(n).setIdentity();
  J.block(n, es::kP, 3, 3).setIdentity();
  J.block(n + 3, es::kTheta, 3, 3).setIdentity();
  EXPECT_TRUE(s.P.topLeftCorner(n + 6, n + 6).isApprox(J * P0 * J.transpose(), 1e-12));
  // AND duplicates are refused, and capacity is respected
  EXPECT_EQ(augmentClone(11, es::kMaxClones, &s), CloneStatus::kDuplicateId);
  EXPECT_EQ(augmentClone(12, 3, &s), CloneStatus::kFull);
  // WHEN the middle clone (id 9) is marginalised
  ASSERT_EQ(marginaliseClone(9, &s), CloneStatus::kOk);
  // THEN its rows and columns are gone and the others keep their blocks
  std::vector<int> keep;
  for (int i = 0; i < n + 6; ++i) {
    if (i < es::cloneOffset(1) || i >= es::cloneOffset(2)) keep.push_back(i);
  }
  const Eigen::MatrixXd Paug = J * P0 * J.transpose();
  for (std::size_t r = 0; r < keep.size(); ++r) {
    for (std::size_t c = 0; c < keep.size(); ++c) {
      EXPECT_NEAR(s.P(static_cast<int>(r), static_cast<int>(c)), Paug(keep[r], keep[c]), 1e-12);
    }
  }
  EXPECT_EQ(s.clones[1].id, 11u);
  EXPECT_EQ(marginaliseClone(9, &s), CloneStatus::kUnknownId);
}

// Every systematic state on (systematic_states.h), with non-zero nominal values, two clones behind
// which the systematic block sits, and a random covariance.
EkfConfig systematicConfig() {
  EkfConfig c = mountedConfig();
  c.dvl_scale_prior_sigma = 0.01;
  c.dvl_misalignment_prior_sigma_rad = 0.02;
  c.dvl_bias_prior_sigma_mps = 0.005;
  c.heading_bias_prior_sigma_rad = 0.01;
  c.heading_deviation_prior_sigma_rad = 0.02;
  return c;
}

FilterState randomSystematicState(std::mt19937_64& rng, const EkfConfig& c) {
  std::normal_distribution<double> n(0.0, 1.0);
  FilterState s;
  s.sys_layout = systematicLayout(c);
  s.x = randomNominal(rng);
  s.x.sys.dvl_scale = 0.02 * n(rng);
  s.x.sys.dvl_misalignment_rad = 0.1 * Eigen::Vector3d(n(rng), n(rng), n(rng));
  s.x.sys.dvl_bias_mps = 0.01 * Eigen::Vector3d(n(rng), n(rng), n(rng));
  s.x.sys.heading_bias_rad = 0.05 * n(rng);
  s.x.sys.heading_deviation_rad = 0.05 * Eigen::Vector4d(n(rng), n(rng), n(rng), n(rng));
  s.w_robot_meas_radps = Eigen::Vector3d(0.2, -0.3, 0.5);
  for (std::uint32_t id : {7u, 9u}) EXPECT_EQ(augmentClone(id, es::kMaxClones, &s), CloneStatus::kOk);
  const int n_dim = s.dim();
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(n_dim, n_dim);
  s.P.topLeftCorner(n_dim, n_dim) = A * A.transpose() + Eigen::MatrixXd::Identity(n_dim, n_dim);
  return s;
}

TEST(EkfJacobian, DvlWithScaleMisalignmentAndBiasMatchesNumericDifferentiation) {
  // GIVEN a turned DVL with a lever arm, a scale error, a misalignment of up to ~0.2 rad and a velocity
  // bias of ~1 cm/s in the state
  std::mt19937_64 rng(21);
  const EkfConfig c = systematicConfig();
  DvlSample m;
  m.valid = true;
  m.v_dvl_mps = Eigen::Vector3d(0.3, 0.1, -0.05);
  for (int trial = 0; trial < 3; ++trial) {
    const FilterState s = randomSystematicState(rng, c);
    ASSERT_EQ(s.dim(), es::kCoreDim + 2 * es::kCloneDim + 12);
    // WHEN / THEN the analytic H (scale, misalignment and bias columns included) matches the numeric one
    expectJacobianMatches(s, [&](const FilterState& st, Linearization* l) { return linearizeDvl(st, m, c, l); },
                          1e-6);
  }
}

TEST(EkfJacobian, HeadingWithBiasAndDeviationMatchesNumericDifferentiation) {
  // GIVEN tilted attitudes, a compass bias and deviation terms of up to ~0.1 rad in the state
  std::mt19937_64 rng(22);
  const EkfConfig c = systematicConfig();
  HeadingSample m;
  m.heading_rad = 1.0;
  for (bool is_true : {false, true}) {
    m.is_true = is_true;
    for (int trial = 0; trial < 3; ++trial) {
      // WHEN / THEN the analytic H matches the numeric one (a true heading has no deviation columns)
      expectJacobianMatches(randomSystematicState(rng, c),
                            [&](const FilterState& st, Linearization* l) { return linearizeHeading(st, m, c, l); },
                            1e-6);
    }
  }
}

TEST(EkfJacobian, CloneAugmentationMovesTheSystematicBlockBehindTheNewClone) {
  // GIVEN a state with two clones and every systematic state
  std::mt19937_64 rng(23);
  const EkfConfig c = systematicConfig();
  FilterState s = randomSystematicState(rng, c);
  const int n = s.dim();
  const int o = s.sysOffset();
  const Eigen::MatrixXd P0 = s.P.topLeftCorner(n, n);
  // WHEN a third clone is added
  ASSERT_EQ(augmentClone(11, es::kMaxClones, &s), CloneStatus::kOk);
  // THEN P_aug = J P J^T, J inserting the clone's rows (copies of dp, dtheta) before the systematic block
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + 6, n);
  J.topLeftCorner(o, o).setIdentity();
  J.block(o, es::kP, 3, 3).setIdentity();
  J.block(o + 3, es::kTheta, 3, 3).setIdentity();
  J.block(o + 6, o, n - o, n - o).setIdentity();
  const Eigen::MatrixXd Paug = J * P0 * J.transpose();
  EXPECT_TRUE(s.P.topLeftCorner(n + 6, n + 6).isApprox(Paug, 1e-12));
  // AND marginalising the new clone gives the state back
  ASSERT_EQ(marginaliseClone(11, &s), CloneStatus::kOk);
  EXPECT_TRUE(s.P.topLeftCorner(n, n).isApprox(P0, 1e-12));
}

TEST(EkfJacobian, GaussMarkovBiasPropagationMatchesNumericDifferentiation) {
  // GIVEN Gauss-Markov gyro and accelerometer biases with short correlation times (large decay per step)
  std::mt19937_64 rng(24);
  EkfConfig c;
  c.gyro_bias_gm_tau_s = 2.0;
  c.gyro_bias_gm_sigma_radps = 1e-4;
  c.accel_bias_gm_tau_s = 5.0;
  c.accel_bias_gm_sigma_mps2 = 1e-3;
  RobotImu u;
  u.w_robot_radps = Eigen::Vector3d(0.3, -0.5, 0.8);
  u.f_robot_mps2 = Eigen::Vector3d(0.4, -0.2, 9.9);
  const double dt = 0.5;
  const auto step = [&](const NominalState& x) {
    CoreMatrix Phi = CoreMatrix::Identity(), Q = CoreMatrix::Zero();
    NominalState out = propagateNominal(x, u, dt, c.gravity_mps2);
    applyBiasGaussMarkov(c, dt, &Phi, &Q, &out);
    return out;
  };
  for (int trial = 0; trial < 3; ++trial) {
    const NominalState x = randomNominal(rng);
    CoreMatrix Phi = propagationJacobian(x, u, dt);
    CoreMatrix Q = propagationNoise(c, dt);
    NominalState unused = x;
    applyBiasGaussMarkov(c, dt, &Phi, &Q, &unused);
    // WHEN each error is perturbed and the nominal step (with the decay) repeated
    const NominalState y0 = step(x);
    for (int j = 0; j < es::kCoreDim; ++j) {
      Vec15 dx = Vec15::Zero();
      dx(j) = kEps;
      const Vec15 col = (boxMinus(step(retractNominal(x, dx)), y0) - boxMinus(step(retractNominal(x, -dx)), y0)) /
                        (2.0 * kEps);
      // THEN Phi matches, the bias block being exp(-dt / tau)
      for (int i = 0; i < es::kCoreDim; ++i) EXPECT_NEAR(Phi(i, j), col(i), 1e-6) << i << "," << j;
    }
    EXPECT_NEAR(Phi(es::kBg, es::kBg), std::exp(-dt / 2.0), 1e-15);
    // AND the driving noise keeps the stationary variance: exp(-2dt/tau) sigma^2 + q = sigma^2 (+ random walk)
    const double rw = c.accel_bias_rw_mps3_rthz * c.accel_bias_rw_mps3_rthz * dt;
    EXPECT_NEAR(Q(es::kBa, es::kBa) - rw, 1e-6 * (1.0 - std::exp(-2.0 * dt / 5.0)), 1e-18);
  }
}

TEST(EkfJacobian, So3HelpersAgreeWithDefinitions) {
  // GIVEN a rotation vector and a small increment
  const Eigen::Vector3d phi(0.3, -0.6, 0.9), d(1e-6, -2e-6, 1.5e-6);
  // THEN Exp(phi + d) = Exp(phi) Exp(Jr d) and Log inverts Exp, including near zero
  const Eigen::Matrix3d lhs = expSo3(phi + d);
  const Eigen::Matrix3d rhs = expSo3(phi) * expSo3(rightJacobianSo3(phi) * d);
  EXPECT_TRUE(lhs.isApprox(rhs, 1e-11));
  EXPECT_TRUE((rightJacobianSo3(phi) * rightJacobianInverseSo3(phi)).isIdentity(1e-12));
  EXPECT_TRUE(logSo3(expSo3(phi)).isApprox(phi, 1e-12));
  EXPECT_TRUE(logSo3(expSo3(1e-9 * phi)).isApprox(1e-9 * phi, 1e-9));
  EXPECT_TRUE(expSo3Quat(phi).toRotationMatrix().isApprox(expSo3(phi), 1e-12));
  EXPECT_NEAR(wrapPi(3.5 * M_PI), -0.5 * M_PI, 1e-12);
}

TEST(EkfGate, ChiSquareThresholdsHaveTheScalarGateTailProbability) {
  // GIVEN the textbook 95 % quantiles
  EXPECT_NEAR(chiSquareTail(1, 3.841), 0.05, 1e-4);
  EXPECT_NEAR(chiSquareTail(2, 5.991), 0.05, 1e-4);
  EXPECT_NEAR(chiSquareTail(3, 7.815), 0.05, 1e-4);
  EXPECT_NEAR(chiSquareTail(4, 9.488), 0.05, 1e-4);
  EXPECT_NEAR(chiSquareTail(5, 11.070), 0.05, 1e-4);
  EXPECT_NEAR(chiSquareTail(6, 12.592), 0.05, 1e-4);
  // WHEN a 3-sigma gate is built THEN c_1 = 9 and c_k has the same tail (0.27 %)
  const GateThresholds g = makeGateThresholds(3.0);
  EXPECT_DOUBLE_EQ(g.chi2[1], 9.0);
  for (int k = 2; k <= es::kMaxMeasDim; ++k) {
    EXPECT_NEAR(chiSquareTail(k, g.chi2[static_cast<std::size_t>(k)]), std::erfc(3.0 / std::sqrt(2.0)), 1e-9);
  }
  EXPECT_NEAR(g.chi2[2], -2.0 * std::log(std::erfc(3.0 / std::sqrt(2.0))), 1e-6);
  // AND one axis at 5 sigma is rejected even when the 6-dof d^2 alone would pass
  MeasVector nu = MeasVector::Zero(6);
  nu(2) = 4.0;
  const MeasMatrix S = MeasMatrix::Identity(6, 6);
  EXPECT_GT(innovationTestRatio(nu, S, S, g), 1.0);
  nu(2) = 2.5;
  EXPECT_LT(innovationTestRatio(nu, S, S, g), 1.0);
}

}  // namespace
}  // namespace deepnav
