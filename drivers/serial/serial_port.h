#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <sys/types.h>

namespace deepnav {

// A serial line (termios): raw mode, 8 data bits, no flow control, non-blocking; parity and stop bits
// as configured. read() waits at most timeout_ms with poll(), so a driver thread never blocks for
// longer than its timeout and can notice a stop request.
class SerialPort {
 public:
  enum class Parity { kNone, kEven, kOdd };
  SerialPort() = default;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;
  ~SerialPort();

  // Baud rates: the POSIX/Linux standard ones from 1200 to 4000000.
  bool open(const std::string& device, int baud, Parity parity, int stop_bits, std::string* error);
  void close();
  bool isOpen() const { return fd_ >= 0; }
  int fd() const { return fd_; }

  // Bytes read (> 0), 0 on timeout, -1 on error or hang-up (the device went away: close and reopen).
  ssize_t read(uint8_t* data, size_t n, int timeout_ms);
  // Writes everything (waiting up to timeout_ms in total); false on error or timeout.
  bool write(const uint8_t* data, size_t n, int timeout_ms);

  static bool baudSupported(int baud);

 private:
  int fd_ = -1;
  std::string device_;
};

}  // namespace deepnav
