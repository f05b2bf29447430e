#include "board/service/output_publisher.h"

#include "board/service/health_monitor.h"
#include "drivers/outputs/nav_datagram.h"
#include "drivers/realtime/realtime.h"

namespace deepnav {

bool OutputPublisher::start(const BoardConfig::Outputs& c, const LiveLoop* loop, std::string* error) {
  loop_ = loop;
  if (c.modbus_enabled) {
    std::string why;
    if (!modbus_.start(c.modbus_address, c.modbus_port, c.modbus_max_clients, &why)) {
      if (error) *error = "outputs.modbus_port: " + why;
      return false;
    }
    modbus_on_ = true;
  }
  if (!c.udp_destinations.empty()) {
    std::string why;
    if (!udp_.open(c.udp_destinations, &why)) {
      if (error) *error = "outputs.udp_destinations: " + why;
      return false;
    }
  }
  stop_.store(false);
  thread_ = std::thread([this] { run(); });
  return true;
}

void OutputPublisher::stop() {
  stop_.store(true, std::memory_order_release);
  tick_seq_.fetch_add(1, std::memory_order_release);
  tick_seq_.notify_one();
  if (thread_.joinable()) thread_.join();
  if (modbus_on_) modbus_.stop();
  modbus_on_ = false;
}

void OutputPublisher::onTick(const NavSolution& solution, const InputCounters& counters) {
  TickCopy& slot = ticks_.back();
  slot.sequence = ++loop_sequence_;
  slot.solution = solution;
  slot.counters = counters;
  ticks_.publish();
  tick_seq_.fetch_add(1, std::memory_order_release);
  tick_seq_.notify_one();
  if (next_) next_->onTick(solution, counters);
}

NavOutput OutputPublisher::latest() const {
  std::lock_guard<std::mutex> lock(latest_mutex_);
  return latest_;
}

void OutputPublisher::run() {
  setThreadName("deepnav-outputs");
  std::uint32_t seen = tick_seq_.load(std::memory_order_acquire);
  NavOutput out;
  std::uint8_t datagram[kNavDatagramSize];
  while (true) {
    // stop() may have run before this thread first read the sequence (a start-up that fails right after
    // start()): its increment is then already in `seen` and the wait would never return.
    if (stop_.load(std::memory_order_acquire)) return;
    tick_seq_.wait(seen, std::memory_order_acquire);
    seen = tick_seq_.load(std::memory_order_acquire);
    if (stop_.load(std::memory_order_acquire)) return;
    if (!ticks_.update()) continue;
    const TickCopy& t = ticks_.front();
    out.sequence = t.sequence;
    out.solution = t.solution;
    out.health = health_.load(std::memory_order_relaxed);
    HealthSample sample;
    sample.loop = loop_->stats();
    sample.recorder_drops = loop_->recorderDrops();
    sample.inputs_refused = loop_->inputsRefused();
    fillLoopCounters(sample, &out.counters);
    out.counters.imu = t.counters.imu;
    out.counters.dvl = t.counters.dvl;
    out.counters.depth = t.counters.depth;
    out.counters.heading = t.counters.heading;
    out.counters.attitude = t.counters.attitude;
    out.counters.vision = t.counters.vision;
    if (modbus_on_) modbus_.update(out);
    if (udp_.destinationCount() > 0) {
      encodeNavDatagram(out, datagram);
      udp_.send(datagram, sizeof datagram);
    }
    std::lock_guard<std::mutex> lock(latest_mutex_);
    latest_ = out;
  }
}

}  // namespace deepnav
