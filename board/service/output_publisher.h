#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "board/config/board_config.h"
#include "board/loop/live_loop.h"
#include "drivers/outputs/modbus_tcp_server.h"
#include "drivers/outputs/triple_buffer.h"
#include "drivers/outputs/udp_sender.h"

namespace deepnav {

// Hands every tick's solution to the vehicle: Modbus TCP registers and UDP datagrams (the MCAP
// recording is the loop's own). On the loop thread, onTick() only copies the solution into a triple
// buffer and wakes the outputs thread, which adds the loop counters and health bits, updates the
// register block and sends the datagrams. So a slow client or a full socket never touches the loop.
class OutputPublisher : public TickObserver {
 public:
  OutputPublisher() = default;
  ~OutputPublisher() override { stop(); }

  // Opens the outputs the board enables; loop supplies the counters. On error the message names the key.
  bool start(const BoardConfig::Outputs& config, const LiveLoop* loop, std::string* error);
  void stop();

  // Another observer called after this one on the loop thread (embedding, tests); nullptr: none.
  void chain(TickObserver* next) { next_ = next; }
  void onTick(const NavSolution& solution, const InputCounters& counters) override;

  // Health bits of the last window (set by the service's health monitor, carried by every output).
  void setHealth(std::uint32_t bits) { health_.store(bits, std::memory_order_relaxed); }
  // The latest complete output (for STATUS=); sequence 0 before the first tick.
  NavOutput latest() const;
  std::uint64_t datagramsSent() const { return udp_.sent(); }

 private:
  struct TickCopy {
    std::uint32_t sequence = 0;  // tick number on the loop thread: gaps mean the outputs skipped ticks
    NavSolution solution;
    InputCounters counters;
  };
  void run();

  const LiveLoop* loop_ = nullptr;
  TickObserver* next_ = nullptr;
  std::uint32_t loop_sequence_ = 0;  // loop thread only
  TripleBuffer<TickCopy> ticks_;
  std::atomic<std::uint32_t> tick_seq_{0};
  std::atomic<std::uint32_t> health_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
  bool modbus_on_ = false;
  ModbusTcpServer modbus_;
  UdpSender udp_;
  mutable std::mutex latest_mutex_;
  NavOutput latest_;
};

}  // namespace deepnav
