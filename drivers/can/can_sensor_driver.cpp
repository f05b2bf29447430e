#include "drivers/can/can_sensor_driver.h"

#include <algorithm>
#include <poll.h>

#include "drivers/clock/monotonic_clock.h"
#include "drivers/parsers/n2k_heading_pgns.h"

namespace deepnav {

bool CanSensorDriver::configure(const CanSensorConfig& config, std::string* error) {
  config_ = config;
  monitor_ = CanBusMonitor(config.bus_off_recovery_s);
  counters_ = {};
  if (!mapping_.parse(config.imu_mapping, error)) return false;
  // PDU2 PGNs sit in identifier bits 8-25 (DP, PF, PS); priority and source are free. Mapped
  // identifiers are accepted exactly. More than the filter table holds: accept every frame instead and
  // let onFrame() sort them.
  num_filters_ = 0;
  for (uint32_t pgn : {kPgnVesselHeading, kPgnAttitude}) filters_[num_filters_++] = {pgn << 8, 0x03FFFF00u, true};
  for (int i = 0; i < mapping_.numFields(); ++i) {
    CanFilter f;
    f.id = mapping_.fieldId(i, &f.extended);
    f.mask = f.extended ? 0x1FFFFFFFu : 0x7FFu;
    const bool seen = std::any_of(filters_, filters_ + num_filters_, [&](const CanFilter& g) {
      return g.id == f.id && g.mask == f.mask && g.extended == f.extended;
    });
    if (seen) continue;
    if (num_filters_ == SocketCan::kMaxFilters) {
      num_filters_ = 0;
      break;
    }
    filters_[num_filters_++] = f;
  }
  return true;
}

bool CanSensorDriver::openSocket(std::string* error) {
  return socket_.open(config_.interface, filters_, num_filters_, error);
}

bool CanSensorDriver::init(const CanSensorConfig& config, std::string* error) {
  if (!configure(config, error)) return false;
  own_interface_ = true;
  return openSocket(error);
}

bool CanSensorDriver::initOnSocket(const CanSensorConfig& config, int fd, std::string* error) {
  if (!configure(config, error)) return false;
  own_interface_ = false;
  socket_.adopt(fd);
  return true;
}

void CanSensorDriver::deliver(bool accepted) {
  ++counters_.samples;
  if (!accepted) ++counters_.sink_refused;
}

void CanSensorDriver::onFrame(const CanFrame& frame, TimeUs t_us, SampleSink* sink) {
  ++counters_.frames;
  monitor_.onDataFrame();
  if (mapping_.matches(frame)) {
    CanFieldMapping::Output out;
    if (!mapping_.apply(frame, t_us, &out)) {
      ++counters_.bad_frames;
      return;
    }
    if (out.has_imu) deliver(sink->onImu(out.imu));
    if (out.has_heading) deliver(sink->onHeading(out.heading));
    if (out.has_attitude) deliver(sink->onAttitude(out.attitude));
    return;
  }
  N2kMessage m;
  const char* why = "";
  const N2kAssembler::Result r = assembler_.add(frame, &m, &why);
  if (r == N2kAssembler::Result::kError) ++counters_.bad_frames;
  if (r != N2kAssembler::Result::kMessage) return;
  ++counters_.messages;
  if (m.pgn == kPgnVesselHeading && (config_.heading_source < 0 || m.source == config_.heading_source)) {
    N2kVesselHeading h;
    HeadingSample s;
    if (!decodeN2kVesselHeading(m, &h, &why)) return void(++counters_.bad_frames);
    if (headingSampleFromN2k(h, t_us, &s)) return deliver(sink->onHeading(s));
  } else if (m.pgn == kPgnAttitude && (config_.attitude_source < 0 || m.source == config_.attitude_source)) {
    N2kAttitude a;
    AttitudeSample s;
    if (!decodeN2kAttitude(m, &a, &why)) return void(++counters_.bad_frames);
    if (attitudeSampleFromN2k(a, t_us, &s)) return deliver(sink->onAttitude(s));
  }
  ++counters_.ignored;
}

bool CanSensorDriver::poll(int timeout_ms, SampleSink* sink) {
  const TimeUs now = monotonicUs();
  if (monitor_.recoveryDue(now) && own_interface_) {
    std::string error;
    monitor_.markRecoveryAttempt(now);
    if (!SocketCan::requestRestart(config_.interface, &error)) ++counters_.restart_requests_failed;
    if (openSocket(&error)) ++counters_.reopens;
  }
  if (!socket_.isOpen()) {
    std::string error;
    if (!own_interface_ || !openSocket(&error)) {
      ::poll(nullptr, 0, timeout_ms);
      return false;
    }
    ++counters_.reopens;
  }
  CanFrame frame;
  uint32_t error_id = 0;
  switch (socket_.read(&frame, &error_id, timeout_ms)) {
    case SocketCan::Read::kFrame: onFrame(frame, monotonicUs(), sink); return true;
    case SocketCan::Read::kErrorFrame: monitor_.onErrorFrame(error_id, frame, monotonicUs()); return true;
    case SocketCan::Read::kTimeout: return true;
    case SocketCan::Read::kFailed: socket_.close(); return false;
  }
  return true;
}

}  // namespace deepnav
