#pragma once
// A Modbus RTU pressure sensor for tests: a libmodbus slave on the master side of a pty pair, answering
// until destroyed; the driver under test opens path(), the pty's slave side.
#include <modbus.h>
#include <pty.h>
#include <sys/select.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstring>
#include <string>
#include <thread>

namespace deepnav::test {

class FakeSensor {
 public:
  explicit FakeSensor(int slave_id) {
    char name[128];
    if (openpty(&master_, &slave_, name, nullptr, nullptr) != 0) return;
    path_ = name;
    ctx_ = modbus_new_rtu(name, 115200, 'N', 8, 1);  // the device name is not opened: the socket is set below
    modbus_set_slave(ctx_, slave_id);
    modbus_set_socket(ctx_, master_);
    map_ = modbus_mapping_new(0, 0, 100, 100);
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeSensor() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (map_) modbus_mapping_free(map_);
    if (ctx_) modbus_free(ctx_);
    if (master_ >= 0) ::close(master_);
    if (slave_ >= 0) ::close(slave_);
  }
  const std::string& path() const { return path_; }
  // Float32 pressure in pascals at input registers 10-11, high word first.
  void setPressure(float pa) {
    uint32_t bits;
    std::memcpy(&bits, &pa, 4);
    map_->tab_input_registers[10] = uint16_t(bits >> 16);
    map_->tab_input_registers[11] = uint16_t(bits & 0xFFFF);
  }
  void setHolding(int address, uint16_t value) { map_->tab_registers[address] = value; }

 private:
  void serve() {
    uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
    while (!stop_) {
      fd_set set;
      FD_ZERO(&set);
      FD_SET(master_, &set);
      timeval tv{0, 20000};
      if (::select(master_ + 1, &set, nullptr, nullptr, &tv) <= 0) continue;
      const int n = modbus_receive(ctx_, query);
      if (n > 0) modbus_reply(ctx_, query, n, map_);
    }
  }

  int master_ = -1, slave_ = -1;
  std::string path_;
  modbus_t* ctx_ = nullptr;
  modbus_mapping_t* map_ = nullptr;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

}  // namespace deepnav::test
