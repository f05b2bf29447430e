// The Aravis stereo driver against Aravis's own fake GigE Vision cameras on loopback: two in-process
// cameras (arv_gv_fake_camera_new) serving a simulator texture through a fill pattern, or two
// arv-fake-gv-camera-0.8 processes for the camera killed mid-stream. The two cameras need two
// addresses (127.0.0.1 and 127.0.0.2); the test makes a private network namespace for them
// (tests/support/private_loopback.h) so it never touches the machine's own interfaces.
#include <arv.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "drivers/buffers/live_inputs.h"
#include "drivers/camera/aravis_stereo_camera.h"
#include "drivers/camera/gvcp_probe.h"
#include "drivers/clock/monotonic_clock.h"
#include "tests/support/private_loopback.h"
#include "tools/sim/render/procedural_noise.h"

extern char** environ;

namespace deepnav {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr int kDisparityPx = 12;
constexpr int kScrollPxPerFrame = 3;

std::string g_loopback_problem = "not prepared";

class LoopbackEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { g_loopback_problem = testing::prepareLoopback(); }
};
const auto* const g_env = ::testing::AddGlobalTestEnvironment(new LoopbackEnvironment);

// --- simulator images through the fake cameras' fill pattern --------------------------------------

// Frame k of a camera: the simulator's seabed texture scrolled by 3k pixels (the right camera sees it
// 12 px further on: a fronto-parallel scene at constant disparity); the first 8 bytes carry k, so a
// delivered image can be checked pixel by pixel against the frame it claims to be.
struct Scene {
  cv::Mat texture;  // CV_8UC1, wider than the image
  Scene() {
    cv::Mat noise = sim::fractalNoiseImage(1024, kHeight, 24.0f, 4, 0.5f, 7u);
    noise.convertTo(texture, CV_8UC1, 100.0, 128.0);
  }
  void render(std::uint64_t k, int side, std::uint8_t* out, int width, int height) const {
    for (int y = 0; y < height; ++y) {
      const std::uint8_t* row = texture.ptr<std::uint8_t>(y % texture.rows);
      for (int x = 0; x < width; ++x) {
        const auto shift = static_cast<std::uint64_t>(x) + k * kScrollPxPerFrame + static_cast<std::uint64_t>(side * kDisparityPx);
        out[y * width + x] = row[shift % static_cast<std::uint64_t>(texture.cols)];
      }
    }
    std::memcpy(out, &k, sizeof(k));
  }
  // True when the image is exactly frame k of `side`, with k read from the image.
  bool matches(const cv::Mat& image, int side, std::uint64_t* k_out) const {
    std::uint64_t k = 0;
    std::memcpy(&k, image.data, sizeof(k));
    std::vector<std::uint8_t> expected(static_cast<std::size_t>(image.cols * image.rows));
    render(k, side, expected.data(), image.cols, image.rows);
    *k_out = k;
    return std::memcmp(expected.data(), image.data, expected.size()) == 0;
  }
};

// What the fake camera made: frame k's fill time (monotonic), the test's record of when the camera
// acted on the trigger that made it.
struct FillState {
  static constexpr std::size_t kTimes = 4096;
  const Scene* scene = nullptr;
  int side = 0;
  std::atomic<std::uint64_t> frames{0};
  std::array<std::atomic<TimeUs>, kTimes> fill_us{};
  TimeUs fillTime(std::uint64_t k) const { return fill_us[k % kTimes].load(); }
};

void fillFromScene(ArvBuffer* buffer, void* data, guint32, guint32, ArvPixelFormat pixel_format) {
  auto* state = static_cast<FillState*>(data);
  const int w = arv_buffer_get_image_width(buffer);
  const int h = arv_buffer_get_image_height(buffer);
  auto* pixels = static_cast<std::uint8_t*>(const_cast<void*>(arv_buffer_get_data(buffer, nullptr)));
  // The fake camera allocated the buffer for its current region (its payload, w * h bytes in Mono8);
  // the received size is only set once the frame is sent.
  if (pixels == nullptr || pixel_format != ARV_PIXEL_FORMAT_MONO_8) return;
  const std::uint64_t k = state->frames.fetch_add(1);
  state->fill_us[k % FillState::kTimes].store(monotonicUs());
  state->scene->render(k, state->side, pixels, w, h);
}

