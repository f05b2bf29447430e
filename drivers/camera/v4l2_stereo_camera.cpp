#include "drivers/camera/v4l2_stereo_camera.h"

#include <poll.h>

#include <algorithm>
#include <cmath>

#include "drivers/clock/monotonic_clock.h"

namespace deepnav {

V4l2StereoCamera::V4l2StereoCamera(const CameraSourceConfig& config) : config_(config) {
  sides_[0].index = 0;
  sides_[1].index = 1;
  pairer_.setTolerance(static_cast<TimeUs>(std::llround(config_.pair_tolerance_ms * 1000.0)));
  pairer_.setMaxPending(config_.stream_buffers / 2);
}

bool V4l2StereoCamera::openSide(Side& s, std::string* error) {
  const std::string& path = s.index == 0 ? config_.left : config_.right;
  std::string e;
  if (!s.capture.open(path, config_.width_px, config_.height_px, format_, config_.rate_hz, config_.exposure_us,
                      config_.stream_buffers, &e)) {
    if (error) *error = std::string(s.index == 0 ? "camera.left" : "camera.right") + ": " + e;
    return false;
  }
  counters_.side(s.index).connected.store(true, std::memory_order_relaxed);
  s.failed = false;
  return true;
}

bool V4l2StereoCamera::open(std::string* error) {
  if (!validateCameraSourceConfig(config_, error, &format_)) return false;
  if (openSide(sides_[0], error) && openSide(sides_[1], error)) return true;
  for (auto& s : sides_) closeSide(s);  // both cameras or neither
  return false;
}

bool V4l2StereoCamera::start(FramePool* pool, SpscRing<int>* frames, std::string* error) {
  const bool cameras_open = sides_[0].capture.isOpen() && sides_[1].capture.isOpen();
  if (!checkStart(config_, pool, frames, cameras_open, error)) return false;
  writer_ = std::make_unique<StereoPairWriter>(pool, frames, &counters_);
  for (auto& s : sides_) {
    if (!s.capture.start(error)) return false;
    s.last_good_or_open_us = monotonicUs();
  }
  stop_.store(false);
  thread_ = std::thread([this] { run(); });
  return true;
}

void V4l2StereoCamera::stop() {
  stop_.store(true, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
  for (auto& s : sides_) closeSide(s);
}

void V4l2StereoCamera::closeSide(Side& s) {
  std::array<FramePairer::Frame, FramePairer::kMaxPending> waiting{};
  const int n = pairer_.flush(s.index, &waiting);
  for (int i = 0; i < n; ++i) counters_.unpaired.fetch_add(1, std::memory_order_relaxed);
  for (auto& h : s.held) h.busy = false;  // the buffers go with the device
  s.capture.close();
  counters_.side(s.index).connected.store(false, std::memory_order_relaxed);
}

void V4l2StereoCamera::run() {
  while (!stop_.load(std::memory_order_acquire)) {
    std::array<pollfd, 2> fds{};
    for (std::size_t i = 0; i < 2; ++i) {
      fds[i].fd = sides_[i].capture.isOpen() ? sides_[i].capture.fd() : -1;  // poll ignores fd -1
      fds[i].events = POLLIN;
    }
    poll(fds.data(), fds.size(), 10);
    for (std::size_t i = 0; i < 2; ++i) {
      if (fds[i].revents & (POLLIN | POLLERR | POLLHUP)) drain(sides_[i]);
    }
    checkHealth(monotonicUs());
  }
}

void V4l2StereoCamera::drain(Side& s) {
  auto& counters = counters_.side(s.index);
  for (;;) {
    V4l2Capture::Frame f;
    std::string e;
    const int r = s.capture.dequeue(&f, &e);
    if (r == 0) return;
    if (r < 0) {
      s.failed = true;  // unplugged or broken: checkHealth() reopens it
      return;
    }
    CameraFrameStatus status = f.error ? CameraFrameStatus::kDeviceError : CameraFrameStatus::kOk;
    const std::size_t row = static_cast<std::size_t>(f.image.width_px) *
                            static_cast<std::size_t>(bytesPerPixelTimes2(f.image.format)) / 2;
    if (status == CameraFrameStatus::kOk &&
        f.image.size_bytes < f.image.stride_bytes * static_cast<std::size_t>(f.image.height_px - 1) + row) {
      status = CameraFrameStatus::kSizeMismatch;
    }
    counters.count(status);
    if (status != CameraFrameStatus::kOk) {
      s.capture.requeue(f.index);
      continue;
    }
    const TimeUs now_us = monotonicUs();
    counters.last_good_frame_us.store(now_us, std::memory_order_relaxed);
    s.last_good_or_open_us = now_us;
    counters.stale.store(false, std::memory_order_relaxed);
    s.held[static_cast<std::size_t>(f.index)] = {f, true};
    finish(pairer_.offer(s.index, f.t_us, s.index * V4l2Capture::kMaxBuffers + f.index));
  }
}

void V4l2StereoCamera::recycle(int handle) {
  Side& s = sides_[static_cast<std::size_t>(handle / V4l2Capture::kMaxBuffers)];
  Held& h = s.held[static_cast<std::size_t>(handle % V4l2Capture::kMaxBuffers)];
  if (!h.busy) return;
  h.busy = false;
  s.capture.requeue(h.frame.index);
}

void V4l2StereoCamera::finish(const FramePairer::Result& r) {
  for (int i = 0; i < r.dropped_count; ++i) {
    counters_.unpaired.fetch_add(1, std::memory_order_relaxed);
    recycle(r.dropped[static_cast<std::size_t>(i)].handle);
  }
  if (!r.paired) return;
  auto held = [this](int handle) -> const V4l2Capture::Frame& {
    return sides_[static_cast<std::size_t>(handle / V4l2Capture::kMaxBuffers)]
        .held[static_cast<std::size_t>(handle % V4l2Capture::kMaxBuffers)]
        .frame;
  };
  const V4l2Capture::Frame& l = held(r.left.handle);
  const V4l2Capture::Frame& rr = held(r.right.handle);
  // Pairs match on the drivers' stamps; the capture time handed on is never later than the dequeue
  // (vivid, for one, stamps the end of the frame period before that period is over).
  writer_->write(l.image, rr.image, std::min(l.t_us, l.dequeued_us), std::abs(l.t_us - rr.t_us),
                 static_cast<std::uint32_t>(std::lround(config_.exposure_us)), l.sequence);
  recycle(r.left.handle);
  recycle(r.right.handle);
}

void V4l2StereoCamera::checkHealth(TimeUs now_us) {
  for (auto& s : sides_) {
    auto& counters = counters_.side(s.index);
    const bool stale = !s.capture.isOpen() || s.failed || now_us - s.last_good_or_open_us > config_.stale_after_us;
    if (stale && !counters.stale.load(std::memory_order_relaxed)) {
      counters.stale.store(true, std::memory_order_relaxed);
      counters.stale_events.fetch_add(1, std::memory_order_relaxed);
    }
    if (!stale || now_us < s.next_reconnect_us) continue;
    s.next_reconnect_us = now_us + config_.reconnect_interval_us;
    closeSide(s);
    std::string error;
    if (openSide(s, &error) && s.capture.start(&error)) {
      s.last_good_or_open_us = monotonicUs();
      counters.reconnects.fetch_add(1, std::memory_order_relaxed);
    } else {
      closeSide(s);
      counters.reconnect_failures.fetch_add(1, std::memory_order_relaxed);
    }
  }
}

}  // namespace deepnav
