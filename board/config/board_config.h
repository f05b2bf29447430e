#pragma once
#include <array>
#include <string>
#include <vector>

#include "board/config/param_table.h"
#include "drivers/buffers/live_inputs.h"
#include "drivers/camera/camera_config.h"
#include "drivers/recording/recording_writer.h"
#include "nav/ekf/ekf_config.h"
#include "nav/markers/marker_pose_covariance.h"
#include "nav/markers/panel_pose_config.h"
#include "nav/stage/stage_config.h"
#include "vision/calib/pinax_model.h"
#include "vision/pipeline/vision_pipeline_config.h"

#include <Eigen/Geometry>

namespace deepnav {

// Everything one vehicle's board.yaml sets. Each field is declared once, with unit, default and range:
// the board's own in board_config.cpp, a module's next to its config struct (ekfParams(), stageParams(),
// liveInputCapacityParams(), panelPoseParams(), markerCovarianceParams(), flatPortParams(), pinaxParams(), visionPipelineParams()), whose structs are held here as the module reads them (no
// copies). The comments here only say what the group is for.
struct BoardConfig {
  struct Loop {
    int rate_hz;             // nav loop tick rate
    int budget_us;           // nav tick time budget; longer ticks count as overruns
    int vision_budget_us;    // vision worker budget per frame
    int vision_latency_ms;   // replay: when a frame's vision result becomes available after capture
    double late_tick_tolerance;  // a tick later than this fraction of the period counts as late
    double output_tau_s;     // time constant of the published pose's smoothing (0: the EKF's pose)
  } loop;
  struct Buffers {
    LiveInputCapacities inputs;  // the drivers' rings and frame pool (drivers/buffers/live_inputs.h): buffers.imu ... frames
    int vision_results;
    int record;              // recorder queue, in records
  } buffers;
  struct Recording {
    bool enabled;
    RecordingOptions options;  // the recorder's: compression, chunk_*, record_images (image size: camera.*)
  } recording;
  struct Camera {
    int width_px;
    int height_px;
    int channels;
    double rate_hz;
    double fx_px;              // rectified pinhole intrinsics of the left camera
    double fy_px;
    double cx_px;
    double cy_px;
    double baseline_m;
    Eigen::Vector3d p_cam_in_robot_m;  // left camera optical centre in the robot frame
    Eigen::Quaterniond q_robot_body;   // mounting of the FLU camera body (optical z = body x)
    std::string calibration_file;      // stereo calibration of the raw images (OpenCV YAML); empty: rectified
    struct Port {                      // flat port in front of each camera (vision/calib/flat_port.h)
      std::string model;               // none | flat
      PinaxConfig pinax;               // the rectification's: the port's d0, d1, indices and reference distance
    } port;
    CameraSourceConfig source;         // the live stereo driver (drivers/camera): camera.driver, left, ...
  } camera;
  struct Markers {
    bool enabled;               // false: no marker detection, no panel pose, no marker pose fused
    bool panel_in_filter;       // the fixed panel as a clone in the EKF (nav/pipeline/panel_anchor.h)
    std::string panel_file;     // panel description (knowledge base); empty: no markers
    PanelPoseConfig panel_pose;          // markers.panel_min_observations ... markers.max_distance_m
    MarkerCovarianceConfig covariance;   // markers.pos_floor_m ... markers.rot_per_d_rad_per_m
  } markers;
  struct Stage {
    bool fuse_markers_in_stage2;  // false: the paper's T_L3 (stage 2 on VO and nav sensors alone)
    StageConfig machine;          // stage.min_workspace_time_s, min_faces_seen_fraction, stage2_without_panel
  } stage;
  // The vision worker's own config (vision/pipeline/vision_pipeline_config.h): the vision.* keys land in it;
  // visionConfig() (board/config/vehicle_setup.h) adds the image size, rig, markers and rectification.
  VisionPipelineConfig vision;
  struct Sources {                // where `deepnav run` takes its inputs (board/service/README.md)
    std::string replay_path;      // recording played as the sensors, relative to the board file
    std::string dvl_serial;       // devices, checked by the board validation; empty: not fitted
    std::string ahrs_serial;
    std::string depth_serial;
    std::string can_interface;
  } sources;
  struct Outputs {                // NavSolution to the vehicle at loop rate (board/service/README.md)
    bool modbus_enabled;
    std::string modbus_address;
    int modbus_port;
    int modbus_max_clients;
    std::string udp_destinations;  // "host:port,host:port"; empty: no UDP
  } outputs;
  struct Service {
    std::string recording_dir;    // where `deepnav run` writes its recording; empty: no recording
    std::string state_dir;        // where `deepnav run` keeps its workspace across restarts; empty: none
  } service;
  struct Realtime {
    int loop_priority;            // SCHED_FIFO priority of the nav loop thread; 0: normal scheduling
    std::string loop_cpus;        // CPU list of the nav loop thread ("2" or "2-3,5"); empty: any
    std::string process_cpus;     // CPU list of every other thread; empty: any
    bool mlockall;                // lock all memory (no page faults in the loop)
  } realtime;
  struct SerialSensors {         // serial DVL and AHRS drivers (drivers/serial, drivers/parsers/README.md)
    std::string dvl_protocol;     // pd0 | pd6 | wl-a50
    int dvl_baud;
    std::string ahrs_protocol;    // xsens | nmea0183
    int ahrs_baud;
    double reopen_interval_s;     // a vanished port is reopened this often
  } serial;
  struct CanSensors {             // CAN compass/attitude/IMU driver (drivers/can)
    int heading_source;           // NMEA 2000 source address of PGN 127250; -1: any
    int attitude_source;          // of PGN 127257; -1: any
    std::string imu_mapping;      // CanFieldMapping spec for a non-NMEA-2000 sensor; empty: none
    double bus_off_recovery_s;    // restart the controller after this long in bus-off
  } can;
  struct ModbusDepth {            // Modbus RTU depth sensor (drivers/modbus), on sources.depth_serial
    int baud;
    std::string parity;           // N | E | O
    int stop_bits;
    int slave_id;
    std::string register_kind;    // input | holding
    int register_address;
    std::string value_type;       // u16 | i16 | u32 | i32 | f32
    bool high_word_first;
    double scale_pa;              // pascals per count
    double offset_pa;
    double atmospheric_pa;
    double water_density_kgpm3;
    double rate_hz;
    int timeout_ms;
  } modbus_depth;
  EkfConfig ekf;  // navigation filter: mounting, noise, gates, timeouts, delayed-fusion window
};

// Parses and validates a board file; unknown keys, wrong types and out-of-range values fail with one
// message naming the file, the key and the allowed range.
bool loadBoardConfig(const std::string& path, BoardConfig* config, std::string* error);

// The same from YAML text already in memory (e.g. the board stored in a recording); `name` is used in
// messages in place of a file name.
bool loadBoardConfigText(const std::string& text, const std::string& name, BoardConfig* config,
                         std::string* error);

// The built-in defaults (what an empty board.yaml gives).
BoardConfig defaultBoardConfig();

// True when every declared default parses and lies in its range (a test guards the table).
bool checkBoardDefaults(std::string* error);

// Markdown table of every board parameter (unit, default, range, meaning).
std::string describeBoardParams();

}  // namespace deepnav
