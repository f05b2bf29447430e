#include "drivers/camera/aravis_stereo_camera.h"

#include <arpa/inet.h>
#include <arv.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "drivers/camera/gvcp_probe.h"
#include "drivers/clock/monotonic_clock.h"

namespace deepnav {
namespace {

ArvPixelFormat arvPixelFormat(PixelFormat f) {
  switch (f) {
    case PixelFormat::kMono8: return ARV_PIXEL_FORMAT_MONO_8;
    case PixelFormat::kBayerRG8: return ARV_PIXEL_FORMAT_BAYER_RG_8;
    case PixelFormat::kBayerGR8: return ARV_PIXEL_FORMAT_BAYER_GR_8;
    case PixelFormat::kBayerGB8: return ARV_PIXEL_FORMAT_BAYER_GB_8;
    case PixelFormat::kBayerBG8: return ARV_PIXEL_FORMAT_BAYER_BG_8;
    case PixelFormat::kRgb8: return ARV_PIXEL_FORMAT_RGB_8_PACKED;
    case PixelFormat::kBgr8: return ARV_PIXEL_FORMAT_BGR_8_PACKED;
    case PixelFormat::kYuyv: return ARV_PIXEL_FORMAT_YUV_422_YUYV_PACKED;
  }
  return ARV_PIXEL_FORMAT_MONO_8;
}

CameraFrameStatus frameStatusOf(ArvBufferStatus s) {
  switch (s) {
    case ARV_BUFFER_STATUS_SUCCESS: return CameraFrameStatus::kOk;
    case ARV_BUFFER_STATUS_CLEARED: return CameraFrameStatus::kCleared;
    case ARV_BUFFER_STATUS_TIMEOUT: return CameraFrameStatus::kTimeout;
    case ARV_BUFFER_STATUS_MISSING_PACKETS: return CameraFrameStatus::kMissingPackets;
    case ARV_BUFFER_STATUS_WRONG_PACKET_ID: return CameraFrameStatus::kWrongPacketId;
    case ARV_BUFFER_STATUS_SIZE_MISMATCH: return CameraFrameStatus::kSizeMismatch;
    case ARV_BUFFER_STATUS_FILLING: return CameraFrameStatus::kFilling;
    case ARV_BUFFER_STATUS_ABORTED: return CameraFrameStatus::kAborted;
    default: return CameraFrameStatus::kUnknown;
  }
}

// Takes the GError (if any): true when there was none; else fills *error with context and the message.
bool ok(GError*& e, const std::string& context, std::string* error) {
  if (e == nullptr) return true;
  if (error) *error = context + ": " + e->message;
  g_clear_error(&e);
  return false;
}

bool isIpv4(const std::string& s, bool* loopback) {
  in_addr a{};
  if (inet_pton(AF_INET, s.c_str(), &a) != 1) return false;
  *loopback = (ntohl(a.s_addr) >> 24) == 127;
  return true;
}

// CLOCK_REALTIME minus CLOCK_MONOTONIC, in microseconds: Aravis stamps buffers with the wall clock.
TimeUs realtimeMinusMonotonicUs() {
  const TimeUs mono = monotonicUs();
  const TimeUs real = g_get_real_time();
  return real - mono;
}

void onStreamEvent(void* user_data, ArvStreamCallbackType type, ArvBuffer* /*buffer*/) {
  if (type == ARV_STREAM_CALLBACK_TYPE_BUFFER_DONE) {
    static_cast<AravisStereoCamera*>(user_data)->notifyBufferReady();
  }
}

}  // namespace

// Heartbeat thread of an ArvGvDevice.
struct AravisControlLost {
  static void callback(ArvDevice* /*device*/, gpointer side_index_and_owner) {
    auto* side = static_cast<std::pair<AravisStereoCamera*, int>*>(side_index_and_owner);
    side->first->notifyControlLost(side->second);
  }
};

AravisStereoCamera::AravisStereoCamera(const CameraSourceConfig& config) : config_(config) {
  for (int i = 0; i < 2; ++i) {
    sides_[static_cast<std::size_t>(i)].owner = this;
    sides_[static_cast<std::size_t>(i)].index = i;
  }
  pairer_.setTolerance(static_cast<TimeUs>(std::llround(config_.pair_tolerance_ms * 1000.0)));
  pairer_.setMaxPending(config_.stream_buffers / 2);
}

AravisStereoCamera::~AravisStereoCamera() {
  stop();
  for (auto& s : sides_) closeSide(s);
}

void AravisStereoCamera::notifyBufferReady() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    buffer_ready_ = true;
  }
  wake_.notify_one();
}

