// End-to-end properties of the EKF on a built-in truth generator: an ROV circling at constant depth
// with yaw, roll and pitch motion; a perfect IMU from the trajectory's derivatives plus the configured
// noise; DVL, depth, compass, AHRS, marker poses and VO relative poses with known noise.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/ekf.h"
#include "nav/ekf/initial_alignment.h"

namespace deepnav {
namespace {

// ---------------------------------------------------------------------------------------------------
// Truth
// ---------------------------------------------------------------------------------------------------
struct Truth {
  Eigen::Vector3d p, v, a;
  Eigen::Matrix3d R;  // R_odom_robot
  Eigen::Vector3d w;  // body rate, robot frame
};

struct CircleTrajectory {
  double radius_m = 4.0;
  double speed_mps = 0.25;
  double depth_m = 10.0;
  double yaw_amp_rad = 0.3, yaw_hz = 0.05;
  double roll_amp_rad = 0.05, roll_hz = 0.11;
  double pitch_amp_rad = 0.04, pitch_hz = 0.07;

  Truth at(double t) const {
    const double wc = speed_mps / radius_m;
    constexpr double k2Pi = 2.0 * std::numbers::pi;
    Truth x;
    x.p = Eigen::Vector3d(radius_m * std::sin(wc * t), radius_m * (1.0 - std::cos(wc * t)), -depth_m);
    x.v = Eigen::Vector3d(speed_mps * std::cos(wc * t), speed_mps * std::sin(wc * t), 0.0);
    x.a = Eigen::Vector3d(-speed_mps * wc * std::sin(wc * t), speed_mps * wc * std::cos(wc * t), 0.0);
    const double yaw = wc * t + yaw_amp_rad * std::sin(k2Pi * yaw_hz * t);
    const double yaw_d = wc + yaw_amp_rad * k2Pi * yaw_hz * std::cos(k2Pi * yaw_hz * t);
    const double roll = roll_amp_rad * std::sin(k2Pi * roll_hz * t);
    const double roll_d = roll_amp_rad * k2Pi * roll_hz * std::cos(k2Pi * roll_hz * t);
    const double pitch = pitch_amp_rad * std::sin(k2Pi * pitch_hz * t + 0.5);
    const double pitch_d = pitch_amp_rad * k2Pi * pitch_hz * std::cos(k2Pi * pitch_hz * t + 0.5);
    x.R = quatFromRollPitchYaw(roll, pitch, yaw).toRotationMatrix();
    // ZYX Euler rates to body rates.
    const double sr = std::sin(roll), cr = std::cos(roll), sp = std::sin(pitch), cp = std::cos(pitch);
    x.w = Eigen::Vector3d(roll_d - yaw_d * sp, pitch_d * cr + yaw_d * sr * cp, -pitch_d * sr + yaw_d * cr * cp);
    return x;
  }
};

// ---------------------------------------------------------------------------------------------------
// Sensor streams
// ---------------------------------------------------------------------------------------------------
struct Noise {
  double dvl_mps = 0.01, depth_m = 0.05, heading_rad = 0.035, attitude_rad = 0.0087;
  double pose_m = 0.05, pose_rad = 0.02, vo_m = 0.02, vo_rad = 0.01;
};

using Payload = std::variant<ImuSample, DvlSample, DepthSample, HeadingSample, AttitudeSample, PoseMeasurement,
                             RelativePoseMeasurement, CloneRequest, CloneRelease>;

struct Event {
  TimeUs t_arrival_us = 0;
  TimeUs t_us = 0;  // capture time
  std::uint64_t seq = 0;
  Payload what;
  bool outlier = false;
  NavSource source = kSrcCount;
};

struct ScenarioOptions {
  std::uint64_t seed = 1;
  double duration_s = 60.0;
  double imu_hz = 100.0;
  double dvl_hz = 5.0, depth_hz = 5.0, heading_hz = 5.0, attitude_hz = 5.0, pose_hz = 1.0, vo_hz = 2.0;
  NavSource outage_source = kSrcCount;  // this source is silent in [outage_start_s, outage_end_s)
  double outage_start_s = 0.0, outage_end_s = 0.0;
  int outlier_every = 0;                // every n-th sample of each aiding source is an outlier
  double max_delay_s = 0.0;             // 0: fused right after the IMU epoch that covers it
  double measurement_end_s = 1e9;       // no measurement captured after this
};

class ScenarioGenerator {
 public:
  ScenarioGenerator(const ScenarioOptions& o, const EkfConfig& c) : o_(o), c_(c), rng_(o.seed) {}

