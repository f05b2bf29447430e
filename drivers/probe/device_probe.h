#pragma once
#include <string>

namespace deepnav {

// Start-up reachability checks of a board's devices. Each returns false with a short reason (the caller
// names the board key and the device); none keeps anything open.

// A serial port: the device node exists, opens read-write, and is a terminal.
bool probeSerialPort(const std::string& path, std::string* reason);

// A SocketCAN interface: it exists and is up.
bool probeCanInterface(const std::string& name, std::string* reason);

// A GigE Vision camera at an IPv4 address: it answers a GVCP discovery command (UDP port 3956: 8-byte
// header 0x42, flags 0x01 = acknowledge, command 0x0002, length 0, request id) with a DISCOVERY_ACK
// (answer 0x0003, 248-byte body) within timeout_ms. port is 3956 except in tests.
bool probeGigeCamera(const std::string& address, int timeout_ms, std::string* reason, int port = 3956);

}  // namespace deepnav