void AravisStereoCamera::notifyControlLost(int side) {
  sides_[static_cast<std::size_t>(side)].control_lost.store(true, std::memory_order_release);
  counters_.side(side).control_lost.fetch_add(1, std::memory_order_relaxed);
  notifyBufferReady();
}

bool AravisStereoCamera::open(std::string* error) {
  if (!validateCameraSourceConfig(config_, error, &format_)) return false;
  if (openSide(sides_[0], error) && openSide(sides_[1], error)) return true;
  for (auto& s : sides_) closeSide(s);  // both cameras or neither
  return false;
}

bool AravisStereoCamera::openSide(Side& s, std::string* error) {
  const std::string& id = idOf(s);
  const std::string where = std::string(nameOf(s)) + " '" + id + "'";
  GError* e = nullptr;
  bool loopback = false;
  if (isIpv4(id, &loopback)) {
    s.address = id;
    s.camera = arv_camera_new(id.c_str(), &e);
  } else {
    // Match the name against what discovery reports; Aravis itself only opens by device id.
    arv_update_device_list();
    std::string device_id;
    for (unsigned i = 0; i < arv_get_n_devices(); ++i) {
      for (const char* field : {arv_get_device_id(i), arv_get_device_serial_nbr(i),
                                arv_get_device_physical_id(i), arv_get_device_address(i)}) {
        if (field != nullptr && id == field) device_id = arv_get_device_id(i);
      }
      const char* address = arv_get_device_address(i);
      if (!device_id.empty() && address != nullptr && isIpv4(address, &loopback)) s.address = address;
      if (!device_id.empty()) break;
    }
    if (device_id.empty()) {
      if (error) *error = where + ": no such camera among the " + std::to_string(arv_get_n_devices()) + " found";
      return false;
    }
    s.camera = arv_camera_new(device_id.c_str(), &e);
  }
  if (!ok(e, where + ": cannot open", error) || s.camera == nullptr) {
    if (s.camera) g_object_unref(s.camera);
    s.camera = nullptr;
    return false;
  }
  ArvDevice* device = arv_camera_get_device(s.camera);
  const bool gige = arv_camera_is_gv_device(s.camera);
  if (gige) {
    // On loopback there is no packet socket (it needs a real NIC); the plain UDP socket is used.
    if (loopback) {
      arv_gv_device_set_stream_options(ARV_GV_DEVICE(device), ARV_GV_STREAM_OPTION_PACKET_SOCKET_DISABLED);
    }
    if (config_.packet_size_bytes > 0) {
      arv_camera_gv_set_packet_size(s.camera, config_.packet_size_bytes, &e);
    } else {
      arv_camera_gv_auto_packet_size(s.camera, &e);
    }
    if (!ok(e, where + ": packet size (camera.packet_size_bytes)", error)) return closeSide(s), false;
    auto* cookie = new std::pair<AravisStereoCamera*, int>(this, s.index);
    g_signal_connect_data(device, "control-lost", G_CALLBACK(AravisControlLost::callback), cookie,
                          [](gpointer data, GClosure*) { delete static_cast<std::pair<AravisStereoCamera*, int>*>(data); },
                          static_cast<GConnectFlags>(0));
  }

  arv_camera_set_acquisition_mode(s.camera, ARV_ACQUISITION_MODE_CONTINUOUS, &e);
  if (!ok(e, where + ": AcquisitionMode Continuous", error)) return closeSide(s), false;
  arv_camera_set_pixel_format(s.camera, arvPixelFormat(format_), &e);
  if (!ok(e, where + ": PixelFormat " + config_.pixel_format + " (camera.pixel_format)", error)) {
    return closeSide(s), false;
  }
  arv_camera_set_region(s.camera, config_.offset_x_px, config_.offset_y_px, config_.width_px, config_.height_px, &e);
  gint x = 0, y = 0, w = 0, h = 0;
  if (e == nullptr) arv_camera_get_region(s.camera, &x, &y, &w, &h, &e);
  if (!ok(e, where + ": region (camera.width_px, height_px, offset_x_px, offset_y_px)", error)) {
    return closeSide(s), false;
  }
  if (x != config_.offset_x_px || y != config_.offset_y_px || w != config_.width_px || h != config_.height_px) {
    if (error) {
      *error = where + ": region " + std::to_string(config_.width_px) + "x" + std::to_string(config_.height_px) +
               "+" + std::to_string(config_.offset_x_px) + "+" + std::to_string(config_.offset_y_px) +
               " not accepted; the camera set " + std::to_string(w) + "x" + std::to_string(h) + "+" +
               std::to_string(x) + "+" + std::to_string(y) +
               " (camera.width_px, height_px, offset_x_px, offset_y_px)";
    }
    return closeSide(s), false;
  }

  if (config_.exposure_us > 0) {
    if (arv_camera_is_exposure_auto_available(s.camera, nullptr)) {
      arv_camera_set_exposure_time_auto(s.camera, ARV_AUTO_OFF, &e);
      g_clear_error(&e);
    }
    arv_camera_set_exposure_time(s.camera, config_.exposure_us, &e);
    if (!ok(e, where + ": ExposureTime (camera.exposure_us)", error)) return closeSide(s), false;
  } else {
    arv_camera_set_exposure_time_auto(s.camera, ARV_AUTO_CONTINUOUS, &e);
    if (!ok(e, where + ": ExposureAuto Continuous (camera.exposure_us: 0)", error)) return closeSide(s), false;
  }
  const double exposure = arv_camera_get_exposure_time(s.camera, &e);
  g_clear_error(&e);
  s.exposure_us = exposure > 0 ? static_cast<std::uint32_t>(std::lround(exposure)) : 0;

  if (config_.trigger == "free") {
    arv_camera_clear_triggers(s.camera, &e);
    if (e == nullptr) arv_camera_set_frame_rate(s.camera, config_.rate_hz, &e);
    if (!ok(e, where + ": AcquisitionFrameRate (camera.rate_hz)", error)) return closeSide(s), false;
  } else {
    const std::string source = config_.trigger == "software" ? "Software" : config_.trigger_line;
    arv_camera_set_trigger(s.camera, source.c_str(), &e);
    if (!ok(e, where + ": trigger source " + source + " (camera.trigger, camera.trigger_line)", error)) {
      return closeSide(s), false;
    }
  }

  s.stream = arv_camera_create_stream(s.camera, onStreamEvent, this, &e);
  if (!ok(e, where + ": cannot create the stream", error) || s.stream == nullptr) return closeSide(s), false;
  if (gige) {
    g_object_set(s.stream, "socket-buffer", ARV_GV_STREAM_SOCKET_BUFFER_AUTO, "packet-resend",
                 config_.packet_resend ? ARV_GV_STREAM_PACKET_RESEND_ALWAYS : ARV_GV_STREAM_PACKET_RESEND_NEVER,
                 nullptr);
  }
  const guint payload = arv_camera_get_payload(s.camera, &e);
  if (!ok(e, where + ": PayloadSize", error)) return closeSide(s), false;
  for (int i = 0; i < config_.stream_buffers; ++i) arv_stream_push_buffer(s.stream, arv_buffer_new_allocate(payload));
  s.control_lost.store(false);
  s.device_offset_valid = false;
  counters_.side(s.index).connected.store(true, std::memory_order_relaxed);
  return true;
}

