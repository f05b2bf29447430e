#include "tools/sim/sensor_simulator.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "sim_test_events.h"
#include "tools/sim/rotation.h"

namespace deepnav::sim {
namespace {

using test::bitEqual;
using test::ofStream;
using test::runAll;

Scenario shortScenario(double duration_s) {
  Scenario s;
  s.duration_s = duration_s;
  return s;
}

TEST(SimSensorSimulator, StreamIsTimeOrderedWithEveryRate) {
  const std::vector<SimEvent> events = runAll(Scenario{}, 1);
  for (std::size_t i = 1; i < events.size(); ++i) ASSERT_LE(events[i - 1].t_us, events[i].t_us) << i;
  // 120 s, both ends included.
  EXPECT_EQ(ofStream(events, SimStream::kGroundTruth).size(), 12001u);
  EXPECT_EQ(ofStream(events, SimStream::kImu).size(), 12001u);
  EXPECT_EQ(ofStream(events, SimStream::kDvl).size(), 601u);
  EXPECT_EQ(ofStream(events, SimStream::kCompass).size(), 1201u);
  EXPECT_EQ(ofStream(events, SimStream::kAttitude).size(), 1201u);
  EXPECT_EQ(ofStream(events, SimStream::kDepth).size(), 1201u);
  EXPECT_EQ(ofStream(events, SimStream::kCamera).size(), 1201u);
  for (const SimEvent& e : events) {
    ASSERT_EQ(e.sample.index(), static_cast<std::size_t>(e.stream));
    ASSERT_EQ(e.t_us, std::visit([](const auto& s) { return s.t_us; }, e.sample));
  }
  // Ground truth comes first at a shared instant.
  EXPECT_EQ(events[0].stream, SimStream::kGroundTruth);
  EXPECT_EQ(events[1].stream, SimStream::kImu);
}

TEST(SimSensorSimulator, SameSeedIsBitEqualAndOtherSeedsDiffer) {
  const Scenario scenario = shortScenario(20.0);
  const std::vector<SimEvent> a = runAll(scenario, 77), b = runAll(scenario, 77), c = runAll(scenario, 78);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(bitEqual(a[i], b[i])) << i;
  ASSERT_EQ(a.size(), c.size());
  int differing_sensor_samples = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].stream, c[i].stream);
    if (a[i].stream == SimStream::kCamera) {
      EXPECT_TRUE(bitEqual(a[i], c[i]));  // the true camera poses do not depend on the seed
    } else if (a[i].stream != SimStream::kGroundTruth && !bitEqual(a[i], c[i])) {
      ++differing_sensor_samples;
    }
  }
  EXPECT_EQ(differing_sensor_samples, 2001 + 101 + 201 * 3);  // every noisy sample differs
}

TEST(SimSensorSimulator, SensorsDrawFromIndependentSubStreams) {
  // Switching the compass off leaves the IMU noise untouched.
  Scenario scenario = shortScenario(5.0);
  const std::vector<SimEvent> with = ofStream(runAll(scenario, 3), SimStream::kImu);
  scenario.compass.enabled = false;
  const std::vector<SimEvent> without = ofStream(runAll(scenario, 3), SimStream::kImu);
  ASSERT_EQ(with.size(), without.size());
  for (std::size_t i = 0; i < with.size(); ++i) ASSERT_TRUE(bitEqual(with[i], without[i]));
}

TEST(SimSensorSimulator, GroundTruthMatchesTheTrajectory) {
  SensorSimulator sim;
  std::string error;
  ASSERT_TRUE(sim.init(shortScenario(3.0), 5, &error)) << error;
  SimEvent e;
  while (sim.next(&e)) {
    if (e.stream != SimStream::kGroundTruth) continue;
    const auto& g = std::get<GroundTruthSample>(e.sample);
    const KinematicState s = sim.truthAt(e.t_us);
    ASSERT_EQ(g.p_robot_in_odom_m, s.p_robot_in_odom_m);
    ASSERT_EQ(g.w_robot_radps, s.w_robot_radps);
  }
}

