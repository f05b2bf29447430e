#pragma once
#include <string>

#include "nav/types/time.h"

namespace deepnav {

// How the stereo cameras are reached and set up (board.yaml `camera.*`). The image size, channel count
// and frame rate come from the board's camera block (camera.width_px, height_px, channels, rate_hz),
// which also sizes the frame pool, so a driver can never deliver a frame of another size.
struct CameraSourceConfig {
  std::string driver;        // none | aravis | v4l2
  std::string left;          // Aravis: device id, serial number, user id or IPv4 address; V4L2: /dev/videoN
  std::string right;
  std::string pixel_format;  // mono8 | bayer_rg8 | bayer_gr8 | bayer_gb8 | bayer_bg8 | rgb8 | bgr8 | yuyv
  int offset_x_px;           // region of interest on the sensor (GenICam OffsetX/OffsetY)
  int offset_y_px;
  double exposure_us;        // 0: the camera's automatic exposure
  std::string trigger;       // free | software | hardware
  std::string trigger_line;  // hardware trigger input (GenICam TriggerSource), e.g. Line1
  double pair_tolerance_ms;  // largest left/right timestamp difference of one pair
  std::string timestamp;     // host (arrival on this computer) | device (cameras' clocks, e.g. PTP)
  TimeUs stale_after_us;     // a camera without a good frame for this long is stale
  TimeUs reconnect_interval_us;  // a stale camera is reopened at most this often
  bool packet_resend;        // GigE Vision: ask the camera to resend lost packets
  int packet_size_bytes;     // GigE Vision stream packet size; 0: negotiated with the camera
  int stream_buffers;        // driver buffers per camera (Aravis buffers, V4L2 mmap buffers)

  // From the board's camera block (not keys of their own).
  int width_px = 0;
  int height_px = 0;
  int channels = 1;
  double rate_hz = 10.0;
};

}  // namespace deepnav
