#include "drivers/serial/serial_port.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

namespace deepnav {
namespace {

struct BaudEntry {
  int baud;
  speed_t speed;
};

constexpr BaudEntry kBauds[] = {{1200, B1200},       {2400, B2400},       {4800, B4800},       {9600, B9600},
                                {19200, B19200},     {38400, B38400},     {57600, B57600},     {115200, B115200},
                                {230400, B230400},   {460800, B460800},   {500000, B500000},   {576000, B576000},
                                {921600, B921600},   {1000000, B1000000}, {1152000, B1152000}, {1500000, B1500000},
                                {2000000, B2000000}, {3000000, B3000000}, {4000000, B4000000}};

bool speedFor(int baud, speed_t* speed) {
  for (const BaudEntry& e : kBauds) {
    if (e.baud == baud) return *speed = e.speed, true;
  }
  return false;
}

}  // namespace

SerialPort::~SerialPort() { close(); }

bool SerialPort::baudSupported(int baud) {
  speed_t s;
  return speedFor(baud, &s);
}

bool SerialPort::open(const std::string& device, int baud, Parity parity, int stop_bits, std::string* error) {
  close();
  speed_t speed;
  if (!speedFor(baud, &speed)) return *error = device + ": unsupported baud rate " + std::to_string(baud), false;
  if (stop_bits != 1 && stop_bits != 2) return *error = device + ": stop bits must be 1 or 2", false;
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return *error = device + ": cannot open: " + std::strerror(errno), false;
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    *error = device + ": not a terminal: " + std::strerror(errno);
    ::close(fd);
    return false;
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~(CRTSCTS | CSTOPB | PARENB | PARODD);
  if (stop_bits == 2) tio.c_cflag |= CSTOPB;
  if (parity != Parity::kNone) tio.c_cflag |= PARENB | (parity == Parity::kOdd ? PARODD : 0);
  tio.c_iflag &= ~(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, speed);
  ::cfsetospeed(&tio, speed);
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
    *error = device + ": cannot configure: " + std::strerror(errno);
    ::close(fd);
    return false;
  }
  ::tcflush(fd, TCIFLUSH);
  fd_ = fd;
  device_ = device;
  return true;
}

void SerialPort::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

ssize_t SerialPort::read(uint8_t* data, size_t n, int timeout_ms) {
  if (fd_ < 0) return -1;
  pollfd p{fd_, POLLIN, 0};
  const int r = ::poll(&p, 1, timeout_ms);
  if (r < 0) return errno == EINTR ? 0 : -1;
  if (r == 0) return 0;
  if (p.revents & POLLIN) {
    const ssize_t got = ::read(fd_, data, n);
    if (got > 0) return got;
    if (got < 0 && (errno == EAGAIN || errno == EINTR)) return 0;
    return -1;  // 0 bytes with POLLIN: end of file (the other side closed)
  }
  return (p.revents & (POLLHUP | POLLERR | POLLNVAL)) ? -1 : 0;
}

bool SerialPort::write(const uint8_t* data, size_t n, int timeout_ms) {
  size_t done = 0;
  while (done < n) {
    pollfd p{fd_, POLLOUT, 0};
    if (fd_ < 0 || ::poll(&p, 1, timeout_ms) <= 0) return false;
    const ssize_t w = ::write(fd_, data + done, n - done);
    if (w < 0 && errno != EAGAIN && errno != EINTR) return false;
    if (w > 0) done += size_t(w);
  }
  return true;
}

}  // namespace deepnav
