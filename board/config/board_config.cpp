#include "board/config/board_config.h"

#include "board/config/dense_stereo_range.h"
#include "board/config/text_file.h"
#include "board/config/yaml_document.h"

#include <yaml-cpp/yaml.h>

namespace deepnav {
namespace {

using P = ParamSpec<BoardConfig>;

#define DEEPNAV_FIELD(expr) [](BoardConfig& c) -> void* { return &c.expr; }

// Up to the buffers' own keys (the live input capacities follow).
const std::array kBoardHeadParams = {
    P{"loop.rate_hz", ParamType::kInt, "Hz", 10, 1000, "100", "", "nav loop tick rate",
      DEEPNAV_FIELD(loop.rate_hz)},
    P{"loop.budget_us", ParamType::kInt, "us", 100, 100000, "2000", "",
      "time budget of one nav tick; a longer tick counts as an overrun", DEEPNAV_FIELD(loop.budget_us)},
    P{"loop.vision_budget_us", ParamType::kInt, "us", 1000, 5000000, "100000", "",
      "vision worker budget per stereo pair; longer counts as a vision overrun",
      DEEPNAV_FIELD(loop.vision_budget_us)},
    P{"loop.vision_latency_ms", ParamType::kInt, "ms", 0, 500, "150", "",
      "replay: delay between a frame's capture and the arrival of its vision result",
      DEEPNAV_FIELD(loop.vision_latency_ms)},
    P{"loop.late_tick_tolerance", ParamType::kDouble, "period", 0.05, 10.0, "0.5", "",
      "a tick that starts later than this fraction of the period counts as late",
      DEEPNAV_FIELD(loop.late_tick_tolerance)},
    P{"loop.output_tau_s", ParamType::kDouble, "s", 0, 5, "0.3", "",
      "published pose follows the EKF's corrections with this time constant (output predictor; 0: none)",
      DEEPNAV_FIELD(loop.output_tau_s)},
};

// Between the live input capacities (liveInputCapacityParams()) and the camera port's keys.
const std::array kBoardBuffersTailParams = {
    P{"buffers.vision_results", ParamType::kInt, "results", 4, 4096, "32", "", "vision result ring capacity",
      DEEPNAV_FIELD(buffers.vision_results)},
    P{"buffers.record", ParamType::kInt, "records", 64, 1048576, "8192", "",
      "recorder queue between the loop and the MCAP writer thread", DEEPNAV_FIELD(buffers.record)},
    P{"recording.enabled", ParamType::kBool, "-", 0, 0, "true", "", "record every consumed sample and output",
      DEEPNAV_FIELD(recording.enabled)},
    // Default nullptr: RecordingOptions' initialiser (drivers/recording/recording_writer.h), read as it is.
    P{"recording.compression", ParamType::kChoice, "-", 0, 0, nullptr, "zstd|lz4|none",
      "MCAP chunk compression", DEEPNAV_FIELD(recording.options.compression)},
    P{"recording.chunk_max_duration_s", ParamType::kDouble, "s", 0.01, 1.0, nullptr, "",
      "a chunk closes (and is flushed to disk) at least this often, bounding what a crash loses",
      DEEPNAV_FIELD(recording.options.chunk_max_duration_s)},
    P{"recording.chunk_size_kib", ParamType::kInt, "KiB", 16, 65536, nullptr, "",
      "a chunk closes when its uncompressed size exceeds this", DEEPNAV_FIELD(recording.options.chunk_size_kib)},
    P{"recording.record_images", ParamType::kBool, "-", 0, 0, nullptr, "",
      "record stereo images (large) besides the navigation samples", DEEPNAV_FIELD(recording.options.record_images)},
    P{"camera.width_px", ParamType::kInt, "px", 16, 8192, "688", "", "image width of each camera",
      DEEPNAV_FIELD(camera.width_px)},
    P{"camera.height_px", ParamType::kInt, "px", 16, 8192, "516", "", "image height of each camera",
      DEEPNAV_FIELD(camera.height_px)},
    P{"camera.channels", ParamType::kInt, "-", 1, 3, "1", "", "1 = grey, 3 = colour (BGR)",
      DEEPNAV_FIELD(camera.channels)},
    P{"camera.rate_hz", ParamType::kDouble, "Hz", 0.1, 100, "10", "", "stereo pair rate",
      DEEPNAV_FIELD(camera.rate_hz)},
    P{"camera.fx_px", ParamType::kDouble, "px", 1, 100000, "700", "", "focal length along x (rectified)",
      DEEPNAV_FIELD(camera.fx_px)},
    P{"camera.fy_px", ParamType::kDouble, "px", 1, 100000, "700", "", "focal length along y (rectified)",
      DEEPNAV_FIELD(camera.fy_px)},
    P{"camera.cx_px", ParamType::kDouble, "px", 0, 8192, "343.5", "", "principal point x", DEEPNAV_FIELD(camera.cx_px)},
    P{"camera.cy_px", ParamType::kDouble, "px", 0, 8192, "257.5", "", "principal point y", DEEPNAV_FIELD(camera.cy_px)},
    P{"camera.baseline_m", ParamType::kDouble, "m", 0.01, 5, "0.30", "", "stereo baseline (right camera along +x)",
      DEEPNAV_FIELD(camera.baseline_m)},
    P{"camera.p_cam_in_robot_m", ParamType::kVec3, "m", -10, 10, "[0.6, 0.15, -0.2]", "",
      "left camera optical centre in the robot frame", DEEPNAV_FIELD(camera.p_cam_in_robot_m)},
    P{"camera.rotation_deg", ParamType::kRotation, "deg", -360, 360, "[0, 0, 0]", "",
      "mounting of the camera body (FLU, optical axis = body x) in the robot frame, [roll, pitch, yaw]",
      DEEPNAV_FIELD(camera.q_robot_body)},
    P{"camera.calibration_file", ParamType::kString, "path", 0, 0, "''", "",
      "stereo calibration of the raw images (`deepnav calibrate` output), relative to the board file; empty: "
      "frames arrive rectified with the camera.* intrinsics", DEEPNAV_FIELD(camera.calibration_file)},
    P{"camera.port.model", ParamType::kChoice, "-", 0, 0, "none", "none|flat",
      "refraction correction: none (in-air, dome port or in-water calibration) or flat (PinAx, in-air calibration)",
      DEEPNAV_FIELD(camera.port.model)},
};

// Between the port's keys (flatPortParams(), pinaxParams()) and the markers' own.
const std::array kCameraSourceParams = {
    P{"camera.driver", ParamType::kChoice, "-", 0, 0, "none", "none|aravis|v4l2",
      "live stereo camera driver (drivers/camera); none: frames come only from a replay", DEEPNAV_FIELD(camera.source.driver)},
    P{"camera.left", ParamType::kString, "-", 0, 0, "''", "",
      "left camera: Aravis IPv4 address, device id, serial number or physical id; V4L2 device path",
      DEEPNAV_FIELD(camera.source.left)},
    P{"camera.right", ParamType::kString, "-", 0, 0, "''", "", "right camera, as camera.left",
      DEEPNAV_FIELD(camera.source.right)},
    P{"camera.pixel_format", ParamType::kChoice, "-", 0, 0, "mono8",
      "mono8|bayer_rg8|bayer_gr8|bayer_gb8|bayer_bg8|rgb8|bgr8|yuyv",
      "pixel format asked of the cameras (converted to camera.channels)", DEEPNAV_FIELD(camera.source.pixel_format)},
    P{"camera.offset_x_px", ParamType::kInt, "px", 0, 8192, "0", "", "region of interest: left edge on the sensor",
      DEEPNAV_FIELD(camera.source.offset_x_px)},
    P{"camera.offset_y_px", ParamType::kInt, "px", 0, 8192, "0", "", "region of interest: top edge on the sensor",
      DEEPNAV_FIELD(camera.source.offset_y_px)},
    P{"camera.exposure_us", ParamType::kDouble, "us", 0, 10000000, "0", "",
      "exposure time of both cameras; 0: the cameras' automatic exposure", DEEPNAV_FIELD(camera.source.exposure_us)},
    P{"camera.trigger", ParamType::kChoice, "-", 0, 0, "free", "free|software|hardware",
      "free-running at camera.rate_hz, software trigger of both at camera.rate_hz, or hardware trigger line",
      DEEPNAV_FIELD(camera.source.trigger)},
    P{"camera.trigger_line", ParamType::kString, "-", 0, 0, "Line1", "",
      "hardware trigger input of both cameras (GenICam TriggerSource)", DEEPNAV_FIELD(camera.source.trigger_line)},
    P{"camera.pair_tolerance_ms", ParamType::kDouble, "ms", 0.001, 1000, "10", "",
      "largest left/right timestamp difference of a stereo pair (below half the frame period)",
      DEEPNAV_FIELD(camera.source.pair_tolerance_ms)},
    P{"camera.timestamp", ParamType::kChoice, "-", 0, 0, "host", "host|device",
      "pair on arrival time at this computer, or on the cameras' clocks (synchronised, e.g. PTP)",
      DEEPNAV_FIELD(camera.source.timestamp)},
    P{"camera.stale_after_s", ParamType::kDurationS, "s", 0.01, 60, "1.0", "",
      "a camera without a good frame for this long is flagged stale and reopened", DEEPNAV_FIELD(camera.source.stale_after_us)},
    P{"camera.reconnect_interval_s", ParamType::kDurationS, "s", 0.05, 600, "2.0", "",
      "time between two attempts to reopen a lost camera", DEEPNAV_FIELD(camera.source.reconnect_interval_us)},
    P{"camera.packet_resend", ParamType::kBool, "-", 0, 0, "true", "",
      "GigE Vision: ask the camera to resend lost stream packets", DEEPNAV_FIELD(camera.source.packet_resend)},
    P{"camera.packet_size_bytes", ParamType::kInt, "bytes", 0, 16384, "0", "",
      "GigE Vision stream packet size (jumbo frames: up to 9000); 0: negotiated with the camera",
      DEEPNAV_FIELD(camera.source.packet_size_bytes)},
    P{"camera.stream_buffers", ParamType::kInt, "buffers", 4, 32, "8", "",
      "driver buffers per camera (Aravis buffers, V4L2 mmap buffers), allocated at start-up",
      DEEPNAV_FIELD(camera.source.stream_buffers)},
    P{"markers.enabled", ParamType::kBool, "-", 0, 0, "true", "",
      "the marker chain: detection, panel pose, marker robot poses (false: none of them, the panel is never "
      "fixed and the run stays in stage 1; with vision.vo_mode=none the dead-reckoning run)",
      DEEPNAV_FIELD(markers.enabled)},
    P{"markers.panel_in_filter", ParamType::kBool, "-", 0, 0, "false", "",
      "hold the fixed panel in the EKF: the robot pose at the fix is cloned into the state for good and every "
      "marker is fused as a pose relative to that clone, so the panel's error in odom (the robot's error when "
      "it was measured) stays in the covariance and the compass, DVL and VO refine it (nav/pipeline/panel_anchor.h); "
      "takes one of the EKF's clones from the visual odometry. false: marker poses are fused in odom as if the "
      "panel were exact",
      DEEPNAV_FIELD(markers.panel_in_filter)},
    P{"markers.panel_file", ParamType::kString, "path", 0, 0, "''", "",
      "panel description (knowledge base), relative to the board file; empty: no markers",
      DEEPNAV_FIELD(markers.panel_file)},
};

// Between the markers' keys and the stage machine's.
const std::array kStageBoardParams = {
    P{"stage.fuse_markers_in_stage2", ParamType::kBool, "-", 0, 0, "true", "",
      "fuse marker robot poses in stage 2 (false: the paper's T_L3, VO and navigation sensors only)",
      DEEPNAV_FIELD(stage.fuse_markers_in_stage2)},
};

// Between the vision worker's keys (visionPipelineParams()) and the filter's (ekfParams()).
const std::array kBoardTailParams = {
    P{"sources.replay_path", ParamType::kString, "path", 0, 0, "''", "",
      "`deepnav run`: recording played as the sensors, relative to the board file (sim and bench rigs)",
      DEEPNAV_FIELD(sources.replay_path)},
    P{"sources.dvl_serial", ParamType::kString, "path", 0, 0, "''", "",
      "DVL serial port (e.g. /dev/ttyS1); empty: not fitted", DEEPNAV_FIELD(sources.dvl_serial)},
    P{"sources.ahrs_serial", ParamType::kString, "path", 0, 0, "''", "",
      "AHRS serial port; empty: not fitted", DEEPNAV_FIELD(sources.ahrs_serial)},
    P{"sources.depth_serial", ParamType::kString, "path", 0, 0, "''", "",
      "depth sensor serial port (Modbus RTU); empty: not fitted", DEEPNAV_FIELD(sources.depth_serial)},
    P{"sources.can_interface", ParamType::kString, "iface", 0, 0, "''", "",
      "SocketCAN interface of the IMU and compass (e.g. can0); empty: not fitted",
      DEEPNAV_FIELD(sources.can_interface)},
    P{"outputs.modbus_enabled", ParamType::kBool, "-", 0, 0, "false", "",
      "serve the solution as Modbus TCP registers (board/service/README.md)", DEEPNAV_FIELD(outputs.modbus_enabled)},
    P{"outputs.modbus_address", ParamType::kString, "IPv4", 0, 0, "0.0.0.0", "",
      "Modbus TCP listening address", DEEPNAV_FIELD(outputs.modbus_address)},
    P{"outputs.modbus_port", ParamType::kInt, "-", 1, 65535, "502", "", "Modbus TCP listening port",
      DEEPNAV_FIELD(outputs.modbus_port)},
    P{"outputs.modbus_max_clients", ParamType::kInt, "-", 1, 32, "4", "", "Modbus TCP clients served at once",
      DEEPNAV_FIELD(outputs.modbus_max_clients)},
    P{"outputs.udp_destinations", ParamType::kString, "host:port", 0, 0, "''", "",
      "UDP solution datagrams, one per tick, to each 'IPv4:port' of this comma-separated list; empty: none",
      DEEPNAV_FIELD(outputs.udp_destinations)},
    P{"service.recording_dir", ParamType::kString, "path", 0, 0, "recordings", "",
      "`deepnav run` records to DIR/deepnav-<UTC time>.mcap (relative to the working directory); empty: no recording",
      DEEPNAV_FIELD(service.recording_dir)},
    P{"service.state_dir", ParamType::kString, "path", 0, 0, "''", "",
      "`deepnav run` saves the workspace (map and T_panel_map) to DIR/workspace when stage 2 is entered and "
      "reloads it at start-up, to resume in stage 2 once the markers fix the panel (relative to the working "
      "directory); empty: not kept",
      DEEPNAV_FIELD(service.state_dir)},
    P{"realtime.loop_priority", ParamType::kInt, "-", 0, 99, "0", "",
      "SCHED_FIFO priority of the nav loop thread; 0: normal scheduling", DEEPNAV_FIELD(realtime.loop_priority)},
    P{"realtime.loop_cpus", ParamType::kString, "CPU list", 0, 0, "''", "",
      "CPUs of the nav loop thread, e.g. '3' or '2-3'; empty: any", DEEPNAV_FIELD(realtime.loop_cpus)},
    P{"realtime.process_cpus", ParamType::kString, "CPU list", 0, 0, "''", "",
      "CPUs of every other thread (vision, recorder, drivers, outputs); empty: any",
      DEEPNAV_FIELD(realtime.process_cpus)},
    P{"realtime.mlockall", ParamType::kBool, "-", 0, 0, "false", "",
      "lock all current and future memory (mlockall), so the loop never page-faults",
      DEEPNAV_FIELD(realtime.mlockall)},
    P{"serial.dvl_protocol", ParamType::kChoice, "-", 0, 0, "pd0", "pd0|pd6|wl-a50",
      "protocol of the DVL on sources.dvl_serial", DEEPNAV_FIELD(serial.dvl_protocol)},
    P{"serial.dvl_baud", ParamType::kInt, "baud", 1200, 4000000, "115200", "", "DVL serial line speed (8 data bits, no parity)",
      DEEPNAV_FIELD(serial.dvl_baud)},
    P{"serial.ahrs_protocol", ParamType::kChoice, "-", 0, 0, "xsens", "xsens|nmea0183",
      "protocol of the AHRS or compass on sources.ahrs_serial (Xsens MTData2, or NMEA 0183 HDT/HDG/HDM)",
      DEEPNAV_FIELD(serial.ahrs_protocol)},
    P{"serial.ahrs_baud", ParamType::kInt, "baud", 1200, 4000000, "115200", "", "AHRS serial line speed",
      DEEPNAV_FIELD(serial.ahrs_baud)},
    P{"serial.reopen_interval_s", ParamType::kDouble, "s", 0.05, 60, "1.0", "",
      "a serial device that went away is reopened this often", DEEPNAV_FIELD(serial.reopen_interval_s)},
    P{"can.heading_source", ParamType::kInt, "-", -1, 253, "-1", "",
      "NMEA 2000 source address whose PGN 127250 is the heading; -1: any", DEEPNAV_FIELD(can.heading_source)},
    P{"can.attitude_source", ParamType::kInt, "-", -1, 253, "-1", "",
      "NMEA 2000 source address whose PGN 127257 is the attitude; -1: any", DEEPNAV_FIELD(can.attitude_source)},
    P{"can.imu_mapping", ParamType::kString, "-", 0, 0, "''", "",
      "fields of a non-NMEA-2000 CAN IMU/compass, 'ID:BYTE:TYPE:SCALE:TARGET;...' (drivers/parsers/README.md)",
      DEEPNAV_FIELD(can.imu_mapping)},
    P{"can.bus_off_recovery_s", ParamType::kDouble, "s", 0.01, 60, "1.0", "",
      "after this long in bus-off the driver restarts the controller and reopens its socket",
      DEEPNAV_FIELD(can.bus_off_recovery_s)},
    P{"modbus_depth.baud", ParamType::kInt, "baud", 1200, 4000000, "9600", "", "depth sensor Modbus RTU line speed",
      DEEPNAV_FIELD(modbus_depth.baud)},
    P{"modbus_depth.parity", ParamType::kChoice, "-", 0, 0, "N", "N|E|O", "depth sensor serial parity",
      DEEPNAV_FIELD(modbus_depth.parity)},
    P{"modbus_depth.stop_bits", ParamType::kInt, "-", 1, 2, "1", "", "depth sensor serial stop bits",
      DEEPNAV_FIELD(modbus_depth.stop_bits)},
    P{"modbus_depth.slave_id", ParamType::kInt, "-", 1, 247, "1", "", "Modbus address of the depth sensor",
      DEEPNAV_FIELD(modbus_depth.slave_id)},
    P{"modbus_depth.register_kind", ParamType::kChoice, "-", 0, 0, "input", "input|holding",
      "register table holding the pressure (function 4 or 3)", DEEPNAV_FIELD(modbus_depth.register_kind)},
    P{"modbus_depth.register_address", ParamType::kInt, "-", 0, 65534, "0", "",
      "first register of the pressure value (0-based protocol address)", DEEPNAV_FIELD(modbus_depth.register_address)},
    P{"modbus_depth.value_type", ParamType::kChoice, "-", 0, 0, "f32", "u16|i16|u32|i32|f32",
      "encoding of the pressure value (32-bit types take two registers)", DEEPNAV_FIELD(modbus_depth.value_type)},
    P{"modbus_depth.high_word_first", ParamType::kBool, "-", 0, 0, "true", "",
      "32-bit values: the first register holds the high 16 bits", DEEPNAV_FIELD(modbus_depth.high_word_first)},
    P{"modbus_depth.scale_pa", ParamType::kDouble, "Pa/count", -1e9, 1e9, "1.0", "",
      "pressure = value * scale_pa + offset_pa (e.g. 100 for mbar, 1e5 for bar)", DEEPNAV_FIELD(modbus_depth.scale_pa)},
    P{"modbus_depth.offset_pa", ParamType::kDouble, "Pa", -1e9, 1e9, "0.0", "", "pressure offset",
      DEEPNAV_FIELD(modbus_depth.offset_pa)},
    P{"modbus_depth.atmospheric_pa", ParamType::kDouble, "Pa", 0, 200000, "101325", "",
      "surface pressure subtracted before depth = (p - p_atm) / (rho g)", DEEPNAV_FIELD(modbus_depth.atmospheric_pa)},
    P{"modbus_depth.water_density_kgpm3", ParamType::kDouble, "kg/m^3", 990, 1100, "1025", "",
      "water density of the depth model", DEEPNAV_FIELD(modbus_depth.water_density_kgpm3)},
    P{"modbus_depth.rate_hz", ParamType::kDouble, "Hz", 0.1, 100, "10", "", "depth sensor poll rate",
      DEEPNAV_FIELD(modbus_depth.rate_hz)},
    P{"modbus_depth.timeout_ms", ParamType::kInt, "ms", 5, 5000, "100", "", "Modbus response timeout",
      DEEPNAV_FIELD(modbus_depth.timeout_ms)},
};

#undef DEEPNAV_FIELD

// The dense stereo runs on the camera images reduced by vision.dense_scale_down (vision/cloud/stereo_cloud.cpp
// refuses a size the factor does not divide); its disparity range must stay below the reduced width
// (board/config/dense_stereo_range.h: OpenCV's SGBM throws there).
bool checkDenseStereoSize(const BoardConfig& c, const std::string& name, std::string* error) {
  const int s = c.vision.dense.scale_down;
  if (c.camera.width_px % s != 0 || c.camera.height_px % s != 0) {
    if (error) {
      *error = name + ": keys 'camera.width_px' and 'camera.height_px' (" + std::to_string(c.camera.width_px) + "x" +
               std::to_string(c.camera.height_px) + ") must be multiples of 'vision.dense_scale_down' (" +
               std::to_string(s) + ")";
    }
    return false;
  }
  std::string why;
  const int disparities = c.vision.dense.num_disparities;
  if (!denseStereoRangeFits(denseStereoMethodName(c.vision.dense.method), c.camera.width_px / s, disparities, &why)) {
    if (error) {
      *error = name + ": key 'vision.dense_disparities' (" + std::to_string(disparities) +
               ") does not fit 'camera.width_px' (" + std::to_string(c.camera.width_px) + " px, matched at 1/" +
               std::to_string(s) + " by 'vision.dense_scale_down'): " + why;
    }
    return false;
  }
  return true;
}

// Where a board's default differs from the module's own: the bare filter checks no frozen IMU (its tests feed
// a noiseless resting IMU), a vehicle's IMU noise never repeats; a vehicle's ORB VO starts a new map after 10
// lost pairs and its plane registration covariance is scaled for correlated stereo errors (the bare
// pipeline's never resets and takes the covariance as it comes).
struct BoardDefault {
  const char* key;
  const char* default_text;
};
constexpr BoardDefault kBoardDefaults[] = {{"vision.orb_reset_after_lost_frames", "10"},
                                           {"vision.planes_covariance_scale", "1000"},
                                           {"ekf.imu_stuck_after_samples", "10"}};

// Every key of a board file, in the order `deepnav config --list` prints them, bound to `c`.
std::vector<ParamSpecView> boardParams(BoardConfig& c) {
  std::vector<ParamSpecView> views = bindParams(kBoardHeadParams, c);
  appendModuleParams(liveInputCapacityParams(), kBuffersSection, c.buffers.inputs, &views);
  const std::vector<ParamSpecView> buffers = bindParams(kBoardBuffersTailParams, c);
  views.insert(views.end(), buffers.begin(), buffers.end());
  appendModuleParams(flatPortParams(), kCameraPortSection, c.camera.port.pinax.port, &views);
  appendModuleParams(pinaxParams(), kCameraPortSection, c.camera.port.pinax, &views);
  const std::vector<ParamSpecView> source = bindParams(kCameraSourceParams, c);
  views.insert(views.end(), source.begin(), source.end());
  appendModuleParams(panelPoseParams(), kMarkersSection, c.markers.panel_pose, &views);
  appendModuleParams(markerCovarianceParams(), kMarkersSection, c.markers.covariance, &views);
  const std::vector<ParamSpecView> stage = bindParams(kStageBoardParams, c);
  views.insert(views.end(), stage.begin(), stage.end());
  appendModuleParams(stageParams(), kStageSection, c.stage.machine, &views);
  appendModuleParams(visionPipelineParams(), kVisionSection, c.vision, &views);
  const std::vector<ParamSpecView> tail = bindParams(kBoardTailParams, c);
  views.insert(views.end(), tail.begin(), tail.end());
  appendModuleParams(ekfParams(), kEkfSection, c.ekf, &views);
  for (const BoardDefault& d : kBoardDefaults) {
    for (ParamSpecView& v : views) {
      if (v.key == d.key) v.default_text = d.default_text;
    }
  }
  return views;
}

// The module configs' own checks: their declared ranges (which the file's keys already passed) and the
// rules between fields. The camera port's (validatePinaxConfig) runs where the port is used, when the
// rectification is built with camera.port.model flat: a board that does not use the port is not refused.
bool validateModules(const BoardConfig& c, std::string* error) {
  return validateEkfConfig(c.ekf, error) && validateStageConfig(c.stage.machine, error) &&
         validatePanelPoseConfig(c.markers.panel_pose, error) &&
         validateMarkerCovarianceConfig(c.markers.covariance, error) && validateVisionPipelineConfig(c.vision, error);
}

}  // namespace

BoardConfig defaultBoardConfig() {
  BoardConfig config{};
  std::string error;
  // Every default is valid by construction (BoardConfig.DeclaredDefaultsAreAllValid checks it).
  applyDefaults(boardParams(config), &error);
  return config;
}

bool checkBoardDefaults(std::string* error) {
  BoardConfig config{};
  const std::vector<ParamSpecView> views = boardParams(config);
  if (!applyDefaults(views, error)) return false;
  // A default taken from a struct's initialiser was never parsed: it must lie in the declared range too.
  for (const ParamSpecView& v : views) {
    if (!paramInRange(v.type, v.min, v.max, v.choices, v.target)) {
      if (error) *error = "<built-in defaults>: key '" + v.key + "' is out of its declared range";
      return false;
    }
  }
  return validateModules(config, error);
}

bool loadBoardConfigText(const std::string& text, const std::string& name, BoardConfig* config,
                         std::string* error) {
  *config = defaultBoardConfig();
  YAML::Node root;
  if (!parseYamlDocument(text, name, &root, error)) return false;
  if (!applyParams(boardParams(*config), root, name, error)) return false;
  std::string module_error;
  if (!validateModules(*config, &module_error)) {
    if (error) *error = name + ": " + module_error;
    return false;
  }
  return checkDenseStereoSize(*config, name, error);
}

bool loadBoardConfig(const std::string& path, BoardConfig* config, std::string* error) {
  std::string text;
  if (!readTextFile(path, "the board file", &text, error)) {
    *config = defaultBoardConfig();
    return false;
  }
  return loadBoardConfigText(text, path, config, error);
}

std::string describeBoardParams() {
  BoardConfig config{};
  return describeParams(boardParams(config));
}

}  // namespace deepnav
