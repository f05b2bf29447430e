#pragma once
#include <cstdint>
#include <string>

#include "drivers/can/can_bus_monitor.h"
#include "drivers/can/socketcan.h"
#include "drivers/parsers/can_field_mapping.h"
#include "drivers/parsers/n2k_assembler.h"
#include "drivers/parsers/sample_sink.h"

namespace deepnav {

struct CanSensorConfig {
  std::string interface;       // e.g. can0
  int heading_source = -1;     // NMEA 2000 source address of the compass (127250); -1: any
  int attitude_source = -1;    // source address of the attitude sensor (127257); -1: any
  std::string imu_mapping;     // CanFieldMapping spec for a non-NMEA-2000 IMU/compass; empty: none
  double bus_off_recovery_s = 1.0;  // restart the controller after this long in bus-off
};

// Compass, attitude sensor or IMU on a CAN bus: NMEA 2000 PGN 127250 (heading) and 127257 (attitude),
// single frame or fast packet, and/or the frames of a configured mapping. The socket's acceptance
// filters pass only those frames plus error frames; bus-off is detected from the error frames and,
// when the kernel does not restart the controller itself (restart-ms), the driver asks for a restart
// and reopens its socket after bus_off_recovery_s.
class CanSensorDriver {
 public:
  struct Counters {
    uint64_t frames = 0, messages = 0, samples = 0, sink_refused = 0, bad_frames = 0, ignored = 0;
    uint64_t reopens = 0, restart_requests_failed = 0;
  };

  bool init(const CanSensorConfig& config, std::string* error);
  // Tests: run the same logic on an already connected socket (socketpair carrying struct can_frame).
  bool initOnSocket(const CanSensorConfig& config, int fd, std::string* error);
  // One step: wait up to timeout_ms for a frame, handle it. False while the socket is down.
  bool poll(int timeout_ms, SampleSink* sink);
  // Handles one data frame (also used by poll()).
  void onFrame(const CanFrame& frame, TimeUs t_us, SampleSink* sink);

  const Counters& counters() const { return counters_; }
  const CanBusMonitor& bus() const { return monitor_; }

 private:
  bool configure(const CanSensorConfig& config, std::string* error);
  bool openSocket(std::string* error);
  void deliver(bool accepted);

  CanSensorConfig config_;
  SocketCan socket_;
  bool own_interface_ = true;  // false on an adopted socket: cannot be reopened
  CanBusMonitor monitor_;
  N2kAssembler assembler_;
  CanFieldMapping mapping_;
  CanFilter filters_[SocketCan::kMaxFilters];
  int num_filters_ = 0;
  Counters counters_;
};

}  // namespace deepnav
