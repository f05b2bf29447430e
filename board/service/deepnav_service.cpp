#include "board/service/deepnav_service.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <thread>

#include "board/config/sensor_driver_configs.h"
#include "board/service/driver_summary.h"
#include "board/service/status_text.h"
#include "drivers/clock/monotonic_clock.h"
#include "drivers/realtime/realtime.h"

namespace deepnav {
namespace {

constexpr TimeUs kStartDelayUs = 200'000;     // threads start before the first replayed sample
constexpr TimeUs kDrainUs = 500'000;          // after a replay's last sample, before stopping
constexpr TimeUs kPollUs = 50'000;            // how often the main thread looks at stop requests
constexpr TimeUs kHealthWindowUs = 500'000;   // health evaluation period (at most half the watchdog)
constexpr TimeUs kStatusPeriodUs = 1'000'000;  // STATUS= period
constexpr TimeUs kThreadStartTimeoutUs = 2'000'000;

std::string utcStamp() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%dT%H%M%SZ", &tm);
  return buf;
}

bool prepareRecordingPath(const BoardConfig& c, const ServiceOptions& o, std::string* path, std::string* error) {
  if (o.no_recording) return true;
  if (!o.recording_path.empty()) {
    *path = o.recording_path;
    return true;
  }
  if (c.service.recording_dir.empty()) return true;
  std::error_code ec;
  std::filesystem::create_directories(c.service.recording_dir, ec);
  if (ec || ::access(c.service.recording_dir.c_str(), W_OK) != 0) {
    if (error) {
      *error = "service.recording_dir: " + c.service.recording_dir + " is not a writable directory" +
               (ec ? ": " + ec.message() : "");
    }
    return false;
  }
  *path = c.service.recording_dir + "/deepnav-" + utcStamp() + ".mcap";
  return true;
}

}  // namespace

DeepnavService::~DeepnavService() {
  std::string ignored;
  shutdown(&ignored);
}

bool DeepnavService::init(const ServiceOptions& options, std::string* error) {
  options_ = options;
  if (!notifier_.open(error)) return false;
  watchdog_us_ = SystemdNotifier::watchdogIntervalUs();
  notifier_.send("STATUS=validating " + options.board_path);
  if (!loadVehicleSetup(options.board_path, &setup_, error)) return false;
  if (!validateBoard(setup_, options.board_path, options.replay_path, &board_, error)) return false;
  live_ = board_.has_devices;
  const BoardConfig& c = setup_.config;
  if (board_.has_process_cpus && !setThreadCpus(board_.process_cpus, error)) {
    if (error) *error = "realtime.process_cpus: " + *error;
    return false;
  }
  if (c.realtime.mlockall && !lockAllMemory(error)) {
    if (error) *error = "realtime.mlockall: " + *error;
    return false;
  }
  if (!prepareRecordingPath(c, options, &recording_path_, error)) return false;
  // Outputs first: a busy port fails the start before a recording file is created.
  loop_ = std::make_unique<LiveLoop>();
  if (!publisher_.start(c.outputs, loop_.get(), error)) return false;
  if (live_ ? !openLiveDrivers(error) : !source_.open(board_.replay_path, error)) return false;
  const bool keep_state = !c.service.state_dir.empty();
  bool restore_workspace = false;
  if (keep_state && !prepareWorkspaceState(c.service.state_dir, setup_, loop_.get(), &restore_workspace, error)) {
    return false;
  }
  if (!loop_->init(setup_, recording_path_, error)) return false;
  if (keep_state && !attachWorkspaceState(c.service.state_dir, restore_workspace, loop_.get(), &workspace_saver_, error)) {
    return false;
  }
  publisher_.chain(options.tick_observer);
  loop_->setTickObserver(&publisher_);
  loop_->setThreadStartHook([this](const char* thread) { applyLoopThreadSettings(thread); });
  return true;
}

void DeepnavService::applyLoopThreadSettings(const char* thread) {
  setThreadName((std::string("deepnav-") + thread).c_str());
  if (std::string(thread) != "nav") return;
  const BoardConfig::Realtime& r = setup_.config.realtime;
  std::string why;
  if (board_.has_loop_cpus && !setThreadCpus(board_.loop_cpus, &why)) {
    loop_thread_error_ = "realtime.loop_cpus: " + why;
  } else if (r.loop_priority > 0 && !setThreadFifo(r.loop_priority, &why)) {
    loop_thread_error_ = "realtime.loop_priority: " + why;
  }
  loop_thread_state_.store(loop_thread_error_.empty() ? 1 : -1, std::memory_order_release);
}

// Live sources: the sensor drivers the board lists (serial DVL/AHRS, CAN, Modbus depth) and the stereo
// cameras; devices are opened here, before any thread starts, so a device that went away since the
// validation fails the start with its name.
bool DeepnavService::openLiveDrivers(std::string* error) {
  const BoardConfig& c = setup_.config;
  if (!sensorThreadsConfig(c, &sensor_config_, error)) return false;
  if (c.camera.source.driver.empty() || c.camera.source.driver == "none") return true;
  CameraSourceConfig camera = c.camera.source;
  camera.width_px = c.camera.width_px;
  camera.height_px = c.camera.height_px;
  camera.channels = c.camera.channels;
  camera.rate_hz = c.camera.rate_hz;
  cameras_ = makeCameraSource(camera, error);
  return cameras_ && cameras_->open(error);
}