CameraSourceConfig baseConfig() {
  CameraSourceConfig c;
  c.driver = "aravis";
  c.left = "127.0.0.1";
  c.right = "GV02";  // found by serial number through Aravis's discovery
  c.pixel_format = "mono8";
  c.offset_x_px = 0;
  c.offset_y_px = 0;
  c.exposure_us = 2000;
  c.trigger = "software";
  c.trigger_line = "Line1";
  c.pair_tolerance_ms = 10;
  c.timestamp = "host";
  c.stale_after_us = 300'000;
  c.reconnect_interval_us = 500'000;
  c.packet_resend = true;
  c.packet_size_bytes = 1400;
  c.stream_buffers = 8;
  c.width_px = kWidth;
  c.height_px = kHeight;
  c.channels = 1;
  c.rate_hz = 20;
  return c;
}

struct Inputs {
  FramePool pool;
  SpscRing<int> frames;
  Inputs() {
    EXPECT_TRUE(pool.allocate(6, kWidth, kHeight, 1));
    EXPECT_TRUE(frames.allocate(8));
  }
};

bool waitFor(const std::function<bool()>& condition, double timeout_s) {
  const TimeUs end = monotonicUs() + sToUs(timeout_s);
  while (monotonicUs() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return condition();
}

class AravisStereoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!g_loopback_problem.empty()) GTEST_SKIP() << g_loopback_problem;
  }
};

struct FakePairFills {
  const Scene* scene;
  const FillState* left;
  const FillState* right;
};

// Two in-process fake cameras serving the scene.
struct FakePair {
  Scene scene;
  std::array<FillState, 2> fill;
  std::array<ArvGvFakeCamera*, 2> cameras{};
  bool start(double gvsp_lost_ratio) {
    const char* addresses[2] = {"127.0.0.1", "127.0.0.2"};
    const char* serials[2] = {"GV01", "GV02"};
    for (int i = 0; i < 2; ++i) {
      fill[static_cast<std::size_t>(i)].scene = &scene;
      fill[static_cast<std::size_t>(i)].side = i;
      cameras[static_cast<std::size_t>(i)] = arv_gv_fake_camera_new(addresses[i], serials[i]);
      if (!arv_gv_fake_camera_is_running(cameras[static_cast<std::size_t>(i)])) return false;
      g_object_set(cameras[static_cast<std::size_t>(i)], "gvsp-lost-ratio", gvsp_lost_ratio, nullptr);
      // The fake camera looks at its software-trigger register on a grid of this rate (default 25 Hz,
      // i.e. up to 40 ms late); a real camera exposes microseconds after the trigger.
      arv_fake_camera_set_trigger_frequency(arv_gv_fake_camera_get_fake_camera(cameras[static_cast<std::size_t>(i)]), 1000.0);
      arv_fake_camera_set_fill_pattern(arv_gv_fake_camera_get_fake_camera(cameras[static_cast<std::size_t>(i)]),
                                       fillFromScene, &fill[static_cast<std::size_t>(i)]);
    }
    return true;
  }
  FakePairFills fills() const { return {&scene, &fill[0], &fill[1]}; }
  ~FakePair() {
    for (auto* c : cameras) {
      if (c != nullptr) g_object_unref(c);
    }
  }
};