  std::vector<Event> generate() {
    addImu();
    addSource(kSrcDvl, o_.dvl_hz, 0.003);
    addSource(kSrcDepth, o_.depth_hz, 0.047);
    addSource(kSrcHeading, o_.heading_hz, 0.071);
    addSource(kSrcAttitude, o_.attitude_hz, 0.113);
    addSource(kSrcMarkers, o_.pose_hz, 0.517);
    addVo();
    setArrivals();
    std::sort(events_.begin(), events_.end(), [](const Event& a, const Event& b) {
      const bool ai = std::holds_alternative<ImuSample>(a.what), bi = std::holds_alternative<ImuSample>(b.what);
      if (a.t_arrival_us != b.t_arrival_us) return a.t_arrival_us < b.t_arrival_us;
      if (ai != bi) return ai;  // the IMU epoch first, then what arrived with it
      return a.seq < b.seq;
    });
    return std::move(events_);
  }

  // Initial state: truth at 0 plus an error drawn from the configured initial covariance.
  EkfInitialState initialState() {
    const Truth t0 = traj_.at(0.0);
    EkfInitialState s;
    s.x.p_robot_in_odom_m = t0.p + c_.init_pos_sigma_m * gauss3();
    s.x.v_robot_in_odom_mps = t0.v + c_.init_vel_sigma_mps * gauss3();
    const Eigen::Vector3d dth(c_.init_roll_pitch_sigma_rad * n(), c_.init_roll_pitch_sigma_rad * n(),
                              c_.init_yaw_sigma_rad * n());
    s.x.q_odom_robot = Eigen::Quaterniond(expSo3(-dth) * t0.R);
    s.x.b_gyro_radps = bg0_ - c_.init_gyro_bias_sigma_radps * gauss3();
    s.x.b_accel_mps2 = ba0_ - c_.init_accel_bias_sigma_mps2 * gauss3();
    return s;
  }

  const CircleTrajectory& trajectory() const { return traj_; }
  const std::vector<Eigen::Vector3d>& gyroBiasAtImu() const { return bg_at_imu_; }

 private:
  double n() { return gauss_(rng_); }
  Eigen::Vector3d gauss3() { return Eigen::Vector3d(n(), n(), n()); }
  bool silent(NavSource s, double t) const {
    return t > o_.measurement_end_s || (s == o_.outage_source && t >= o_.outage_start_s && t < o_.outage_end_s);
  }

  void push(TimeUs t_us, Payload p, NavSource src, bool outlier = false) {
    Event e;
    e.t_us = t_us;
    e.seq = seq_++;
    e.what = std::move(p);
    e.source = src;
    e.outlier = outlier;
    events_.push_back(std::move(e));
  }

  void addImu() {
    const double dt = 1.0 / o_.imu_hz;
    const double sg = c_.gyro_arw_radps_rthz / std::sqrt(dt), sa = c_.accel_vrw_mps2_rthz / std::sqrt(dt);
    bg0_ = c_.init_gyro_bias_sigma_radps * gauss3();
    ba0_ = c_.init_accel_bias_sigma_mps2 * gauss3();
    Eigen::Vector3d bg = bg0_, ba = ba0_;
    const int steps = static_cast<int>(std::lround(o_.duration_s * o_.imu_hz));
    for (int k = 1; k <= steps; ++k) {
      // The sample stamped t_k averages (t_k - dt, t_k]: the truth at the middle of the interval.
      bg += c_.gyro_bias_rw_radps2_rthz * std::sqrt(dt) * gauss3();
      ba += c_.accel_bias_rw_mps3_rthz * std::sqrt(dt) * gauss3();
      const Truth x = traj_.at((k - 0.5) * dt);
      ImuSample s;
      s.t_us = sToUs(k * dt);
      s.w_imu_radps = x.w + bg + sg * gauss3();
      s.f_imu_mps2 = x.R.transpose() * (x.a + Eigen::Vector3d(0.0, 0.0, c_.gravity_mps2)) + ba + sa * gauss3();
      bg_at_imu_.push_back(bg);
      push(s.t_us, s, kSrcImu);
    }
  }

  void addSource(NavSource src, double hz, double phase_s) {
    if (hz <= 0.0) return;
    int count = 0;
    for (double t = phase_s; t < o_.duration_s - 0.02; t += 1.0 / hz) {
      if (silent(src, t)) continue;
      const bool outlier = o_.outlier_every > 0 && (++count % o_.outlier_every == 0);
      addSample(src, t, outlier);
    }
  }

  // One axis off by k sigma, k uniform in [5, 50], random sign; no other noise on an outlier.
  double outlierOffset(double sigma) {
    std::uniform_real_distribution<double> k(5.0, 50.0);
    return (n() > 0.0 ? 1.0 : -1.0) * k(rng_) * sigma;
  }
  int randomAxis(int n_axes) { return std::uniform_int_distribution<int>(0, n_axes - 1)(rng_); }

