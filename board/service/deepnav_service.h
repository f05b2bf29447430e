#pragma once
#include <atomic>
#include <memory>
#include <string>

#include "board/config/vehicle_setup.h"
#include "board/loop/live_loop.h"
#include "board/service/board_validation.h"
#include "board/service/health_monitor.h"
#include "board/service/output_publisher.h"
#include "board/service/workspace_state.h"
#include "drivers/camera/camera_source.h"
#include "drivers/replay/replay_source.h"
#include "drivers/sensor_io/sensor_threads.h"
#include "drivers/systemd/notifier.h"
#include "drivers/systemd/stop_signals.h"

namespace deepnav {

struct ServiceOptions {
  std::string board_path;
  std::string replay_path;      // overrides sources.replay_path
  std::string recording_path;   // overrides service.recording_dir (a file path)
  bool no_recording = false;
  double duration_s = 0.0;      // stop after this long (0: until a stop signal, or the end of a replay)
  TickObserver* tick_observer = nullptr;  // an extra observer of every tick (embedding, tests)
};

// `deepnav run`: the vehicle's service. init() loads and validates the board and allocates everything
// (loop, vision worker, recorder, outputs); run() starts the threads, tells systemd READY=1, feeds its
// watchdog while the nav loop is healthy, reports STATUS= with stage and health, and stops cleanly (the
// recording closed) on a stop signal, requestStop(), the end of a replay or the duration.
class DeepnavService {
 public:
  DeepnavService() = default;
  ~DeepnavService();
  DeepnavService(const DeepnavService&) = delete;
  DeepnavService& operator=(const DeepnavService&) = delete;

  // Failure means the board is not fit to run: the message names the key or device.
  bool init(const ServiceOptions& options, std::string* error);
  // Runs until stopped; false on a runtime failure. signals: the stop signals, blocked by the caller
  // before init() so that every thread inherits the mask (nullptr: only requestStop() and the end
  // conditions stop the run).
  bool run(StopSignals* signals, std::string* error);
  void requestStop() { stop_requested_.store(true, std::memory_order_release); }

  const std::string& recordingPath() const { return recording_path_; }
  // Why run() returned: "signal SIGTERM", "end of replay", "duration", "requested".
  const std::string& stopReason() const { return stop_reason_; }
  NavOutput lastOutput() const { return publisher_.latest(); }

 private:
  bool startThreads(std::string* error);
  bool openLiveDrivers(std::string* error);
  bool startLiveDrivers(std::string* error);
  void applyLoopThreadSettings(const char* thread);
  void evaluateHealth(bool* healthy);
  void shutdown(std::string* error);

  ServiceOptions options_;
  VehicleSetup setup_;
  ValidatedBoard board_;
  std::string recording_path_;
  std::unique_ptr<WorkspaceSaver> workspace_saver_;  // service.state_dir (before loop_: outlives its threads)
  std::unique_ptr<LiveLoop> loop_;
  ReplaySource source_;
  bool live_ = false;                       // the board's devices are the sources (else a replay)
  std::unique_ptr<CameraSource> cameras_;   // live stereo pair, when camera.driver is not none
  SensorThreadsConfig sensor_config_;
  SensorThreads sensors_;
  OutputPublisher publisher_;
  HealthMonitor health_;
  SystemdNotifier notifier_;
  TimeUs watchdog_us_ = 0;
  std::atomic<bool> stop_requested_{false};
  std::atomic<int> loop_thread_state_{0};  // 0 not started, 1 settings applied, -1 failed
  std::string loop_thread_error_;
  std::string stop_reason_;
  bool running_ = false;
};

}  // namespace deepnav