bool DeepnavService::startLiveDrivers(std::string* error) {
  if (!sensors_.start(sensor_config_, &loop_->inputs(), error)) return false;
  return !cameras_ || cameras_->start(&loop_->inputs().pool, &loop_->inputs().frames, error);
}

bool DeepnavService::startThreads(std::string* error) {
  // Live: the loop's clock is the monotonic clock the drivers stamp with. Replay: the recording's clock
  // mapped onto now.
  const TimeUs offset = live_ ? 0 : source_.firstTimeUs() - (monotonicUs() + kStartDelayUs);
  if (!loop_->start(offset, error)) return false;
  running_ = true;
  const TimeUs deadline = monotonicUs() + kThreadStartTimeoutUs;
  while (loop_thread_state_.load(std::memory_order_acquire) == 0 && monotonicUs() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (loop_thread_state_.load(std::memory_order_acquire) != 1) {
    if (error) *error = loop_thread_error_.empty() ? "loop: the nav thread did not start" : loop_thread_error_;
    return false;
  }
  if (live_) return startLiveDrivers(error);
  source_.start(&loop_->inputs(), offset);
  return true;
}

void DeepnavService::evaluateHealth(bool* healthy) {
  const NavOutput last = publisher_.latest();
  HealthSample sample;
  sample.loop = loop_->stats();
  sample.recorder_drops = loop_->recorderDrops();
  sample.recorder_failures = loop_->recorderWriteFailures();
  sample.inputs_refused = loop_->inputsRefused();
  sample.vision_failures = loop_->visionFailures();
  sample.faults = last.solution.faults;
  sample.solution_finite = isFinite(last.solution);
  publisher_.setHealth(health_.update(sample));
  *healthy = health_.healthy();
}

bool DeepnavService::run(StopSignals* signals, std::string* error) {
  if (!startThreads(error)) {
    std::string ignored;
    shutdown(&ignored);
    return false;
  }
  const std::string sources = live_ ? std::string("live devices") : board_.replay_path;
  notifier_.send("READY=1\nSTATUS=running: " + sources);
  std::fprintf(stderr, "deepnav run: running (board %s, sources %s, recording %s, watchdog %s)\n",
               options_.board_path.c_str(), sources.c_str(),
               recording_path_.empty() ? "off" : recording_path_.c_str(),
               watchdog_us_ > 0 ? (std::to_string(watchdog_us_ / 1000) + " ms").c_str() : "off");
  const TimeUs window_us = watchdog_us_ > 0 ? std::min(kHealthWindowUs, watchdog_us_ / 2) : kHealthWindowUs;
  const TimeUs start_us = monotonicUs();
  TimeUs next_health = start_us + window_us;
  TimeUs next_status = start_us + kStatusPeriodUs;
  TimeUs source_done_us = 0;
  while (true) {
    const TimeUs now = monotonicUs();
    const TimeUs wait_us = std::min({kPollUs, next_health - now, next_status - now});
    if (signals) {
      if (const int sig = signals->wait(wait_us); sig != 0) {
        stop_reason_ = std::string("signal ") + (sig == SIGTERM ? "SIGTERM" : sig == SIGINT ? "SIGINT" : "SIGHUP");
        break;
      }
    } else if (wait_us > 0) {
      std::this_thread::sleep_for(std::chrono::microseconds(wait_us));
    }
    if (stop_requested_.load(std::memory_order_acquire)) {
      stop_reason_ = "requested";
      break;
    }
    const TimeUs t = monotonicUs();
    if (options_.duration_s > 0 && t - start_us >= sToUs(options_.duration_s)) {
      stop_reason_ = "duration";
      break;
    }
    if (!live_ && source_.finished() && source_done_us == 0) source_done_us = t;
    if (source_done_us > 0 && t - source_done_us >= kDrainUs) {
      stop_reason_ = "end of replay";
      break;
    }
    if (t >= next_health) {
      bool healthy = false;
      evaluateHealth(&healthy);
      // Only a loop that ticked since the last window feeds the watchdog.
      if (healthy && watchdog_us_ > 0) notifier_.send("WATCHDOG=1");
      next_health += window_us;
      if (next_health < t) next_health = t + window_us;
    }
    if (t >= next_status) {
      NavOutput out = publisher_.latest();
      out.health = health_.bits();
      notifier_.send("STATUS=" + formatStatus(out));
      next_status += kStatusPeriodUs;
      if (next_status < t) next_status = t + kStatusPeriodUs;
    }
  }
  notifier_.send("STOPPING=1\nSTATUS=stopping: " + stop_reason_);
  std::string why;
  shutdown(&why);
  if (!why.empty() && error) *error = why;
  return why.empty();
}

void DeepnavService::shutdown(std::string* error) {
  if (!running_) return;
  running_ = false;
  // The loop first: its last ticks still have their inputs, and the recording closes as soon as possible.
  std::string why;
  if (cameras_) cameras_->stop();
  sensors_.stop();
  const std::string drivers = formatDriverSummary(sensors_.status());
  if (!drivers.empty()) std::fprintf(stderr, "deepnav run: sensor drivers at stop: %s\n", drivers.c_str());
  const bool closed = loop_->stop(&why);
  source_.stop();
  publisher_.stop();
  if (!closed && error) *error = "recording: " + why;
  if (!source_.error().empty()) std::fprintf(stderr, "deepnav run: replay source: %s\n", source_.error().c_str());
}

}  // namespace deepnav
