#include "tools/sim/dive_recorder.h"

#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "base/overloaded.h"
#include "board/config/panel_file.h"
#include "board/config/recording_options.h"
#include "board/config/vehicle_setup.h"
#include "tools/sim/faults/frame_corruption.h"
#include "tools/sim/port_calibration.h"
#include "tools/sim/render/panel_knowledge.h"
#include "tools/sim/render/stereo_renderer.h"
#include "drivers/recording/recording_writer.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"

namespace deepnav::sim {
namespace {

// The vehicle's odometry frame: ENU axes, origin at the robot's start position horizontally and at the
// sea surface vertically (z = -depth, as the filter integrates it). The simulator's scene frame has its
// origin at the panel site; ground truth is recorded in the vehicle's frame so the two compare directly.
Eigen::Vector3d sceneToOdomOffset(const SensorSimulator& sim) {
  const Eigen::Vector3d start = sim.truthAt(0).p_robot_in_odom_m;
  return Eigen::Vector3d(start.x(), start.y(), sim.scenario().environment.odom_origin_depth_m);
}

TruthSample toTruth(const GroundTruthSample& g, const Eigen::Vector3d& scene_to_odom_m) {
  TruthSample t = g;
  t.p_robot_in_odom_m -= scene_to_odom_m;
  return t;
}

// Renders the pair of a camera tick into one reused frame and records it, followed by its ground truth
// (poses in the recorded odometry frame, visible markers, depth and disparity maps of the left image).
struct FrameRecorder {
  StereoRenderer renderer;
  StereoFrame frame;
  RenderTruth render_truth;
  FrameTruth truth;
  bool enabled = false;
  std::uint64_t seed = 0;

