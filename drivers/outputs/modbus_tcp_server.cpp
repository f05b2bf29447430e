#include "drivers/outputs/modbus_tcp_server.h"

#include <modbus/modbus.h>
#include <sys/select.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace deepnav {
namespace {

bool isWriteFunction(std::uint8_t f) {
  switch (f) {
    case MODBUS_FC_WRITE_SINGLE_COIL:
    case MODBUS_FC_WRITE_SINGLE_REGISTER:
    case MODBUS_FC_WRITE_MULTIPLE_COILS:
    case MODBUS_FC_WRITE_MULTIPLE_REGISTERS:
    case MODBUS_FC_MASK_WRITE_REGISTER:
    case MODBUS_FC_WRITE_AND_READ_REGISTERS:
      return true;
    default:
      return false;
  }
}

}  // namespace

bool ModbusTcpServer::start(const std::string& address, int port, int max_clients, std::string* error) {
  const std::string where = "Modbus TCP server on " + address + ":" + std::to_string(port);
  ctx_ = modbus_new_tcp(address.c_str(), port);
  served_ = modbus_mapping_new_start_address(0, 0, 0, 0, 0, reg::kCount, 0, reg::kCount);
  if (!ctx_ || !served_) {
    if (error) *error = where + ": cannot allocate the libmodbus context";
    stop();
    return false;
  }
  // A client that starts a request must finish it promptly; the thread only reads readable sockets.
  modbus_set_byte_timeout(ctx_, 0, 200000);
  modbus_set_indication_timeout(ctx_, 0, 200000);
  listen_fd_ = modbus_tcp_listen(ctx_, max_clients);
  if (listen_fd_ < 0) {
    if (error) *error = where + ": cannot listen: " + modbus_strerror(errno);
    stop();
    return false;
  }
  max_clients_ = max_clients;
  client_fds_.reserve(static_cast<std::size_t>(max_clients));
  stop_.store(false);
  thread_ = std::thread([this] { run(); });
  return true;
}

void ModbusTcpServer::stop() {
  stop_.store(true, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
  for (int fd : client_fds_) ::close(fd);
  client_fds_.clear();
  if (listen_fd_ >= 0) ::close(listen_fd_);
  listen_fd_ = -1;
  if (ctx_) modbus_free(ctx_);
  ctx_ = nullptr;
  if (served_) modbus_mapping_free(served_);
  served_ = nullptr;
}

void ModbusTcpServer::update(const NavOutput& out) {
  std::array<std::uint16_t, reg::kCount> regs;
  encodeRegisters(out, regs.data());
  std::lock_guard<std::mutex> lock(pending_mutex_);
  pending_ = regs;
  pending_fresh_ = true;
}

void ModbusTcpServer::run() {
  while (!stop_.load(std::memory_order_acquire)) {
    fd_set readable;
    FD_ZERO(&readable);
    FD_SET(listen_fd_, &readable);
    int max_fd = listen_fd_;
    for (int fd : client_fds_) {
      FD_SET(fd, &readable);
      max_fd = std::max(max_fd, fd);
    }
    timeval timeout{0, 100000};  // wake up to notice stop()
    const int n = ::select(max_fd + 1, &readable, nullptr, nullptr, &timeout);
    if (n <= 0) continue;
    if (FD_ISSET(listen_fd_, &readable)) {
      int listen_fd = listen_fd_;
      const int fd = modbus_tcp_accept(ctx_, &listen_fd);
      if (fd >= 0 && static_cast<int>(client_fds_.size()) < max_clients_) {
        client_fds_.push_back(fd);
      } else if (fd >= 0) {
        ::close(fd);  // over the limit: refuse politely by closing
      }
    }
    for (std::size_t i = 0; i < client_fds_.size();) {
      bool keep = true;
      if (FD_ISSET(client_fds_[i], &readable)) serve(client_fds_[i], &keep);
      if (keep) {
        ++i;
      } else {
        ::close(client_fds_[i]);
        client_fds_.erase(client_fds_.begin() + static_cast<std::ptrdiff_t>(i));
      }
    }
  }
}

void ModbusTcpServer::serve(int fd, bool* keep) {
  std::uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
  modbus_set_socket(ctx_, fd);
  const int rc = modbus_receive(ctx_, query);
  if (rc < 0) {
    *keep = false;  // closed by the client, or a malformed request
    return;
  }
  if (rc == 0) return;
  {
    std::lock_guard<std::mutex> lock(pending_mutex_);
    if (pending_fresh_) {
      std::copy(pending_.begin(), pending_.end(), served_->tab_registers);
      std::copy(pending_.begin(), pending_.end(), served_->tab_input_registers);
      pending_fresh_ = false;
    }
  }
  const int header = modbus_get_header_length(ctx_);
  if (isWriteFunction(query[header])) {
    if (modbus_reply_exception(ctx_, query, MODBUS_EXCEPTION_ILLEGAL_FUNCTION) < 0) *keep = false;
    return;
  }
  if (modbus_reply(ctx_, query, rc, served_) < 0) *keep = false;
}

}  // namespace deepnav
