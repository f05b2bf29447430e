#pragma once
#include <string>

namespace deepnav {

// Start-up reachability checks of a board's devices. Each returns false with a short reason (the caller
// names the board key and the device); none keeps anything open.

// A serial port: the device node exists, opens read-write, and is a terminal.
bool probeSerialPort(const std::string& path, std::string* reason);

// A SocketCAN interface: it exists and is up.
bool probeCanInterface(const std::string& name, std::string* reason);

// A V4L2 capture device: the node exists and opens read-write.
bool probeVideoDevice(const std::string& path, std::string* reason);

// (GigE Vision cameras: gvcpDeviceAnswers() in drivers/camera/gvcp_probe.h.)

}  // namespace deepnav