  void addSample(NavSource src, double t, bool outlier) {
    const Truth x = traj_.at(t);
    const TimeUs t_us = sToUs(t);
    if (src == kSrcDvl) {
      DvlSample m;
      m.t_us = t_us;
      m.valid = true;
      const Eigen::Matrix3d R_dr = c_.q_robot_dvl.toRotationMatrix().transpose();
      m.v_dvl_mps = R_dr * (x.R.transpose() * x.v + x.w.cross(c_.p_dvl_in_robot_m));
      if (outlier) m.v_dvl_mps(randomAxis(3)) += outlierOffset(noise_.dvl_mps);
      else m.v_dvl_mps += noise_.dvl_mps * gauss3();
      m.fom_mps = noise_.dvl_mps;
      push(t_us, m, src, outlier);
    } else if (src == kSrcDepth) {
      DepthSample m;
      m.t_us = t_us;
      m.depth_m = -(x.p + x.R * c_.p_depth_in_robot_m).z();
      m.depth_m += outlier ? outlierOffset(noise_.depth_m) : noise_.depth_m * n();
      m.sigma_m = noise_.depth_m;
      push(t_us, m, src, outlier);
    } else if (src == kSrcHeading) {
      HeadingSample m;
      m.t_us = t_us;
      const double yaw = std::atan2(x.R(1, 0), x.R(0, 0));
      m.heading_rad = wrapPi(std::numbers::pi / 2.0 - yaw);
      m.heading_rad += outlier ? outlierOffset(noise_.heading_rad) : noise_.heading_rad * n();
      m.sigma_rad = noise_.heading_rad;
      push(t_us, m, src, outlier);
    } else if (src == kSrcAttitude) {
      AttitudeSample m;
      m.t_us = t_us;
      m.roll_rad = std::atan2(x.R(2, 1), x.R(2, 2));
      m.pitch_rad = -std::asin(x.R(2, 0));
      const int axis = randomAxis(2);
      m.roll_rad += outlier ? (axis == 0 ? outlierOffset(noise_.attitude_rad) : 0.0) : noise_.attitude_rad * n();
      m.pitch_rad += outlier ? (axis == 1 ? outlierOffset(noise_.attitude_rad) : 0.0) : noise_.attitude_rad * n();
      m.sigma_rad = noise_.attitude_rad;
      push(t_us, m, src, outlier);
    } else if (src == kSrcMarkers) {
      push(t_us, poseSample(t_us, x, outlier), src, outlier);
    }
  }

  PoseMeasurement poseSample(TimeUs t_us, const Truth& x, bool outlier) {
    PoseMeasurement m;
    m.t_us = t_us;
    Eigen::Vector3d dp = noise_.pose_m * gauss3(), dth = noise_.pose_rad * gauss3();
    if (outlier) {
      dp.setZero();
      dth.setZero();
      const int axis = randomAxis(6);
      if (axis < 3) dp(axis) = outlierOffset(noise_.pose_m);
      else dth(axis - 3) = outlierOffset(noise_.pose_rad);
    }
    m.p_robot_in_odom_m = x.p + dp;
    m.q_odom_robot = Eigen::Quaterniond(expSo3(dth) * x.R);
    m.cov_pose.setZero();
    m.cov_pose.diagonal() << Eigen::Vector3d::Constant(noise_.pose_m * noise_.pose_m),
        Eigen::Vector3d::Constant(noise_.pose_rad * noise_.pose_rad);
    return m;
  }

  void addVo() {
    if (o_.vo_hz <= 0.0) return;
    std::uint32_t id = 0;
    bool has_prev = false;
    Truth prev;
    int count = 0;
    for (double t = 0.25; t < o_.duration_s - 0.02; t += 1.0 / o_.vo_hz, ++id) {
      if (silent(kSrcVoOrb, t)) {  // tracking lost: the last keyframe is released
        if (has_prev) push(sToUs(t), CloneRelease{sToUs(t), id - 1}, kSrcCount);
        has_prev = false;
        continue;
      }
      const Truth x = traj_.at(t);
      push(sToUs(t), CloneRequest{sToUs(t), id}, kSrcCount);
      if (has_prev) {
        const bool outlier = o_.outlier_every > 0 && (++count % o_.outlier_every == 0);
        push(sToUs(t), relativeSample(sToUs(t), id - 1, prev, x, outlier), kSrcVoOrb, outlier);
      }
      prev = x;
      has_prev = true;
    }
  }

  RelativePoseMeasurement relativeSample(TimeUs t_us, std::uint32_t clone_id, const Truth& a, const Truth& b,
                                         bool outlier) {
    RelativePoseMeasurement m;
    m.t_us = t_us;
    m.clone_id = clone_id;
    m.release_clone = true;
    Eigen::Vector3d dp = noise_.vo_m * gauss3(), dth = noise_.vo_rad * gauss3();
    if (outlier) {
      dp.setZero();
      dth.setZero();
      const int axis = randomAxis(6);
      if (axis < 3) dp(axis) = outlierOffset(noise_.vo_m);
      else dth(axis - 3) = outlierOffset(noise_.vo_rad);
    }
    m.p_robotb_in_robota_m = a.R.transpose() * (b.p - a.p) + dp;
    m.q_robota_robotb = Eigen::Quaterniond(a.R.transpose() * b.R * expSo3(dth));
    m.cov.setZero();
    m.cov.diagonal() << Eigen::Vector3d::Constant(noise_.vo_m * noise_.vo_m),
        Eigen::Vector3d::Constant(noise_.vo_rad * noise_.vo_rad);
    return m;
  }