// Integrates body rate and specific force with RK4 over pairs of IMU periods (the middle sample is the
// half step), from the true initial state.
TEST(SimSensorSimulator, PerfectImuIntegratesBackToTheTrajectory) {
  Scenario scenario;
  scenario.imu.gyro_noise_deg_per_sqrt_h = 0.0;
  scenario.imu.gyro_bias_rw_deg_per_h_per_sqrt_h = 0.0;
  scenario.imu.gyro_initial_bias_deg_per_h = 0.0;
  scenario.imu.accel_noise_mps_per_sqrt_h = 0.0;
  scenario.imu.accel_bias_rw_mps2_per_sqrt_h = 0.0;
  scenario.imu.accel_initial_bias_mps2 = 0.0;
  SensorSimulator sim;
  std::string error;
  ASSERT_TRUE(sim.init(scenario, 1, &error)) << error;
  std::vector<ImuSample> imu;
  SimEvent e;
  while (sim.next(&e))
    if (e.stream == SimStream::kImu) imu.push_back(std::get<ImuSample>(e.sample));
  ASSERT_EQ(imu.size(), 12001u);

  struct State {
    Eigen::Quaterniond q;
    Eigen::Vector3d v, p;
  };
  struct Derivative {
    Eigen::Vector4d dq;  // coefficients (x, y, z, w)
    Eigen::Vector3d dv, dp;
  };
  const Eigen::Vector3d g(0.0, 0.0, -scenario.environment.gravity_mps2);
  auto derivative = [&](const State& x, const ImuSample& m) {
    const Eigen::Quaterniond w(0.0, m.w_imu_radps.x(), m.w_imu_radps.y(), m.w_imu_radps.z());
    return Derivative{0.5 * (x.q * w).coeffs(), x.q * m.f_imu_mps2 + g, x.v};
  };
  auto step = [](const State& x, const Derivative& d, double h) {
    State y;
    y.q.coeffs() = x.q.coeffs() + h * d.dq;
    y.v = x.v + h * d.dv;
    y.p = x.p + h * d.dp;
    return y;
  };
  const KinematicState start = sim.truthAt(0);
  State x{start.q_odom_robot, start.v_robot_in_odom_mps, start.p_robot_in_odom_m};
  const double h = 0.02;
  for (std::size_t k = 0; k + 2 < imu.size(); k += 2) {
    const Derivative k1 = derivative(x, imu[k]);
    const Derivative k2 = derivative(step(x, k1, h / 2), imu[k + 1]);
    const Derivative k3 = derivative(step(x, k2, h / 2), imu[k + 1]);
    const Derivative k4 = derivative(step(x, k3, h), imu[k + 2]);
    x.q.coeffs() += h / 6.0 * (k1.dq + 2 * k2.dq + 2 * k3.dq + k4.dq);
    x.q.normalize();
    x.v += h / 6.0 * (k1.dv + 2 * k2.dv + 2 * k3.dv + k4.dv);
    x.p += h / 6.0 * (k1.dp + 2 * k2.dp + 2 * k3.dp + k4.dp);
  }
  const KinematicState end = sim.truthAt(imu.back().t_us);
  EXPECT_LT((x.p - end.p_robot_in_odom_m).norm(), 0.03);
  EXPECT_LT((x.v - end.v_robot_in_odom_mps).norm(), 0.001);
  EXPECT_LT(x.q.angularDistance(end.q_odom_robot), 1e-5);
  std::cout << "RK4 dead reckoning error after 120 s: " << (x.p - end.p_robot_in_odom_m).norm() * 1e3 << " mm\n";
}

TEST(SimSensorSimulator, DvlDropsOutWhenTheAltitudeLeavesItsWindow) {
  // GIVEN a DVL 0.3 m below the robot origin that locks only above 1.5 m: the dive starts with the DVL
  // 1.7 m above the seabed, then circles with it at 1.2 m
  Scenario scenario;
  scenario.dvl.min_altitude_m = 1.5;
  const std::vector<SimEvent> dvl = ofStream(runAll(scenario, 2), SimStream::kDvl);
  int valid_early = 0, valid_late = 0;
  for (const SimEvent& e : dvl) {
    const auto& d = std::get<DvlSample>(e.sample);
    if (e.t_us < sToUs(4.0) && d.valid) ++valid_early;
    if (e.t_us > sToUs(40.0) && d.valid) ++valid_late;
  }
  EXPECT_EQ(valid_early, 20);  // 0 .. 3.8 s at 5 Hz
  EXPECT_EQ(valid_late, 0);
  EXPECT_EQ(dvl.size(), 601u);  // an invalid ensemble is still reported, flagged
}

TEST(SimSensorSimulator, CameraTicksSeeThePanel) {
  SensorSimulator sim;
  std::string error;
  ASSERT_TRUE(sim.init(Scenario{}, 1, &error)) << error;
  const CameraConfig& cam = sim.scenario().camera;
  SimEvent e;
  std::uint32_t expected_index = 0;
  while (sim.next(&e)) {
    if (e.stream != SimStream::kCamera) continue;
    const auto& tick = std::get<CameraTick>(e.sample);
    EXPECT_EQ(tick.frame_index, expected_index++);
    if (e.t_us < sToUs(30.0)) continue;  // circling: the panel centre (0.75 m up) is in both images
    for (const auto& [p, q] : {std::pair{tick.p_left_cam_in_odom_m, tick.q_odom_left_cam},
                               std::pair{tick.p_right_cam_in_odom_m, tick.q_odom_right_cam}}) {
      const Eigen::Vector3d c = q.conjugate() * (Eigen::Vector3d(0.0, 0.0, 0.75) - p);
      ASSERT_GT(c.z(), 1.5);
      const double u = cam.fx_px * c.x() / c.z() + cam.cx_px, v = cam.fy_px * c.y() / c.z() + cam.cy_px;
      EXPECT_GT(u, 0.0);
      EXPECT_LT(u, cam.width_px);
      EXPECT_GT(v, 0.0);
      EXPECT_LT(v, cam.height_px);
    }
  }
  EXPECT_EQ(expected_index, 1201u);
}

TEST(SimSensorSimulator, RefusesABadScenario) {
  Scenario scenario;
  scenario.dvl.min_altitude_m = 100.0;
  SensorSimulator sim;
  std::string error;
  EXPECT_FALSE(sim.init(scenario, 1, &error));
  EXPECT_NE(error.find("dvl"), std::string::npos) << error;
  SimEvent e;
  EXPECT_FALSE(sim.next(&e));
}

}  // namespace
}  // namespace deepnav::sim
