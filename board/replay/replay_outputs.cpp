#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "board/loop/scheduler.h"
#include "board/replay/bench_replay.h"
#include "board/replay/output_file.h"

namespace deepnav {
namespace {

bool writeTum(const std::string& path, const std::vector<StampedPose>& poses, std::string* error) {
  std::ofstream out;
  if (!openOutput(&out, path, error)) return false;
  char line[256];
  for (const auto& p : poses) {
    const auto& t = p.p_robot_in_odom_m;
    const auto& q = p.q_odom_robot;
    std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", p.t_s, t.x(), t.y(), t.z(), q.x(),
                  q.y(), q.z(), q.w());
    out << line;
  }
  return closeOutput(&out, path, error);
}

std::string statsJson(const ErrorStats& s, double scale) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "{\"mean\": %.6f, \"std\": %.6f, \"rms\": %.6f, \"max\": %.6f, \"count\": %zu}",
                s.mean * scale, s.std * scale, s.rms * scale, s.max * scale, s.count);
  return buf;
}

std::string loopJson(const LoopStats& l) {
  std::ostringstream o;
  o << "{\"ticks\": " << l.ticks << ", \"late_ticks\": " << l.late_ticks << ", \"max_lateness_us\": "
    << l.max_lateness_us << ", \"tasks\": [";
  for (int i = 0; i < l.task_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    o << (i ? ", " : "") << "{\"name\": \"" << l.names[k] << "\", \"runs\": " << l.runs[k]
      << ", \"overruns\": " << l.overruns[k] << ", \"mean_us\": " << l.mean_us[k] << ", \"max_us\": " << l.max_us[k]
      << "}";
  }
  o << "]}";
  return o.str();
}

std::string inputsJson(const InputCounters& c) {
  std::ostringstream o;
  o << "{\"imu\": " << c.imu << ", \"dvl\": " << c.dvl << ", \"depth\": " << c.depth << ", \"heading\": " << c.heading
    << ", \"attitude\": " << c.attitude << ", \"vision\": " << c.vision << ", \"accepted\": " << c.accepted
    << ", \"rejected\": " << c.rejected << ", \"queued\": " << c.queued << ", \"dropped_late\": " << c.dropped_late
    << ", \"bad_input\": " << c.bad_input << ", \"not_aligned\": " << c.not_aligned << "}";
  return o.str();
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
}

// A number, or null when it is not finite (JSON has no NaN).
std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string frameErrorsJson(const TrajectoryErrors& e) {
  return "{\"position_m\": " + statsJson(e.position, 1.0) + ", \"orientation_deg\": " +
         statsJson(e.orientation, 180.0 / M_PI) + "}";
}

std::string optionalErrorsJson(const std::optional<TrajectoryErrors>& e) {
  return e ? frameErrorsJson(*e) : std::string("null");
}

// {"whole": {...}, "stage2": {...} or null, "stage2_first_60s": {...} or null}
std::string wholeAndStage2Json(const FrameErrors& f) {
  return "{\"whole\": " + frameErrorsJson(f.whole) + ", \"stage2\": " + optionalErrorsJson(f.stage2) +
         ", \"stage2_first_" + std::to_string(static_cast<int>(kStage2WindowS)) +
         "s\": " + optionalErrorsJson(f.stage2_window) + "}";
}

std::string ateJson(const AlignedTrajectoryErrors& a) {
  std::ostringstream o;
  const Eigen::Matrix3d R = a.T_align.linear();
  const Eigen::Vector3d t = a.T_align.translation();
  o << "{\"position_rmse_m\": " << num(a.errors.position.rms) << ", \"rotation_rmse_deg\": "
    << num(a.errors.orientation.rms * 180.0 / M_PI) << ", \"position_m\": " << statsJson(a.errors.position, 1.0)
    << ", \"rotation_deg\": " << statsJson(a.errors.orientation, 180.0 / M_PI) << ", \"alignment\": {\"t_m\": ["
    << num(t.x()) << ", " << num(t.y()) << ", " << num(t.z()) << "], \"angle_deg\": "
    << num(Eigen::AngleAxisd(R).angle() * 180.0 / M_PI) << "}}";
  return o.str();
}