  void setArrivals() {
    const TimeUs dt_us = sToUs(1.0 / o_.imu_hz);
    std::uniform_real_distribution<double> delay(0.1, 1.0);
    for (Event& e : events_) {
      if (std::holds_alternative<ImuSample>(e.what)) {
        e.t_arrival_us = e.t_us;
      } else if (o_.max_delay_s <= 0.0) {
        e.t_arrival_us = (e.t_us + dt_us - 1) / dt_us * dt_us;  // the IMU epoch that covers it
      } else if (std::holds_alternative<CloneRequest>(e.what) || std::holds_alternative<CloneRelease>(e.what)) {
        e.t_arrival_us = e.t_us + sToUs(0.03);  // the image reaches the loop shortly after capture
      } else {
        e.t_arrival_us = e.t_us + sToUs(o_.max_delay_s * delay(rng_));
      }
    }
  }

  ScenarioOptions o_;
  EkfConfig c_;
  CircleTrajectory traj_;
  Noise noise_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
  std::vector<Event> events_;
  std::uint64_t seq_ = 0;
  Eigen::Vector3d bg0_ = Eigen::Vector3d::Zero(), ba0_ = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> bg_at_imu_;
};

FuseResult feed(Ekf& ekf, const Event& e) {
  if (const auto* m = std::get_if<ImuSample>(&e.what)) {
    ekf.setImu(*m);
    return {FuseStatus::kAccepted, 0.0};
  }
  if (const auto* m = std::get_if<DvlSample>(&e.what)) return ekf.fuseDvl(*m);
  if (const auto* m = std::get_if<DepthSample>(&e.what)) return ekf.fuseDepth(*m);
  if (const auto* m = std::get_if<HeadingSample>(&e.what)) return ekf.fuseHeading(*m);
  if (const auto* m = std::get_if<AttitudeSample>(&e.what)) return ekf.fuseAttitude(*m);
  if (const auto* m = std::get_if<PoseMeasurement>(&e.what)) return ekf.fusePose(*m);
  if (const auto* m = std::get_if<RelativePoseMeasurement>(&e.what)) return ekf.fuseRelativePose(*m);
  if (const auto* c = std::get_if<CloneRequest>(&e.what)) return ekf.clonePose(c->t_us, c->id);
  const auto* r = std::get_if<CloneRelease>(&e.what);
  return ekf.releaseClone(r->t_us, r->id);
}

EkfConfig scenarioConfig() {
  EkfConfig c;
  c.q_robot_dvl = quatFromRollPitchYaw(0.0, 0.0, std::numbers::pi / 4.0);  // a DVL turned 45 deg
  c.p_dvl_in_robot_m = Eigen::Vector3d(0.3, 0.0, -0.2);
  c.p_depth_in_robot_m = Eigen::Vector3d(-0.2, 0.1, 0.1);
  return c;
}

bool isImu(const Event& e) { return std::holds_alternative<ImuSample>(e.what); }

double poseNees(const Ekf& ekf, const Truth& x, bool position) {
  const FilterState& s = ekf.state();
  if (position) {
    const Eigen::Vector3d e = x.p - s.x.p_robot_in_odom_m;
    return e.dot(s.P.block<3, 3>(es::kP, es::kP).ldlt().solve(e));
  }
  const Eigen::Vector3d e = logSo3(x.R * s.x.q_odom_robot.toRotationMatrix().transpose());
  return e.dot(s.P.block<3, 3>(es::kTheta, es::kTheta).ldlt().solve(e));
}

struct RunResult {
  std::vector<FuseResult> results;  // one per event
  bool always_finite = true;
};

template <class OnImu>
RunResult run(Ekf& ekf, const std::vector<Event>& events, OnImu on_imu) {
  RunResult r;
  r.results.reserve(events.size());
  for (const Event& e : events) {
    r.results.push_back(feed(ekf, e));
    r.always_finite = r.always_finite && isFinite(ekf.solution());
    if (isImu(e)) on_imu(e);
  }
  return r;
}

// ---------------------------------------------------------------------------------------------------
// (a) consistency
// ---------------------------------------------------------------------------------------------------
TEST(EkfScenario, NeesOfPositionAndAttitudeInsideChiSquareBounds) {
  // GIVEN 24 Monte Carlo runs of 60 s with every aiding source, the initial error drawn from P0
  const EkfConfig config = scenarioConfig();
  constexpr double kLo = 0.2158, kHi = 9.3484;  // chi2_3 2.5 % and 97.5 % quantiles
  int inside_p = 0, inside_th = 0, epochs = 0, below_p = 0, above_p = 0;
  double sum_p = 0.0, sum_th = 0.0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    ScenarioOptions o;
    o.seed = seed;
    ScenarioGenerator gen(o, config);
    const std::vector<Event> events = gen.generate();
    Ekf ekf;
    ASSERT_TRUE(ekf.init(config, nullptr));
    ASSERT_TRUE(ekf.reset(0, gen.initialState()));
    // WHEN the filter runs, NEES sampled every 0.5 s
    const RunResult r = run(ekf, events, [&](const Event& e) {
      if (e.t_us % 500'000 != 0) return;
      const Truth x = gen.trajectory().at(usToS(e.t_us));
      const double np = poseNees(ekf, x, true), nt = poseNees(ekf, x, false);
      inside_p += (np >= kLo && np <= kHi);
      below_p += np < kLo;
      above_p += np > kHi;
      inside_th += (nt >= kLo && nt <= kHi);
      sum_p += np;
      sum_th += nt;
      ++epochs;
    });
    EXPECT_TRUE(r.always_finite);
    EXPECT_EQ(ekf.counters().numeric_resets, 0u);
  }

  // THEN at least 90 % of the epochs are inside the two-sided 95 % bounds
  const double frac_p = static_cast<double>(inside_p) / epochs, frac_th = static_cast<double>(inside_th) / epochs;
  RecordProperty("nees_position_mean", std::to_string(sum_p / epochs));
  RecordProperty("nees_attitude_mean", std::to_string(sum_th / epochs));
  EXPECT_GE(frac_p, 0.90) << "mean position NEES " << sum_p / epochs;
  EXPECT_GE(frac_th, 0.90) << "mean attitude NEES " << sum_th / epochs;
  std::printf("NEES: position %.1f %% inside (mean %.2f, %d below, %d above), attitude %.1f %% inside (mean %.2f), "
              "%d epochs\n", 100.0 * frac_p, sum_p / epochs, below_p, above_p, 100.0 * frac_th, sum_th / epochs, epochs);
}

// ---------------------------------------------------------------------------------------------------
// (b) sensor stop and resume
// ---------------------------------------------------------------------------------------------------
struct OutageCase {
  NavSource src;
  double hz;
  double (*variance)(const FilterState&);  // the uncertainty this source bounds
};

double velVar(const FilterState& s) { return s.P.block<3, 3>(es::kV, es::kV).trace(); }
double zVar(const FilterState& s) { return s.P(es::kP + 2, es::kP + 2); }
double yawVar(const FilterState& s) { return s.P(es::kTheta + 2, es::kTheta + 2); }
double tiltVar(const FilterState& s) { return s.P(es::kTheta, es::kTheta) + s.P(es::kTheta + 1, es::kTheta + 1); }
double xyVar(const FilterState& s) { return s.P(es::kP, es::kP) + s.P(es::kP + 1, es::kP + 1); }

TEST(EkfScenario, EachSourceGoesStaleWithinThreePeriodsAndRefusesCleanly) {
  const OutageCase cases[] = {{kSrcDvl, 5.0, velVar},     {kSrcDepth, 5.0, zVar},     {kSrcHeading, 5.0, yawVar},
                              {kSrcAttitude, 5.0, tiltVar}, {kSrcMarkers, 1.0, xyVar}, {kSrcVoOrb, 2.0, xyVar}};
  constexpr double kStart = 20.0, kEnd = 30.0;
  for (const OutageCase& oc : cases) {
    SCOPED_TRACE(testing::Message() << "source " << static_cast<int>(oc.src));
    // GIVEN timeouts of 2.5 sample periods and a 10 s outage of one source. In the VO case the markers are
    // off (VO is then the only horizontal aid); in the AHRS case DVL, markers and VO are off: with them,
    // roll and pitch stay observable through gravity and the velocity aiding, and their variance would
    // not grow without the AHRS at all (checked: it keeps shrinking).
    EkfConfig config = scenarioConfig();
    const TimeUs timeout = sToUs(2.5 / oc.hz);
    config.timeout_dvl_us = config.timeout_depth_us = config.timeout_heading_us = config.timeout_attitude_us =
        sToUs(2.5 / 5.0);
    config.timeout_markers_us = sToUs(2.5 / 1.0);
    config.timeout_vo_us = sToUs(2.5 / 2.0);
    ScenarioOptions o;
    o.seed = 40 + static_cast<std::uint64_t>(oc.src);
    o.duration_s = 36.0;
    o.outage_source = oc.src;
    o.outage_start_s = kStart;
    o.outage_end_s = kEnd;
    if (oc.src == kSrcVoOrb) o.pose_hz = 0.0;
    if (oc.src == kSrcAttitude) o.dvl_hz = o.pose_hz = o.vo_hz = 0.0;
    ScenarioGenerator gen(o, config);
    const std::vector<Event> events = gen.generate();
    TimeUs last_before = 0;
    for (const Event& e : events) {
      if (e.source == oc.src && e.t_us < sToUs(kStart)) last_before = std::max(last_before, e.t_us);
    }
    Ekf ekf;
    ASSERT_TRUE(ekf.init(config, nullptr));
    ASSERT_TRUE(ekf.reset(0, gen.initialState()));
    // WHEN it runs
    TimeUs first_stale = -1, last_stale = -1;
    bool stale_before = false;
    double var_before = 0.0, var_end = 0.0;
    const RunResult r = run(ekf, events, [&](const Event& e) {
      const bool stale = (ekf.solution().faults & staleBit(oc.src)) != 0;
      if (e.t_us > sToUs(5.0) && e.t_us < sToUs(kStart)) stale_before = stale_before || stale;
      if (stale && first_stale < 0 && e.t_us >= sToUs(kStart)) first_stale = e.t_us;
      if (stale) last_stale = e.t_us;
      if (e.t_us == sToUs(kStart)) var_before = oc.variance(ekf.state());
      if (e.t_us == sToUs(kEnd)) var_end = oc.variance(ekf.state());
    });
    // THEN the stale flag rises within 3 periods of the last sample, the covariance grows meanwhile,
    EXPECT_FALSE(stale_before);
    ASSERT_GE(first_stale, 0);
    EXPECT_LE(first_stale - last_before, sToUs(3.0 / oc.hz));
    EXPECT_GE(first_stale - last_before, timeout);
    EXPECT_GT(var_end, var_before);
    // AND after the outage the flag clears within one period (two for VO: a pair of images is needed),
    // the first samples are fused and the gate rejects no more than its nominal false-alarm share
    EXPECT_LE(last_stale, sToUs(kEnd + (oc.src == kSrcVoOrb ? 2.0 : 1.0) / oc.hz));
    int resumed = 0, accepted = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
      if (events[i].source != oc.src || events[i].t_us < sToUs(kEnd)) continue;
      ++resumed;
      accepted += r.results[i].status == FuseStatus::kAccepted;
      if (resumed <= 2) {
        EXPECT_EQ(r.results[i].status, FuseStatus::kAccepted) << "t " << events[i].t_us;
      }
    }
    EXPECT_GE(resumed, 5);
    EXPECT_GE(accepted, 0.9 * resumed);
    EXPECT_EQ(ekf.counters().numeric_resets, 0u);
    EXPECT_TRUE(r.always_finite);
  }
}

// ---------------------------------------------------------------------------------------------------
// (c) outliers
// ---------------------------------------------------------------------------------------------------
TEST(EkfScenario, OutliersOfFiveToFiftySigmaAreAllRejected) {
  // GIVEN every 5th sample of each aiding source off by 5..50 sigma on one axis
  const EkfConfig config = scenarioConfig();
  ScenarioOptions o;
  o.seed = 7;
  o.outlier_every = 5;
  ScenarioGenerator gen(o, config);
  const std::vector<Event> events = gen.generate();
  Ekf ekf;
  ASSERT_TRUE(ekf.init(config, nullptr));
  ASSERT_TRUE(ekf.reset(0, gen.initialState()));
  // WHEN the filter runs
  bool reject_flag_seen = false;
  const RunResult r = run(ekf, events, [&](const Event&) {
    reject_flag_seen = reject_flag_seen || (ekf.solution().faults & rejectBit(kSrcDvl)) != 0;
  });
  // THEN no outlier is accepted, the good samples are (nearly all) accepted, the estimate stays close
  int outliers = 0, false_accepts = 0, good = 0, good_accepted = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (events[i].source == kSrcImu || events[i].source == kSrcCount) continue;
    if (events[i].outlier) {
      ++outliers;
      false_accepts += r.results[i].status != FuseStatus::kRejected;
    } else {
      ++good;
      good_accepted += r.results[i].status == FuseStatus::kAccepted;
    }
  }
  EXPECT_GT(outliers, 100);
  EXPECT_EQ(false_accepts, 0);
  EXPECT_GE(good_accepted, 0.97 * good);
  EXPECT_TRUE(reject_flag_seen);
  const Truth x = gen.trajectory().at(usToS(ekf.state().t_us));
  EXPECT_LT((x.p - ekf.state().x.p_robot_in_odom_m).norm(), 0.2);
  EXPECT_GE(ekf.solution().rejected_total, static_cast<std::uint32_t>(outliers));
  EXPECT_TRUE(r.always_finite);
}

