#include "tools/sim/scenario_loader.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/sim/sensors/attitude_grades.h"
#include "tools/sim/sensors/compass_grades.h"
#include "tools/sim/sensors/depth_grades.h"
#include "tools/sim/sensors/imu_grades.h"
#include "tools/sim/trajectory.h"
#include "tools/sim/yaml_section.h"
#include "board/config/text_file.h"
#include "board/config/yaml_document.h"
#include "vision/calib/flat_port.h"

namespace deepnav::sim {

namespace {

// Ranges are wide enough for any sane dive and narrow enough to catch unit mistakes (ms for s, deg for
// rad). Units are printed in the messages.
constexpr double kMaxDepth_m = 11000.0;
constexpr double kMaxLever_m = 10.0;
constexpr double kMaxAngle_deg = 360.0;

void readEnvironment(YamlSection s, EnvironmentConfig* c) {
  s.number("seabed_depth_m", &c->seabed_depth_m, 1.0, kMaxDepth_m, "m");
  s.number("odom_origin_depth_m", &c->odom_origin_depth_m, 0.0, kMaxDepth_m, "m");
  s.number("water_density_kgpm3", &c->water_density_kgpm3, 990.0, 1100.0, "kg/m^3");
  s.number("gravity_mps2", &c->gravity_mps2, 9.7, 9.9, "m/s^2");
  s.number("atmospheric_pressure_pa", &c->atmospheric_pressure_pa, 80000.0, 120000.0, "Pa");
  s.finish();
}

void readPlume(YamlSection s, SedimentPlumeConfig* c) {
  s.number("t_start_s", &c->t_start_s, 0.0, 86400.0, "s");
  s.numbers("centre_in_odom_m", &c->centre_in_odom_m, -1000.0, 1000.0, "m");
  s.number("radius_m", &c->radius_m, 0.05, 50.0, "m");
  s.number("height_m", &c->height_m, 0.05, 50.0, "m");
  s.number("growth_mps", &c->growth_mps, 0.0, 1.0, "m/s");
  s.number("attenuation_per_m", &c->attenuation_per_m, 0.0, 50.0, "1/m");
  s.number("rise_s", &c->rise_s, 0.1, 3600.0, "s");
  s.number("decay_s", &c->decay_s, 1.0, 86400.0, "s");
  s.finish();
}

void readWater(YamlSection s, YamlReadErrors* errors, WaterConfig* c) {
  const int preset = s.choice("preset", {"clear", "moderate", "murky"});
  if (preset >= 0) c->preset = static_cast<WaterPreset>(preset);
  s.integer("fish_count", &c->fish_count, 0, 50, "(count)");
  s.number("lamp_outside_m", &c->lamp_outside_m, 0.0, 2.0, "m");
  s.number("lamp_above_m", &c->lamp_above_m, -2.0, 2.0, "m");
  s.number("lamp_forward_m", &c->lamp_forward_m, -1.0, 2.0, "m");
  s.number("lamp_beam_half_angle_deg", &c->lamp_beam_half_angle_deg, 5.0, 90.0, "deg");
  s.boolean("lamp_backscatter", &c->lamp_backscatter);
  s.number("scattering_albedo", &c->scattering_albedo, 0.0, 1.0, "(fraction)");
  s.number("phase_g", &c->phase_g, 0.0, 0.99, "(mean cosine)");
  s.numbers("current_mps", &c->current_mps, -3.0, 3.0, "m/s");
  s.number("snow_density_per_m3", &c->snow_density_per_m3, 0.0, 5000.0, "1/m^3");
  s.numbers("snow_diameter_mm", &c->snow_diameter_mm, 0.05, 20.0, "mm");
  s.number("snow_sink_mps", &c->snow_sink_mps, 0.0, 0.01, "m/s");
  s.number("snow_albedo", &c->snow_albedo, 0.0, 1.0, "(fraction)");
  s.number("forward_scatter_mrad_per_m", &c->forward_scatter_mrad_per_m, 0.0, 100.0, "mrad/m");
  const YAML::Node plumes = s.sequence("plumes");
  if (plumes.IsDefined() && !plumes.IsNull()) {
    if (!plumes.IsSequence()) {
      errors->fail("key '" + s.keyPath("plumes") + "' must be a list");
    } else {
      c->plumes.clear();
      for (std::size_t i = 0; i < plumes.size() && !errors->failed(); ++i) {
        SedimentPlumeConfig p;
        readPlume(YamlSection(plumes[i], s.keyPath("plumes") + "[" + std::to_string(i) + "]", errors), &p);
        c->plumes.push_back(p);
      }
    }
  }
  if (!errors->failed() && !(c->snow_diameter_mm[0] <= c->snow_diameter_mm[1]))
    errors->fail("key '" + s.keyPath("snow_diameter_mm") + "' must be [min, max] with min <= max");
  s.finish();
}

void readPanel(YamlSection s, PanelGeometry* c) {
  s.numbers("centre_in_odom_m", &c->centre_in_odom_m, -1000.0, 1000.0, "m");
  s.number("half_width_m", &c->half_width_m, 0.2, 10.0, "m");
  s.number("height_m", &c->height_m, 0.2, 10.0, "m");
  s.number("corner_radius_m", &c->corner_radius_m, 0.0, 2.0, "m");
  s.number("front_yaw_deg", &c->front_yaw_deg, -kMaxAngle_deg, kMaxAngle_deg, "deg");
  s.boolean("markers_enabled", &c->markers_enabled);
  s.finish();
}

// One waypoint of `trajectory.plan`; absent keys keep the previous waypoint's values (times excepted).
void readWaypoint(YamlSection s, PlanWaypoint* w) {
  s.number("bearing_deg", &w->bearing_deg, -720.0, 720.0, "deg");
  s.number("standoff_m", &w->standoff_m, 0.3, 200.0, "m");
  s.number("depth_m", &w->depth_m, 0.0, kMaxDepth_m, "m");
  s.number("face_alignment", &w->face_alignment, 0.0, 1.0, "(fraction)");
  s.number("move_s", &w->move_s, 0.0, 3600.0, "s");
  s.number("hold_s", &w->hold_s, 0.0, 86400.0, "s");
  s.finish();
}

void readPlan(const YAML::Node& list, const std::string& path, YamlReadErrors* errors,
              std::vector<PlanWaypoint>* plan) {
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) return errors->fail("key '" + path + "' must be a list");
  for (std::size_t i = 0; i < list.size() && !errors->failed(); ++i) {
    PlanWaypoint w = plan->empty() ? PlanWaypoint{} : plan->back();
    w.move_s = 0.0;
    w.hold_s = 0.0;
    const std::string item = path + "[" + std::to_string(i) + "]";
    readWaypoint(YamlSection(list[i], item, errors), &w);
    if (i > 0 && !(w.move_s > 0.0) && !errors->failed())
      return errors->fail("key '" + item + ".move_s' must be > 0 after the first waypoint");
    plan->push_back(w);
  }
}

void readTrajectory(YamlSection s, YamlReadErrors* errors, TrajectoryConfig* c) {
  s.number("standoff_m", &c->standoff_m, 0.3, 20.0, "m");
  s.number("start_distance_m", &c->start_distance_m, 0.3, 200.0, "m");
  s.number("start_depth_m", &c->start_depth_m, 0.0, kMaxDepth_m, "m");
  s.number("circle_depth_m", &c->circle_depth_m, 0.0, kMaxDepth_m, "m");
  s.number("start_hold_s", &c->start_hold_s, 0.0, 3600.0, "s");
  s.number("approach_s", &c->approach_s, 1.0, 3600.0, "s");
  s.number("dwell_s", &c->dwell_s, 0.0, 3600.0, "s");
  s.number("traverse_s", &c->traverse_s, 1.0, 3600.0, "s");
  s.number("face_alignment", &c->face_alignment, 0.0, 1.0, "(fraction)");
  s.number("surge_amplitude_m", &c->surge_amplitude_m, 0.0, 2.0, "m");
  s.number("sway_amplitude_m", &c->sway_amplitude_m, 0.0, 2.0, "m");
  s.number("heave_amplitude_m", &c->heave_amplitude_m, 0.0, 2.0, "m");
  s.number("roll_amplitude_deg", &c->roll_amplitude_deg, 0.0, 30.0, "deg");
  s.number("pitch_amplitude_deg", &c->pitch_amplitude_deg, 0.0, 30.0, "deg");
  s.number("yaw_amplitude_deg", &c->yaw_amplitude_deg, 0.0, 90.0, "deg");
  s.number("disturbance_period_s", &c->disturbance_period_s, 1.0, 600.0, "s");
  readPlan(s.sequence("plan"), s.keyPath("plan"), errors, &c->plan);
  s.finish();
}

void readImu(YamlSection s, ImuConfig* c) {
  // The grade first, whatever its place in the file: the explicit keys below override its figures.
  const int grade = s.choice("grade", imuGradeNames());
  if (grade >= 0) applyImuGrade(static_cast<ImuGrade>(grade), c);
  s.boolean("enabled", &c->enabled);
  s.number("rate_hz", &c->rate_hz, 1.0, 2000.0, "Hz");
  s.number("gyro_noise_deg_per_sqrt_h", &c->gyro_noise_deg_per_sqrt_h, 0.0, 100.0, "deg/sqrt(h)");
  s.number("gyro_bias_rw_deg_per_h_per_sqrt_h", &c->gyro_bias_rw_deg_per_h_per_sqrt_h, 0.0, 1000.0, "deg/h/sqrt(h)");
  s.number("gyro_initial_bias_deg_per_h", &c->gyro_initial_bias_deg_per_h, 0.0, 10000.0, "deg/h");
  s.number("gyro_bias_instability_deg_per_h", &c->gyro_bias_instability_deg_per_h, 0.0, 10000.0, "deg/h");
  s.number("gyro_bias_correlation_time_s", &c->gyro_bias_correlation_time_s, 1.0, 1e6, "s");
  s.number("gyro_scale_factor_ppm", &c->gyro_scale_factor_ppm, 0.0, 1e5, "ppm");
  s.number("gyro_misalignment_mrad", &c->gyro_misalignment_mrad, 0.0, 100.0, "mrad");
  s.number("accel_noise_mps_per_sqrt_h", &c->accel_noise_mps_per_sqrt_h, 0.0, 100.0, "m/s/sqrt(h)");
  s.number("accel_bias_rw_mps2_per_sqrt_h", &c->accel_bias_rw_mps2_per_sqrt_h, 0.0, 10.0, "m/s^2/sqrt(h)");
  s.number("accel_initial_bias_mps2", &c->accel_initial_bias_mps2, 0.0, 10.0, "m/s^2");
  s.number("accel_bias_instability_mps2", &c->accel_bias_instability_mps2, 0.0, 10.0, "m/s^2");
  s.number("accel_bias_correlation_time_s", &c->accel_bias_correlation_time_s, 1.0, 1e6, "s");
  s.number("accel_scale_factor_ppm", &c->accel_scale_factor_ppm, 0.0, 1e5, "ppm");
  s.number("accel_misalignment_mrad", &c->accel_misalignment_mrad, 0.0, 100.0, "mrad");
  s.numbers("mount_rpy_deg", &c->mount_rpy_deg, -kMaxAngle_deg, kMaxAngle_deg, "deg");
  s.numbers("p_imu_in_robot_m", &c->p_imu_in_robot_m, -kMaxLever_m, kMaxLever_m, "m");
  s.number("vibration_accel_rms_mps2", &c->vibration_accel_rms_mps2, 0.0, 50.0, "m/s^2");
  s.number("vibration_gyro_rms_deg_per_s", &c->vibration_gyro_rms_deg_per_s, 0.0, 100.0, "deg/s");
  s.numbers("vibration_frequencies_hz", &c->vibration_frequencies_hz, 0.1, 10000.0, "Hz");
  s.finish();
}

void readDvl(YamlSection s, DvlConfig* c) {
  // The grade's table first, then the explicit keys, which override it wherever they are in the file.
  const int grade = s.choice("grade", dvlGradeNames());
  if (grade >= 0) applyDvlGrade(static_cast<DvlGrade>(grade), c);
  s.boolean("enabled", &c->enabled);
  s.number("rate_hz", &c->rate_hz, 0.1, 100.0, "Hz");
  s.numbers("p_dvl_in_robot_m", &c->p_dvl_in_robot_m, -kMaxLever_m, kMaxLever_m, "m");
  s.numbers("mount_rpy_deg", &c->mount_rpy_deg, -kMaxAngle_deg, kMaxAngle_deg, "deg");
  s.number("noise_fraction_of_speed", &c->noise_fraction_of_speed, 0.0, 0.5, "(fraction)");
  s.number("noise_floor_mps", &c->noise_floor_mps, 0.0, 1.0, "m/s");
  s.number("min_altitude_m", &c->min_altitude_m, 0.0, 1000.0, "m");
  s.number("max_altitude_m", &c->max_altitude_m, 0.1, 1000.0, "m");
  s.number("beam_angle_deg", &c->beam_angle_deg, 5.0, 60.0, "deg");
  s.number("beam_azimuth_offset_deg", &c->beam_azimuth_offset_deg, -kMaxAngle_deg, kMaxAngle_deg, "deg");
  s.number("range_noise_m", &c->range_noise_m, 0.0, 10.0, "m");
  s.number("beam_noise_fraction", &c->beam_noise_fraction, 0.0, 0.5, "(fraction)");
  s.number("beam_noise_floor_mps", &c->beam_noise_floor_mps, 0.0, 1.0, "m/s");
  s.number("scale_factor_percent", &c->scale_factor_percent, -10.0, 10.0, "%");
  s.number("scale_factor_sigma_percent", &c->scale_factor_sigma_percent, 0.0, 10.0, "%");
  s.number("bias_sigma_mps", &c->bias_sigma_mps, 0.0, 0.1, "m/s");
  s.numbers("misalignment_rpy_deg", &c->misalignment_rpy_deg, -30.0, 30.0, "deg");
  s.boolean("ray_cast", &c->ray_cast);
  s.number("lock_range_jump_fraction", &c->lock_range_jump_fraction, 0.0, 10.0, "(fraction)");
  s.number("outlier_probability", &c->outlier_probability, 0.0, 1.0, "(fraction)");
  s.number("outlier_magnitude_mps", &c->outlier_magnitude_mps, 0.0, 10.0, "m/s");
  s.number("max_ping_rate_hz", &c->max_ping_rate_hz, 0.0, 100.0, "Hz");
  s.number("ping_processing_ms", &c->ping_processing_ms, 0.0, 1000.0, "ms");
  s.finish();
}

void readCompass(YamlSection s, YamlReadErrors* errors, CompassConfig* c) {
  // The grade first, whatever its place in the file: the explicit keys below override its figures.
  const int grade = s.choice("grade", compassGradeNames());
  if (grade >= 0) applyCompassGrade(static_cast<CompassGrade>(grade + 1), c);
  s.boolean("enabled", &c->enabled);
  s.number("rate_hz", &c->rate_hz, 0.1, 200.0, "Hz");
  s.number("noise_deg", &c->noise_deg, 0.0, 90.0, "deg");
  s.number("bias_deg", &c->bias_deg, -180.0, 180.0, "deg");
  s.number("declination_deg", &c->declination_deg, -180.0, 180.0, "deg");
  s.boolean("true_north", &c->true_north);
  s.number("residual_bias_deg", &c->residual_bias_deg, -180.0, 180.0, "deg");
  s.number("residual_bias_sigma_deg", &c->residual_bias_sigma_deg, 0.0, 90.0, "deg");
  s.number("deviation_a_deg", &c->deviation.a_deg, -90.0, 90.0, "deg");
  s.number("deviation_b_deg", &c->deviation.b_deg, -90.0, 90.0, "deg");
  s.number("deviation_c_deg", &c->deviation.c_deg, -90.0, 90.0, "deg");
  s.number("deviation_d_deg", &c->deviation.d_deg, -90.0, 90.0, "deg");
  s.number("deviation_e_deg", &c->deviation.e_deg, -90.0, 90.0, "deg");
  s.numbers("p_compass_in_robot_m", &c->p_compass_in_robot_m, -kMaxLever_m, kMaxLever_m, "m");
  s.number("earth_horizontal_field_ut", &c->earth_horizontal_field_ut, 1.0, 70.0, "uT");
  s.number("earth_vertical_field_ut", &c->earth_vertical_field_ut, -70.0, 70.0, "uT");
  s.numbers("panel_permanent_moment_am2", &c->panel_magnet.permanent_moment_am2, -1e5, 1e5, "A m^2");
  s.number("panel_induced_moment_am2_per_ut", &c->panel_magnet.induced_moment_am2_per_ut, 0.0, 1000.0, "A m^2/uT");
  s.numbers("panel_dipole_position_m", &c->panel_magnet.dipole_position_m, -20.0, 20.0, "m");
  if (!errors->failed() && c->true_north && c->magneticErrorsActive())
    errors->fail("key '" + s.keyPath("true_north") + "': a gyrocompass has no magnetic deviation or panel field " +
                 "(set the deviation_* and panel_* moment keys to 0)");
  s.finish();
}

void readDepth(YamlSection s, DepthConfig* c) {
  // The grade first, whatever its place in the file: the explicit keys below override its figures.
  const int grade = s.choice("grade", depthGradeNames());
  if (grade >= 0) applyDepthGrade(static_cast<DepthGrade>(grade + 1), c);
  s.boolean("enabled", &c->enabled);
  s.number("rate_hz", &c->rate_hz, 0.1, 200.0, "Hz");
  s.number("noise_m", &c->noise_m, 0.0, 100.0, "m");
  s.numbers("p_sensor_in_robot_m", &c->p_sensor_in_robot_m, -kMaxLever_m, kMaxLever_m, "m");
  s.number("resolution_pa", &c->resolution_pa, 0.0, 1e5, "Pa");
  s.number("density_error_kgpm3", &c->density_error_kgpm3, -50.0, 50.0, "kg/m^3");
  s.number("drift_m_per_h", &c->drift_m_per_h, -10.0, 10.0, "m/h");
  s.finish();
}

void readAttitude(YamlSection s, AttitudeConfig* c) {
  // The grade first, whatever its place in the file: the explicit keys below override its figures.
  const int grade = s.choice("grade", attitudeGradeNames());
  if (grade >= 0) applyAttitudeGrade(static_cast<AttitudeGrade>(grade + 1), c);
  s.boolean("enabled", &c->enabled);
  s.number("rate_hz", &c->rate_hz, 0.1, 200.0, "Hz");
  s.number("noise_deg", &c->noise_deg, 0.0, 90.0, "deg");
  s.number("roll_bias_deg", &c->roll_bias_deg, -90.0, 90.0, "deg");
  s.number("pitch_bias_deg", &c->pitch_bias_deg, -90.0, 90.0, "deg");
  s.number("bias_sigma_deg", &c->bias_sigma_deg, 0.0, 90.0, "deg");
  s.finish();
}

// `timing`: one map per sensor stream (stamp = t + clock_offset + clock_drift t + latency; sensor_timing.h).
void readTiming(YamlSection s, TimingConfig* c) {
  for (const char* name : {"imu", "dvl", "compass", "attitude", "depth", "camera"}) {
    StreamTiming& t = c->of(*streamFromName(name));
    YamlSection stream = s.section(name);
    stream.number("latency_ms", &t.latency_ms, 0.0, 10000.0, "ms");
    stream.number("clock_offset_ms", &t.clock_offset_ms, -1e5, 1e5, "ms");
    stream.number("clock_drift_ppm", &t.clock_drift_ppm, -1e4, 1e4, "ppm");
    stream.finish();
  }
  s.finish();
}

void readArmWindow(YamlSection s, YamlReadErrors* errors, ArmWindow* w) {
  s.number("t_start_s", &w->t_start_s, 0.0, 1e6, "s");
  s.number("t_end_s", &w->t_end_s, 0.0, 1e6, "s");
  s.number("reach_m", &w->reach_m, 0.2, 1.2, "m");
  s.number("height_m", &w->height_m, -0.5, 0.6, "m");
  s.number("lateral_m", &w->lateral_m, -0.5, 0.5, "m");
  s.number("deploy_s", &w->deploy_s, 0.1, 60.0, "s");
  s.number("sway_m", &w->sway_m, 0.0, 0.2, "m");
  s.number("sway_period_s", &w->sway_period_s, 1.0, 600.0, "s");
  if (errors->failed()) return;
  if (!s.has("t_start_s") || !s.has("t_end_s"))
    return errors->fail("'" + s.path() + "' needs 't_start_s' and 't_end_s'");
  if (!(w->t_end_s >= w->t_start_s + 2.0 * w->deploy_s))
    return errors->fail("key '" + s.keyPath("t_end_s") + "' must be at least t_start_s + 2 deploy_s (" +
                        std::to_string(w->t_start_s + 2.0 * w->deploy_s) + " s)");
  s.finish();
}

void readArm(const YAML::Node& list, const std::string& path, YamlReadErrors* errors, std::vector<ArmWindow>* arm) {
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) return errors->fail("key '" + path + "' must be a list");
  for (std::size_t i = 0; i < list.size() && !errors->failed(); ++i) {
    ArmWindow w;
    readArmWindow(YamlSection(list[i], path + "[" + std::to_string(i) + "]", errors), errors, &w);
    if (!arm->empty() && !errors->failed() && w.t_start_s < arm->back().t_end_s)
      return errors->fail("key '" + path + "[" + std::to_string(i) + "].t_start_s' must not be before the previous "
                          "window's end (windows in time order, not overlapping)");
    arm->push_back(w);
  }
}

