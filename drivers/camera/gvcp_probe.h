#pragma once
#include <string>

namespace deepnav {

// True when a GigE Vision device answers a unicast GVCP discovery at `ipv4` (UDP port 3956) within
// timeout_ms. Used before reopening a lost camera, because opening an absent camera through Aravis
// blocks for seconds of control-channel retries.
bool gvcpDeviceAnswers(const std::string& ipv4, int timeout_ms);

}  // namespace deepnav
