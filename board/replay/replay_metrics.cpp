#include "board/replay/replay_metrics.h"

#include <cmath>
#include <sstream>

#include "nav/metrics/trajectory_association.h"

namespace deepnav {
namespace {

constexpr double kMaxTruthGapS = 0.05;

bool parseNumbers(const std::string& text, int count, double* out) {
  std::istringstream in(text);
  for (int i = 0; i < count; ++i) {
    if (!(in >> out[i]) || !std::isfinite(out[i])) return false;
  }
  std::string rest;
  return !(in >> rest);
}

Eigen::Isometry3d toIsometry(const StampedPose& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = p.q_odom_robot.normalized().toRotationMatrix();
  T.translation() = p.p_robot_in_odom_m;
  return T;
}

// The pose expressed in another frame: T_frame_robot = T_odom_frame^-1 T_odom_robot.
StampedPose inFrame(const Eigen::Isometry3d& T_odom_frame, const StampedPose& p) {
  const Eigen::Isometry3d T = T_odom_frame.inverse() * toIsometry(p);
  StampedPose out;
  out.t_s = p.t_s;
  out.p_robot_in_odom_m = T.translation();
  out.q_odom_robot = Eigen::Quaterniond(T.linear()).normalized();
  return out;
}

// Pairs of associated poses: all of them, those of stage 2, those of its first kStage2WindowS.
struct Pairs {
  std::vector<StampedPose> est, truth, est2, truth2, est_window, truth_window;

  void add(const StampedPose& e, const StampedPose& t, bool stage2, bool in_window) {
    est.push_back(e);
    truth.push_back(t);
    if (!stage2) return;
    est2.push_back(e);
    truth2.push_back(t);
    if (!in_window) return;
    est_window.push_back(e);
    truth_window.push_back(t);
  }
};

FrameErrors frameErrors(const Pairs& p) {
  FrameErrors f;
  f.whole = trajectoryErrors(p.est, p.truth);
  if (!p.est2.empty()) f.stage2 = trajectoryErrors(p.est2, p.truth2);
  if (!p.est_window.empty()) f.stage2_window = trajectoryErrors(p.est_window, p.truth_window);
  return f;
}

void nees(const std::vector<ReplayTick>& ticks, const std::vector<StampedPose>& truth, ReplayMetrics* m) {
  for (const ReplayTick& k : ticks) {
    const std::optional<StampedPose> t = interpolatePose(truth, k.filter_t_s, kMaxTruthGapS);
    if (!t) continue;
    m->nees_t_s.push_back(k.filter_t_s);
    m->nees_position.push_back(positionNees(k.p_filter_m, t->p_robot_in_odom_m, k.P_position_m2));
    m->nees_heading.push_back(headingNees(k.q_filter, t->q_odom_robot, k.var_yaw_rad2));
  }
  m->nees_position_summary = summarizeNees(m->nees_position, 3);
  m->nees_heading_summary = summarizeNees(m->nees_heading, 1);
}

}  // namespace

std::optional<Eigen::Isometry3d> truthPanelFromMetadata(const std::map<std::string, std::string>* record,
                                                        std::string* error) {
  if (!record) return std::nullopt;
  const auto pos = record->find("p_panel_in_odom_m");
  const auto yaw = record->find("yaw_odom_panel_deg");
  const auto rot = record->find("q_odom_panel_xyzw");
  if (pos == record->end() && yaw == record->end() && rot == record->end()) return std::nullopt;
  double p[3], q[4], yaw_deg = 0.0;
  Eigen::Quaterniond quat = Eigen::Quaterniond::Identity();
  bool ok = pos != record->end() && parseNumbers(pos->second, 3, p);
  if (ok && rot != record->end()) {
    ok = parseNumbers(rot->second, 4, q);
    quat = Eigen::Quaterniond(q[3], q[0], q[1], q[2]);
    ok = ok && quat.norm() > 0.5;
  } else if (ok && yaw != record->end()) {
    ok = parseNumbers(yaw->second, 1, &yaw_deg);
    quat = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()));
  } else {
    ok = false;
  }
  if (!ok) {
    if (error) {
      *error = std::string(kTruthPanelMetadata) +
               ": true panel pose unreadable (p_panel_in_odom_m \"x y z\" with yaw_odom_panel_deg or "
               "q_odom_panel_xyzw \"x y z w\"): no panel-relative error";
    }
    return std::nullopt;
  }
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = quat.normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  return T;
}

ReplayMetrics computeMetrics(const std::vector<StampedPose>& estimate, const std::vector<ReplayTick>& ticks,
                             const std::vector<StampedPose>& truth,
                             const std::optional<Eigen::Isometry3d>& truth_T_odom_panel) {
  ReplayMetrics m;
  Pairs odom, panel;
  bool any_panel_estimate = false;
  double stage2_from_s = -1.0;
  for (std::size_t k = 0; k < estimate.size() && k < ticks.size(); ++k) {
    const std::optional<StampedPose> t = interpolatePose(truth, estimate[k].t_s, kMaxTruthGapS);
    if (!t) continue;
    const bool stage2 = ticks[k].stage == NavStage::kOptimised;
    if (stage2 && stage2_from_s < 0.0) stage2_from_s = estimate[k].t_s;
    const bool in_window = stage2 && estimate[k].t_s < stage2_from_s + kStage2WindowS;
    odom.add(estimate[k], *t, stage2, in_window);
    if (!ticks[k].panel_fixed) continue;
    any_panel_estimate = true;
    if (!truth_T_odom_panel) continue;
    panel.add(inFrame(ticks[k].T_odom_panel, estimate[k]), inFrame(*truth_T_odom_panel, *t), stage2, in_window);
  }
  m.odom = frameErrors(odom);
  if (!any_panel_estimate) {
    m.panel_absent_reason = "the board never fixed the panel";
  } else if (!truth_T_odom_panel) {
    m.panel_absent_reason = std::string("the recording has no true panel pose (") + kTruthPanelMetadata + ")";
  } else {
    m.panel = frameErrors(panel);
    m.panel_estimate = std::move(panel.est);
    m.panel_truth = std::move(panel.truth);
  }
  m.ate = alignedTrajectoryErrors(odom.est, odom.truth);
  m.rpe = relativePoseErrors(odom.est, odom.truth, kRpeDeltaM);
  nees(ticks, truth, &m);
  return m;
}

}  // namespace deepnav
