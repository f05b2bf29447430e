// Serial sensor drivers end to end: real termios ports (a pty pair from openpty), bytes written on the
// master side as the sensor would send them, samples out of SerialSensorDriver.
#include <pty.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/serial/serial_sensor_driver.h"
#include "tests/support/sensor_frames.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

struct Collect : SampleSink {
  std::vector<DvlSample> dvl;
  std::vector<HeadingSample> heading;
  std::vector<AttitudeSample> attitude;
  std::vector<ImuSample> imu;
  bool onDvl(const DvlSample& s) override { return dvl.push_back(s), true; }
  bool onHeading(const HeadingSample& s) override { return heading.push_back(s), true; }
  bool onAttitude(const AttitudeSample& s) override { return attitude.push_back(s), true; }
  bool onImu(const ImuSample& s) override { return imu.push_back(s), true; }
};

class PtyPair {
 public:
  PtyPair() {
    char name[128];
    if (openpty(&master_, &slave_, name, nullptr, nullptr) == 0) path_ = name;
  }
  ~PtyPair() {
    if (master_ >= 0) close(master_);
    if (slave_ >= 0) close(slave_);
  }
  bool ok() const { return !path_.empty(); }
  const std::string& path() const { return path_; }
  // Writes in pieces, as a UART delivers them.
  void send(const std::vector<uint8_t>& bytes, size_t piece = 61) {
    for (size_t i = 0; i < bytes.size(); i += piece) {
      const size_t n = std::min(piece, bytes.size() - i);
      ASSERT_EQ(::write(master_, bytes.data() + i, n), ssize_t(n));
    }
  }

 private:
  int master_ = -1, slave_ = -1;
  std::string path_;
};

std::vector<uint8_t> readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path shared() { return deepnav::testing::sharedDataDir(); }

// Runs the driver until `done` says so or 3 s pass; the writer runs in its own thread.
template <typename Done>
void runDriver(SerialSensorDriver* driver, Collect* sink, const std::function<void()>& writer, Done done) {
  std::thread t(writer);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (!done() && std::chrono::steady_clock::now() < until) driver->poll(20, sink);
  t.join();
  for (int i = 0; i < 5; ++i) driver->poll(10, sink);  // drain
}

TEST(SerialPty, Pd0DvlFromTheRealCapture) {
  const auto file = shared() / "dvl" / "LA100204.PD0";
  if (shared().empty() || !std::filesystem::exists(file)) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  PtyPair pty;
  ASSERT_TRUE(pty.ok());
  SerialSensorDriver driver;
  std::string error;
  ASSERT_TRUE(driver.init({pty.path(), 115200, SerialPort::Parity::kNone, 1, SensorProtocol::kPd0, 1.0}, &error)) << error;
  const auto bytes = readFile(file);
  Collect sink;
  runDriver(&driver, &sink, [&] { pty.send(bytes); }, [&] { return driver.counters().frames >= 107; });
  EXPECT_EQ(driver.counters().frames, 107u);
  EXPECT_EQ(driver.counters().bad_frames, 0u);
  EXPECT_EQ(sink.dvl.size(), 52u);  // the ensembles with bottom track
  EXPECT_EQ(driver.bytesRead(), bytes.size());
  EXPECT_EQ(driver.reopens(), 0u);  // the line stayed up
  for (size_t i = 1; i < sink.dvl.size(); ++i) EXPECT_GE(sink.dvl[i].t_us, sink.dvl[i - 1].t_us);
}