  bool init(const Scenario& scenario, std::uint64_t sim_seed, const BoardConfig& board, bool render, bool maps,
            std::string* error) {
    seed = sim_seed;
    enabled = render && scenario.camera.enabled;
    if (!enabled) return true;
    if (!allocateStereoFrame(frame, scenario.camera.width_px, scenario.camera.height_px, board.camera.channels)) {
      if (error) *error = "sim: cannot allocate the stereo frame";
      return false;
    }
    if (!renderer.init(scenario, seed, board.camera.channels, error)) return false;
    renderer.useSecondThread();  // the right view on the second core: same recording, about half the time
    renderer.allocateTruth(&render_truth);
    if (!maps) return true;  // empty maps: the writer records poses and marker ids only
    truth.depth_m = render_truth.depth_m;  // shares the pixels: the renderer fills them
    truth.disparity_px = render_truth.disparity_px;
    return true;
  }
  void record(const CameraTick& tick, const SensorSimulator& sim, const Eigen::Vector3d& scene_to_odom_m,
              RecordingWriter* writer, DiveRecordSummary* summary) {
    if (!enabled || !renderer.render(tick, &frame, &render_truth)) return;
    if (tick.corrupted) corruptStereoFrame(seed, tick.frame_index, &frame);
    frame.exposure_us = 4000;
    writer->recordFrame(frame, -1);
    // The robot's pose at the exposure, as the tick's camera poses (the stamp carries the camera's clock
    // offset and latency, timing.camera).
    const KinematicState robot = sim.truthAt(tick.exposure_t_us);
    truth.t_us = tick.t_us;
    truth.sequence = frame.sequence;
    truth.p_robot_in_odom_m = robot.p_robot_in_odom_m - scene_to_odom_m;
    truth.q_odom_robot = robot.q_odom_robot;
    truth.p_left_cam_in_odom_m = tick.p_left_cam_in_odom_m - scene_to_odom_m;
    truth.q_odom_left_cam = tick.q_odom_left_cam;
    truth.p_right_cam_in_odom_m = tick.p_right_cam_in_odom_m - scene_to_odom_m;
    truth.q_odom_right_cam = tick.q_odom_right_cam;
    truth.visible_marker_ids = render_truth.visible_marker_ids;
    writer->recordFrameTruth(truth);
    ++summary->frames;
  }
};

// Sensor samples become loop inputs; camera ticks become rendered stereo pairs. Dispatched by the sample's
// type, so the stream enum and the variant's order cannot disagree here.
void recordEvent(const SimEvent& e, const SensorSimulator& sim, const Eigen::Vector3d& scene_to_odom_m,
                 FrameRecorder* frames, RecordingWriter* writer, DiveRecordSummary* summary) {
  std::visit(Overloaded{[&](const GroundTruthSample& g) { writer->recordTruth(toTruth(g, scene_to_odom_m)); },
                        [&](const CameraTick& tick) {
                          ++summary->camera_ticks;
                          frames->record(tick, sim, scene_to_odom_m, writer, summary);
                        },
                        [&](const auto& input) { writer->recordInputArrived(input, e.t_us); }},
             e.sample);
}

// The run's identity and the true panel pose in the recorded odometry frame (T_odom_panel: footprint
// centre on the seabed, x along the front face's outward normal, z up; makePanelDescription's frame), so
// that an evaluation can score the robot relative to the panel.
std::map<std::string, std::string> simMetadata(const DiveRecordOptions& o, const Scenario& scenario,
                                               const Eigen::Vector3d& scene_to_odom_m) {
  const Eigen::Vector3d p_panel_in_odom_m =
      Eigen::Vector3d(scenario.panel.centre_in_odom_m[0], scenario.panel.centre_in_odom_m[1],
                      scenario.environment.seabedZInOdom_m()) - scene_to_odom_m;
  char position[128];
  std::snprintf(position, sizeof(position), "%.9g %.9g %.9g", p_panel_in_odom_m.x(), p_panel_in_odom_m.y(),
                p_panel_in_odom_m.z());
  char yaw[64];
  std::snprintf(yaw, sizeof(yaw), "%.9g", scenario.panel.front_yaw_deg);
  return {{"scenario", o.scenario_path},
          {"seed", std::to_string(o.seed)},
          {"p_panel_in_odom_m", position},
          {"yaw_odom_panel_deg", yaw}};
}

}  // namespace

bool recordDive(const DiveRecordOptions& o, DiveRecordSummary* summary, std::string* error) {
  *summary = DiveRecordSummary{};
  Scenario scenario;
  if (!loadScenario(o.scenario_path, &scenario, error)) return false;
  VehicleSetup setup;
  if (!loadVehicleSetup(o.board_path, &setup, error)) return false;
  bool port_described = false;
  if (!describeSimulatedPort(scenario, &setup, &port_described, error)) return false;
  if (port_described && o.progress)
    std::fprintf(stderr, "sim: flat port: the recording's board names the simulated in-air calibration and "
                         "camera.port (replay with --set camera.port.model=none for no correction)\n");
  SensorSimulator sim;
  if (!sim.init(scenario, o.seed, error)) return false;
  auto frames = std::make_unique<FrameRecorder>();
  if (!frames->init(scenario, o.seed, setup.config, o.render, o.truth_maps, error)) return false;
  RecordingWriter writer;
  RecordingOptions recording = recordingOptions(setup.config);
  recording.truth_maps = frames->enabled && o.truth_maps;
  if (!writer.open(o.out_path, recording, error)) return false;
  for (const auto& [name, values] : recordingMetadata(setup)) writer.recordMetadata(name, values);
  const Eigen::Vector3d scene_to_odom_m = sceneToOdomOffset(sim);
  writer.recordMetadata("deepnav.sim", simMetadata(o, scenario, scene_to_odom_m));
  SimEvent e;
  TimeUs next_report_us = 0;
  while (sim.next(&e)) {
    recordEvent(e, sim, scene_to_odom_m, frames.get(), &writer, summary);
    summary->duration_s = usToS(e.t_us);
    if (o.progress && e.t_us >= next_report_us) {
      std::fprintf(stderr, "sim: %5.1f / %.0f s simulated\n", usToS(e.t_us), scenario.duration_s);
      next_report_us = e.t_us + 30 * kUsPerS;
    }
  }
  summary->messages = writer.messages();
  if (writer.failures() > 0) {
    if (error) *error = o.out_path + ": " + std::to_string(writer.failures()) + " messages could not be written";
    return false;
  }
  return writer.close(error);
}

bool writeScenarioPanel(const std::string& scenario_path, const std::string& out_path, std::string* error) {
  Scenario scenario;
  return loadScenario(scenario_path, &scenario, error) &&
         writePanelDescription(out_path, makePanelDescription(scenario), error);
}

}  // namespace deepnav::sim