std::string rpeJson(const RelativePoseErrors& r) {
  std::ostringstream o;
  o << "{\"delta_m\": " << num(r.delta_m) << ", \"pairs\": " << r.length_m.size()
    << ", \"translation_rmse_m\": " << num(r.translation.rms) << ", \"rotation_rmse_deg\": "
    << num(r.rotation.rms * 180.0 / M_PI) << ", \"translation_percent\": " << statsJson(r.translation_percent, 1.0)
    << ", \"rotation_deg_per_m\": " << statsJson(r.rotation_rad_per_m, 180.0 / M_PI) << "}";
  return o.str();
}

std::string neesJson(const NeesSummary& n) {
  std::ostringstream o;
  o << "{\"dof\": " << n.dof << ", \"count\": " << n.count << ", \"mean\": " << num(n.mean)
    << ", \"median\": " << num(n.median) << ", \"band\": [" << num(n.band.lo) << ", " << num(n.band.hi)
    << "], \"mean_band\": [" << num(n.mean_band.lo) << ", " << num(n.mean_band.hi)
    << "], \"in_band_fraction\": " << num(n.in_band_fraction) << ", \"above_fraction\": "
    << num(n.above_fraction) << ", \"below_fraction\": " << num(n.below_fraction) << "}";
  return o.str();
}

std::string modalityJson(const ModalityCount& m) {
  std::ostringstream o;
  o << "{\"offered\": " << m.offered << ", \"fused\": " << m.fused << ", \"rejected_gate\": " << m.rejected_gate
    << ", \"rejected_other\": " << m.rejected_other << ", \"gate_resets\": " << m.gate_resets << "}";
  return o.str();
}

std::string modalitiesJson(const ModalityCounts& m) {
  return "{\"dvl\": " + modalityJson(m.dvl) + ", \"compass\": " + modalityJson(m.compass) +
         ", \"depth\": " + modalityJson(m.depth) + ", \"attitude\": " + modalityJson(m.attitude) +
         ", \"markers\": " + modalityJson(m.markers) + ", \"vo_orb\": " + modalityJson(m.vo_orb) +
         ", \"vo_planes\": " + modalityJson(m.vo_planes) + "}";
}

void writeMetricsJson(std::ostream& out, const ReplaySummary& s) {
  const ReplayMetrics& m = s.metrics;
  out << "  \"truth_panel\": " << (s.truth_T_odom_panel ? "true" : "false") << ",\n";
  out << "  \"odom_error\": " << wholeAndStage2Json(m.odom) << ",\n";
  out << "  \"panel_error\": " << (m.panel ? wholeAndStage2Json(*m.panel) : std::string("null")) << ",\n";
  if (!m.panel) out << "  \"panel_error_absent\": " << jsonString(m.panel_absent_reason) << ",\n";
  out << "  \"ate\": " << ateJson(m.ate) << ",\n";
  out << "  \"rpe\": " << rpeJson(m.rpe) << ",\n";
  out << "  \"nees\": {\"position\": " << neesJson(m.nees_position_summary)
      << ", \"heading\": " << neesJson(m.nees_heading_summary) << "},\n";
}

bool writeNees(const std::string& path, const ReplayMetrics& m, std::string* error) {
  std::ofstream out;
  if (!openOutput(&out, path, error)) return false;
  out << "t_s,nees_position,nees_heading\n";
  char line[128];
  for (std::size_t k = 0; k < m.nees_t_s.size(); ++k) {
    std::snprintf(line, sizeof line, "%.6f,%.6g,%.6g\n", m.nees_t_s[k], m.nees_position[k], m.nees_heading[k]);
    out << line;
  }
  return closeOutput(&out, path, error);
}