TEST(SerialPty, NmeaHeadingFromTheRealLog) {
  const auto file = shared() / "nmea" / "saab-r4.log";
  if (shared().empty() || !std::filesystem::exists(file)) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  PtyPair pty;
  ASSERT_TRUE(pty.ok());
  SerialSensorDriver driver;
  std::string error;
  ASSERT_TRUE(driver.init({pty.path(), 4800, SerialPort::Parity::kNone, 1, SensorProtocol::kNmea0183, 1.0}, &error)) << error;
  auto bytes = readFile(file);
  // A pty in raw mode passes every byte; newline handling is the parser's job.
  Collect sink;
  runDriver(&driver, &sink, [&] { pty.send(bytes); }, [&] { return driver.counters().frames >= 122; });
  EXPECT_EQ(driver.counters().frames, 122u);
  EXPECT_EQ(sink.heading.size(), 12u);
  int at_4_0 = 0, at_4_1 = 0;  // the log holds 5 x "$HEHDT,4.0,T" and 7 x "$HEHDT,4.1,T"
  for (const auto& h : sink.heading) {
    at_4_0 += std::abs(h.heading_rad - 4.0 * M_PI / 180) < 1e-9;
    at_4_1 += std::abs(h.heading_rad - 4.1 * M_PI / 180) < 1e-9;
    EXPECT_TRUE(h.is_true);
  }
  EXPECT_EQ(at_4_0, 5);
  EXPECT_EQ(at_4_1, 7);
}

TEST(SerialPty, XsensImuAndAttitude) {
  PtyPair pty;
  ASSERT_TRUE(pty.ok());
  SerialSensorDriver driver;
  std::string error;
  ASSERT_TRUE(driver.init({pty.path(), 921600, SerialPort::Parity::kNone, 1, SensorProtocol::kXsens, 1.0}, &error)) << error;
  std::vector<uint8_t> bytes;
  const float q[4] = {1, 0, 0, 0}, acc[3] = {0, 0, 9.81f}, gyr[3] = {0.1f, 0, 0};
  for (uint16_t i = 0; i < 200; ++i) {
    const auto m = test::buildMtData2(i, q, acc, gyr);
    bytes.insert(bytes.end(), m.begin(), m.end());
  }
  bytes[100] ^= 0x10;  // one damaged message
  Collect sink;
  runDriver(&driver, &sink, [&] { pty.send(bytes, 37); }, [&] { return sink.imu.size() >= 199; });
  EXPECT_EQ(sink.imu.size(), 199u);
  EXPECT_EQ(sink.attitude.size(), 199u);
  EXPECT_GE(driver.counters().bad_frames, 1u);
  EXPECT_NEAR(sink.imu.back().w_imu_radps.x(), 0.1, 1e-6);
}

TEST(SerialPty, WaterLinkedSerialDvl) {
  PtyPair pty;
  ASSERT_TRUE(pty.ok());
  SerialSensorDriver driver;
  std::string error;
  ASSERT_TRUE(driver.init({pty.path(), 115200, SerialPort::Parity::kNone, 1, SensorProtocol::kWlA50, 1.0}, &error)) << error;
  std::string text;
  for (int i = 0; i < 50; ++i) {
    text += test::wlSentence("wru,0,0.1,2.0,-40,-90");
    text += test::wlSentence("wrz,0.100,0.200,0.010,y,1.90,0.002,1e-06;0;0;0;1e-06;0;0;0;1e-06," + std::to_string(1000 + i) +
                             ",1040,250.0,0");
  }
  Collect sink;
  runDriver(&driver, &sink, [&] { pty.send(std::vector<uint8_t>(text.begin(), text.end())); },
            [&] { return sink.dvl.size() >= 50; });
  ASSERT_EQ(sink.dvl.size(), 50u);
  EXPECT_EQ(driver.counters().ignored, 50u);  // the transducer sentences carry nothing for the loop
  EXPECT_TRUE(sink.dvl[0].valid);
  EXPECT_NEAR(sink.dvl[0].v_dvl_mps.y(), -0.2, 1e-12);
}

TEST(SerialPty, MissingDeviceIsAClearError) {
  SerialSensorDriver driver;
  std::string error;
  EXPECT_FALSE(driver.init({"/dev/does-not-exist", 9600, SerialPort::Parity::kNone, 1, SensorProtocol::kPd6, 1.0}, &error));
  EXPECT_NE(error.find("/dev/does-not-exist"), std::string::npos) << error;
  SerialPort port;
  EXPECT_FALSE(port.open("/dev/null", 9600, SerialPort::Parity::kNone, 1, &error));  // not a terminal
  EXPECT_NE(error.find("not a terminal"), std::string::npos) << error;
  EXPECT_FALSE(port.open("/dev/null", 12345, SerialPort::Parity::kNone, 1, &error));
}

}  // namespace
}  // namespace deepnav
