#include "drivers/can/can_bus_monitor.h"

#include <linux/can.h>
#include <linux/can/error.h>

namespace deepnav {

void CanBusMonitor::onErrorFrame(uint32_t can_id, const CanFrame& f, TimeUs t_us) {
  ++error_frames_;
  if (can_id & CAN_ERR_CNT) {  // error counters in bytes 6 (tx) and 7 (rx)
    tx_errors_ = f.data[6];
    rx_errors_ = f.data[7];
  }
  if (can_id & CAN_ERR_RESTARTED) {
    if (state_ == State::kBusOff) ++restarts_;
    state_ = State::kActive;
  }
  if (can_id & CAN_ERR_CRTL) {
    const uint8_t c = f.data[1];
    if (c & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) {
      state_ = State::kPassive;
    } else if (c & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) {
      if (state_ != State::kPassive) state_ = State::kWarning;
    } else if (c & CAN_ERR_CRTL_ACTIVE) {
      state_ = State::kActive;
    }
  }
  if (can_id & CAN_ERR_BUSOFF) {
    if (state_ != State::kBusOff) {
      ++bus_off_count_;
      bus_off_since_us_ = t_us;
      last_attempt_us_ = t_us;
    }
    state_ = State::kBusOff;
  }
}

void CanBusMonitor::onDataFrame() {
  if (state_ == State::kBusOff) ++restarts_;
  if (state_ == State::kBusOff) state_ = State::kActive;
}

bool CanBusMonitor::recoveryDue(TimeUs t_us) const {
  return state_ == State::kBusOff && t_us - last_attempt_us_ >= recovery_us_ && t_us - bus_off_since_us_ >= recovery_us_;
}

void CanBusMonitor::markRecoveryAttempt(TimeUs t_us) {
  ++recovery_attempts_;
  last_attempt_us_ = t_us;
}

const char* canBusStateName(CanBusMonitor::State state) {
  switch (state) {
    case CanBusMonitor::State::kActive: return "error-active";
    case CanBusMonitor::State::kWarning: return "error-warning";
    case CanBusMonitor::State::kPassive: return "error-passive";
    case CanBusMonitor::State::kBusOff: return "bus-off";
  }
  return "?";
}

}  // namespace deepnav
