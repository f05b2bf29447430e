#pragma once
// Helpers to run the simulator and compare streams bit for bit (test code).
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tools/sim/sensor_simulator.h"

namespace deepnav::sim::test {

// Every number of an event, in a fixed order.
inline std::vector<double> flatten(const SimEvent& e) {
  std::vector<double> x{static_cast<double>(e.t_us), static_cast<double>(e.stream)};
  auto add = [&x](const auto& m) {
    for (int i = 0; i < m.size(); ++i) x.push_back(m.data()[i]);
  };
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        x.push_back(static_cast<double>(s.t_us));
        if constexpr (std::is_same_v<T, GroundTruthSample>) {
          add(s.p_robot_in_odom_m), add(s.q_odom_robot.coeffs()), add(s.v_robot_in_odom_mps);
          add(s.w_robot_radps), add(s.gyro_bias_radps), add(s.accel_bias_mps2);
        } else if constexpr (std::is_same_v<T, ImuSample>) {
          add(s.w_imu_radps), add(s.f_imu_mps2);
        } else if constexpr (std::is_same_v<T, DvlSample>) {
          add(s.v_dvl_mps), add(s.cov_v_dvl_mps2);
          for (double r : s.beam_range_m) x.push_back(r);
          x.insert(x.end(), {double(s.beam_valid_mask), double(s.valid), s.fom_mps, s.altitude_m});
        } else if constexpr (std::is_same_v<T, HeadingSample>) {
          x.insert(x.end(), {s.heading_rad, double(s.is_true), s.sigma_rad});
        } else if constexpr (std::is_same_v<T, AttitudeSample>) {
          x.insert(x.end(), {s.roll_rad, s.pitch_rad, s.sigma_rad});
        } else if constexpr (std::is_same_v<T, DepthSample>) {
          x.insert(x.end(), {s.pressure_pa, s.depth_m, s.sigma_m});
        } else if constexpr (std::is_same_v<T, CameraTick>) {
          x.push_back(double(s.frame_index));
          add(s.p_left_cam_in_odom_m), add(s.q_odom_left_cam.coeffs());
          add(s.p_right_cam_in_odom_m), add(s.q_odom_right_cam.coeffs());
        }
      },
      e.sample);
  return x;
}

inline bool bitEqual(const SimEvent& a, const SimEvent& b) {
  const std::vector<double> x = flatten(a), y = flatten(b);
  return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
}

inline std::vector<SimEvent> runAll(const Scenario& scenario, std::uint64_t seed) {
  SensorSimulator sim;
  std::string error;
  EXPECT_TRUE(sim.init(scenario, seed, &error)) << error;
  std::vector<SimEvent> events;
  SimEvent e;
  while (sim.next(&e)) events.push_back(e);
  return events;
}

inline std::vector<SimEvent> ofStream(const std::vector<SimEvent>& events, SimStream stream) {
  std::vector<SimEvent> out;
  for (const SimEvent& e : events)
    if (e.stream == stream) out.push_back(e);
  return out;
}

// A 20 s default scenario with one fault.
inline Scenario withFault(const FaultSpec& fault) {
  Scenario s;
  s.duration_s = 20.0;
  s.faults.push_back(fault);
  return s;
}

inline FaultSpec fault(SimStream stream, FaultKind kind, double t_start_s, double t_end_s) {
  FaultSpec f;
  f.stream = stream;
  f.kind = kind;
  f.t_start_s = t_start_s;
  f.t_end_s = t_end_s;
  return f;
}

}  // namespace deepnav::sim::test
