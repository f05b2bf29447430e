// The service's pure pieces: register map and datagram encodings, the triple buffer, the health monitor,
// status text, CPU-list and UDP-destination parsing.
#include <gtest/gtest.h>

#include <cmath>

#include "board/service/health_monitor.h"
#include "board/service/status_text.h"
#include "drivers/outputs/nav_datagram.h"
#include "drivers/outputs/register_map.h"
#include "drivers/outputs/triple_buffer.h"
#include "drivers/outputs/udp_sender.h"
#include "drivers/realtime/realtime.h"

namespace deepnav {
namespace {

NavOutput sampleOutput() {
  NavOutput o;
  o.sequence = 0x12345678u;
  NavSolution& s = o.solution;
  s.t_us = 0x0102030405060708LL;
  s.p_robot_in_odom_m = {1.5, -2.25, -40.0};
  // Robot facing north-east-ish: ENU yaw 30 deg -> compass heading 60 deg.
  s.q_odom_robot = Eigen::AngleAxisd(30.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ());
  s.v_robot_in_odom_mps = {0.5, 0.0, 0.1};
  s.w_robot_radps = {0.0, 0.0, 0.1};
  for (int i = 0; i < 6; ++i) s.cov_pose(i, i) = 0.01 * (i + 1);
  for (int i = 0; i < 3; ++i) s.cov_v_mps2(i, i) = 0.001 * (i + 1);
  s.stage = NavStage::kWorkspace;
  s.status = kStatusAttitudeValid | kStatusDepthValid;
  s.faults = staleBit(kSrcDvl);
  s.image_quality = 0.75;
  s.rejected_total = 3;
  s.dropped_late_total = 4;
  o.health = kHealthSensorStale;
  o.counters.ticks = (1ull << 32) + 7;  // the PLC sees counters modulo 2^32
  o.counters.imu = 1000;
  return o;
}

TEST(RegisterMap, EncodesTheDocumentedFields) {
  std::uint16_t r[reg::kCount];
  encodeRegisters(sampleOutput(), r);
  EXPECT_EQ(r[reg::kMagic], 0x444E);
  EXPECT_EQ(r[reg::kVersion], 1);
  EXPECT_EQ(r[reg::kSequence], 0x1234);  // high word first
  EXPECT_EQ(r[reg::kSequence + 1], 0x5678);
  EXPECT_EQ(registerU64(r, reg::kTimeUs), 0x0102030405060708ull);
  EXPECT_EQ(r[reg::kStage], 1);
  EXPECT_EQ(registerU32(r, reg::kFaults), staleBit(kSrcDvl));
  EXPECT_EQ(registerU32(r, reg::kHealth), kHealthSensorStale);
  EXPECT_FLOAT_EQ(registerFloat(r, reg::kEast), 1.5f);
  EXPECT_FLOAT_EQ(registerFloat(r, reg::kDepth), 40.0f);
  EXPECT_NEAR(registerFloat(r, reg::kYaw), 30.0f, 1e-4);
  EXPECT_NEAR(registerFloat(r, reg::kHeading), 60.0f, 1e-4);
  // Velocity in the robot frame: 0.5 m/s east seen from a robot yawed 30 deg left of east.
  EXPECT_NEAR(registerFloat(r, reg::kVelForward), 0.5 * std::cos(M_PI / 6), 1e-6);
  EXPECT_NEAR(registerFloat(r, reg::kVelLeft), -0.5 * std::sin(M_PI / 6), 1e-6);
  EXPECT_NEAR(registerFloat(r, reg::kRateYaw), 0.1 * 180.0 / M_PI, 1e-4);
  EXPECT_FLOAT_EQ(registerFloat(r, reg::kVarYaw), 0.06f);
  EXPECT_FLOAT_EQ(registerFloat(r, reg::kVarVelUp), 0.003f);
  EXPECT_FLOAT_EQ(registerFloat(r, reg::kImageQuality), 0.75f);
  EXPECT_EQ(registerU32(r, reg::kTicks), 7u);
  EXPECT_EQ(registerU32(r, reg::kImuCount), 1000u);
  EXPECT_EQ(registerU32(r, reg::kRejected), 3u);
}

TEST(RegisterMap, HeadingWrapsIntoZeroTo360) {
  NavOutput o = sampleOutput();
  o.solution.q_odom_robot = Eigen::AngleAxisd(135.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ());  // facing north-west
  std::uint16_t r[reg::kCount];
  encodeRegisters(o, r);
  EXPECT_NEAR(registerFloat(r, reg::kHeading), 315.0f, 1e-3);
}

TEST(RegisterMap, DescriptionListsEveryRegisterOnce) {
  const std::string table = describeRegisterMap();
  EXPECT_NE(table.find("| 0 | 1 | u16 | `magic`"), std::string::npos);
  EXPECT_NE(table.find("| 102 | 2 | u32 | `vision_results`"), std::string::npos);
}

TEST(NavDatagram, RoundTripsAndRejectsCorruption) {
  const NavOutput in = sampleOutput();
  std::uint8_t buf[kNavDatagramSize];
  encodeNavDatagram(in, buf);
  EXPECT_EQ(std::string(reinterpret_cast<char*>(buf), 4), "DNAV");
  EXPECT_EQ(buf[6] | (buf[7] << 8), 336);  // little-endian length
  NavOutput out;
  std::string error;
  ASSERT_TRUE(decodeNavDatagram(buf, sizeof buf, &out, &error)) << error;
  EXPECT_EQ(out.sequence, in.sequence);
  EXPECT_EQ(out.solution.t_us, in.solution.t_us);
  EXPECT_EQ(out.solution.p_robot_in_odom_m, in.solution.p_robot_in_odom_m);
  EXPECT_EQ(out.solution.q_odom_robot.coeffs(), in.solution.q_odom_robot.coeffs());
  EXPECT_EQ(out.solution.cov_pose.diagonal(), in.solution.cov_pose.diagonal());
  EXPECT_EQ(out.solution.faults, in.solution.faults);
  EXPECT_EQ(out.health, in.health);
  EXPECT_EQ(out.counters.ticks, in.counters.ticks);
  EXPECT_EQ(out.solution.dropped_late_total, 4u);
  buf[100] ^= 0x01;
  EXPECT_FALSE(decodeNavDatagram(buf, sizeof buf, &out, &error));
  EXPECT_NE(error.find("CRC"), std::string::npos);
  EXPECT_FALSE(decodeNavDatagram(buf, sizeof buf - 1, &out, &error));
}

TEST(TripleBuffer, ReaderSeesTheLatestValueOnce) {
  TripleBuffer<int> b;
  EXPECT_FALSE(b.update());
  b.back() = 1;
  b.publish();
  b.back() = 2;
  b.publish();
  ASSERT_TRUE(b.update());
  EXPECT_EQ(b.front(), 2);
  EXPECT_FALSE(b.update());
  b.back() = 3;
  b.publish();
  ASSERT_TRUE(b.update());
  EXPECT_EQ(b.front(), 3);
}

TEST(HealthMonitor, StallLateOverrunAndSensorBits) {
  HealthMonitor m;
  HealthSample s;
  s.loop.task_count = 2;
  s.loop.names = {"nav", "vision"};
  s.loop.ticks = 100;
  m.update(s);
  EXPECT_TRUE(m.healthy());
  // GIVEN no tick during the window THEN stalled, and not healthy
  EXPECT_EQ(m.update(s) & kHealthLoopStalled, kHealthLoopStalled);
  EXPECT_FALSE(m.healthy());
  // GIVEN ticks, late ticks, a vision overrun and a stale DVL THEN those bits, and healthy
  s.loop.ticks = 150;
  s.loop.late_ticks = 2;
  s.loop.overruns[1] = 1;
  s.faults = staleBit(kSrcDvl);
  const std::uint32_t bits = m.update(s);
  EXPECT_EQ(bits, kHealthLoopLate | kHealthVisionOverrun | kHealthSensorStale);
  EXPECT_TRUE(m.healthy());
  EXPECT_EQ(healthWords(bits), "late vision-overrun sensor-stale");
  // GIVEN a non-finite solution THEN not healthy
  s.loop.ticks = 200;
  s.solution_finite = false;
  m.update(s);
  EXPECT_FALSE(m.healthy());
}

TEST(StatusText, NamesStageHealthAndSensors) {
  const std::string s = formatStatus(sampleOutput());
  EXPECT_NE(s.find("stage 1 workspace | health sensor-stale"), std::string::npos) << s;
  EXPECT_NE(s.find("imu ok (1000), dvl stale (0)"), std::string::npos) << s;
}

TEST(Realtime, CpuListsParseAndNameBadCpus) {
  cpu_set_t set;
  std::string error;
  ASSERT_TRUE(parseCpuList("0", &set, &error)) << error;
  EXPECT_EQ(CPU_COUNT(&set), 1);
  EXPECT_FALSE(parseCpuList("0-", &set, &error));
  EXPECT_FALSE(parseCpuList("1-0", &set, &error));
  EXPECT_FALSE(parseCpuList("100000", &set, &error));
  EXPECT_NE(error.find("names CPU 100000"), std::string::npos) << error;
}

TEST(UdpSender, DestinationsParseAndNameTheBadEntry) {
  std::vector<sockaddr_in> d;
  std::string error;
  ASSERT_TRUE(UdpSender::parseDestinations("127.0.0.1:5600, 10.0.0.255:6000", &d, &error)) << error;
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(ntohs(d[1].sin_port), 6000);
  EXPECT_TRUE(UdpSender::parseDestinations("", &d, &error));
  EXPECT_TRUE(d.empty());
  EXPECT_FALSE(UdpSender::parseDestinations("127.0.0.1:5600,127.0.0.1:99999", &d, &error));
  EXPECT_NE(error.find("'127.0.0.1:99999'"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
