#include <cstdio>
#include <fstream>
#include <sstream>

#include "board/loop/scheduler.h"
#include "board/replay/bench_replay.h"

namespace deepnav {
namespace {

bool writeTum(const std::string& path, const std::vector<StampedPose>& poses, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    if (error) *error = path + ": cannot write";
    return false;
  }
  char line[256];
  for (const auto& p : poses) {
    const auto& t = p.p_robot_in_odom_m;
    const auto& q = p.q_odom_robot;
    std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", p.t_s, t.x(), t.y(), t.z(), q.x(),
                  q.y(), q.z(), q.w());
    out << line;
  }
  return static_cast<bool>(out);
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

bool writeFrameStats(const std::string& path, const std::vector<FrameStat>& frames, std::string* error) {
  std::ofstream out(path);
  out << "t_s,stage,image_quality,selected,orb_vo,planes_vo,orb_tracked,planes,markers,face,orb_us,planes_us,map_us,"
         "total_us\n";
  char line[256];
  for (const FrameStat& f : frames) {
    std::snprintf(line, sizeof line, "%.6f,%d,%.6f,%d,%d,%d,%d,%d,%d,%d,%u,%u,%u,%u\n", f.t_s, f.stage,
                  f.image_quality, f.selected, f.orb_vo ? 1 : 0, f.planes_vo ? 1 : 0, f.orb_tracked, f.planes,
                  f.markers, f.face, f.orb_us, f.planes_us, f.map_us, f.total_us);
    out << line;
  }
  if (!out.flush()) {
    if (error) *error = path + ": cannot write";
    return false;
  }
  return true;
}

}  // namespace

bool writeReplayOutputs(const std::string& dir, const ReplaySummary& s, std::string* error) {
  if (!writeTum(dir + "/trajectory.tum", s.estimate, error)) return false;
  if (!s.frame_stats.empty() && !writeFrameStats(dir + "/frames.csv", s.frame_stats, error)) return false;
  if (s.has_truth && !writeTum(dir + "/truth.tum", s.truth, error)) return false;
  std::ofstream out(dir + "/summary.json");
  if (!out) {
    if (error) *error = dir + "/summary.json: cannot write";
    return false;
  }
  out << "{\n  \"mode\": \"" << (s.reproduce ? "reproduce" : "rerun") << "\",\n";
  out << "  \"ticks\": " << s.ticks << ",\n  \"frames\": " << s.frames << ",\n";
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
  out << "  \"vo\": {\"offered\": " << s.vo.measurements << ", \"accepted\": " << s.vo.accepted
      << ", \"rejected\": " << s.vo.rejected << ", \"no_clone\": " << s.vo.no_clone << ", \"accepted_orb\": "
      << s.vo.accepted_by_source[1] << ", \"accepted_planes\": " << s.vo.accepted_by_source[2] << "},\n";
  out << "  \"read\": {\"messages\": " << s.read.messages << ", \"bad_messages\": " << s.read.bad_messages
      << ", \"unknown_topic\": " << s.read.unknown_topic << ", \"incomplete_frames\": " << s.read.incomplete_frames
      << "},\n";
  out << "  \"loop\": " << loopJson(s.loop) << ",\n";
  out << "  \"smoothness_m_a\": " << s.smoothness.m_a << ",\n";
  if (s.has_truth) {
    out << "  \"position_error_m\": " << statsJson(s.errors.position, 1.0) << ",\n";
    out << "  \"orientation_error_deg\": " << statsJson(s.errors.orientation, 180.0 / M_PI) << ",\n";
  }
  out << "  \"warnings\": [";
  for (std::size_t i = 0; i < s.warnings.size(); ++i) out << (i ? ", " : "") << jsonString(s.warnings[i]);
  out << "]\n}\n";
  return static_cast<bool>(out);
}

std::string formatReplaySummary(const ReplaySummary& s) {
  std::ostringstream o;
  char line[256];
  std::snprintf(line, sizeof line, "dive %.1f s replayed in %.2f s (%.1fx real time), %llu ticks, %llu stereo pairs\n",
                s.dive_s, s.wall_s, s.wall_s > 0 ? s.dive_s / s.wall_s : 0.0,
                static_cast<unsigned long long>(s.ticks), static_cast<unsigned long long>(s.frames));
  o << line;
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
  }
  std::snprintf(line, sizeof line, "smoothness m_A = %.4f\n\n", s.smoothness.m_a);
  o << line;
  o << formatLoopStats(s.loop);
  for (const auto& w : s.warnings) o << "warning: " << w << "\n";
  return o.str();
}

}  // namespace deepnav