void readCameraSensor(YamlSection s, CameraSensorConfig* c) {
  s.number("exposure_ref_ms", &c->exposure_ref_ms, 0.01, 1000.0, "ms");
  s.number("exposure_max_ms", &c->exposure_max_ms, 0.01, 1000.0, "ms");
  s.number("full_well_e", &c->full_well_e, 100.0, 1e6, "e-");
  s.number("dark_noise_e", &c->dark_noise_e, 0.0, 1000.0, "e-");
  s.finish();
}

// A flat port key of the scenario, read with the range and unit the port declares (flatPortParams(),
// vision/calib/flat_port.h), the board's; a dimensionless unit ("-") is written as none in messages.
// The rule between two keys (water denser than the housing's air) is the port's, checked when the
// renderer builds it (tools/sim/render/flat_port.cpp).
void readPortKey(YamlSection* port, const char* key, FlatPort* out) {
  for (const ParamDecl<FlatPort>& d : flatPortParams()) {
    if (std::string(d.key) != key) continue;
    const char* unit = std::string(d.unit) == "-" ? "" : d.unit;
    port->number(key, static_cast<double*>(d.field(*out)), d.min, d.max, unit);
    return;
  }
}

// camera.preset first (it sets the rig), then every explicit key, which overrides it.
void readCamera(YamlSection s, YamlReadErrors* errors, CameraConfig* c) {
  const int preset = s.choice("preset", {"none", "dexrov"});
  if (preset >= 0) applyCameraPreset(static_cast<CameraPreset>(preset), c);
  s.boolean("enabled", &c->enabled);
  s.number("rate_hz", &c->rate_hz, 0.1, 100.0, "Hz");
  s.integer("width_px", &c->width_px, 16, 8192, "px");
  s.integer("height_px", &c->height_px, 16, 8192, "px");
  s.number("fx_px", &c->fx_px, 1.0, 100000.0, "px");
  s.number("fy_px", &c->fy_px, 1.0, 100000.0, "px");
  s.number("cx_px", &c->cx_px, 0.0, 8192.0, "px");
  s.number("cy_px", &c->cy_px, 0.0, 8192.0, "px");
  s.number("baseline_m", &c->baseline_m, 0.01, 5.0, "m");
  s.numbers("p_cam_in_robot_m", &c->p_cam_in_robot_m, -kMaxLever_m, kMaxLever_m, "m");
  s.numbers("mount_rpy_deg", &c->mount_rpy_deg, -kMaxAngle_deg, kMaxAngle_deg, "deg");
  YamlSection port = s.section("port");
  const int model = port.choice("model", {"none", "flat"});
  if (model >= 0) c->flat_port = model == 1;
  for (const char* key : {"pinhole_to_glass_m", "glass_thickness_m", "n_glass", "n_water"}) {
    readPortKey(&port, key, &c->port);
  }
  port.finish();
  s.boolean("motion_blur", &c->motion_blur);
  const int noise = s.choice("noise_model", {"water_preset", "emva1288"});
  if (noise >= 0) c->noise_model = static_cast<SensorNoiseModel>(noise);
  readCameraSensor(s.section("sensor"), &c->sensor);
  readArm(s.sequence("arm"), s.keyPath("arm"), errors, &c->arm);
  s.finish();
}