bool writeFrameStats(const std::string& path, const std::vector<FrameStat>& frames, std::string* error) {
  std::ofstream out;
  if (!openOutput(&out, path, error)) return false;
  out << "t_s,stage,image_quality,selected,orb_vo,planes_vo,orb_tracked,planes,markers,face,orb_us,planes_us,map_us,"
         "total_us\n";
  char line[256];
  for (const FrameStat& f : frames) {
    std::snprintf(line, sizeof line, "%.6f,%d,%.6f,%d,%d,%d,%d,%d,%d,%d,%u,%u,%u,%u\n", f.t_s, f.stage,
                  f.image_quality, f.selected, f.orb_vo ? 1 : 0, f.planes_vo ? 1 : 0, f.orb_tracked, f.planes,
                  f.markers, f.face, f.orb_us, f.planes_us, f.map_us, f.total_us);
    out << line;
  }
  return closeOutput(&out, path, error);
}

// The panel-relative error, ATE, RPE and NEES lines under the error table.
std::string formatMetrics(const ReplayMetrics& m) {
  std::ostringstream o;
  char line[256];
  const double deg = 180.0 / M_PI;
  if (m.panel) {
    const auto& p = m.panel->whole;
    std::snprintf(line, sizeof line, "| panel-relative position (m) | %.3f | %.3f | %.3f | %.3f |\n", p.position.mean,
                  p.position.std, p.position.rms, p.position.max);
    o << line;
    std::snprintf(line, sizeof line, "| panel-relative orientation (deg) | %.2f | %.2f | %.2f | %.2f |\n",
                  p.orientation.mean * deg, p.orientation.std * deg, p.orientation.rms * deg, p.orientation.max * deg);
    o << line;
  } else {
    o << "panel-relative error: none (" << m.panel_absent_reason << ")\n";
  }
  std::snprintf(line, sizeof line,
                "ATE after SE(3) alignment: %.3f m, %.2f deg (rmse); RPE per %.0f m: %.2f %% of distance, %.3f deg/m "
                "(%zu segments)\n",
                m.ate.errors.position.rms, m.ate.errors.orientation.rms * deg, m.rpe.delta_m,
                m.rpe.translation_percent.mean, m.rpe.rotation_rad_per_m.mean * deg, m.rpe.length_m.size());
  o << line;
  const NeesSummary& np = m.nees_position_summary;
  const NeesSummary& nh = m.nees_heading_summary;
  std::snprintf(line, sizeof line,
                "NEES position: mean %.2f (band of the mean [%.2f, %.2f]), %.0f %% of ticks in [%.2f, %.2f]; heading: "
                "mean %.2f, %.0f %% in [%.4f, %.2f]\n",
                np.mean, np.mean_band.lo, np.mean_band.hi, 100.0 * np.in_band_fraction, np.band.lo, np.band.hi,
                nh.mean, 100.0 * nh.in_band_fraction, nh.band.lo, nh.band.hi);
  o << line;
  return o.str();
}

}  // namespace

