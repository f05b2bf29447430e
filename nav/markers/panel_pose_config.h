#pragma once
#include <span>
#include <string>

#include "base/param_decl.h"

namespace deepnav {

// Every parameter of the stage-1 panel pose estimator (PanelPoseEstimator), unit in the name,
// default here. "std" thresholds are on the scatter of the single observations (not on the standard
// error of their mean): the panel is fixed when the observations agree, not merely when there are
// many.
struct PanelPoseConfig {
  // --- When the panel is fixed (all must hold) ---
  int min_observations = 30;         // accepted observations
  int min_distinct_markers = 2;      // distinct marker ids among them
  double max_position_std_m = 0.05;  // sqrt of the largest eigenvalue of the position scatter
  double max_angle_std_rad = 0.035;  // (2 deg) the same for the rotation scatter (odom axes)

  // --- Which observations are used ---
  double max_distance_m = 4.0;        // camera-marker distance
  double max_obliqueness_rad = 1.22;  // (70 deg) marker normal vs ray to the camera, (0, pi/2]
  double max_reprojection_px = 2.0;   // RMS corner error of the pose, > 0
  // An ambiguous pose takes the IPPE solution closer in rotation to the running mean (and is
  // rejected while there is no mean); false: ambiguous poses are always rejected.
  bool use_ambiguous = true;

  // --- Outliers ---
  // An observation is rejected when its panel pose is farther from the running mean than
  //   gate = max(floor, outlier_gate_sigma * RMS scatter), for position and for angle.
  double outlier_gate_sigma = 4.0;   // > 0
  double outlier_floor_m = 0.10;     // smallest position gate, > 0
  double outlier_floor_rad = 0.087;  // (5 deg) smallest angle gate, > 0
  // After this many consecutive outlier rejections the running mean itself is taken to be wrong
  // (e.g. the first observation was the outlier): the accumulation restarts from the current
  // observation.
  int restart_after_rejections = 20;  // [1, 100000]
};

// The board keys of the estimator (section kMarkersSection of a board file): unit, range and meaning of
// the fields a board sets, declared once; the defaults are the initialisers above.
inline constexpr const char* kMarkersSection = "markers";
std::span<const ParamDecl<PanelPoseConfig>> panelPoseParams();

// False with a message naming the key when a field is out of range.
bool validatePanelPoseConfig(const PanelPoseConfig& config, std::string* error);

}  // namespace deepnav