void readFaultParams(YamlSection s, FaultSpec* f) {
  switch (f->kind) {
    case FaultKind::kDropout:
      s.number("probability", &f->probability, 0.0, 1.0, "(fraction)");
      break;
    case FaultKind::kOutlier:
      s.number("probability", &f->probability, 0.0, 1.0, "(fraction)");
      s.number("magnitude_sigma", &f->magnitude_sigma, 0.0, 1000.0, "sigma");
      break;
    case FaultKind::kStuck:
      break;
    case FaultKind::kTimeJitter:
      s.number("std_ms", &f->std_ms, 0.0, 1000.0, "ms");
      break;
    case FaultKind::kGarbage:
      s.number("probability", &f->probability, 0.0, 1.0, "(fraction)");
      break;
    case FaultKind::kSlow:
      s.integer("divisor", &f->divisor, 2, 1000, "");
      break;
    case FaultKind::kIntermittent:
      s.number("on_s", &f->on_s, 0.001, 1e6, "s");
      s.number("off_s", &f->off_s, 0.001, 1e6, "s");
      break;
    case FaultKind::kClockJump:
      s.number("offset_ms", &f->offset_ms, -1e5, 1e5, "ms");
      break;
  }
  s.finish();
}

void readFault(YamlSection s, YamlReadErrors* errors, FaultSpec* f) {
  const int stream = s.choice("stream", {"imu", "dvl", "compass", "attitude", "depth", "camera"});
  if (stream >= 0) f->stream = static_cast<SimStream>(stream + 1);  // the list follows SimStream, less ground truth
  const int kind = s.choice("kind", {"dropout", "outlier", "stuck", "time_jitter", "garbage", "slow", "intermittent",
                                     "clock_jump"});
  if (kind >= 0) f->kind = static_cast<FaultKind>(kind);
  s.number("t_start_s", &f->t_start_s, 0.0, 1e6, "s");
  s.number("t_end_s", &f->t_end_s, 0.0, 1e6, "s");
  if (errors->failed()) return;
  if (stream < 0 || kind < 0) return errors->fail("'" + s.path() + "' needs 'stream' and 'kind'");
  if (!s.has("t_start_s") || !s.has("t_end_s"))
    return errors->fail("'" + s.path() + "' needs 't_start_s' and 't_end_s'");
  if (!(f->t_end_s > f->t_start_s))
    return errors->fail("key '" + s.keyPath("t_end_s") + "' must be greater than t_start_s");
  if (f->kind == FaultKind::kOutlier && f->stream == SimStream::kCamera)
    return errors->fail("key '" + s.keyPath("kind") + "': outlier does not apply to the camera stream " +
                        "(allowed: dropout, stuck, time_jitter, garbage, slow, intermittent, clock_jump)");
  readFaultParams(s.section("params"), f);
  s.finish();
}

