#include "nav/metrics/trajectory_association.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace deepnav {
namespace {

// Parses the next whitespace-separated number, advancing `s`.
bool nextNumber(std::string_view& s, double* v) {
  const std::size_t start = s.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos) return false;
  s.remove_prefix(start);
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), *v);
  if (ec != std::errc() || !std::isfinite(*v)) return false;
  s.remove_prefix(static_cast<std::size_t>(ptr - s.data()));
  return true;
}

}  // namespace

std::optional<StampedPose> parseTumLine(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || line[first] == '#') return std::nullopt;
  double v[8];
  for (double& x : v) {
    if (!nextNumber(line, &x)) return std::nullopt;
  }
  StampedPose p;
  p.t_s = v[0];
  p.p_robot_in_odom_m = Eigen::Vector3d(v[1], v[2], v[3]);
  p.q_odom_robot = Eigen::Quaterniond(v[7], v[4], v[5], v[6]);
  if (p.q_odom_robot.norm() < 1e-9) return std::nullopt;
  p.q_odom_robot.normalize();
  return p;
}

std::optional<StampedPose> interpolatePose(std::span<const StampedPose> traj, double t_s, double max_gap_s) {
  if (traj.empty() || t_s < traj.front().t_s || t_s > traj.back().t_s) return std::nullopt;
  const auto hi = std::lower_bound(traj.begin(), traj.end(), t_s,
                                   [](const StampedPose& p, double t) { return p.t_s < t; });
  if (hi->t_s == t_s) return *hi;
  const StampedPose& b = *hi;
  const StampedPose& a = *(hi - 1);
  if (b.t_s - a.t_s > max_gap_s) return std::nullopt;
  const double u = (t_s - a.t_s) / (b.t_s - a.t_s);
  StampedPose out;
  out.t_s = t_s;
  out.p_robot_in_odom_m = (1.0 - u) * a.p_robot_in_odom_m + u * b.p_robot_in_odom_m;
  out.q_odom_robot = a.q_odom_robot.slerp(u, b.q_odom_robot).normalized();
  return out;
}

AssociatedTrajectories associateByTime(std::span<const StampedPose> estimate, std::span<const StampedPose> truth,
                                       double max_gap_s) {
  AssociatedTrajectories out;
  for (const StampedPose& e : estimate) {
    const std::optional<StampedPose> t = interpolatePose(truth, e.t_s, max_gap_s);
    if (!t) continue;
    out.estimate.push_back(e);
    out.truth.push_back(*t);
  }
  return out;
}

}  // namespace deepnav
