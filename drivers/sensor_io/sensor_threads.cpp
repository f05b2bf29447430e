#include "drivers/sensor_io/sensor_threads.h"

#include "drivers/clock/monotonic_clock.h"

namespace deepnav {

uint8_t SensorThreads::canKinds(const SensorThreadsConfig& c) {
  uint8_t kinds = kSampleHeading | kSampleAttitude | kSampleImu;
  if (c.ahrs && c.ahrs->protocol == SensorProtocol::kXsens) kinds &= uint8_t(~(kSampleImu | kSampleAttitude));
  if (c.ahrs && c.ahrs->protocol == SensorProtocol::kNmea0183) kinds &= uint8_t(~kSampleHeading);
  return kinds;
}

bool SensorThreads::start(const SensorThreadsConfig& config, LiveInputs* inputs, std::string* error) {
  stop();
  config_ = config;
  stop_ = false;
  if (config.dvl) {
    dvl_ = std::make_unique<SerialSensorDriver>();
    if (!dvl_->init(*config.dvl, error)) return *error = "DVL: " + *error, false;
  }
  if (config.ahrs) {
    if (config.ahrs->protocol != SensorProtocol::kXsens && config.ahrs->protocol != SensorProtocol::kNmea0183) {
      return *error = "AHRS: protocol must be xsens or nmea0183", false;
    }
    ahrs_ = std::make_unique<SerialSensorDriver>();
    if (!ahrs_->init(*config.ahrs, error)) return *error = "AHRS: " + *error, false;
  }
  if (config.can) {
    can_ = std::make_unique<CanSensorDriver>();
    const bool ok = config.can_socket_fd >= 0 ? can_->initOnSocket(*config.can, config.can_socket_fd, error)
                                              : can_->init(*config.can, error);
    if (!ok) return *error = "CAN: " + *error, false;
  }
  if (config.depth) {
    depth_ = std::make_unique<ModbusDepthSensor>();
    if (!depth_->open(*config.depth, error)) return *error = "depth: " + *error, false;
  }
  if (dvl_) threads_.emplace_back(&SensorThreads::runSerial, this, dvl_.get(), LiveInputsSink(inputs, kSampleDvl));
  if (ahrs_) {
    const uint8_t kinds = config.ahrs->protocol == SensorProtocol::kXsens ? uint8_t(kSampleImu | kSampleAttitude) : uint8_t(kSampleHeading);
    threads_.emplace_back(&SensorThreads::runSerial, this, ahrs_.get(), LiveInputsSink(inputs, kinds));
  }
  if (can_) threads_.emplace_back(&SensorThreads::runCan, this, LiveInputsSink(inputs, canKinds(config)));
  if (depth_) threads_.emplace_back(&SensorThreads::runDepth, this, inputs);
  return true;
}

void SensorThreads::stop() {
  stop_ = true;
  for (std::thread& t : threads_) t.join();
  threads_.clear();
}

void SensorThreads::runSerial(SerialSensorDriver* driver, LiveInputsSink sink) {
  while (!stop_.load(std::memory_order_relaxed)) driver->poll(config_.poll_timeout_ms, &sink);
}

void SensorThreads::runCan(LiveInputsSink sink) {
  while (!stop_.load(std::memory_order_relaxed)) can_->poll(config_.poll_timeout_ms, &sink);
}

void SensorThreads::runDepth(LiveInputs* inputs) {
  const TimeUs period_us = sToUs(1.0 / config_.depth_rate_hz);
  TimeUs next_us = monotonicUs();
  std::string error;
  while (!stop_.load(std::memory_order_relaxed)) {
    DepthSample s;
    if (depth_->read(&s, &error)) {
      inputs->ring<DepthSample>().push(s);
    } else {
      depth_failures_.fetch_add(1, std::memory_order_relaxed);
    }
    depth_reads_.fetch_add(1, std::memory_order_relaxed);
    next_us += period_us;
    // Sleep in short steps so stop() is noticed within the poll timeout.
    while (!stop_.load(std::memory_order_relaxed) && monotonicUs() < next_us) {
      sleepUntilUs(std::min(next_us, monotonicUs() + TimeUs(config_.poll_timeout_ms) * 1000));
    }
  }
}

SensorThreads::Status SensorThreads::status() const {
  Status s;
  s.dvl_on = dvl_ != nullptr;
  s.ahrs_on = ahrs_ != nullptr;
  s.can_on = can_ != nullptr;
  s.depth_on = depth_ != nullptr;
  if (dvl_) {
    s.dvl = dvl_->counters();
    s.dvl_reopens = dvl_->reopens();
  }
  if (ahrs_) {
    s.ahrs = ahrs_->counters();
    s.ahrs_reopens = ahrs_->reopens();
  }
  if (can_) {
    s.can = can_->counters();
    s.can_bus_state = canBusStateName(can_->bus().state());
    s.can_tx_errors = can_->bus().txErrors();
    s.can_rx_errors = can_->bus().rxErrors();
  }
  s.depth_reads = depth_reads_.load(std::memory_order_relaxed);
  s.depth_failures = depth_failures_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace deepnav
