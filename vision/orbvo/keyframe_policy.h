#pragma once

namespace deepnav {

// When a tracked frame becomes a keyframe. A new keyframe is needed when the view has moved on (too
// few of the newest keyframe's points are still tracked), when the camera has moved far enough from
// it for new points to be well triangulated and for the parallax to constrain the bundle
// adjustment, or when it is simply old.
struct KeyframePolicyConfig {
  // Keyframe when tracked < fraction * points of the newest keyframe
  double tracked_fraction = 0.7;
  int min_tracked = 80;             // keyframe when fewer map points are tracked
  double max_translation_m = 0.15;  // keyframe beyond this distance from the newest keyframe
  double max_rotation_deg = 8.0;    // keyframe beyond this rotation from the newest keyframe
  int max_frames = 25;              // keyframe after this many frames without one
};

struct KeyframePolicyInput {
  int tracked = 0;             // map points tracked by the frame
  int keyframe_points = 0;     // map points held by the newest keyframe
  double translation_m = 0.0;  // from the newest keyframe
  double rotation_deg = 0.0;   // from the newest keyframe
  int frames_since_keyframe = 0;
};

inline bool needKeyframe(const KeyframePolicyConfig& c, const KeyframePolicyInput& in) {
  if (in.frames_since_keyframe < 1) return false;
  return in.tracked < c.tracked_fraction * in.keyframe_points || in.tracked < c.min_tracked ||
         in.translation_m > c.max_translation_m || in.rotation_deg > c.max_rotation_deg ||
         in.frames_since_keyframe >= c.max_frames;
}

}  // namespace deepnav
