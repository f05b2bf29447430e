#pragma once
#include <array>
#include <cstdint>

#include "base/marker_observation.h"
#include "nav/types/time.h"
#include "nav/types/vo_measurement.h"

namespace deepnav {

// What the vision worker reports for one stereo pair. It carries the capture time of the images and is
// fused at that time, whatever its arrival time (vision is slow and late).
struct VisionResult {
  TimeUs t_us = 0;                // capture time of the stereo pair
  std::uint64_t sequence = 0;     // frame counter of the pair
  std::uint32_t processing_us = 0;  // worker time spent on this pair (statistics only)
  bool frame_ok = false;          // images decoded and of the expected size
  // MDM contrast features (Ziaei Nafchi & Cheriet 2018) of the left image, each in [0, 1].
  double mdm_f1 = 0.0;
  double mdm_f2 = 0.0;
  double mdm_f3 = 0.0;
  double image_quality = -1.0;    // the paper's m_I(t) in [0, 1]; -1 when not computed
  std::int32_t orb_tracked = 0;   // ORB features tracked in this pair (the 4th term of m_I)
  VoSource vo_selected = VoSource::kNone;  // modality chosen for this pair (stage 2)
  // Visual odometry of this pair (stage 2): the selected one, or both in the "all" mode.
  VoMeasurement vo_orb;
  VoMeasurement vo_planes;
  std::int32_t planes = 0;        // planes extracted in this pair (plane VO ran)
  // Stage-1 workspace map as the vision worker sees it after this pair.
  std::int32_t map_frames = 0;    // clouds inserted
  std::int32_t map_voxels = 0;    // occupied voxels
  bool map_ready = false;         // usable for stage 2 (the stage machine's map_ready)
  // Worker time per part (statistics, Table III(a)); 0 when the part did not run.
  std::uint32_t orb_us = 0;
  std::uint32_t planes_us = 0;
  std::uint32_t map_us = 0;
  // Fiducial markers seen in the left image (at most kMaxMarkers: a 2 m face at 1.5 m shows a few).
  static constexpr int kMaxMarkers = 8;
  std::array<MarkerObservation, kMaxMarkers> markers{};
  std::int32_t marker_count = 0;
  std::int32_t markers_dropped = 0;  // detected beyond kMaxMarkers, not reported
};

}  // namespace deepnav