void AravisStereoCamera::closeSide(Side& s) {
  std::array<FramePairer::Frame, FramePairer::kMaxPending> waiting{};
  const int n = pairer_.flush(s.index, &waiting);
  for (int i = 0; i < n; ++i) {
    counters_.unpaired.fetch_add(1, std::memory_order_relaxed);
    recycle(waiting[static_cast<std::size_t>(i)].handle);
  }
  if (s.camera != nullptr && s.acquiring) arv_camera_stop_acquisition(s.camera, nullptr);
  s.acquiring = false;
  if (s.stream != nullptr) {
    arv_stream_set_emit_signals(s.stream, FALSE);
    g_object_unref(s.stream);
    s.stream = nullptr;
  }
  if (s.camera != nullptr) {
    g_object_unref(s.camera);
    s.camera = nullptr;
  }
  counters_.side(s.index).connected.store(false, std::memory_order_relaxed);
}

bool AravisStereoCamera::startSide(Side& s, std::string* error) {
  GError* e = nullptr;
  {
    // A new acquisition: no trigger outstanding. A trigger unanswered for 2 periods is abandoned and
    // the camera waits up to 2 more for its late frame (trigger_tracker.h). An incomplete GigE frame
    // handed over later (when the next frame's packets arrive) is told apart by its leader's time.
    const TimeUs period_us = static_cast<TimeUs>(std::llround(1e6 / config_.rate_hz));
    std::lock_guard<std::mutex> lock(s.tracker_mutex);
    s.tracker.configure(2 * period_us, 2 * period_us);
    s.tracker.reset();
  }
  arv_camera_start_acquisition(s.camera, &e);
  if (!ok(e, std::string(nameOf(s)) + " '" + idOf(s) + "': AcquisitionStart", error)) return false;
  s.acquiring = true;
  s.last_good_or_open_us = monotonicUs();
  return true;
}

