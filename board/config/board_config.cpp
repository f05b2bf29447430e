#include "board/config/board_config.h"

#include "board/config/text_file.h"


#include <yaml-cpp/yaml.h>

namespace deepnav {
namespace {

using P = ParamSpec<BoardConfig>;

#define DEEPNAV_FIELD(expr) [](BoardConfig& c) -> void* { return &c.expr; }

const std::array kBoardParams = {
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
    P{"buffers.imu", ParamType::kInt, "samples", 8, 65536, "512", "", "IMU ring capacity",
      DEEPNAV_FIELD(buffers.imu)},
    P{"buffers.dvl", ParamType::kInt, "samples", 4, 65536, "64", "", "DVL ring capacity",
      DEEPNAV_FIELD(buffers.dvl)},
    P{"buffers.heading", ParamType::kInt, "samples", 4, 65536, "64", "", "compass ring capacity",
      DEEPNAV_FIELD(buffers.heading)},
    P{"buffers.attitude", ParamType::kInt, "samples", 4, 65536, "64", "", "AHRS attitude ring capacity",
      DEEPNAV_FIELD(buffers.attitude)},
    P{"buffers.depth", ParamType::kInt, "samples", 4, 65536, "64", "", "depth ring capacity",
      DEEPNAV_FIELD(buffers.depth)},
    P{"buffers.frames", ParamType::kInt, "pairs", 2, 64, "6", "", "stereo frames in the preallocated pool",
      DEEPNAV_FIELD(buffers.frames)},
    P{"buffers.vision_results", ParamType::kInt, "results", 4, 4096, "32", "", "vision result ring capacity",
      DEEPNAV_FIELD(buffers.vision_results)},
    P{"buffers.record", ParamType::kInt, "records", 64, 1048576, "8192", "",
      "recorder queue between the loop and the MCAP writer thread", DEEPNAV_FIELD(buffers.record)},
    P{"recording.enabled", ParamType::kBool, "-", 0, 0, "true", "", "record every consumed sample and output",
      DEEPNAV_FIELD(recording.enabled)},
    P{"recording.compression", ParamType::kChoice, "-", 0, 0, "zstd", "zstd|lz4|none",
      "MCAP chunk compression", DEEPNAV_FIELD(recording.compression)},
    P{"recording.chunk_max_duration_s", ParamType::kDouble, "s", 0.01, 1.0, "1.0", "",
      "a chunk closes (and is flushed to disk) at least this often, bounding what a crash loses",
      DEEPNAV_FIELD(recording.chunk_max_duration_s)},
    P{"recording.chunk_size_kib", ParamType::kInt, "KiB", 16, 65536, "4096", "",
      "a chunk closes when its uncompressed size exceeds this", DEEPNAV_FIELD(recording.chunk_size_kib)},
    P{"recording.record_images", ParamType::kBool, "-", 0, 0, "true", "",
      "record stereo images (large) besides the navigation samples", DEEPNAV_FIELD(recording.record_images)},
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
    P{"camera.port.pinhole_to_glass_m", ParamType::kDouble, "m", 0, 0.5, "0.0", "",
      "flat port: distance from the pinhole (entrance pupil) to the inner glass surface, d0",
      DEEPNAV_FIELD(camera.port.pinhole_to_glass_m)},
    P{"camera.port.glass_thickness_m", ParamType::kDouble, "m", 0, 0.2, "0.0", "", "flat port: glass thickness, d1",
      DEEPNAV_FIELD(camera.port.glass_thickness_m)},
    P{"camera.port.n_air", ParamType::kDouble, "-", 1, 2, "1.0", "", "flat port: refractive index inside the housing",
      DEEPNAV_FIELD(camera.port.n_air)},
    P{"camera.port.n_glass", ParamType::kDouble, "-", 1, 3, "1.49", "",
      "flat port: refractive index of the glass (acrylic 1.49, BK7 1.52, sapphire 1.77)",
      DEEPNAV_FIELD(camera.port.n_glass)},
    P{"camera.port.n_water", ParamType::kDouble, "-", 1, 2, "1.34", "", "flat port: refractive index of the water",
      DEEPNAV_FIELD(camera.port.n_water)},
    P{"camera.port.reference_distance_m", ParamType::kDouble, "m", 0.2, 50, "2.0", "",
      "flat port: distance at which the PinAx mapping is exact (middle of the working range)",
      DEEPNAV_FIELD(camera.port.reference_distance_m)},
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
    P{"markers.panel_file", ParamType::kString, "path", 0, 0, "''", "",
      "panel description (knowledge base), relative to the board file; empty: no markers",
      DEEPNAV_FIELD(markers.panel_file)},
    P{"markers.panel_min_observations", ParamType::kInt, "-", 1, 100000, "30", "",
      "marker observations before the panel pose can be fixed", DEEPNAV_FIELD(markers.panel_min_observations)},
    P{"markers.panel_min_distinct_markers", ParamType::kInt, "-", 1, 4096, "2", "",
      "distinct markers before the panel pose can be fixed", DEEPNAV_FIELD(markers.panel_min_distinct_markers)},
    P{"markers.panel_max_position_std_m", ParamType::kDouble, "m", 0.001, 10, "0.05", "",
      "position scatter below which the panel pose is fixed", DEEPNAV_FIELD(markers.panel_max_position_std_m)},
    P{"markers.panel_max_angle_std_rad", ParamType::kDouble, "rad", 0.0001, 1, "0.035", "",
      "rotation scatter below which the panel pose is fixed", DEEPNAV_FIELD(markers.panel_max_angle_std_rad)},
    P{"markers.max_distance_m", ParamType::kDouble, "m", 0.1, 50, "4.0", "",
      "markers farther than this are not used for the panel pose", DEEPNAV_FIELD(markers.max_distance_m)},
    P{"markers.pos_floor_m", ParamType::kDouble, "m", 0, 1, "0.01", "",
      "marker pose position 1-sigma at zero distance", DEEPNAV_FIELD(markers.pos_floor_m)},
    P{"markers.pos_per_d2_per_m", ParamType::kDouble, "1/m", 0, 1, "0.01", "",
      "growth of the position 1-sigma with the squared distance", DEEPNAV_FIELD(markers.pos_per_d2_per_m)},
    P{"markers.rot_floor_rad", ParamType::kDouble, "rad", 0, 1, "0.0087", "",
      "marker pose rotation 1-sigma at zero distance", DEEPNAV_FIELD(markers.rot_floor_rad)},
    P{"markers.rot_per_d_rad_per_m", ParamType::kDouble, "rad/m", 0, 1, "0.0087", "",
      "growth of the rotation 1-sigma with distance", DEEPNAV_FIELD(markers.rot_per_d_rad_per_m)},
    P{"stage.min_workspace_time_s", ParamType::kDouble, "s", 0, 86400, "30", "",
      "time in stage 1 (workspace definition) before stage 2", DEEPNAV_FIELD(stage.min_workspace_time_s)},
    P{"stage.min_faces_seen_fraction", ParamType::kDouble, "-", 0, 1, "0.5", "",
      "fraction of the panel faces seen in stage 1 before stage 2", DEEPNAV_FIELD(stage.min_faces_seen_fraction)},
    P{"sources.replay_path", ParamType::kString, "path", 0, 0, "''", "",
      "`deepnav run`: recording played as the sensors, relative to the board file (sim and bench rigs)",
      DEEPNAV_FIELD(sources.replay_path)},
    P{"sources.camera_left", ParamType::kString, "host", 0, 0, "''", "",
      "left GigE Vision camera (IP address), checked by a GVCP discovery at start-up; empty: not fitted",
      DEEPNAV_FIELD(sources.camera_left)},
    P{"sources.camera_right", ParamType::kString, "host", 0, 0, "''", "",
      "right GigE Vision camera (IP address); empty: not fitted", DEEPNAV_FIELD(sources.camera_right)},
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
    P{"ekf.gravity_mps2", ParamType::kDouble, "m/s^2", 9.7, 9.9, "9.80665", "", "local gravity magnitude",
      DEEPNAV_FIELD(ekf.gravity_mps2)},
    P{"ekf.imu_rotation_deg", ParamType::kRotation, "deg", -180, 180, "[0, 0, 0]", "", "mounting rotation IMU -> robot, [roll, pitch, yaw]",
      DEEPNAV_FIELD(ekf.q_robot_imu)},
    P{"ekf.p_imu_in_robot_m", ParamType::kVec3, "m", -10, 10, "[0, 0, 0]", "", "IMU lever arm in the robot frame (FLU)",
      DEEPNAV_FIELD(ekf.p_imu_in_robot_m)},
    P{"ekf.dvl_rotation_deg", ParamType::kRotation, "deg", -180, 180, "[0, 0, 0]", "", "mounting rotation DVL -> robot, [roll, pitch, yaw]",
      DEEPNAV_FIELD(ekf.q_robot_dvl)},
    P{"ekf.p_dvl_in_robot_m", ParamType::kVec3, "m", -10, 10, "[0, 0, 0]", "", "DVL lever arm in the robot frame",
      DEEPNAV_FIELD(ekf.p_dvl_in_robot_m)},
    P{"ekf.p_depth_in_robot_m", ParamType::kVec3, "m", -10, 10, "[0, 0, 0]", "", "pressure port position in the robot frame",
      DEEPNAV_FIELD(ekf.p_depth_in_robot_m)},
    P{"ekf.gyro_arw_radps_rthz", ParamType::kDouble, "rad/s/sqrt(Hz)", 1e-07, 1, "1.0e-4", "", "gyro angle random walk",
      DEEPNAV_FIELD(ekf.gyro_arw_radps_rthz)},
    P{"ekf.accel_vrw_mps2_rthz", ParamType::kDouble, "m/s^2/sqrt(Hz)", 1e-06, 10, "1.0e-3", "", "accelerometer velocity random walk",
      DEEPNAV_FIELD(ekf.accel_vrw_mps2_rthz)},
    P{"ekf.gyro_bias_rw_radps2_rthz", ParamType::kDouble, "rad/s^2/sqrt(Hz)", 0, 1, "1.0e-5", "", "gyro bias random walk",
      DEEPNAV_FIELD(ekf.gyro_bias_rw_radps2_rthz)},
    P{"ekf.accel_bias_rw_mps3_rthz", ParamType::kDouble, "m/s^3/sqrt(Hz)", 0, 10, "1.0e-4", "", "accelerometer bias random walk",
      DEEPNAV_FIELD(ekf.accel_bias_rw_mps3_rthz)},
    P{"ekf.init_pos_sigma_m", ParamType::kDouble, "m", 0.0001, 10000.0, "0.1", "", "initial position 1-sigma",
      DEEPNAV_FIELD(ekf.init_pos_sigma_m)},
    P{"ekf.init_vel_sigma_mps", ParamType::kDouble, "m/s", 0.0001, 100, "0.1", "", "initial velocity 1-sigma",
      DEEPNAV_FIELD(ekf.init_vel_sigma_mps)},
    P{"ekf.init_yaw_sigma_rad", ParamType::kDouble, "rad", 0.0001, 3.5, "0.1", "", "initial yaw 1-sigma (after the first heading)",
      DEEPNAV_FIELD(ekf.init_yaw_sigma_rad)},
    P{"ekf.dvl_sigma_mps", ParamType::kDouble, "m/s", 1e-05, 1, "0.01", "", "DVL velocity 1-sigma per axis when the sample carries none",
      DEEPNAV_FIELD(ekf.dvl_sigma_mps)},
    P{"ekf.depth_sigma_m", ParamType::kDouble, "m", 0.0001, 10, "0.05", "", "depth 1-sigma when the sample carries none",
      DEEPNAV_FIELD(ekf.depth_sigma_m)},
    P{"ekf.heading_sigma_rad", ParamType::kDouble, "rad", 0.0001, 1, "0.035", "", "compass heading 1-sigma when the sample carries none",
      DEEPNAV_FIELD(ekf.heading_sigma_rad)},
    P{"ekf.attitude_sigma_rad", ParamType::kDouble, "rad", 1e-05, 1, "0.0087", "", "AHRS roll/pitch 1-sigma when the sample carries none",
      DEEPNAV_FIELD(ekf.attitude_sigma_rad)},
    P{"ekf.magnetic_declination_rad", ParamType::kDouble, "rad", -3.15, 3.15, "0.0", "", "true = magnetic + declination (east positive)",
      DEEPNAV_FIELD(ekf.magnetic_declination_rad)},
    P{"ekf.heading_bias_rad", ParamType::kDouble, "rad", -3.15, 3.15, "0.0", "", "compass bias (measured = true + bias), e.g. hard iron",
      DEEPNAV_FIELD(ekf.heading_bias_rad)},
    P{"ekf.gate_dvl_sigma", ParamType::kDouble, "sigma", 1, 100, "3.0", "", "DVL innovation gate",
      DEEPNAV_FIELD(ekf.gate_dvl_sigma)},
    P{"ekf.gate_depth_sigma", ParamType::kDouble, "sigma", 1, 100, "3.0", "", "depth innovation gate",
      DEEPNAV_FIELD(ekf.gate_depth_sigma)},
    P{"ekf.gate_heading_sigma", ParamType::kDouble, "sigma", 1, 100, "3.0", "", "compass innovation gate",
      DEEPNAV_FIELD(ekf.gate_heading_sigma)},
    P{"ekf.gate_attitude_sigma", ParamType::kDouble, "sigma", 1, 100, "3.0", "", "AHRS innovation gate",
      DEEPNAV_FIELD(ekf.gate_attitude_sigma)},
    P{"ekf.gate_pose_sigma", ParamType::kDouble, "sigma", 1, 100, "3.0", "", "marker pose innovation gate",
      DEEPNAV_FIELD(ekf.gate_pose_sigma)},
    P{"ekf.gate_relative_pose_sigma", ParamType::kDouble, "sigma", 1, 100, "3.0", "", "visual odometry innovation gate",
      DEEPNAV_FIELD(ekf.gate_relative_pose_sigma)},
    P{"ekf.timeout_imu_s", ParamType::kDurationS, "s", 0, 10, "0.05", "", "IMU stale after this long without a sample (0: not monitored)",
      DEEPNAV_FIELD(ekf.timeout_imu_us)},
    P{"ekf.timeout_dvl_s", ParamType::kDurationS, "s", 0, 60, "1.0", "", "DVL stale timeout",
      DEEPNAV_FIELD(ekf.timeout_dvl_us)},
    P{"ekf.timeout_depth_s", ParamType::kDurationS, "s", 0, 60, "1.0", "", "depth stale timeout",
      DEEPNAV_FIELD(ekf.timeout_depth_us)},
    P{"ekf.timeout_heading_s", ParamType::kDurationS, "s", 0, 60, "1.0", "", "compass stale timeout",
      DEEPNAV_FIELD(ekf.timeout_heading_us)},
    P{"ekf.timeout_attitude_s", ParamType::kDurationS, "s", 0, 60, "1.0", "", "AHRS stale timeout",
      DEEPNAV_FIELD(ekf.timeout_attitude_us)},
    P{"ekf.max_delay_s", ParamType::kDurationS, "s", 0.01, 2.0, "0.5", "", "measurements older than this are dropped and counted",
      DEEPNAV_FIELD(ekf.max_delay_us)},
    P{"ekf.history_imu_capacity", ParamType::kInt, "epochs", 8, 4096, "160", "", "IMU epochs kept for re-propagation (cover max_delay at the IMU rate)",
      DEEPNAV_FIELD(ekf.history_imu_capacity)},
    P{"ekf.history_meas_capacity", ParamType::kInt, "measurements", 8, 4096, "128", "", "measurements kept for re-fusion inside the window",
      DEEPNAV_FIELD(ekf.history_meas_capacity)},
    P{"ekf.align_imu_samples", ParamType::kInt, "samples", 1, 1000, "20", "", "IMU samples averaged for the initial roll/pitch",
      DEEPNAV_FIELD(ekf.align_imu_samples)},
};

#undef DEEPNAV_FIELD

}  // namespace

BoardConfig defaultBoardConfig() {
  BoardConfig config{};
  std::string error;
  // Every default is valid by construction (BoardConfig.DeclaredDefaultsAreAllValid checks it).
  applyDefaults(bindParams(kBoardParams, config), &error);
  return config;
}

bool checkBoardDefaults(std::string* error) {
  BoardConfig config{};
  return applyDefaults(bindParams(kBoardParams, config), error) && validateEkfConfig(config.ekf, error);
}

bool loadBoardConfigText(const std::string& text, const std::string& name, BoardConfig* config,
                         std::string* error) {
  *config = defaultBoardConfig();
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    if (error) *error = name + ": not valid YAML (line " + std::to_string(e.mark.line + 1) + "): " + e.msg;
    return false;
  }
  if (!applyParams(bindParams(kBoardParams, *config), root, name, error)) return false;
  std::string ekf_error;
  if (!validateEkfConfig(config->ekf, &ekf_error)) {
    if (error) *error = name + ": " + ekf_error;
    return false;
  }
  return true;
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
  return describeParams(bindParams(kBoardParams, config));
}

}  // namespace deepnav