bool writeReplayOutputs(const std::string& dir, const ReplaySummary& s, std::string* error) {
  if (!writeTum(dir + "/trajectory.tum", s.estimate, error)) return false;
  if (!s.frame_stats.empty() && !writeFrameStats(dir + "/frames.csv", s.frame_stats, error)) return false;
  if (s.has_truth && !writeTum(dir + "/truth.tum", s.truth, error)) return false;
  if (s.has_truth && !writeNees(dir + "/nees.csv", s.metrics, error)) return false;
  if (!s.vo_consistency.rows.empty() &&
      !writeVoConsistencyCsv(dir + "/vo_consistency.csv", s.vo_consistency, error)) {
    return false;
  }
  if (s.metrics.panel && (!writeTum(dir + "/panel_trajectory.tum", s.metrics.panel_estimate, error) ||
                          !writeTum(dir + "/panel_truth.tum", s.metrics.panel_truth, error))) {
    return false;
  }
  const std::string summary_path = dir + "/summary.json";
  std::ofstream out;
  if (!openOutput(&out, summary_path, error)) return false;
  out << "{\n  \"mode\": \"" << (s.reproduce ? "reproduce" : "rerun") << "\",\n";
  out << "  \"ticks\": " << s.ticks << ",\n  \"frames\": " << s.frames << ",\n";
  out << "  \"vision_failures\": " << s.vision_failures << ",\n";
  out << "  \"solutions_compared\": " << s.solutions_compared << ",\n  \"mismatches\": " << s.mismatches << ",\n";
  out << "  \"dive_s\": " << s.dive_s << ",\n  \"wall_s\": " << s.wall_s << ",\n";
  out << "  \"inputs\": " << inputsJson(s.inputs) << ",\n";
  out << "  \"markers\": {\"images\": " << s.markers.images << ", \"observations\": " << s.markers.observations
      << ", \"unknown_id\": " << s.markers.unknown_id << ", \"panel_observations_accepted\": " << s.panel.accepted
      << ", \"panel_rejected_outlier\": " << s.panel.rejected_outlier << ", \"panel_fixed_at_s\": "
      << s.panel_fixed_at_s << ", \"poses_fused\": " << s.markers.fused << ", \"poses_accepted\": "
      << s.markers.accepted << "},\n";
  out << "  \"stage2_at_s\": " << s.stage2_at_s << ",\n";
  out << "  \"workspace\": {\"restored\": " << (s.workspace_restored ? "true" : "false")
      << ", \"map_frames\": " << s.map_frames << ", \"map_voxels\": " << s.map_voxels << "},\n";
  out << "  \"modalities\": " << modalitiesJson(s.modalities) << ",\n";
  out << "  \"estimator_states\": " << estimatorStatesJson(s.estimator_states) << ",\n";
  out << "  \"vo_consistency\": " << voConsistencyJson(s.vo_consistency) << ",\n";
  out << "  \"vo\": {\"offered\": " << s.vo.measurements << ", \"accepted\": " << s.vo.accepted
      << ", \"rejected\": " << s.vo.rejected << ", \"no_clone\": " << s.vo.no_clone
      << ", \"clones_late\": " << s.vo.clones_late << ", \"accepted_orb\": "
      << s.vo.accepted_by_source[1] << ", \"accepted_planes\": " << s.vo.accepted_by_source[2] << "},\n";
  out << "  \"read\": {\"messages\": " << s.read.messages << ", \"bad_messages\": " << s.read.bad_messages
      << ", \"unknown_topic\": " << s.read.unknown_topic << ", \"incomplete_frames\": " << s.read.incomplete_frames
      << "},\n";
  out << "  \"loop\": " << loopJson(s.loop) << ",\n";
  out << "  \"smoothness_m_a\": " << s.smoothness.m_a << ",\n";
  if (s.has_truth) {
    out << "  \"position_error_m\": " << statsJson(s.errors.position, 1.0) << ",\n";
    out << "  \"orientation_error_deg\": " << statsJson(s.errors.orientation, 180.0 / M_PI) << ",\n";
    writeMetricsJson(out, s);
  }
  out << "  \"warnings\": [";
  for (std::size_t i = 0; i < s.warnings.size(); ++i) out << (i ? ", " : "") << jsonString(s.warnings[i]);
  out << "]\n}\n";
  return closeOutput(&out, summary_path, error);
}

