#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "nav/metrics/nees.h"
#include "nav/metrics/relative_pose_error.h"
#include "nav/metrics/stamped_pose.h"
#include "nav/metrics/trajectory_alignment.h"
#include "nav/metrics/trajectory_errors.h"
#include "nav/types/nav_solution.h"

namespace deepnav {

// What a replay notes at each loop tick besides the published pose (ReplaySummary::estimate, to which
// it is parallel): the stage, the board's panel estimate, and the filter's own pose and covariance (the
// published pose is the output smoother's, nav/pipeline/output_smoother.h; the NEES is the filter's).
struct ReplayTick {
  NavStage stage = NavStage::kInit;
  bool panel_fixed = false;
  Eigen::Isometry3d T_odom_panel = Eigen::Isometry3d::Identity();  // the board's estimate, when fixed
  double filter_t_s = 0.0;  // time of the filter's state (its last IMU sample, up to one IMU period old)
  Eigen::Vector3d p_filter_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_filter = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d P_position_m2 = Eigen::Matrix3d::Zero();
  double var_yaw_rad2 = 0.0;
};

// One modality's results: offered to the filter, fused, rejected by the innovation gate, and the rest
// (invalid, too late, frozen, before alignment, VO without a clone).
struct ModalityCount {
  std::uint64_t offered = 0;
  std::uint64_t fused = 0;
  std::uint64_t rejected_gate = 0;
  std::uint64_t rejected_other = 0;
  std::uint64_t gate_resets = 0;  // lockout recoveries (nav/ekf/gate_reset.h)
};
struct ModalityCounts {
  ModalityCount dvl, compass, depth, attitude, markers, vo_orb, vo_planes;
};
// VO results the loop was offered per source (counted as the replay feeds them; VoFusion counts only
// the total).
struct VoOffers {
  std::uint64_t orb = 0;
  std::uint64_t planes = 0;
};

// The true panel pose in the recording's odometry frame, from the simulator's metadata record
// "deepnav.sim" (tools/sim/dive_recorder.cpp): "p_panel_in_odom_m" ("x y z", metres: the footprint
// centre on the seabed) and either "yaw_odom_panel_deg" (the panel stands upright: a rotation about z)
// or "q_odom_panel_xyzw" ("x y z w"). nullopt when the record or its panel keys are absent (recordings
// of older simulators, vehicle logs), or malformed (then *error says why).
inline constexpr const char* kTruthPanelMetadata = "deepnav.sim";
std::optional<Eigen::Isometry3d> truthPanelFromMetadata(const std::map<std::string, std::string>* record,
                                                        std::string* error);

// Errors of one frame (odometry or panel) over the whole dive, over stage 2 and over the first
// kStage2WindowS of stage 2 (nullopt: no tick there). Without markers in stage 2 (T_L3) that window is a
// marker-less stretch of visual odometry of a stated length, comparable between runs and dives.
struct FrameErrors {
  TrajectoryErrors whole;
  std::optional<TrajectoryErrors> stage2;
  std::optional<TrajectoryErrors> stage2_window;
};

inline constexpr double kStage2WindowS = 60.0;

struct ReplayMetrics {
  FrameErrors odom;                        // published pose against the truth, unaligned
  std::optional<FrameErrors> panel;        // T_panel_robot: estimate (board's panel) vs truth; nullopt:
                                           // no panel estimate or no true panel pose
  std::string panel_absent_reason;         // why panel is nullopt
  AlignedTrajectoryErrors ate;             // SE(3) Umeyama, whole dive
  RelativePoseErrors rpe;                  // 1 m segments
  std::vector<double> nees_t_s, nees_position, nees_heading;
  NeesSummary nees_position_summary, nees_heading_summary;
  std::vector<StampedPose> panel_estimate, panel_truth;  // T_panel_robot per tick (TUM, panel frame)
};

inline constexpr double kRpeDeltaM = 1.0;

// The metrics of a replay from its per-tick records and the truth (sorted by time).
ReplayMetrics computeMetrics(const std::vector<StampedPose>& estimate, const std::vector<ReplayTick>& ticks,
                             const std::vector<StampedPose>& truth,
                             const std::optional<Eigen::Isometry3d>& truth_T_odom_panel);

}  // namespace deepnav
