#include "board/service/board_validation.h"

#include <arpa/inet.h>

#include <filesystem>
#include <vector>

#include "drivers/camera/gvcp_probe.h"
#include "drivers/outputs/udp_sender.h"
#include "drivers/probe/device_probe.h"
#include "drivers/realtime/realtime.h"
#include "drivers/replay/recording_reader.h"

namespace deepnav {
namespace {

constexpr int kCameraProbeTimeoutMs = 500;

struct Device {
  const char* key;
  const char* what;
  const std::string* value;
  enum Kind { kSerial, kCan } kind;
};

class Checker {
 public:
  Checker(const std::string& board_path, std::string* error) : board_(board_path), error_(error) {}
  bool fail(const std::string& key, const std::string& what) {
    if (error_) *error_ = board_ + ": " + key + ": " + what;
    return false;
  }

 private:
  std::string board_;
  std::string* error_;
};

std::string makeRecordingHint() {
  return "make one with build/bin/deepnav-sim --scenario tools/sim/scenarios/default.yaml --out dive.mcap "
         "and set sources.replay_path to it (or pass --replay dive.mcap)";
}

bool checkCameras(const CameraSourceConfig& c, Checker& check, bool* any) {
  if (c.driver == "none") return true;
  *any = true;
  const struct {
    const char* key;
    const char* what;
    const std::string* id;
  } cameras[] = {{"camera.left", "left camera", &c.left}, {"camera.right", "right camera", &c.right}};
  for (const auto& cam : cameras) {
    const std::string& id = *cam.id;
    if (id.empty()) return check.fail(cam.key, std::string("is empty but camera.driver is ") + c.driver);
    std::string reason;
    in_addr ip{};
    if (c.driver == "v4l2" && !probeVideoDevice(id, &reason)) {
      return check.fail(cam.key, std::string(cam.what) + " " + id + " is not reachable: " + reason);
    }
    // Aravis cameras named by IPv4 address are probed by a GVCP discovery; a device id, serial number
    // or user id is resolved by the driver when it opens the camera.
    if (c.driver == "aravis" && ::inet_pton(AF_INET, id.c_str(), &ip) == 1 &&
        !gvcpDeviceAnswers(id, kCameraProbeTimeoutMs)) {
      return check.fail(cam.key, std::string(cam.what) + " " + id +
                                     " is not reachable: no GigE Vision device answers a GVCP discovery within " +
                                     std::to_string(kCameraProbeTimeoutMs) + " ms");
    }
  }
  return true;
}

bool checkDevices(const BoardConfig& c, Checker& check, bool* any) {
  *any = false;
  if (!checkCameras(c.camera.source, check, any)) return false;
  const BoardConfig::Sources& s = c.sources;
  const Device devices[] = {
      {"sources.dvl_serial", "DVL serial port", &s.dvl_serial, Device::kSerial},
      {"sources.ahrs_serial", "AHRS serial port", &s.ahrs_serial, Device::kSerial},
      {"sources.depth_serial", "depth sensor serial port", &s.depth_serial, Device::kSerial},
      {"sources.can_interface", "CAN interface", &s.can_interface, Device::kCan},
  };
  for (const Device& d : devices) {
    if (d.value->empty()) continue;
    *any = true;
    std::string reason;
    const bool ok = d.kind == Device::kSerial ? probeSerialPort(*d.value, &reason) : probeCanInterface(*d.value, &reason);
    if (!ok) return check.fail(d.key, std::string(d.what) + " " + *d.value + " is not reachable: " + reason);
  }
  return true;
}

bool checkReplay(const VehicleSetup& setup, const std::string& path, const std::string& key, Checker& check) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    return check.fail(key, "recording " + path + " not found; " + makeRecordingHint());
  }
  RecordingReader reader;
  std::string why;
  if (!reader.open(path, &why)) return check.fail(key, "recording " + path + " cannot be read: " + why);
  if (reader.count(Topic::kLeftImage) == 0) return true;
  // The frame pool is sized from camera.*: the recorded images must fit it.
  VehicleSetup recorded;
  bool found = false;
  if (!setupFromMetadata(reader.metadata("deepnav.board"), reader.metadata("deepnav.panel"), path, &recorded, &why,
                         &found) ||
      !found) {
    return true;  // no stored board: mismatched frames are refused and counted at run time
  }
  const BoardConfig::Camera& mine = setup.config.camera;
  const BoardConfig::Camera& theirs = recorded.config.camera;
  if (mine.width_px != theirs.width_px || mine.height_px != theirs.height_px || mine.channels != theirs.channels) {
    return check.fail("camera.width_px", "the board's camera is " + std::to_string(mine.width_px) + "x" +
                                             std::to_string(mine.height_px) + "x" + std::to_string(mine.channels) +
                                             " but recording " + path + " holds " + std::to_string(theirs.width_px) +
                                             "x" + std::to_string(theirs.height_px) + "x" +
                                             std::to_string(theirs.channels) + " images");
  }
  return true;
}

