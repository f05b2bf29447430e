// Camera driver pieces that need no camera: pairing by timestamp, pixel conversion, config checks.
#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "drivers/camera/camera_source.h"
#include "drivers/camera/frame_pairer.h"
#include "drivers/camera/raw_image.h"

namespace deepnav {
namespace {

TEST(FramePairer, PairsTheNearestFrameWithinTolerance) {
  FramePairer p(5'000);
  EXPECT_FALSE(p.offer(0, 100'000, 1).paired);
  const auto r = p.offer(1, 103'000, 2);
  ASSERT_TRUE(r.paired);
  EXPECT_EQ(r.left.handle, 1);
  EXPECT_EQ(r.right.handle, 2);
  EXPECT_EQ(r.dropped_count, 0);
  EXPECT_EQ(p.pending(0), 0);
  EXPECT_EQ(p.pending(1), 0);
}

TEST(FramePairer, FramesBeyondToleranceAreNeverPairedAndDroppedOnceUnreachable) {
  // GIVEN a left frame at 100 ms and a right frame 20 ms later (tolerance 5 ms)
  FramePairer p(5'000);
  p.offer(0, 100'000, 1);
  auto r = p.offer(1, 120'000, 2);
  // THEN no pair, and the left frame (older than 120 - 5 ms) is handed back
  EXPECT_FALSE(r.paired);
  ASSERT_EQ(r.dropped_count, 1);
  EXPECT_EQ(r.dropped[0].handle, 1);
  // WHEN the left frame of the right one's trigger arrives, they pair
  r = p.offer(0, 121'000, 3);
  ASSERT_TRUE(r.paired);
  EXPECT_EQ(r.left.handle, 3);
  EXPECT_EQ(r.right.handle, 2);
}

TEST(FramePairer, ChoosesTheClosestOfSeveralCandidates) {
  FramePairer p(10'000);
  p.offer(1, 95'000, 7);
  p.offer(1, 102'000, 8);
  const auto r = p.offer(0, 101'000, 1);
  ASSERT_TRUE(r.paired);
  EXPECT_EQ(r.right.handle, 8);
  ASSERT_EQ(r.dropped_count, 1);  // 95 ms can no longer pair: the right side moved past it
  EXPECT_EQ(r.dropped[0].handle, 7);
}

TEST(FramePairer, ALonelySideKeepsAtMostMaxPendingFrames) {
  FramePairer p(1'000);
  p.setMaxPending(3);
  int dropped = 0;
  for (int i = 0; i < 10; ++i) dropped += p.offer(0, i * 100'000, i).dropped_count;
  EXPECT_EQ(p.pending(0), 3);
  EXPECT_EQ(dropped, 7);
  std::array<FramePairer::Frame, FramePairer::kMaxPending> out{};
  EXPECT_EQ(p.flush(0, &out), 3);
  EXPECT_EQ(out[0].handle, 7);
  EXPECT_EQ(p.pending(0), 0);
}

TEST(RawImage, BayerRg8OfARedSceneDebayersToRed) {
  // GenICam BayerRG8: even rows R G R G, odd rows G B G B. A pure red scene has R = 200, G = B = 0.
  cv::Mat mosaic(8, 8, CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < 8; y += 2) {
    for (int x = 0; x < 8; x += 2) mosaic.at<std::uint8_t>(y, x) = 200;
  }
  RawImage in{mosaic.data, mosaic.total(), 8, 8, 8, PixelFormat::kBayerRG8};
  cv::Mat bgr(8, 8, CV_8UC3);
  ASSERT_TRUE(convertRawImage(in, bgr));
  const cv::Vec3b centre = bgr.at<cv::Vec3b>(4, 4);
  EXPECT_GT(centre[2], 150);  // red
  EXPECT_LT(centre[1], 30);
  EXPECT_LT(centre[0], 30);
}

TEST(RawImage, StrideIsHonouredAndShortBuffersRefused) {
  // 4x2 grey image stored with 6-byte rows (2 bytes of padding each).
  const std::uint8_t data[12] = {1, 2, 3, 4, 99, 99, 5, 6, 7, 8, 99, 99};
  cv::Mat out(2, 4, CV_8UC1);
  RawImage in{data, sizeof(data), 4, 2, 6, PixelFormat::kMono8};
  ASSERT_TRUE(convertRawImage(in, out));
  EXPECT_EQ(out.at<std::uint8_t>(1, 0), 5);
  EXPECT_EQ(out.at<std::uint8_t>(1, 3), 8);
  in.size_bytes = 9;  // the last row would run past the buffer
  EXPECT_FALSE(convertRawImage(in, out));
  in.size_bytes = sizeof(data);
  cv::Mat wrong(3, 4, CV_8UC1);
  EXPECT_FALSE(convertRawImage(in, wrong));
}

TEST(RawImage, YuyvGivesItsLumaAsGrey) {
  const std::uint8_t yuyv[8] = {10, 128, 20, 128, 30, 128, 40, 128};  // Y0 U Y1 V Y2 U Y3 V
  cv::Mat out(1, 4, CV_8UC1);
  ASSERT_TRUE(convertRawImage({yuyv, 8, 4, 1, 8, PixelFormat::kYuyv}, out));
  EXPECT_EQ(out.at<std::uint8_t>(0, 0), 10);
  EXPECT_EQ(out.at<std::uint8_t>(0, 3), 40);
}

CameraSourceConfig goodConfig() {
  CameraSourceConfig c;
  c.driver = "aravis";
  c.left = "192.168.1.10";
  c.right = "192.168.1.11";
  c.pixel_format = "mono8";
  c.offset_x_px = 0;
  c.offset_y_px = 0;
  c.exposure_us = 5000;
  c.trigger = "hardware";
  c.trigger_line = "Line1";
  c.pair_tolerance_ms = 5;
  c.timestamp = "device";
  c.stale_after_us = 1'000'000;
  c.reconnect_interval_us = 2'000'000;
  c.packet_resend = true;
  c.packet_size_bytes = 9000;
  c.stream_buffers = 8;
  c.width_px = 688;
  c.height_px = 516;
  c.channels = 1;
  c.rate_hz = 10;
  return c;
}

TEST(CameraSourceConfig, ChecksNameTheKey) {
  std::string error;
  EXPECT_TRUE(validateCameraSourceConfig(goodConfig(), &error)) << error;

  CameraSourceConfig c = goodConfig();
  c.pair_tolerance_ms = 60;  // half the 100 ms period is the limit
  EXPECT_FALSE(validateCameraSourceConfig(c, &error));
  EXPECT_NE(error.find("camera.pair_tolerance_ms"), std::string::npos) << error;

  c = goodConfig();
  c.right = c.left;
  EXPECT_FALSE(validateCameraSourceConfig(c, &error));
  EXPECT_NE(error.find("camera.left and camera.right"), std::string::npos) << error;

  c = goodConfig();
  c.driver = "v4l2";  // V4L2 cameras free-run
  EXPECT_FALSE(validateCameraSourceConfig(c, &error));
  EXPECT_NE(error.find("camera.trigger"), std::string::npos) << error;

  c = goodConfig();
  c.driver = "none";
  EXPECT_EQ(makeCameraSource(c, &error), nullptr);
  EXPECT_NE(error.find("camera.driver"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
