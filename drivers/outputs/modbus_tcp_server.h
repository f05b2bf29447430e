#pragma once
#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "drivers/outputs/register_map.h"

typedef struct _modbus modbus_t;
typedef struct _modbus_mapping_t modbus_mapping_t;

namespace deepnav {

// A read-only Modbus TCP server (libmodbus) of the register map in register_map.h, for the vehicle PLC.
// Its thread serves up to max_clients connections; update() hands it a new register block without ever
// waiting on a client (the block is copied under a short lock, replies go out from the server's own copy).
// Writes are answered with exception 1 (illegal function): the map belongs to deepnav.
class ModbusTcpServer {
 public:
  ModbusTcpServer() = default;
  ~ModbusTcpServer() { stop(); }
  ModbusTcpServer(const ModbusTcpServer&) = delete;
  ModbusTcpServer& operator=(const ModbusTcpServer&) = delete;

  // Listens on address:port (address "0.0.0.0": every interface); on error the message names the address.
  bool start(const std::string& address, int port, int max_clients, std::string* error);
  void stop();
  void update(const NavOutput& out);

 private:
  void run();
  void serve(int fd, bool* keep);

  modbus_t* ctx_ = nullptr;
  modbus_mapping_t* served_ = nullptr;  // the server thread's copy
  int listen_fd_ = -1;
  int max_clients_ = 1;
  std::vector<int> client_fds_;
  std::mutex pending_mutex_;
  std::array<std::uint16_t, reg::kCount> pending_{};
  bool pending_fresh_ = false;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

}  // namespace deepnav
