// The V4L2 stereo driver against the kernel's virtual video test driver (vivid): two capture devices
// streaming vivid's 75 % colour bars through mmap buffers. This machine's kernel has no vivid, so the
// test skips here; tools/vm/run-kernel-tests.sh runs it in a VM with Debian's kernel
// (modprobe vivid n_devs=2 node_types=0x1,0x1).
#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "drivers/buffers/frame_pool.h"
#include "drivers/buffers/spsc_ring.h"
#include "drivers/camera/camera_source.h"
#include "drivers/camera/v4l2_stereo_camera.h"
#include "drivers/clock/monotonic_clock.h"

namespace deepnav {
namespace {

constexpr int kWidth = 640;  // one of vivid's webcam sizes
constexpr int kHeight = 360;

// Video capture nodes driven by vivid.
std::vector<std::string> vividCaptureDevices() {
  std::vector<std::string> found;
  for (int i = 0; i < 64; ++i) {
    const std::string path = "/dev/video" + std::to_string(i);
    const int fd = open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    v4l2_capability cap{};
    if (ioctl(fd, VIDIOC_QUERYCAP, &cap) == 0) {
      const std::uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
      if (std::strcmp(reinterpret_cast<const char*>(cap.driver), "vivid") == 0 && (caps & V4L2_CAP_VIDEO_CAPTURE)) {
        found.push_back(path);
      }
    }
    close(fd);
  }
  return found;
}

CameraSourceConfig vividConfig(const std::vector<std::string>& devices) {
  CameraSourceConfig c;
  c.driver = "v4l2";
  c.left = devices[0];
  c.right = devices[1];
  c.pixel_format = "mono8";
  c.offset_x_px = 0;
  c.offset_y_px = 0;
  c.exposure_us = 0;
  c.trigger = "free";
  c.trigger_line = "";
  c.pair_tolerance_ms = 40;  // the two devices free-run from their own STREAMON; under emulation they jitter
  c.timestamp = "host";
  c.stale_after_us = 2'000'000;
  c.reconnect_interval_us = 1'000'000;
  c.packet_resend = false;
  c.packet_size_bytes = 0;
  c.stream_buffers = 6;
  c.width_px = kWidth;
  c.height_px = kHeight;
  c.channels = 1;
  c.rate_hz = 10;
  return c;
}

// Mean grey level of each eighth of one row: vivid's 75 % colour bars (white, yellow, cyan, green,
// magenta, red, blue, black) have strictly decreasing luma from left to right.
bool looksLikeColourBars(const cv::Mat& image, std::string* why) {
  const int y = image.rows * 3 / 4;  // below vivid's text overlay
  const std::uint8_t* row = image.ptr<std::uint8_t>(y);
  const int bar = image.cols / 8;
  double previous = 1e9;
  for (int b = 0; b < 8; ++b) {
    double sum = 0;
    // The middle half of each bar: clear of the edges' filtering.
    for (int x = b * bar + bar / 4; x < b * bar + 3 * bar / 4; ++x) sum += row[x];
    const double mean = sum / (bar / 2);
    *why += std::to_string(static_cast<int>(mean)) + " ";
    if (mean >= previous - 5) return false;
    previous = mean;
  }
  return true;
}

TEST(VividStereo, PairsOfColourBarsArriveThroughMmapStreaming) {
  const std::vector<std::string> devices = vividCaptureDevices();
  if (devices.size() < 2) {
    GTEST_SKIP() << "needs two vivid capture devices (modprobe vivid n_devs=2 node_types=0x1,0x1); found "
                 << devices.size() << ". tools/vm/run-kernel-tests.sh runs this test in a VM that has them";
  }
  // GIVEN the two vivid devices as a stereo camera
  FramePool pool;
  SpscRing<int> frames;
  ASSERT_TRUE(pool.allocate(4, kWidth, kHeight, 1));
  ASSERT_TRUE(frames.allocate(4));
  auto camera = makeCameraSource(vividConfig(devices), nullptr);
  ASSERT_NE(camera, nullptr);
  std::string error;
  ASSERT_TRUE(camera->open(&error)) << error;
  ASSERT_TRUE(camera->start(&pool, &frames, &error)) << error;

  // WHEN it runs until 5 pairs have come (at most 10 s: the VM emulates the CPU)
  int pairs = 0, bars = 0;
  bool increasing = true, on_our_clock = true;
  TimeUs worst_age_us = 0;
  TimeUs last_t_us = 0;
  std::string levels;
  const TimeUs end = monotonicUs() + 10'000'000;
  while (pairs < 5 && monotonicUs() < end) {
    int slot = -1;
    while (frames.tryPop(slot)) {
      const StereoFrame& f = pool.frame(slot);
      levels.clear();
      if (looksLikeColourBars(f.left, &levels) && looksLikeColourBars(f.right, &levels)) ++bars;
      if (f.t_us <= last_t_us) increasing = false;
      const TimeUs age_us = monotonicUs() - f.t_us;
      if (age_us < 0 || age_us > 2'000'000) {
        on_our_clock = false;
        worst_age_us = age_us;
      }
      last_t_us = f.t_us;
      ++pairs;
      pool.release(slot);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const CameraStatus s = camera->status();
  camera->stop();

  // THEN the pairs carry vivid's bars on both sides, on the monotonic clock, within tolerance
  EXPECT_GE(pairs, 5) << cameraStatusJson(s);
  EXPECT_EQ(bars, pairs) << "bar levels of the last pair: " << levels;
  EXPECT_TRUE(increasing);
  EXPECT_TRUE(on_our_clock) << "a pair " << worst_age_us << " us old";
  EXPECT_LE(s.max_pair_skew_us, 40'000);
  EXPECT_EQ(s.left.bad(), 0u) << cameraStatusJson(s);
  EXPECT_EQ(s.right.bad(), 0u) << cameraStatusJson(s);
}

TEST(VividStereo, SizeTheDeviceCannotGiveIsAStartUpErrorNamingTheDevice) {
  const std::vector<std::string> devices = vividCaptureDevices();
  if (devices.size() < 2) GTEST_SKIP() << "needs two vivid capture devices (see the test above)";
  CameraSourceConfig c = vividConfig(devices);
  c.width_px = 333;  // not one of the webcam input's discrete sizes
  c.height_px = 211;
  auto camera = makeCameraSource(c, nullptr);
  std::string error;
  EXPECT_FALSE(camera->open(&error));
  EXPECT_NE(error.find("camera.left: " + devices[0]), std::string::npos) << error;
  EXPECT_NE(error.find("the device offers"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