// Pops every delivered pair; checks each image against the scene frame it carries.
struct PairCheck {
  int pairs = 0;
  int bad_left = 0, bad_right = 0;
  // Pairs whose two frames were made by the cameras less than half a trigger period apart: one
  // trigger's. (Frame counters cannot tell: a camera whose tick was skipped makes one frame less.)
  int same_trigger = 0;
  TimeUs worst_fill_skew_us = 0;
  TimeUs last_t_us = 0;
  std::uint64_t last_sequence = 0;
  bool increasing = true;
  TimeUs worst_latency_us = 0;
  void drain(Inputs& in, const FakePairFills& fills) {
    int slot = -1;
    while (in.frames.tryPop(slot)) {
      const StereoFrame& f = in.pool.frame(slot);
      std::uint64_t kl = 0, kr = 0;
      if (!fills.scene->matches(f.left, 0, &kl)) ++bad_left;
      if (!fills.scene->matches(f.right, 1, &kr)) ++bad_right;
      const TimeUs fill_skew_us = std::abs(fills.left->fillTime(kl) - fills.right->fillTime(kr));
      worst_fill_skew_us = std::max(worst_fill_skew_us, fill_skew_us);
      if (fill_skew_us < 25'000) ++same_trigger;  // the trigger period is 50 ms
      if (f.t_us <= last_t_us || (pairs > 0 && f.sequence <= last_sequence)) increasing = false;
      last_sequence = f.sequence;
      last_t_us = f.t_us;
      worst_latency_us = std::max(worst_latency_us, monotonicUs() - f.t_us);
      ++pairs;
      in.pool.release(slot);
    }
  }
  // Drains every 5 ms for duration_us, as a consumer polling the frame ring would.
  void drainFor(Inputs& in, const FakePairFills& fills, TimeUs duration_us) {
    const TimeUs end = monotonicUs() + duration_us;
    while (monotonicUs() < end) {
      drain(in, fills);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
};

TEST_F(AravisStereoTest, SynchronisedPairsArriveWithinToleranceWithTheCamerasPixels) {
  // GIVEN two fake GigE cameras on 127.0.0.1 and 127.0.0.2 serving the scene, software-triggered
  FakePair fakes;
  ASSERT_TRUE(fakes.start(0.0));
  Inputs in;
  AravisStereoCamera camera(baseConfig());
  std::string error;
  ASSERT_TRUE(camera.open(&error)) << error;
  ASSERT_TRUE(camera.start(&in.pool, &in.frames, &error)) << error;

  // WHEN the driver runs for 1.5 s at 20 Hz
  PairCheck check;
  check.drainFor(in, fakes.fills(), 1'500'000);
  camera.stop();
  check.drain(in, fakes.fills());
  const CameraStatus s = camera.status();

  // THEN pairs arrive at about the trigger rate, each image exactly the camera's, both from one trigger
  EXPECT_GE(check.pairs, 20) << cameraStatusJson(s);
  EXPECT_EQ(check.bad_left, 0);
  EXPECT_EQ(check.bad_right, 0);
  EXPECT_EQ(check.same_trigger, check.pairs) << "worst fill skew " << check.worst_fill_skew_us << " us";
  EXPECT_TRUE(check.increasing);
  EXPECT_LE(s.max_pair_skew_us, 10'000);
  EXPECT_LT(check.worst_latency_us, 200'000);  // capture time is on this machine's monotonic clock
  EXPECT_EQ(s.left.bad(), 0u) << cameraStatusJson(s);
  EXPECT_EQ(s.right.bad(), 0u) << cameraStatusJson(s);
  EXPECT_EQ(s.pairs, static_cast<std::uint64_t>(check.pairs));
  EXPECT_TRUE(s.left.connected && s.right.connected);
  EXPECT_FALSE(s.left.stale || s.right.stale);
}

// Busy threads competing for the CPUs with the cameras, the receive threads and the driver.
struct CpuHog {
  std::atomic<bool> stop{false};
  std::vector<std::thread> threads;
  explicit CpuHog(int n) {
    for (int i = 0; i < n; ++i) {
      threads.emplace_back([this] {
        volatile std::uint64_t x = 0;
        while (!stop.load(std::memory_order_relaxed)) x = x + 1;
      });
    }
  }
  ~CpuHog() {
    stop.store(true);
    for (auto& t : threads) t.join();
  }
};

TEST_F(AravisStereoTest, UnderCpuLoadPairsAreNeverMixedAndLateFramesAreCountedNotPaired) {
  // GIVEN the software-triggered fake cameras, paired on their own clocks (the in-process fake cameras
  // share this host's clock, as PTP-synchronised cameras share one: under load the fake cameras'
  // threads are starved too, and only their clocks say when they really "exposed"), and four busy
  // threads on this 2-core machine
  FakePair fakes;
  ASSERT_TRUE(fakes.start(0.0));
  Inputs in;
  CameraSourceConfig config = baseConfig();
  config.timestamp = "device";
  AravisStereoCamera camera(config);
  std::string error;
  ASSERT_TRUE(camera.open(&error)) << error;
  ASSERT_TRUE(camera.start(&in.pool, &in.frames, &error)) << error;
  PairCheck check;
  {
    CpuHog hog(4);
    // WHEN the driver runs for 2 s under that load
    check.drainFor(in, fakes.fills(), 2'000'000);
  }
  camera.stop();
  check.drain(in, fakes.fills());
  const CameraStatus s = camera.status();
  std::printf("under load: %d pairs of 40 ticks, worst fill skew %lld us; %s\n", check.pairs,
              static_cast<long long>(check.worst_fill_skew_us), cameraStatusJson(s).c_str());

  // THEN every pair delivered is one trigger's, with the cameras' exact pixels; what could not be
  // paired was counted (unpaired, skipped ticks, unattributed frames)
  EXPECT_GT(check.pairs, 0) << cameraStatusJson(s);
  EXPECT_EQ(check.same_trigger, check.pairs) << "worst fill skew " << check.worst_fill_skew_us << " us";
  EXPECT_EQ(check.bad_left, 0);
  EXPECT_EQ(check.bad_right, 0);
  EXPECT_TRUE(check.increasing);
  EXPECT_LE(s.max_pair_skew_us, 10'000);
}

TEST_F(AravisStereoTest, LostPacketsAreCountedAndTheirFramesNeverPassedOn) {
  // GIVEN fake cameras losing 1 % of their stream packets, and no resend
  FakePair fakes;
  ASSERT_TRUE(fakes.start(0.01));
  Inputs in;
  CameraSourceConfig config = baseConfig();
  config.packet_resend = false;
  AravisStereoCamera camera(config);
  std::string error;
  ASSERT_TRUE(camera.open(&error)) << error;
  ASSERT_TRUE(camera.start(&in.pool, &in.frames, &error)) << error;

  // WHEN the driver runs for at least 2 s, and on until a few pairs came through (at most 10 s): at 1 %
  // loss most frames lose a packet, and a lost frame holds its camera's trigger for up to 4 periods, so
  // 2 s can hold only a handful of intact pairs (0 in about 1 run of 6)
  PairCheck check;
  const TimeUs start = monotonicUs();
  while (monotonicUs() < start + 2'000'000 ||
         (check.pairs < 3 && monotonicUs() < start + 10'000'000)) {
    check.drain(in, fakes.fills());
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  camera.stop();
  check.drain(in, fakes.fills());
  const CameraStatus s = camera.status();

  // THEN incomplete frames are counted per status on both cameras, and every pair handed on is intact
  const auto missing = static_cast<std::size_t>(CameraFrameStatus::kMissingPackets);
  const auto timeout = static_cast<std::size_t>(CameraFrameStatus::kTimeout);
  EXPECT_GT(s.left.frames[missing] + s.left.frames[timeout], 0u) << cameraStatusJson(s);
  EXPECT_GT(s.right.frames[missing] + s.right.frames[timeout], 0u) << cameraStatusJson(s);
  EXPECT_GT(check.pairs, 0) << cameraStatusJson(s);
  EXPECT_EQ(check.bad_left, 0);
  EXPECT_EQ(check.bad_right, 0);
  // A frame whose partner was lost finds no pair: it is counted, not paired with another trigger's.
  EXPECT_GT(s.unpaired, 0u);
}

// --- a camera process killed mid-stream -------------------------------------------------------------

pid_t spawnFakeCamera(const char* address, const char* serial) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  std::string a = address, s = serial;
  char name[] = "arv-fake-gv-camera-0.8";
  char opt_i[] = "-i";
  char opt_s[] = "-s";
  char* argv[] = {name, opt_i, a.data(), opt_s, s.data(), nullptr};
  pid_t pid = -1;
  if (posix_spawnp(&pid, name, &actions, nullptr, argv, environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

void killAndReap(pid_t pid) {
  if (pid <= 0) return;
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
}

bool fakeCameraToolInstalled() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = dirs.find(':', start);
    const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (access((dir + "/arv-fake-gv-camera-0.8").c_str(), X_OK) == 0) return true;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return false;
}

TEST_F(AravisStereoTest, CameraKilledMidStreamIsFlaggedStaleAndReconnectedWhenItReturns) {
  if (!fakeCameraToolInstalled()) GTEST_SKIP() << "arv-fake-gv-camera-0.8 not found (Debian package aravis-tools-cli)";
  // GIVEN two fake camera processes streaming pairs
  pid_t left = spawnFakeCamera("127.0.0.1", "GV01");
  pid_t right = spawnFakeCamera("127.0.0.2", "GV02");
  ASSERT_GT(left, 0);
  ASSERT_GT(right, 0);
  Inputs in;
  CameraSourceConfig config = baseConfig();
  config.right = "127.0.0.2";
  // The processes take a moment to listen; opening a camera that is not there yet blocks for seconds.
  ASSERT_TRUE(waitFor([] { return gvcpDeviceAnswers("127.0.0.1", 50) && gvcpDeviceAnswers("127.0.0.2", 50); }, 5.0));
  auto owned = std::make_unique<AravisStereoCamera>(config);
  AravisStereoCamera& camera = *owned;
  std::string error;
  ASSERT_TRUE(camera.open(&error)) << error;
  ASSERT_TRUE(camera.start(&in.pool, &in.frames, &error)) << error;
  auto drain = [&] {
    int slot = -1;
    while (in.frames.tryPop(slot)) in.pool.release(slot);
  };
  ASSERT_TRUE(waitFor([&] { drain(); return camera.status().pairs >= 5; }, 3.0)) << cameraStatusJson(camera.status());

  // WHEN the right camera is killed
  killAndReap(right);
  // THEN it is flagged stale and no pair is formed without it
  ASSERT_TRUE(waitFor([&] { drain(); return camera.status().right.stale; }, 2.0)) << cameraStatusJson(camera.status());
  const std::uint64_t pairs_at_loss = camera.status().pairs;
  EXPECT_FALSE(camera.status().left.stale);

  // WHEN it comes back
  right = spawnFakeCamera("127.0.0.2", "GV02");
  ASSERT_GT(right, 0);
  EXPECT_EQ(camera.status().pairs, pairs_at_loss);  // nothing paired while it was away
  // THEN the driver reopens it and pairs flow again
  const bool resumed = waitFor(
      [&] {
        drain();
        const CameraStatus s = camera.status();
        return s.right.reconnects >= 1 && s.pairs >= pairs_at_loss + 5 && !s.right.stale;
      },
      10.0);
  const CameraStatus s = camera.status();
  owned.reset();  // closes both cameras while they still answer
  killAndReap(left);
  killAndReap(right);
  EXPECT_TRUE(resumed) << cameraStatusJson(s);
  EXPECT_GE(s.right.stale_events, 1u);
  EXPECT_EQ(s.left.reconnects, 0u) << cameraStatusJson(s);
}

TEST_F(AravisStereoTest, MissingCameraAtStartUpIsNamedInTheError) {
  FakePair fakes;
  ASSERT_TRUE(fakes.start(0.0));
  CameraSourceConfig config = baseConfig();
  config.right = "NO-SUCH-CAMERA";
  AravisStereoCamera camera(config);
  std::string error;
  EXPECT_FALSE(camera.open(&error));
  EXPECT_NE(error.find("camera.right 'NO-SUCH-CAMERA'"), std::string::npos) << error;
}

TEST_F(AravisStereoTest, PixelFormatTheCameraLacksIsAStartUpErrorNamingTheKey) {
  FakePair fakes;
  ASSERT_TRUE(fakes.start(0.0));
  CameraSourceConfig config = baseConfig();
  config.pixel_format = "yuyv";  // the fake camera offers Mono8, Mono16, RGB8 and Bayer 8-bit only
  AravisStereoCamera camera(config);
  std::string error;
  EXPECT_FALSE(camera.open(&error));
  EXPECT_NE(error.find("camera.left '127.0.0.1'"), std::string::npos) << error;
  EXPECT_NE(error.find("camera.pixel_format"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
