#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "drivers/parsers/sensor_stream_decoder.h"
#include "drivers/serial/serial_port.h"

namespace deepnav {

struct SerialSensorConfig {
  std::string device;  // e.g. /dev/ttyS1
  int baud = 115200;
  SerialPort::Parity parity = SerialPort::Parity::kNone;
  int stop_bits = 1;
  SensorProtocol protocol = SensorProtocol::kPd0;
  double reopen_interval_s = 1.0;  // after the device disappears, try to reopen this often
};

// One serial sensor (DVL, compass, AHRS): reads the port, stamps each read with the monotonic clock,
// decodes, hands samples to the sink. poll() is the whole steady-state step: it waits at most
// timeout_ms, allocates nothing, throws nothing; a vanished device is closed and reopened.
class SerialSensorDriver {
 public:
  bool init(const SerialSensorConfig& config, std::string* error);
  // One step: wait up to timeout_ms for bytes, decode them. Returns false while the port is down.
  bool poll(int timeout_ms, SampleSink* sink);
  const SensorStreamDecoder::Counters& counters() const { return decoder_.counters(); }
  uint64_t bytesRead() const { return bytes_read_; }
  // Times the port was opened again after the device vanished.
  uint64_t reopens() const { return reopens_; }

 private:
  SerialSensorConfig config_;
  SerialPort port_;
  SensorStreamDecoder decoder_;
  std::array<uint8_t, 4096> buffer_{};
  TimeUs next_reopen_us_ = 0;
  uint64_t reopens_ = 0;
  uint64_t bytes_read_ = 0;
};

}  // namespace deepnav