// ---------------------------------------------------------------------------------------------------
// (d) delayed fusion
// ---------------------------------------------------------------------------------------------------
TEST(EkfScenario, DelayedFusionEqualsInOrderOracle) {
  // GIVEN the same samples fused in capture order (oracle) and delivered up to 450 ms late, in random
  // order, including clone requests and VO relative poses
  const EkfConfig config = scenarioConfig();
  ScenarioOptions o;
  o.seed = 11;
  o.duration_s = 30.0;
  o.measurement_end_s = 29.0;
  ScenarioGenerator gen_oracle(o, config);
  const std::vector<Event> in_order = gen_oracle.generate();
  const EkfInitialState x0 = gen_oracle.initialState();
  o.max_delay_s = 0.45;
  ScenarioGenerator gen_late(o, config);
  const std::vector<Event> late = gen_late.generate();
  Ekf oracle, delayed;
  ASSERT_TRUE(oracle.init(config, nullptr));
  ASSERT_TRUE(delayed.init(config, nullptr));
  ASSERT_TRUE(oracle.reset(0, x0));
  ASSERT_TRUE(delayed.reset(0, x0));
  // WHEN both run to the end
  run(oracle, in_order, [](const Event&) {});
  const RunResult r = run(delayed, late, [](const Event&) {});
  // THEN the delayed filter replayed, dropped nothing, and ends within 1e-6 of the oracle
  EXPECT_GT(delayed.counters().replays, 100u);
  EXPECT_EQ(delayed.solution().dropped_late_total, 0u);
  const FilterState& a = oracle.state();
  const FilterState& b = delayed.state();
  ASSERT_EQ(a.t_us, b.t_us);
  ASSERT_EQ(a.n_clones, b.n_clones);
  EXPECT_LT((a.x.p_robot_in_odom_m - b.x.p_robot_in_odom_m).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((a.x.v_robot_in_odom_mps - b.x.v_robot_in_odom_mps).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(a.x.q_odom_robot.angularDistance(b.x.q_odom_robot), 1e-6);
  EXPECT_LT((a.x.b_gyro_radps - b.x.b_gyro_radps).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((a.x.b_accel_mps2 - b.x.b_accel_mps2).cwiseAbs().maxCoeff(), 1e-6);
  const int n = a.dim();
  EXPECT_LT((a.P.topLeftCorner(n, n) - b.P.topLeftCorner(n, n)).cwiseAbs().maxCoeff(), 1e-9);
  std::printf("delayed vs oracle: |dp| %.3g m, |dv| %.3g m/s, %u replays\n",
              (a.x.p_robot_in_odom_m - b.x.p_robot_in_odom_m).norm(),
              (a.x.v_robot_in_odom_mps - b.x.v_robot_in_odom_mps).norm(), delayed.counters().replays);
  for (NavSource src : {kSrcDvl, kSrcDepth, kSrcHeading, kSrcAttitude, kSrcMarkers, kSrcVoOrb}) {
    EXPECT_EQ(oracle.health(src).counters.accepted, delayed.health(src).counters.accepted) << src;
    EXPECT_EQ(oracle.health(src).counters.rejected, delayed.health(src).counters.rejected) << src;
  }
  EXPECT_TRUE(r.always_finite);
}

TEST(EkfScenario, MeasurementOlderThanTheWindowIsDroppedAndCounted) {
  // GIVEN a filter 2 s into a run
  const EkfConfig config = scenarioConfig();
  ScenarioOptions o;
  o.duration_s = 2.0;
  ScenarioGenerator gen(o, config);
  const std::vector<Event> events = gen.generate();
  Ekf ekf;
  ASSERT_TRUE(ekf.init(config, nullptr));
  ASSERT_TRUE(ekf.reset(0, gen.initialState()));
  run(ekf, events, [](const Event&) {});
  const TimeUs now = ekf.state().t_us;
  DepthSample d;
  d.depth_m = 10.0;
  // WHEN a depth sample 501 ms old arrives THEN it is dropped and counted; 499 ms old is fused
  d.t_us = now - 501'000;
  EXPECT_EQ(ekf.fuseDepth(d).status, FuseStatus::kDroppedLate);
  EXPECT_EQ(ekf.health(kSrcDepth).counters.dropped_late, 1u);
  d.t_us = now - 499'000;
  EXPECT_EQ(ekf.fuseDepth(d).status, FuseStatus::kAccepted);
  EXPECT_EQ(ekf.solution().dropped_late_total, 1u);
  // AND one newer than the last IMU sample is queued until the IMU reaches it
  d.t_us = now + 5'000;
  EXPECT_EQ(ekf.fuseDepth(d).status, FuseStatus::kQueued);
  const std::uint32_t accepted = ekf.health(kSrcDepth).counters.accepted;
  ImuSample imu = std::get<ImuSample>(events.back().what);
  imu.t_us = now + 10'000;
  ekf.setImu(imu);
  EXPECT_EQ(ekf.health(kSrcDepth).counters.accepted, accepted + 1);
}

// ---------------------------------------------------------------------------------------------------
// (e) bad input
// ---------------------------------------------------------------------------------------------------
TEST(EkfScenario, NanInfAndNegativeVariancesAreRefusedAndOutputStaysFinite) {
  // GIVEN a normal run with a volley of malformed samples every 0.5 s
  const EkfConfig config = scenarioConfig();
  ScenarioOptions o;
  o.seed = 5;
  o.duration_s = 20.0;
  ScenarioGenerator gen(o, config);
  const std::vector<Event> events = gen.generate();
  Ekf ekf;
  ASSERT_TRUE(ekf.init(config, nullptr));
  ASSERT_TRUE(ekf.reset(0, gen.initialState()));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  int volleys = 0;
  bool all_refused = true, huge_rejected = true;
  // WHEN they are fed between the good samples
  const RunResult r = run(ekf, events, [&](const Event& e) {
    if (e.t_us % 500'000 != 0) return;
    ++volleys;
    const TimeUs t = e.t_us;
    const auto refused = [&](FuseResult res) { all_refused = all_refused && res.status == FuseStatus::kBadInput; };
    ImuSample imu;
    imu.t_us = t + 1;
    imu.f_imu_mps2.x() = nan;
    ekf.setImu(imu);
    imu.f_imu_mps2 = Eigen::Vector3d(0.0, 0.0, 1e9);
    ekf.setImu(imu);
    DvlSample dvl;
    dvl.t_us = t;
    dvl.valid = true;
    dvl.v_dvl_mps.y() = inf;
    refused(ekf.fuseDvl(dvl));
    dvl.v_dvl_mps.setZero();
    dvl.cov_v_dvl_mps2.diagonal() << 1e-4, -1e-4, 1e-4;
    refused(ekf.fuseDvl(dvl));
    dvl.cov_v_dvl_mps2.setZero();
    dvl.valid = false;
    refused(ekf.fuseDvl(dvl));
    DepthSample depth;
    depth.t_us = t;
    depth.depth_m = nan;
    refused(ekf.fuseDepth(depth));
    depth.depth_m = 10.0;
    depth.sigma_m = -0.1;
    refused(ekf.fuseDepth(depth));
    HeadingSample heading;
    heading.t_us = t;
    heading.heading_rad = inf;
    refused(ekf.fuseHeading(heading));
    AttitudeSample att;
    att.t_us = t;
    att.sigma_rad = nan;
    refused(ekf.fuseAttitude(att));
    PoseMeasurement pose;
    pose.t_us = t;
    pose.cov_pose(4, 4) = -1.0;
    refused(ekf.fusePose(pose));
    pose.cov_pose(4, 4) = 1.0;
    pose.q_odom_robot.coeffs() << nan, 0.0, 0.0, 1.0;
    refused(ekf.fusePose(pose));
    RelativePoseMeasurement rel;
    rel.t_us = t;
    rel.cov(0, 0) = inf;
    refused(ekf.fuseRelativePose(rel));
    // A finite but absurd pose is not bad input: the gate rejects it.
    pose.q_odom_robot.setIdentity();
    pose.p_robot_in_odom_m = Eigen::Vector3d::Constant(1e200);
    huge_rejected = huge_rejected && ekf.fusePose(pose).status == FuseStatus::kRejected;
  });
  // THEN every malformed sample is refused and counted, and nothing non-finite ever comes out
  EXPECT_TRUE(all_refused);
  EXPECT_TRUE(huge_rejected);
  EXPECT_TRUE(r.always_finite);
  EXPECT_EQ(ekf.health(kSrcImu).counters.bad_input, static_cast<std::uint32_t>(2 * volleys));
  EXPECT_EQ(ekf.health(kSrcDvl).counters.bad_input, static_cast<std::uint32_t>(3 * volleys));
  EXPECT_EQ(ekf.health(kSrcDepth).counters.bad_input, static_cast<std::uint32_t>(2 * volleys));
  EXPECT_EQ(ekf.health(kSrcHeading).counters.bad_input, static_cast<std::uint32_t>(volleys));
  EXPECT_EQ(ekf.health(kSrcAttitude).counters.bad_input, static_cast<std::uint32_t>(volleys));
  EXPECT_EQ(ekf.health(kSrcMarkers).counters.bad_input, static_cast<std::uint32_t>(2 * volleys));
  EXPECT_EQ(ekf.health(kSrcVoOrb).counters.bad_input, static_cast<std::uint32_t>(volleys));
  EXPECT_EQ(ekf.counters().numeric_resets, 0u);
  const Truth x = gen.trajectory().at(usToS(ekf.state().t_us));
  EXPECT_LT((x.p - ekf.state().x.p_robot_in_odom_m).norm(), 0.2);
}

}  // namespace
}  // namespace deepnav
