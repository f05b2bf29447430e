// The CAN driver against a real kernel CAN interface (vcan0). This machine's kernel has no vcan: the
// test skips here and runs in the QEMU VM of tools/vm/run-kernel-tests.sh, where vcan0 exists. Frames
// are written by a second raw socket on the same interface, so the kernel's filters, the error-frame
// option and the loopback are all exercised.
#include <net/if.h>

#include <chrono>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/can/can_sensor_driver.h"
#include "drivers/can/socketcan.h"

namespace deepnav {
namespace {

struct Collect : SampleSink {
  std::vector<HeadingSample> heading;
  std::vector<AttitudeSample> attitude;
  bool onHeading(const HeadingSample& s) override { return heading.push_back(s), true; }
  bool onAttitude(const AttitudeSample& s) override { return attitude.push_back(s), true; }
};

const char* kInterface = "vcan0";

TEST(Vcan, FiltersPassHeadingAndAttitudeOnly) {
  if (::if_nametoindex(kInterface) == 0) GTEST_SKIP() << "no vcan0 on this kernel (run tools/vm/run-kernel-tests.sh)";
  CanSensorDriver driver;
  std::string error;
  CanSensorConfig config;
  config.interface = kInterface;
  ASSERT_TRUE(driver.init(config, &error)) << error;
  SocketCan writer;
  ASSERT_TRUE(writer.open(kInterface, nullptr, 0, &error)) << error;
  CanFrame heading;
  heading.extended = true;
  heading.id = (2u << 26) | (127250u << 8) | 128;
  heading.dlc = 8;
  heading.data = {0, 0x10, 0x27, 0xFF, 0x7F, 0xFF, 0x7F, 0xFC};
  CanFrame attitude = heading;
  attitude.id = (3u << 26) | (127257u << 8) | 128;
  attitude.data = {0, 0xFF, 0x7F, 0x9F, 0x00, 0x07, 0x00, 0xFF};
  CanFrame other = heading;
  other.id = (2u << 26) | (129025u << 8) | 127;  // position rapid update: filtered out by the kernel
  CanFrame standard;
  standard.id = 0x123;
  standard.dlc = 2;
  for (int i = 0; i < 20; ++i) {
    ASSERT_TRUE(writer.write(other));
    ASSERT_TRUE(writer.write(standard));
    ASSERT_TRUE(writer.write(heading));
    ASSERT_TRUE(writer.write(attitude));
  }
  Collect sink;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while ((sink.heading.size() < 20 || sink.attitude.size() < 5) && std::chrono::steady_clock::now() < until) {
    driver.poll(50, &sink);
  }
  driver.poll(50, &sink);
  EXPECT_EQ(sink.heading.size(), 20u);
  EXPECT_EQ(sink.attitude.size(), 20u);
  EXPECT_EQ(driver.counters().frames, 40u);  // the kernel's filters dropped the other 40
  EXPECT_EQ(driver.bus().state(), CanBusMonitor::State::kActive);
}

TEST(Vcan, MissingInterfaceIsAClearError) {
  SocketCan s;
  std::string error;
  EXPECT_FALSE(s.open("nocan7", nullptr, 0, &error));
  EXPECT_NE(error.find("nocan7"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
