#include "drivers/serial/serial_sensor_driver.h"

#include <poll.h>

#include "drivers/clock/monotonic_clock.h"

namespace deepnav {

bool SerialSensorDriver::init(const SerialSensorConfig& config, std::string* error) {
  config_ = config;
  if (!decoder_.init(config.protocol)) return *error = config.device + ": cannot initialise the decoder", false;
  return port_.open(config.device, config.baud, config.parity, config.stop_bits, error);
}

bool SerialSensorDriver::poll(int timeout_ms, SampleSink* sink) {
  if (!port_.isOpen()) {
    const TimeUs now = monotonicUs();
    if (now < next_reopen_us_) {
      ::poll(nullptr, 0, timeout_ms);
      return false;
    }
    std::string error;
    next_reopen_us_ = now + sToUs(config_.reopen_interval_s);
    if (!port_.open(config_.device, config_.baud, config_.parity, config_.stop_bits, &error)) return false;
    ++reopens_;
  }
  const ssize_t n = port_.read(buffer_.data(), buffer_.size(), timeout_ms);
  if (n < 0) {
    port_.close();
    next_reopen_us_ = monotonicUs() + sToUs(config_.reopen_interval_s);
    return false;
  }
  if (n > 0) {
    // The bytes' arrival time: the driver's read is the closest stamp a UART gives.
    bytes_read_ += uint64_t(n);
    decoder_.feed(buffer_.data(), size_t(n), monotonicUs(), sink);
  }
  return true;
}

}  // namespace deepnav
