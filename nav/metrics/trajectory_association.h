#pragma once
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "nav/metrics/stamped_pose.h"

namespace deepnav {

// TUM RGB-D trajectory format, one pose per line: "t tx ty tz qx qy qz qw" (seconds, metres, Hamilton
// quaternion x y z w). Lines starting with '#' and blank lines are not poses (nullopt), nor is a line
// that does not parse or holds a zero quaternion.
std::optional<StampedPose> parseTumLine(std::string_view line);

// Pose at time t_s by linear interpolation of the position and slerp of the orientation between the two
// samples bracketing t_s in a time-sorted trajectory. nullopt when t_s is outside the trajectory or the
// bracketing samples are more than max_gap_s apart.
std::optional<StampedPose> interpolatePose(std::span<const StampedPose> trajectory, double t_s, double max_gap_s);

// Associates an estimate with ground truth by time: ground truth interpolated at every estimate time
// (evo / TUM-tools style, but interpolating rather than taking the nearest sample). Estimates that cannot
// be associated are left out of both outputs, so the outputs have equal length and matching times.
struct AssociatedTrajectories {
  std::vector<StampedPose> estimate;
  std::vector<StampedPose> truth;
};
AssociatedTrajectories associateByTime(std::span<const StampedPose> estimate, std::span<const StampedPose> truth,
                                       double max_gap_s);

}  // namespace deepnav