std::string formatReplaySummary(const ReplaySummary& s) {
  std::ostringstream o;
  char line[256];
  std::snprintf(line, sizeof line, "dive %.1f s replayed in %.2f s (%.1fx real time), %llu ticks, %llu stereo pairs\n",
                s.dive_s, s.wall_s, s.wall_s > 0 ? s.dive_s / s.wall_s : 0.0,
                static_cast<unsigned long long>(s.ticks), static_cast<unsigned long long>(s.frames));
  o << line;
  if (s.frames_not_processed > 0) {
    std::snprintf(line, sizeof line, "dead reckoning (no markers, no VO): %llu stereo pairs not processed\n",
                  static_cast<unsigned long long>(s.frames_not_processed));
    o << line;
  }
  if (s.vision_failures > 0) {
    std::snprintf(line, sizeof line, "vision: %llu stereo pairs failed (a stage threw) and were skipped\n",
                  static_cast<unsigned long long>(s.vision_failures));
    o << line;
  }
  if (s.reproduce) {
    std::snprintf(line, sizeof line, "outputs compared bit for bit: %llu, mismatches: %llu\n",
                  static_cast<unsigned long long>(s.solutions_compared), static_cast<unsigned long long>(s.mismatches));
    o << line;
  }
  std::snprintf(line, sizeof line,
                "inputs: imu %llu, dvl %llu, depth %llu, heading %llu, attitude %llu, vision %llu; "
                "accepted %llu, rejected %llu, dropped late %llu, bad %llu\n",
                static_cast<unsigned long long>(s.inputs.imu), static_cast<unsigned long long>(s.inputs.dvl),
                static_cast<unsigned long long>(s.inputs.depth), static_cast<unsigned long long>(s.inputs.heading),
                static_cast<unsigned long long>(s.inputs.attitude), static_cast<unsigned long long>(s.inputs.vision),
                static_cast<unsigned long long>(s.inputs.accepted), static_cast<unsigned long long>(s.inputs.rejected),
                static_cast<unsigned long long>(s.inputs.dropped_late),
                static_cast<unsigned long long>(s.inputs.bad_input));
  o << line;
  std::snprintf(line, sizeof line,
                "markers: %u observations in %u images; panel %s; %u marker poses fused, %u accepted\n",
                s.markers.observations, s.markers.images,
                s.panel_fixed_at_s >= 0 ? ("fixed at " + std::to_string(s.panel_fixed_at_s) + " s").c_str()
                                        : "not fixed",
                s.markers.fused, s.markers.accepted);
  o << line;
  if (s.stage2_at_s >= 0 || s.vo.measurements > 0) {
    std::snprintf(line, sizeof line,
                  "stage 2 %s%s; map %d clouds, %d voxels; VO: %u offered, %u fused (orb %u, planes %u), %u rejected, "
                  "%u without clone\n",
                  s.stage2_at_s >= 0 ? ("from " + std::to_string(s.stage2_at_s) + " s").c_str() : "never entered",
                  s.workspace_restored ? " (restored workspace)" : "", s.map_frames, s.map_voxels, s.vo.measurements,
                  s.vo.accepted, s.vo.accepted_by_source[1], s.vo.accepted_by_source[2], s.vo.rejected, s.vo.no_clone);
    o << line;
  }
  if (s.has_truth) {
    o << "\n| metric | mean | std | rms | max |\n|---|---|---|---|---|\n";
    const auto& p = s.errors.position;
    const auto& q = s.errors.orientation;
    const double deg = 180.0 / M_PI;
    std::snprintf(line, sizeof line, "| position error (m) | %.3f | %.3f | %.3f | %.3f |\n", p.mean, p.std, p.rms, p.max);
    o << line;
    std::snprintf(line, sizeof line, "| orientation error (deg) | %.2f | %.2f | %.2f | %.2f |\n", q.mean * deg,
                  q.std * deg, q.rms * deg, q.max * deg);
    o << line;
    o << formatMetrics(s.metrics);
  }
  std::snprintf(line, sizeof line, "smoothness m_A = %.4f\n\n", s.smoothness.m_a);
  o << line;
  o << formatLoopStats(s.loop);
  for (const auto& w : s.warnings) o << "warning: " << w << "\n";
  return o.str();
}

}  // namespace deepnav
