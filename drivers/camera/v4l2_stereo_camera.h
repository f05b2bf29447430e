#pragma once
#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "drivers/camera/camera_source.h"
#include "drivers/camera/frame_pairer.h"
#include "drivers/camera/stereo_pair_writer.h"
#include "drivers/camera/v4l2_capture.h"

namespace deepnav {

// Two V4L2 capture devices (camera.left / camera.right: /dev/videoN paths, e.g. USB or analogue
// grabbers) as one stereo source. V4L2 cameras free-run: frames are paired on the kernel's monotonic
// buffer timestamps within camera.pair_tolerance_ms. A buffer flagged V4L2_BUF_FLAG_ERROR is counted
// (device_error) and requeued, never passed on. A device that fails (unplugged) or goes stale is
// closed and reopened every camera.reconnect_interval_s.
class V4l2StereoCamera : public CameraSource {
 public:
  explicit V4l2StereoCamera(const CameraSourceConfig& config);
  ~V4l2StereoCamera() override { stop(); }
  V4l2StereoCamera(const V4l2StereoCamera&) = delete;
  V4l2StereoCamera& operator=(const V4l2StereoCamera&) = delete;

  bool open(std::string* error) override;
  bool start(FramePool* pool, SpscRing<int>* frames, std::string* error) override;
  void stop() override;
  CameraStatus status() const override { return counters_.snapshot(); }

 private:
  struct Held {
    V4l2Capture::Frame frame;
    bool busy = false;
  };
  struct Side {
    int index = 0;
    V4l2Capture capture;
    std::array<Held, V4l2Capture::kMaxBuffers> held{};  // by V4L2 buffer index
    TimeUs last_good_or_open_us = 0;
    TimeUs next_reconnect_us = 0;
    bool failed = false;
  };

  bool openSide(Side& s, std::string* error);
  void run();
  void drain(Side& s);
  void finish(const FramePairer::Result& r);
  void recycle(int handle);  // handle = side * kMaxBuffers + buffer index
  void closeSide(Side& s);
  void checkHealth(TimeUs now_us);

  CameraSourceConfig config_;
  PixelFormat format_ = PixelFormat::kMono8;
  std::array<Side, 2> sides_;
  FramePairer pairer_;
  CameraCounters counters_;
  std::unique_ptr<StereoPairWriter> writer_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

}  // namespace deepnav
