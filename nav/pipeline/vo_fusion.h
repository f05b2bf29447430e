#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Geometry>

#include "nav/ekf/ekf.h"
#include "nav/types/vision_result.h"

namespace deepnav {

struct VoFusionCounters {
  std::uint32_t measurements = 0;  // VO results offered (valid)
  std::uint32_t accepted = 0;
  std::uint32_t rejected = 0;      // by the EKF gate, bad input, too late
  std::uint32_t no_clone = 0;      // reference frame without a clone (before stage 2, or released)
  std::uint32_t clones = 0;        // clones taken
  std::uint32_t clones_late = 0;   // pairs older than the delay window: no clone, later results refer to nothing
  std::array<std::uint32_t, 3> accepted_by_source{};  // index VoSource
};

// What became of the last VO result of one source (evaluation: the replay's VO consistency table).
enum class VoOutcome : std::uint8_t {
  kNone = 0,    // none offered in the last vision result (or outside stage 2)
  kNoClone,     // its reference pair has no clone
  kUnusable,    // not finite
  kFused,       // accepted by the EKF gate
  kQueued,      // ahead of the IMU: fused or gated later (counted as accepted)
  kRejected,    // refused by the EKF gate
  kNotFused,    // bad input, dropped late, filter not aligned
};

// Stage 2 of the paper in the filter: each stereo pair's pose is cloned into the EKF state at its capture
// time (stochastic cloning), and a VO result of a later pair, relative to the pose at an earlier pair's
// capture time, is fused against that clone. Clones of the last `kept` pairs are kept (the ORB VO may
// refer back to its last tracked pair); older ones are released (marginalised). Pure, no allocation.
class VoFusion {
 public:
  void init(const Eigen::Isometry3d& T_robot_cam, int kept_clones);

  // One vision result. active: stage 2 (otherwise every clone is released and nothing is fused).
  void onVision(const VisionResult& v, bool active, Ekf* ekf);

  const VoFusionCounters& counters() const { return counters_; }
  VoOutcome lastOutcome(VoSource source) const { return last_outcome_[static_cast<std::size_t>(source)]; }

 private:
  struct Slot {
    bool used = false;
    TimeUs t_us = 0;
    std::uint32_t id = 0;
  };
  static constexpr int kMaxSlots = 8;

  void fuse(const VoMeasurement& vo, TimeUs t_us, Ekf* ekf);
  void cloneFrame(TimeUs t_us, Ekf* ekf);
  void releaseAll(TimeUs t_us, Ekf* ekf);
  const Slot* find(TimeUs t_us) const;

  Eigen::Isometry3d T_robot_cam_ = Eigen::Isometry3d::Identity();
  int kept_ = 3;
  std::array<Slot, kMaxSlots> slots_{};
  std::uint32_t next_id_ = 1;
  VoFusionCounters counters_;
  std::array<VoOutcome, 3> last_outcome_{};  // index VoSource
};

}  // namespace deepnav