bool AravisStereoCamera::start(FramePool* pool, SpscRing<int>* frames, std::string* error) {
  const bool cameras_open = sides_[0].camera != nullptr && sides_[1].camera != nullptr;
  if (!checkStart(config_, pool, frames, cameras_open, error)) return false;
  writer_ = std::make_unique<StereoPairWriter>(pool, frames, &counters_);
  for (auto& s : sides_) {
    if (!startSide(s, error)) return false;
  }
  stop_.store(false);
  next_trigger_us_ = monotonicUs();
  thread_ = std::thread([this] { run(); });
  if (config_.trigger == "software") {
    for (auto& s : sides_) trigger_threads_[static_cast<std::size_t>(s.index)] = std::thread([this, &s] { runTrigger(s); });
  }
  return true;
}

void AravisStereoCamera::stop() {
  stop_.store(true, std::memory_order_release);
  wake_.notify_one();
  for (auto& t : trigger_threads_) {
    if (t.joinable()) t.join();
  }
  if (thread_.joinable()) thread_.join();
  for (auto& s : sides_) {
    if (s.camera != nullptr && s.acquiring) arv_camera_stop_acquisition(s.camera, nullptr);
    s.acquiring = false;
  }
}

void AravisStereoCamera::run() {
  while (!stop_.load(std::memory_order_acquire)) {
    for (auto& s : sides_) drain(s);
    checkHealth(monotonicUs());
    // Sleep until a buffer completes or the health check comes round.
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait_for(lock, std::chrono::milliseconds(10),
                   [this] { return buffer_ready_ || stop_.load(std::memory_order_acquire); });
    buffer_ready_ = false;
  }
}