void readFaults(const YAML::Node& list, YamlReadErrors* errors, std::vector<FaultSpec>* faults) {
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) return errors->fail("key 'faults' must be a list");
  for (std::size_t i = 0; i < list.size() && !errors->failed(); ++i) {
    FaultSpec f;
    readFault(YamlSection(list[i], "faults[" + std::to_string(i) + "]", errors), errors, &f);
    faults->push_back(f);
  }
}

// Checks that span several keys.
void checkConsistency(const Scenario& s, YamlReadErrors* errors) {
  if (errors->failed()) return;
  const double seabed = s.environment.seabed_depth_m;
  if (!(s.trajectory.circle_depth_m < seabed) || !(s.trajectory.start_depth_m < seabed))
    return errors->fail("keys 'trajectory.start_depth_m' and 'trajectory.circle_depth_m' must be shallower than "
                        "'environment.seabed_depth_m' (" + std::to_string(seabed) + " m)");
  for (std::size_t i = 0; i < s.trajectory.plan.size(); ++i)
    if (!(s.trajectory.plan[i].depth_m < seabed))
      return errors->fail("key 'trajectory.plan[" + std::to_string(i) + "].depth_m' must be shallower than "
                          "'environment.seabed_depth_m' (" + std::to_string(seabed) + " m)");
  if (!(s.dvl.min_altitude_m < s.dvl.max_altitude_m))
    return errors->fail("key 'dvl.min_altitude_m' must be less than 'dvl.max_altitude_m'");
  if (!(s.panel.corner_radius_m < s.panel.half_width_m))
    return errors->fail("key 'panel.corner_radius_m' must be less than 'panel.half_width_m'");
  if (!(s.trajectory.start_distance_m >= s.trajectory.standoff_m))
    return errors->fail("key 'trajectory.start_distance_m' must be >= 'trajectory.standoff_m'");
  if (!(s.camera.cx_px < s.camera.width_px) || !(s.camera.cy_px < s.camera.height_px))
    return errors->fail("keys 'camera.cx_px' and 'camera.cy_px' must lie inside the image");
}

}  // namespace

