#pragma once
#include <array>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "drivers/camera/camera_source.h"
#include "drivers/camera/frame_pairer.h"
#include "drivers/camera/raw_image.h"
#include "drivers/camera/stereo_pair_writer.h"
#include "drivers/camera/trigger_tracker.h"

// Aravis types, declared here so that only this driver's .cpp includes <arv.h>.
typedef struct _ArvCamera ArvCamera;
typedef struct _ArvStream ArvStream;
typedef struct _ArvBuffer ArvBuffer;

namespace deepnav {

// Two GigE Vision cameras through Aravis as one stereo source.
//
// open() finds each camera (camera.left / camera.right: an IPv4 address, or a device id, serial
// number or physical id from Aravis's discovery), sets pixel format, region, exposure, frame rate and
// trigger through GenICam features, and gives each stream camera.stream_buffers buffers allocated
// there and then. The driver thread then takes completed buffers from both streams: any status other
// than SUCCESS, or a frame of the wrong size or format, is counted per status and handed straight back
// to its stream; good frames are paired by timestamp (FramePairer) and each pair is copied into the
// frame pool. In software-trigger mode one thread per camera triggers it at camera.rate_hz, both on
// the same absolute times (a control-channel write to a dead camera blocks for seconds of retries:
// it stalls neither the frames nor the other camera); each camera has at most one trigger
// outstanding (TriggerTracker), so every frame is tagged with the tick it answers and only frames of
// the same tick are paired.
// A camera with no good frame for camera.stale_after_s is flagged stale and no longer triggered; a
// stale camera, or one whose control channel Aravis reports lost, is probed (GVCP discovery, 100 ms)
// every camera.reconnect_interval_s and reopened once it answers. Reopening allocates: it is the
// recovery path, not the steady state.
class AravisStereoCamera : public CameraSource {
 public:
  explicit AravisStereoCamera(const CameraSourceConfig& config);
  ~AravisStereoCamera() override;
  AravisStereoCamera(const AravisStereoCamera&) = delete;
  AravisStereoCamera& operator=(const AravisStereoCamera&) = delete;

  bool open(std::string* error) override;
  bool start(FramePool* pool, SpscRing<int>* frames, std::string* error) override;
  void stop() override;
  CameraStatus status() const override { return counters_.snapshot(); }

  // Called from Aravis's threads.
  void notifyBufferReady();
  void notifyControlLost(int side);

 private:
  static constexpr int kHeld = FramePairer::kMaxPending + 1;

  struct Held {
    ArvBuffer* buffer = nullptr;
    TimeUs t_us = 0;  // capture time on the monotonic clock
    std::int64_t tick = -1;  // software trigger tick it answers (-1: not software-triggered)
  };
  struct Side {
    AravisStereoCamera* owner = nullptr;
    int index = 0;
    ArvCamera* camera = nullptr;
    ArvStream* stream = nullptr;
    std::array<Held, kHeld> held{};  // good frames waiting in the pairer
    std::atomic<bool> control_lost{false};
    bool acquiring = false;
    TimeUs last_good_or_open_us = 0;
    TimeUs next_reconnect_us = 0;
    TimeUs device_offset_us = 0;     // monotonic - device clock (minimum seen), for camera.timestamp: device
    bool device_offset_valid = false;
    std::uint32_t exposure_us = 0;
    std::string address;             // IPv4 address found at open, probed before reopening
    // Held by the camera's trigger thread around each trigger, and try-locked by the driver thread
    // to reopen the camera (so it never waits on a write to a dead camera).
    std::mutex control_mutex;
    // Software trigger: which tick the camera's next frame answers. Shared by the trigger thread and
    // the driver thread (short critical sections, never around a camera call).
    std::mutex tracker_mutex;
    TriggerTracker tracker;
  };

  bool openSide(Side& s, std::string* error);
  void closeSide(Side& s);
  bool startSide(Side& s, std::string* error);
  void run();
  void runTrigger(Side& s);
  void drain(Side& s);
  void handleBuffer(Side& s, ArvBuffer* buffer);
  std::int64_t triggerTickOf(Side& s, TimeUs arrival_us, TimeUs* written_us);
  bool exposureStartUnknown(const Side& s, TimeUs written_us, TimeUs arrival_us) const;
  void publishTriggerCounts(Side& s);  // with tracker_mutex held
  void finish(const FramePairer::Result& r);
  Held& held(int handle);  // handle = side * kHeld + slot
  void recycle(int handle);
  void checkHealth(TimeUs now_us);
  const std::string& idOf(const Side& s) const { return s.index == 0 ? config_.left : config_.right; }
  const char* nameOf(const Side& s) const { return s.index == 0 ? "camera.left" : "camera.right"; }

  CameraSourceConfig config_;
  PixelFormat format_ = PixelFormat::kMono8;
  std::array<Side, 2> sides_;
  FramePairer pairer_;
  CameraCounters counters_;
  std::unique_ptr<StereoPairWriter> writer_;
  std::thread thread_;
  std::array<std::thread, 2> trigger_threads_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool buffer_ready_ = false;  // guarded by mutex_
  TimeUs next_trigger_us_ = 0;
};

}  // namespace deepnav
