// A module's keys are declared once, next to its config struct (ParamDecl): the board reads its files
// through that declaration into the module's own struct, and the module validates against the same
// range, so a value the board refuses is one the module refuses too (and the reverse).
#include "board/config/board_config.h"
#include "board/config/camera_rectification.h"
#include "board/config/vehicle_setup.h"
#include "vision/pipeline/vision_pipeline.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace deepnav {
namespace {

std::string numberText(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// Values just outside [min, max], written as a board file writes them.
std::vector<std::string> outsideValues(ParamType type, double min, double max) {
  const double step = type == ParamType::kInt || type == ParamType::kSize ? 1.0 : 0.01 * std::max(1.0, std::abs(max - min));
  std::vector<std::string> out;
  for (double v : {min - step, max + step}) {
    out.push_back(type == ParamType::kVec3 ? "[0, 0, " + numberText(v) + "]" : numberText(v));
  }
  return out;
}

// "a.b" and "k", "v" as a board file nests them: "a:\n  b:\n    k: v\n".
std::string nestedYaml(const std::string& section, const std::string& key, const std::string& value) {
  std::string yaml;
  std::string indent;
  std::size_t begin = 0;
  for (std::size_t dot = section.find('.');; dot = section.find('.', begin)) {
    yaml += indent + section.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin) + ":\n";
    indent += "  ";
    if (dot == std::string::npos) break;
    begin = dot + 1;
  }
  return yaml + indent + key + ": " + value + "\n";
}

// Sets the field a declaration lands in from the same number (seconds for a duration).
template <typename Config>
void setField(const ParamDecl<Config>& d, Config* c, double v) {
  void* target = d.field(*c);
  switch (d.type) {
    case ParamType::kInt: *static_cast<int*>(target) = static_cast<int>(v); break;
    case ParamType::kSize: *static_cast<std::size_t*>(target) = static_cast<std::size_t>(v); break;
    case ParamType::kDouble: *static_cast<double*>(target) = v; break;
    case ParamType::kDurationS: *static_cast<TimeUs*>(target) = sToUs(v); break;
    case ParamType::kVec3: *static_cast<Eigen::Vector3d*>(target) = Eigen::Vector3d(0.0, 0.0, v); break;
    default: break;
  }
}

template <typename Config>
void expectOneRange(std::span<const ParamDecl<Config>> decls, const char* section,
                    bool (*validate)(const Config&, std::string*)) {
  for (const auto& d : decls) {
    if (d.type != ParamType::kInt && d.type != ParamType::kSize && d.type != ParamType::kDouble &&
        d.type != ParamType::kDurationS && d.type != ParamType::kVec3) {
      continue;
    }
    const std::string key = std::string(section) + "." + d.key;
    for (const std::string& v : outsideValues(d.type, d.min, d.max)) {
      // WHEN the board file sets the key outside its range THEN the board refuses it, naming the key
      BoardConfig board{};
      std::string error;
      const std::string yaml = nestedYaml(section, d.key, v);
      EXPECT_FALSE(loadBoardConfigText(yaml, "board.yaml", &board, &error)) << yaml;
      EXPECT_NE(error.find("'" + key + "'"), std::string::npos) << error;
      // AND the module, given the same value directly, refuses it too, naming its field and the key
      Config c{};
      const double number = d.type == ParamType::kVec3 ? std::stod(v.substr(7)) : std::stod(v);
      setField(d, &c, number);
      error.clear();
      EXPECT_FALSE(validate(c, &error)) << key << " = " << v;
      EXPECT_NE(error.find(d.member), std::string::npos) << error;
      EXPECT_NE(error.find(key), std::string::npos) << error;
    }
  }
}

TEST(BoardModuleParams, TheBoardAndTheModuleRefuseTheSameValues) {
  expectOneRange<EkfConfig>(ekfParams(), kEkfSection, validateEkfConfig);
  expectOneRange<StageConfig>(stageParams(), kStageSection, validateStageConfig);
  expectOneRange<PanelPoseConfig>(panelPoseParams(), kMarkersSection, validatePanelPoseConfig);
  expectOneRange<MarkerCovarianceConfig>(markerCovarianceParams(), kMarkersSection, validateMarkerCovarianceConfig);
  expectOneRange<VisionPipelineConfig>(visionPipelineParams(), kVisionSection, validateVisionPipelineConfig);
  expectOneRange<FlatPort>(flatPortParams(), kCameraPortSection, validateFlatPort);
  expectOneRange<PinaxConfig>(pinaxParams(), kCameraPortSection, validatePinaxConfig);
  expectOneRange<LiveInputCapacities>(liveInputCapacityParams(), kBuffersSection, validateLiveInputCapacities);
}

TEST(BoardModuleParams, BufferKeysLandInTheCapacitiesTheLoopAllocates) {
  const std::string yaml = "buffers:\n  imu: 1024\n  depth: 16\n  frames: 3\n  record: 100\n";
  BoardConfig c{};
  std::string error;
  ASSERT_TRUE(loadBoardConfigText(yaml, "board.yaml", &c, &error)) << error;
  EXPECT_EQ(c.buffers.inputs.imu, 1024u);
  EXPECT_EQ(c.buffers.inputs.depth, 16u);
  EXPECT_EQ(c.buffers.inputs.frames, 3u);
  EXPECT_EQ(c.buffers.inputs.dvl, LiveInputCapacities{}.dvl);
  EXPECT_EQ(c.buffers.record, 100);
  // The defaults are the capacities' initialisers, listed as the integers they always were
  const BoardConfig d = defaultBoardConfig();
  EXPECT_EQ(d.buffers.inputs.imu, 512u);
  EXPECT_EQ(d.buffers.inputs.heading, 64u);
  EXPECT_EQ(d.buffers.inputs.frames, 6u);
  const std::string table = describeBoardParams();
  EXPECT_NE(table.find("| `buffers.imu` | int | samples | `512` | an integer in [8, 65536] | IMU ring capacity |"),
            std::string::npos);
  EXPECT_NE(table.find("| `buffers.frames` | int | pairs | `6` | an integer in [2, 64] |"), std::string::npos);
  // AND a negative or fractional capacity is refused with the key's message
  EXPECT_FALSE(loadBoardConfigText("buffers:\n  dvl: -4\n", "board.yaml", &c, &error));
  EXPECT_EQ(error, "board.yaml: key 'buffers.dvl' is -4, out of range; allowed: an integer in [4, 65536] (samples)");
  EXPECT_FALSE(loadBoardConfigText("buffers:\n  dvl: 6.5\n", "board.yaml", &c, &error));
  EXPECT_EQ(error, "board.yaml: key 'buffers.dvl' is '6.5'; allowed: an integer in [4, 65536] (samples)");
}

TEST(BoardModuleParams, CameraPortKeysLandInThePinaxConfigTheRectificationUses) {
  const std::string yaml =
      "camera:\n  port:\n    model: flat\n    pinhole_to_glass_m: 0.008\n    glass_thickness_m: 0.012\n"
      "    n_glass: 1.52\n    reference_distance_m: 1.5\n";
  BoardConfig c{};
  std::string error;
  ASSERT_TRUE(loadBoardConfigText(yaml, "board.yaml", &c, &error)) << error;
  EXPECT_EQ(c.camera.port.pinax.port.pinhole_to_glass_m, 0.008);
  EXPECT_EQ(c.camera.port.pinax.port.glass_thickness_m, 0.012);
  EXPECT_EQ(c.camera.port.pinax.port.n_glass, 1.52);
  EXPECT_EQ(c.camera.port.pinax.reference_distance_m, 1.5);
  const RectificationOptions o = rectificationOptions(c);
  EXPECT_EQ(o.correction, PortCorrection::kPinax);
  EXPECT_EQ(o.pinax.port, c.camera.port.pinax.port);
  EXPECT_EQ(o.pinax.reference_distance_m, 1.5);
  // The defaults are the port's and the mapping's initialisers
  const BoardConfig d = defaultBoardConfig();
  EXPECT_EQ(d.camera.port.pinax.port, FlatPort{});
  EXPECT_EQ(d.camera.port.pinax.reference_distance_m, PinaxConfig{}.reference_distance_m);
  // AND the rule between two of them stays the port's: water denser than the housing's air
  FlatPort port;
  port.n_water = port.n_air;
  EXPECT_FALSE(validateFlatPort(port, &error));
  EXPECT_NE(error.find("n_water"), std::string::npos) << error;
}

TEST(BoardModuleParams, GravityHasTheBoardsRangeInTheFilterToo) {
  // GIVEN a filter config with a gravity the board never accepted (the filter once took (0, 20])
  EkfConfig c;
  c.gravity_mps2 = 15.0;
  std::string error;
  // THEN the filter refuses it with the board's range
  EXPECT_FALSE(validateEkfConfig(c, &error));
  EXPECT_EQ(error, "EkfConfig.gravity_mps2 (ekf.gravity_mps2): must be a number in [9.7, 9.9] (m/s^2)");
}

TEST(BoardModuleParams, KeysLandInTheModuleConfigsTheModulesRead) {
  const std::string yaml =
      "markers:\n  panel_min_observations: 7\n  max_distance_m: 3.5\n  rot_floor_rad: 0.02\n"
      "stage:\n  min_workspace_time_s: 12\n  stage2_without_panel: true\n"
      "ekf:\n  gravity_mps2: 9.81\n  timeout_dvl_s: 0.25\n";
  BoardConfig c{};
  std::string error;
  ASSERT_TRUE(loadBoardConfigText(yaml, "board.yaml", &c, &error)) << error;
  EXPECT_EQ(c.markers.panel_pose.min_observations, 7);
  EXPECT_EQ(c.markers.panel_pose.max_distance_m, 3.5);
  EXPECT_EQ(c.markers.covariance.rot_floor_rad, 0.02);
  EXPECT_EQ(c.stage.machine.min_workspace_time_s, 12.0);
  EXPECT_TRUE(c.stage.machine.stage2_without_panel);
  EXPECT_EQ(c.ekf.gravity_mps2, 9.81);
  EXPECT_EQ(c.ekf.timeout_dvl_us, 250000);
}

TEST(BoardModuleParams, DefaultsAreTheModulesInitialisersBarTheBoardsOwn) {
  const BoardConfig c = defaultBoardConfig();
  const EkfConfig ekf;
  EXPECT_EQ(c.ekf.gravity_mps2, ekf.gravity_mps2);
  EXPECT_EQ(c.ekf.gyro_arw_radps_rthz, ekf.gyro_arw_radps_rthz);
  EXPECT_EQ(c.ekf.timeout_imu_us, ekf.timeout_imu_us);
  EXPECT_EQ(c.ekf.q_robot_dvl.coeffs(), ekf.q_robot_dvl.coeffs());
  EXPECT_EQ(c.stage.machine.min_workspace_time_s, StageConfig{}.min_workspace_time_s);
  EXPECT_EQ(c.markers.panel_pose.min_observations, PanelPoseConfig{}.min_observations);
  EXPECT_EQ(c.markers.covariance.pos_floor_m, MarkerCovarianceConfig{}.pos_floor_m);
  // The one board default that differs from the bare filter's: a vehicle's IMU noise never repeats.
  EXPECT_EQ(ekf.imu_stuck_after_samples, 0);
  EXPECT_EQ(c.ekf.imu_stuck_after_samples, 10);
  const std::string table = describeBoardParams();
  EXPECT_NE(table.find("| `ekf.imu_stuck_after_samples` | int | samples | `10` |"), std::string::npos);
  EXPECT_NE(table.find("| `ekf.gravity_mps2` | double | m/s^2 | `9.80665` | a number in [9.7, 9.9] |"),
            std::string::npos);
  EXPECT_NE(table.find("| `ekf.dvl_rotation_deg` | rotation | deg | `[0, 0, 0]` |"), std::string::npos);
}

TEST(BoardModuleParams, VisionKeysLandInThePipelineConfigTheWorkerRuns) {
  // GIVEN a board setting vision keys of each kind (the two choices land in enums)
  const std::string yaml =
      "vision:\n  vo_mode: none\n  dense_method: sgbm-wls\n  quality_hysteresis: 0.1\n  orb_max_tracked: 250\n"
      "  orb_motion_prior: true\n  planes_covariance_scale: 50\n  map_every_n_frames: 3\n";
  VehicleSetup setup;
  std::string error;
  ASSERT_TRUE(parseVehicleSetup(yaml, "", "board.yaml", &setup, &error)) << error;
  // THEN the board holds them in the pipeline's own struct and the worker's config carries them as they are
  const VisionPipelineConfig v = visionConfig(setup);
  EXPECT_EQ(v.modality.mode, VoMode::kNone);
  EXPECT_EQ(v.dense.method, DenseStereoMethod::kSgbmWls);
  EXPECT_EQ(v.modality.hysteresis, 0.1);
  EXPECT_EQ(v.orb_max_tracked, 250);
  EXPECT_TRUE(v.orb.motion_prior.enabled);
  EXPECT_EQ(v.planes.registration.covariance_scale, 50.0);
  EXPECT_EQ(v.workspace.insert_every_n_frames, 3);
  // AND what the board does not set is the board's default
  EXPECT_EQ(v.orb.reset_after_lost_frames, 10);
  EXPECT_EQ(v.dense.num_disparities, 128);
  // AND the camera keys fill the image size and the rig
  EXPECT_EQ(v.width_px, setup.config.camera.width_px);
  EXPECT_EQ(v.rig.baseline_m, setup.config.camera.baseline_m);
}

TEST(BoardModuleParams, VisionChoicesAreTheEnumsInOrder) {
  // The choices of vision.vo_mode and vision.dense_method are positions in VoMode and DenseStereoMethod.
  for (int i = 0; i <= static_cast<int>(VoMode::kNone); ++i) {
    const std::string name = toString(static_cast<VoMode>(i));
    BoardConfig c{};
    std::string error;
    ASSERT_TRUE(loadBoardConfigText("vision:\n  vo_mode: " + name + "\n", "board.yaml", &c, &error)) << error;
    EXPECT_EQ(c.vision.modality.mode, static_cast<VoMode>(i)) << name;
  }
  EXPECT_EQ(denseStereoMethodName(DenseStereoMethod::kElas), "elas");
  EXPECT_EQ(denseStereoMethodName(DenseStereoMethod::kSgbm), "sgbm");
  EXPECT_EQ(denseStereoMethodName(DenseStereoMethod::kSgbmWls), "sgbm-wls");
  // A value that is none of them is refused as before, naming the key and the choices
  BoardConfig c{};
  std::string error;
  EXPECT_FALSE(loadBoardConfigText("vision:\n  vo_mode: fastest\n", "board.yaml", &c, &error));
  EXPECT_EQ(error, "board.yaml: key 'vision.vo_mode' is 'fastest'; allowed: one of adaptive|all|orb|planes|none (-)");
  EXPECT_FALSE(loadBoardConfigText("vision:\n  dense_method: [elas]\n", "board.yaml", &c, &error));
  EXPECT_NE(error.find("key 'vision.dense_method'"), std::string::npos) << error;
}

TEST(BoardModuleParams, ThePipelineRefusesWhatTheBoardRefuses) {
  // GIVEN a pipeline config built in code with a hysteresis the board never accepted ((0.49, 0.5))
  VisionPipelineConfig c;
  c.run_orb = false;
  c.modality.hysteresis = 0.495;
  VisionPipeline pipeline;
  std::string error;
  // THEN the worker refuses it with the board's range
  EXPECT_FALSE(pipeline.init(c, &error));
  EXPECT_EQ(error,
            "VisionPipelineConfig.modality.hysteresis (vision.quality_hysteresis): must be a number in [0, 0.49] (-)");
  // AND an enum outside its choices is refused too
  c.modality.hysteresis = 0.02;
  c.dense.method = static_cast<DenseStereoMethod>(7);
  EXPECT_FALSE(validateVisionPipelineConfig(c, &error));
  EXPECT_NE(error.find("(vision.dense_method)"), std::string::npos) << error;
}

TEST(BoardModuleParams, VisionDefaultsAreTheInitialisersBarTheBoardsOwn) {
  const BoardConfig c = defaultBoardConfig();
  const VisionPipelineConfig bare;
  EXPECT_EQ(c.vision.modality.mode, bare.modality.mode);
  EXPECT_EQ(c.vision.modality.threshold, bare.modality.threshold);
  EXPECT_EQ(c.vision.workspace.map.filter_distance_m, bare.workspace.map.filter_distance_m);
  // The two a vehicle sets apart from the bare pipeline: a new ORB map after 10 lost pairs, the plane
  // registration covariance scaled for correlated stereo errors.
  EXPECT_EQ(bare.orb.reset_after_lost_frames, 0);
  EXPECT_EQ(c.vision.orb.reset_after_lost_frames, 10);
  EXPECT_EQ(bare.planes.registration.covariance_scale, 1.0);
  EXPECT_EQ(c.vision.planes.registration.covariance_scale, 1000.0);
  const std::string table = describeBoardParams();
  EXPECT_NE(table.find("| `vision.vo_mode` | choice | - | `adaptive` | one of adaptive\\|all\\|orb\\|planes\\|none |"),
            std::string::npos);
  EXPECT_NE(table.find("| `vision.planes_covariance_scale` | double | - | `1000` |"), std::string::npos);
}

}  // namespace
}  // namespace deepnav
