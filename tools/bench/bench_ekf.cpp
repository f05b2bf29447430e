// EKF timing: IMU propagation (target <= 5 us), each measurement update (<= 20 us), and a delayed
// update that rewinds and re-propagates 50 IMU samples. Arg = number of stochastic clones in the state.
#include <memory>

#include <benchmark/benchmark.h>

#include "nav/ekf/attitude_updater.h"
#include "nav/ekf/covariance_guard.h"
#include "nav/ekf/depth_updater.h"
#include "nav/ekf/dvl_updater.h"
#include "nav/ekf/ekf.h"
#include "nav/ekf/heading_updater.h"
#include "nav/ekf/measurement_update.h"
#include "nav/ekf/pose_updater.h"
#include "nav/ekf/relative_pose_updater.h"

namespace deepnav {
namespace {

constexpr TimeUs kImuPeriodUs = 10'000;  // 100 Hz

ImuSample imuAt(TimeUs t_us) {
  ImuSample s;
  s.t_us = t_us;
  s.w_imu_radps = Eigen::Vector3d(0.01, -0.02, 0.05);
  s.f_imu_mps2 = Eigen::Vector3d(0.01, -0.02, 9.80665);
  return s;
}

// A filter after 1 s of IMU at 100 Hz (history full up to the 500 ms window), with n clones.
std::unique_ptr<Ekf> steadyFilter(int clones) {
  auto ekf = std::make_unique<Ekf>();
  if (!ekf->init(EkfConfig{}, nullptr)) return nullptr;
  EkfInitialState init;
  init.x.p_robot_in_odom_m = Eigen::Vector3d(1.0, 2.0, -10.0);
  ekf->reset(0, init);
  TimeUs t = 0;
  for (int k = 0; k < 100; ++k) ekf->setImu(imuAt(t += kImuPeriodUs));
  for (int c = 0; c < clones; ++c) {
    ekf->clonePose(t, static_cast<std::uint32_t>(c));
    ekf->setImu(imuAt(t += kImuPeriodUs));
  }
  for (int k = 0; k < 60; ++k) ekf->setImu(imuAt(t += kImuPeriodUs));
  return ekf;
}

void BM_ImuPropagation(benchmark::State& st) {
  auto ekf = steadyFilter(static_cast<int>(st.range(0)));
  TimeUs t = ekf->state().t_us;
  for (auto _ : st) {
    ekf->setImu(imuAt(t += kImuPeriodUs));  // propagation + covariance + snapshot + window trim
  }
  benchmark::DoNotOptimize(ekf->state().x.p_robot_in_odom_m);
}
BENCHMARK(BM_ImuPropagation)->Arg(0)->Arg(4);

// One updater on a state at rest: linearise, gate, Joseph update, inject, condition P (what
// Ekf::applyMeasurement does), with the measurement equal to the prediction so that it is accepted.
template <class Linearize>
void benchUpdate(benchmark::State& st, Linearize linearize) {
  auto ekf = steadyFilter(static_cast<int>(st.range(0)));
  FilterState s;
  copyFilterState(ekf->state(), &s);
  const GateThresholds gate = makeGateThresholds(3.0);
  const VarianceBounds bounds = varianceBoundsFrom(ekf->config());
  Linearization lin;
  for (auto _ : st) {
    linearize(s, &lin);
    const UpdateOutcome r = gateAndUpdate(lin, gate, &s);
    conditionCovariance(bounds, &s);
    benchmark::DoNotOptimize(r);
  }
}

void BM_UpdateDvl(benchmark::State& st) {
  const EkfConfig c;
  benchUpdate(st, [&](const FilterState& s, Linearization* l) {
    DvlSample m;
    m.valid = true;
    m.v_dvl_mps = s.x.q_odom_robot.conjugate() * s.x.v_robot_in_odom_mps;
    return linearizeDvl(s, m, c, l);
  });
}
BENCHMARK(BM_UpdateDvl)->Arg(0)->Arg(4);

void BM_UpdateDepth(benchmark::State& st) {
  const EkfConfig c;
  benchUpdate(st, [&](const FilterState& s, Linearization* l) {
    DepthSample m;
    m.depth_m = -s.x.p_robot_in_odom_m.z();
    return linearizeDepth(s, m, c, l);
  });
}
BENCHMARK(BM_UpdateDepth)->Arg(0)->Arg(4);

void BM_UpdateHeading(benchmark::State& st) {
  const EkfConfig c;
  benchUpdate(st, [&](const FilterState& s, Linearization* l) {
    const Eigen::Matrix3d R = s.x.q_odom_robot.toRotationMatrix();
    HeadingSample m;
    m.heading_rad = 1.5707963267948966 - std::atan2(R(1, 0), R(0, 0));
    return linearizeHeading(s, m, c, l);
  });
}
BENCHMARK(BM_UpdateHeading)->Arg(0)->Arg(4);

void BM_UpdateAttitude(benchmark::State& st) {
  const EkfConfig c;
  benchUpdate(st, [&](const FilterState& s, Linearization* l) {
    const Eigen::Matrix3d R = s.x.q_odom_robot.toRotationMatrix();
    AttitudeSample m;
    m.roll_rad = std::atan2(R(2, 1), R(2, 2));
    m.pitch_rad = -std::asin(R(2, 0));
    return linearizeAttitude(s, m, c, l);
  });
}
BENCHMARK(BM_UpdateAttitude)->Arg(0)->Arg(4);

void BM_UpdatePose(benchmark::State& st) {
  benchUpdate(st, [&](const FilterState& s, Linearization* l) {
    PoseMeasurement m;
    m.p_robot_in_odom_m = s.x.p_robot_in_odom_m;
    m.q_odom_robot = s.x.q_odom_robot;
    m.cov_pose = 1e-3 * Eigen::Matrix<double, 6, 6>::Identity();
    return linearizePose(s, m, l);
  });
}
BENCHMARK(BM_UpdatePose)->Arg(0)->Arg(4);

void BM_UpdateRelativePose(benchmark::State& st) {
  benchUpdate(st, [&](const FilterState& s, Linearization* l) {
    const PoseClone& a = s.clones[0];
    RelativePoseMeasurement m;
    m.clone_id = a.id;
    m.q_robota_robotb = a.q_odom_robot.conjugate() * s.x.q_odom_robot;
    m.p_robotb_in_robota_m = a.q_odom_robot.conjugate() * (s.x.p_robot_in_odom_m - a.p_robot_in_odom_m);
    m.cov = 1e-4 * Eigen::Matrix<double, 6, 6>::Identity();
    return linearizeRelativePose(s, m, l);
  });
}
BENCHMARK(BM_UpdateRelativePose)->Arg(1)->Arg(4);

// Through the Ekf API, in order: one IMU step plus a DVL sample captured inside that step (the filter
// rewinds one epoch to fuse it at its time). Compare with BM_ImuPropagation for the fusion share.
void BM_EkfImuStepWithDvl(benchmark::State& st) {
  auto ekf = steadyFilter(static_cast<int>(st.range(0)));
  TimeUs t = ekf->state().t_us;
  DvlSample m;
  m.valid = true;
  for (auto _ : st) {
    ekf->setImu(imuAt(t += kImuPeriodUs));
    m.t_us = t - kImuPeriodUs / 2;
    m.v_dvl_mps = ekf->state().x.q_odom_robot.conjugate() * ekf->state().x.v_robot_in_odom_mps;
    benchmark::DoNotOptimize(ekf->fuseDvl(m));
  }
}
BENCHMARK(BM_EkfImuStepWithDvl)->Arg(0)->Arg(4);

// A depth sample 495 ms late: rewind to the epoch before it, fuse, re-propagate the 50 buffered IMU
// samples (no other measurement in the window). Timed: the fuseDepth call only.
void BM_DelayedUpdateReplay50Imu(benchmark::State& st) {
  auto ekf = steadyFilter(static_cast<int>(st.range(0)));
  TimeUs t = ekf->state().t_us;
  DepthSample m;
  for (auto _ : st) {
    st.PauseTiming();
    for (int k = 0; k < 60; ++k) ekf->setImu(imuAt(t += kImuPeriodUs));  // the last sample leaves the window
    m.t_us = t - 50 * kImuPeriodUs + kImuPeriodUs / 2;
    m.depth_m = -ekf->state().x.p_robot_in_odom_m.z();
    st.ResumeTiming();
    benchmark::DoNotOptimize(ekf->fuseDepth(m));
  }
}
BENCHMARK(BM_DelayedUpdateReplay50Imu)->Arg(0)->Arg(4);

}  // namespace
}  // namespace deepnav

BENCHMARK_MAIN();
