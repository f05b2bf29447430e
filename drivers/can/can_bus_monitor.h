#pragma once
#include <cstdint>

#include "drivers/parsers/can_frame.h"
#include "nav/types/time.h"

namespace deepnav {

// Controller state of a CAN interface, followed from the kernel's error frames (linux/can/error.h):
// CAN_ERR_CRTL with the warning/passive bits, CAN_ERR_BUSOFF, CAN_ERR_RESTARTED. Pure logic: the socket
// code hands it every error frame and the time; it says when a bus-off has lasted long enough that
// the driver should ask for a restart itself (when the interface has no restart-ms of its own).
class CanBusMonitor {
 public:
  enum class State { kActive, kWarning, kPassive, kBusOff };

  explicit CanBusMonitor(double recovery_s = 1.0) : recovery_us_(sToUs(recovery_s)) {}

  // An error frame (identifier with CAN_ERR_FLAG, as received): updates the state and the counters.
  void onErrorFrame(uint32_t can_id, const CanFrame& frame, TimeUs t_us);
  // A data frame arrived: the controller is receiving again.
  void onDataFrame();
  // True when the bus has been off for the recovery time without a restart: the driver should restart
  // the controller (and reopen its socket). Call markRecoveryAttempt() after trying.
  bool recoveryDue(TimeUs t_us) const;
  void markRecoveryAttempt(TimeUs t_us);

  State state() const { return state_; }
  bool busOff() const { return state_ == State::kBusOff; }
  uint64_t busOffCount() const { return bus_off_count_; }
  uint64_t restarts() const { return restarts_; }
  uint64_t errorFrames() const { return error_frames_; }
  uint64_t recoveryAttempts() const { return recovery_attempts_; }
  // The controller's transmit and receive error counters from the last error-counter frame.
  int txErrors() const { return tx_errors_; }
  int rxErrors() const { return rx_errors_; }

 private:
  TimeUs recovery_us_;
  State state_ = State::kActive;
  TimeUs bus_off_since_us_ = 0;
  TimeUs last_attempt_us_ = 0;
  uint64_t bus_off_count_ = 0, restarts_ = 0, error_frames_ = 0, recovery_attempts_ = 0;
  int tx_errors_ = 0, rx_errors_ = 0;
};

const char* canBusStateName(CanBusMonitor::State state);

}  // namespace deepnav