void AravisStereoCamera::runTrigger(Side& s) {
  const TimeUs period_us = static_cast<TimeUs>(std::llround(1e6 / config_.rate_hz));
  TimeUs next_us = next_trigger_us_;  // the same schedule for both cameras
  auto& counters = counters_.side(s.index);
  while (!stop_.load(std::memory_order_acquire)) {
    sleepUntilUs(std::min(next_us, monotonicUs() + 20'000));
    const TimeUs now = monotonicUs();
    if (now < next_us) continue;  // woke early to look at stop_
    {
      std::lock_guard<std::mutex> lock(s.control_mutex);
      if (s.camera != nullptr && s.acquiring && !counters.stale.load(std::memory_order_relaxed)) {
        // The tick on the shared grid names the trigger on both cameras.
        const std::int64_t tick = (next_us - next_trigger_us_) / period_us;
        bool fire = false;
        {
          std::lock_guard<std::mutex> lock(s.tracker_mutex);
          fire = s.tracker.beginTrigger(tick, now);
          publishTriggerCounts(s);
        }
        if (fire) {
          GError* e = nullptr;
          arv_camera_software_trigger(s.camera, &e);
          if (e != nullptr) {
            g_clear_error(&e);
            {
              std::lock_guard<std::mutex> lock(s.tracker_mutex);
              s.tracker.triggerFailed(monotonicUs());
            }
            notifyControlLost(s.index);
          }
          counters.triggers.fetch_add(1, std::memory_order_relaxed);
        }
      }
    }
    // Next period on the shared grid; after a stall (a dead camera's retries) skip, never burst.
    next_us += period_us;
    if (next_us < now) next_us += ((now - next_us) / period_us + 1) * period_us;
  }
}

void AravisStereoCamera::drain(Side& s) {
  if (s.stream == nullptr) return;
  while (ArvBuffer* b = arv_stream_try_pop_buffer(s.stream)) handleBuffer(s, b);
}

void AravisStereoCamera::publishTriggerCounts(Side& s) {
  auto& counters = counters_.side(s.index);
  const TriggerTracker::Counts& c = s.tracker.counts();
  counters.trigger_skips.store(c.skipped, std::memory_order_relaxed);
  counters.trigger_timeouts.store(c.timeouts, std::memory_order_relaxed);
  counters.unattributed.store(c.unattributed, std::memory_order_relaxed);
}

std::int64_t AravisStereoCamera::triggerTickOf(Side& s, TimeUs arrival_us, TimeUs* written_us) {
  std::lock_guard<std::mutex> lock(s.tracker_mutex);
  const std::int64_t tick = s.tracker.onFrame(arrival_us, written_us);
  publishTriggerCounts(s);
  return tick;
}

void AravisStereoCamera::handleBuffer(Side& s, ArvBuffer* buffer) {
  auto& counters = counters_.side(s.index);
  // Every buffer, good or not, answers the camera's outstanding software trigger.
  const guint64 system_ns = arv_buffer_get_system_timestamp(buffer);
  const TimeUs arrival_us = system_ns == 0 ? monotonicUs()  // no packet of it arrived (cleared, aborted)
                                           : static_cast<TimeUs>(system_ns / 1000) - realtimeMinusMonotonicUs();
  const bool software = config_.trigger == "software";
  TimeUs written_us = 0;
  const std::int64_t tick = software ? triggerTickOf(s, arrival_us, &written_us) : -1;
  CameraFrameStatus status = frameStatusOf(arv_buffer_get_status(buffer));
  if (status == CameraFrameStatus::kOk && arv_buffer_get_payload_type(buffer) != ARV_BUFFER_PAYLOAD_TYPE_IMAGE) {
    status = CameraFrameStatus::kPayloadNotSupported;
  }
  if (status == CameraFrameStatus::kOk &&
      (arv_buffer_get_image_width(buffer) != config_.width_px ||
       arv_buffer_get_image_height(buffer) != config_.height_px ||
       arv_buffer_get_image_pixel_format(buffer) != arvPixelFormat(format_))) {
    status = CameraFrameStatus::kWrongFormat;
  }
  int slot = -1;
  for (int i = 0; i < kHeld && status == CameraFrameStatus::kOk; ++i) {
    if (s.held[static_cast<std::size_t>(i)].buffer == nullptr) {
      slot = i;
      break;
    }
  }
  counters.count(status);
  if (status == CameraFrameStatus::kOk) {
    // The camera is alive, whether or not this frame can be used.
    const TimeUs now_us = monotonicUs();
    counters.last_good_frame_us.store(now_us, std::memory_order_relaxed);
    s.last_good_or_open_us = now_us;
    if (counters.stale.load(std::memory_order_relaxed)) counters.stale.store(false, std::memory_order_relaxed);
  }
  const bool slow = status == CameraFrameStatus::kOk && software && tick >= 0 && config_.timestamp != "device" &&
                    exposureStartUnknown(s, written_us, arrival_us);
  if (slow) counters.slow_triggers.fetch_add(1, std::memory_order_relaxed);
  if (status != CameraFrameStatus::kOk || slot < 0 || (software && tick < 0) || slow) {
    arv_stream_push_buffer(s.stream, buffer);  // never passed on: straight back to the camera's stream
    return;
  }

  // Capture time = middle of the exposure. Host clock: the leader packet arrives right after the
  // readout, so mid-exposure is half an exposure earlier. Device clock: the camera latches the time
  // at exposure start; it is mapped onto the monotonic clock by the smallest arrival - device offset.
  TimeUs key_us = arrival_us;
  TimeUs t_us = arrival_us - s.exposure_us / 2;
  if (software && config_.timestamp != "device") {
    // Software trigger: the exposure starts when the trigger reaches the camera (GVCP write, well
    // under a millisecond); the write time is free of the stream's transit and receive delays.
    key_us = written_us;
    t_us = written_us + s.exposure_us / 2;
  } else if (config_.timestamp == "device") {
    key_us = static_cast<TimeUs>(arv_buffer_get_timestamp(buffer) / 1000);
    const TimeUs offset = arrival_us - key_us;
    if (!s.device_offset_valid || offset < s.device_offset_us) s.device_offset_us = offset;
    s.device_offset_valid = true;
    t_us = key_us + s.device_offset_us + s.exposure_us / 2;
  }
  s.held[static_cast<std::size_t>(slot)] = {buffer, t_us, tick};
  finish(pairer_.offer(s.index, key_us, s.index * kHeld + slot, tick));
}

// With software triggers and host time, a frame is stamped with its trigger's write time: the exposure
// started between that write and the leader's arrival less one exposure. When that window is wider than
// the pairing tolerance, the two frames of the tick may not be one instant: refused. The camera's
// acknowledgement of the write is no bound: a camera busy reading out, or Aravis's fake camera whose
// thread was late, exposes after acknowledging (seen 67-103 ms late, in 3 of 23 runs of
// service_cameras_test on an idle 2-core host, paired with the other camera's frame on time).
bool AravisStereoCamera::exposureStartUnknown(const Side& s, TimeUs written_us, TimeUs arrival_us) const {
  const TimeUs latest_start_us = arrival_us - static_cast<TimeUs>(s.exposure_us);
  return latest_start_us - written_us > static_cast<TimeUs>(std::llround(config_.pair_tolerance_ms * 1000.0));
}

AravisStereoCamera::Held& AravisStereoCamera::held(int handle) {
  return sides_[static_cast<std::size_t>(handle / kHeld)].held[static_cast<std::size_t>(handle % kHeld)];
}

void AravisStereoCamera::recycle(int handle) {
  Side& s = sides_[static_cast<std::size_t>(handle / kHeld)];
  Held& h = held(handle);
  if (h.buffer == nullptr) return;
  if (s.stream != nullptr) {
    arv_stream_push_buffer(s.stream, h.buffer);
  } else {
    g_object_unref(h.buffer);
  }
  h.buffer = nullptr;
}

void AravisStereoCamera::finish(const FramePairer::Result& r) {
  for (int i = 0; i < r.dropped_count; ++i) {
    counters_.unpaired.fetch_add(1, std::memory_order_relaxed);
    recycle(r.dropped[static_cast<std::size_t>(i)].handle);
  }
  if (!r.paired) return;
  const Held& l = held(r.left.handle);
  const Held& rr = held(r.right.handle);
  auto raw = [this](ArvBuffer* b) {
    RawImage img;
    size_t size = 0;
    img.data = static_cast<const std::uint8_t*>(arv_buffer_get_image_data(b, &size));
    img.size_bytes = size;
    img.width_px = arv_buffer_get_image_width(b);
    img.height_px = arv_buffer_get_image_height(b);
    img.format = format_;
    img.stride_bytes = static_cast<std::size_t>(img.width_px) * static_cast<std::size_t>(bytesPerPixelTimes2(format_)) / 2;
    return img;
  };
  const TimeUs skew_us = std::abs(r.left.t_us - r.right.t_us);
  // Sequence: the trigger tick with software triggers (gaps show skipped ticks), else the left frame id.
  writer_->write(raw(l.buffer), raw(rr.buffer), l.t_us, skew_us, sides_[0].exposure_us,
                 l.tick >= 0 ? static_cast<std::uint64_t>(l.tick) : arv_buffer_get_frame_id(l.buffer));
  recycle(r.left.handle);
  recycle(r.right.handle);
}

void AravisStereoCamera::checkHealth(TimeUs now_us) {
  for (auto& s : sides_) {
    auto& counters = counters_.side(s.index);
    const bool lost = s.control_lost.load(std::memory_order_acquire);
    const bool stale = s.camera == nullptr || now_us - s.last_good_or_open_us > config_.stale_after_us;
    if (stale && !counters.stale.load(std::memory_order_relaxed)) {
      counters.stale.store(true, std::memory_order_relaxed);
      counters.stale_events.fetch_add(1, std::memory_order_relaxed);
    }
    if (!(stale || lost) || now_us < s.next_reconnect_us) continue;
    // Opening an absent camera blocks for seconds: ask first whether anything answers there.
    if (!s.address.empty() && !gvcpDeviceAnswers(s.address, 100)) {
      counters.reconnect_failures.fetch_add(1, std::memory_order_relaxed);
      s.next_reconnect_us = now_us + config_.reconnect_interval_us;
      continue;
    }
    std::unique_lock<std::mutex> control(s.control_mutex, std::try_to_lock);
    if (!control.owns_lock()) continue;  // the trigger thread is busy: next round
    s.next_reconnect_us = now_us + config_.reconnect_interval_us;
    closeSide(s);
    std::string error;
    if (openSide(s, &error) && startSide(s, &error)) {
      counters.stale.store(false, std::memory_order_relaxed);
      counters.reconnects.fetch_add(1, std::memory_order_relaxed);
    } else {
      closeSide(s);
      counters.reconnect_failures.fetch_add(1, std::memory_order_relaxed);
    }
  }
}

}  // namespace deepnav