bool parseScenario(const std::string& yaml_text, const std::string& source_name, Scenario* out,
                   std::string* error) {
  YamlReadErrors errors;
  errors.source_name = source_name;
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    if (error) *error = source_name + ": YAML syntax error: " + e.what();
    return false;
  }
  // Repeated keys and a second document, which YAML::Load accepts silently.
  if (!parseYamlDocument(yaml_text, source_name, &root, error)) return false;
  Scenario s;
  s.name = std::filesystem::path(source_name).stem().string();
  YamlSection top(root, "", &errors);
  top.text("name", &s.name);
  top.text("description", &s.description);
  top.number("duration_s", &s.duration_s, 1.0, 86400.0, "s");
  readEnvironment(top.section("environment"), &s.environment);
  readWater(top.section("water"), &errors, &s.water);
  readPanel(top.section("panel"), &s.panel);
  readTrajectory(top.section("trajectory"), &errors, &s.trajectory);
  readImu(top.section("imu"), &s.imu);
  readDvl(top.section("dvl"), &s.dvl);
  readCompass(top.section("compass"), &errors, &s.compass);
  readDepth(top.section("depth"), &s.depth);
  readAttitude(top.section("attitude"), &s.attitude);
  readCamera(top.section("camera"), &errors, &s.camera);
  readTiming(top.section("timing"), &s.timing);
  readFaults(top.sequence("faults"), &errors, &s.faults);
  top.finish();
  checkConsistency(s, &errors);
  if (errors.failed()) {
    if (error) *error = errors.first_error;
    return false;
  }
  *out = s;
  return true;
}

bool loadScenario(const std::string& path, Scenario* out, std::string* error) {
  std::string text;
  return readTextFile(path, "the scenario file", &text, error) && parseScenario(text, path, out, error);
}

}  // namespace deepnav::sim