bool checkCalibration(const BoardConfig::Camera& c, Checker& check) {
  if (c.cx_px >= c.width_px) return check.fail("camera.cx_px", "principal point outside the image width");
  if (c.cy_px >= c.height_px) return check.fail("camera.cy_px", "principal point outside the image height");
  return true;
}

bool checkOutputsAndRealtime(const BoardConfig& c, ValidatedBoard* out, Checker& check) {
  in_addr a{};
  if (c.outputs.modbus_enabled && ::inet_pton(AF_INET, c.outputs.modbus_address.c_str(), &a) != 1) {
    return check.fail("outputs.modbus_address", "'" + c.outputs.modbus_address + "' is not an IPv4 address");
  }
  std::vector<sockaddr_in> destinations;
  std::string why;
  if (!UdpSender::parseDestinations(c.outputs.udp_destinations, &destinations, &why)) {
    return check.fail("outputs.udp_destinations", why);
  }
  out->has_loop_cpus = !c.realtime.loop_cpus.empty();
  if (out->has_loop_cpus && !parseCpuList(c.realtime.loop_cpus, &out->loop_cpus, &why)) {
    return check.fail("realtime.loop_cpus", why);
  }
  out->has_process_cpus = !c.realtime.process_cpus.empty();
  if (out->has_process_cpus && !parseCpuList(c.realtime.process_cpus, &out->process_cpus, &why)) {
    return check.fail("realtime.process_cpus", why);
  }
  return true;
}

}  // namespace

bool validateBoard(const VehicleSetup& setup, const std::string& board_path, const std::string& replay_override,
                   ValidatedBoard* out, std::string* error) {
  Checker check(board_path, error);
  const BoardConfig& c = setup.config;
  if (!checkCalibration(c.camera, check)) return false;
  if (!checkDevices(c, check, &out->has_devices)) return false;
  const std::string key = replay_override.empty() ? "sources.replay_path" : "--replay";
  std::string replay = replay_override;
  if (replay.empty() && !c.sources.replay_path.empty()) {
    replay = (std::filesystem::path(board_path).parent_path() / c.sources.replay_path).lexically_normal().string();
  }
  if (!replay.empty() && out->has_devices) {
    return check.fail(key, "a replay and the board's devices (camera.driver, sources.*_serial, sources.can_interface) are "
                           "exclusive: list devices for a vehicle, a recording for a bench or simulator rig");
  }
  if (replay.empty() && !out->has_devices) {
    return check.fail("sources.replay_path", "is empty and no device is listed: nothing to navigate on; " +
                                                 makeRecordingHint());
  }
  if (!replay.empty() && !checkReplay(setup, replay, key, check)) return false;
  out->replay_path = replay;
  return checkOutputsAndRealtime(c, out, check);
}

}  // namespace deepnav
