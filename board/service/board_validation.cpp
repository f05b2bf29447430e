#include "board/service/board_validation.h"

#include <arpa/inet.h>

#include <filesystem>
#include <vector>

#include "board/config/sensor_driver_configs.h"
#include "board/service/startup_checks.h"
#include "drivers/camera/gvcp_probe.h"
#include "drivers/outputs/udp_sender.h"
#include "drivers/probe/device_probe.h"
#include "drivers/realtime/realtime.h"
#include "drivers/replay/recording_reader.h"
#include "vision/pipeline/vision_pipeline.h"

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
  // A message that already starts with its key ("can.imu_mapping: ...").
  bool fail(const std::string& keyed_message) {
    if (error_) *error_ = board_ + ": " + keyed_message;
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
  const BoardConfig::Sources& s = c.sources;
  // The drivers' settings run derives before opening them (e.g. can.imu_mapping), checked before the
  // devices are probed: the message names the key.
  SensorThreadsConfig drivers;
  std::string why;
  const bool sensors = !s.dvl_serial.empty() || !s.ahrs_serial.empty() || !s.depth_serial.empty() ||
                       !s.can_interface.empty();
  if (sensors && !sensorThreadsConfig(c, &drivers, &why)) return check.fail(why);
  if (!checkCameras(c.camera.source, check, any)) return false;
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
    if (d.kind == Device::kCan && !canInterfaceUsable(*d.value, &reason)) {
      return check.fail(d.key, std::string(d.what) + " " + *d.value + " cannot be used: " + reason);
    }
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

// The Modbus TCP server run starts: the address is one of this host's and the port is free.
bool checkModbusServer(const BoardConfig::Outputs& o, Checker& check) {
  if (!o.modbus_enabled) return true;
  in_addr a{};
  if (::inet_pton(AF_INET, o.modbus_address.c_str(), &a) != 1) {
    return check.fail("outputs.modbus_address", "'" + o.modbus_address + "' is not an IPv4 address");
  }
  std::string why;
  bool foreign = false;
  if (tcpListenable(o.modbus_address, o.modbus_port, &why, &foreign)) return true;
  return check.fail(foreign ? "outputs.modbus_address" : "outputs.modbus_port",
                    "Modbus TCP server on " + o.modbus_address + ":" + std::to_string(o.modbus_port) + ": " + why);
}

// The directories run creates and writes (recording, workspace state); relative paths are taken from the
// working directory, as run does.
bool checkServiceDirectories(const BoardConfig::Service& s, Checker& check) {
  std::string why;
  if (!s.recording_dir.empty() && !directoryUsable(s.recording_dir, &why)) {
    return check.fail("service.recording_dir", why);
  }
  if (!s.state_dir.empty() && !directoryUsable(s.state_dir, &why)) return check.fail("service.state_dir", why);
  return true;
}

// The loop's task table (board/loop/live_loop.cpp): the vision task runs at camera.rate_hz rounded to whole
// hertz, and the scheduler refuses a task of 0 Hz.
bool checkLoopRates(const BoardConfig& c, Checker& check) {
  if (static_cast<int>(c.camera.rate_hz + 0.5) < 1) {
    return check.fail("camera.rate_hz", std::to_string(c.camera.rate_hz) +
                                            " Hz: the vision task runs at the rate rounded to whole hertz, here 0; "
                                            "at least 0.5 Hz is needed");
  }
  return true;
}

// The vision pipeline's own start-up checks (marker dictionary, ORB, dense stereo, plane VO, workspace map)
// on a throw-away pipeline, as the loop's init() makes it; its buffers are freed on return.
bool checkVisionPipeline(const VehicleSetup& setup, Checker& check) {
  std::string why;
  try {
    VisionPipeline pipeline;
    if (pipeline.init(visionConfig(setup), &why)) return true;
  } catch (const std::exception& e) {
    why = std::string("vision: cannot set up the pipeline: ") + e.what();
  }
  return check.fail(why);
}

bool checkRealtimeRights(const BoardConfig::Realtime& r, const ValidatedBoard& out, Checker& check) {
  std::string why;
  if (out.has_process_cpus && !cpusAvailable(out.process_cpus, &why)) return check.fail("realtime.process_cpus", why);
  if (out.has_loop_cpus && !cpusAvailable(out.loop_cpus, &why)) return check.fail("realtime.loop_cpus", why);
  if (r.loop_priority > 0 && !fifoPriorityAllowed(r.loop_priority, &why)) {
    return check.fail("realtime.loop_priority", why);
  }
  if (r.mlockall && !memoryLockable(&why)) return check.fail("realtime.mlockall", why);
  return true;
}

bool checkOutputsAndRealtime(const BoardConfig& c, ValidatedBoard* out, Checker& check) {
  if (!checkModbusServer(c.outputs, check)) return false;
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
  return checkRealtimeRights(c.realtime, *out, check);
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
  return checkLoopRates(c, check) && checkVisionPipeline(setup, check) &&
         checkServiceDirectories(c.service, check) &&
         checkOutputsAndRealtime(c, out, check);
}

}  // namespace deepnav
