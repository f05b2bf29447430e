#include "nav/pipeline/vo_fusion.h"

#include <algorithm>

#include "nav/pipeline/camera_relative_pose.h"

namespace deepnav {

void VoFusion::init(const Eigen::Isometry3d& T_robot_cam, int kept_clones) {
  T_robot_cam_ = T_robot_cam;
  kept_ = std::clamp(kept_clones, 1, kMaxSlots);
  slots_ = {};
  next_id_ = 1;
  counters_ = VoFusionCounters{};
  last_outcome_.fill(VoOutcome::kNone);
}

const VoFusion::Slot* VoFusion::find(TimeUs t_us) const {
  for (const Slot& s : slots_) {
    if (s.used && s.t_us == t_us) return &s;
  }
  return nullptr;
}

void VoFusion::fuse(const VoMeasurement& vo, TimeUs t_us, Ekf* ekf) {
  if (!vo.valid) return;
  ++counters_.measurements;
  VoOutcome& outcome = last_outcome_[static_cast<std::size_t>(vo.source) % last_outcome_.size()];
  const Slot* slot = find(vo.t_reference_us);
  RelativePoseMeasurement m;
  if (!slot) {
    ++counters_.no_clone;
    outcome = VoOutcome::kNoClone;
    return;
  }
  if (!relativePoseFromCamera(vo, T_robot_cam_, t_us, slot->id, &m)) {
    ++counters_.rejected;
    outcome = VoOutcome::kUnusable;
    return;
  }
  const FuseResult r = ekf->fuseRelativePose(m);
  if (r.status == FuseStatus::kAccepted || r.status == FuseStatus::kQueued) {
    ++counters_.accepted;
    ++counters_.accepted_by_source[static_cast<std::size_t>(vo.source)];
    outcome = r.status == FuseStatus::kAccepted ? VoOutcome::kFused : VoOutcome::kQueued;
  } else {
    ++counters_.rejected;
    outcome = r.status == FuseStatus::kRejected ? VoOutcome::kRejected : VoOutcome::kNotFused;
  }
}

void VoFusion::cloneFrame(TimeUs t_us, Ekf* ekf) {
  Slot* target = nullptr;
  int used = 0;
  Slot* oldest = nullptr;
  for (Slot& s : slots_) {
    if (!s.used) {
      if (!target) target = &s;
      continue;
    }
    ++used;
    if (!oldest || s.t_us < oldest->t_us) oldest = &s;
  }
  if (used >= kept_ && oldest) {
    ekf->releaseClone(t_us, oldest->id);
    oldest->used = false;
    target = oldest;
  }
  if (!target) return;
  const std::uint32_t id = next_id_++;
  const FuseResult r = ekf->clonePose(t_us, id);
  if (r.status == FuseStatus::kDroppedLate) ++counters_.clones_late;
  if (r.status != FuseStatus::kAccepted && r.status != FuseStatus::kQueued) return;
  *target = Slot{true, t_us, id};
  ++counters_.clones;
}

void VoFusion::releaseAll(TimeUs t_us, Ekf* ekf) {
  for (Slot& s : slots_) {
    if (!s.used) continue;
    ekf->releaseClone(t_us, s.id);
    s.used = false;
  }
}

void VoFusion::onVision(const VisionResult& v, bool active, Ekf* ekf) {
  last_outcome_.fill(VoOutcome::kNone);
  if (!active) {
    releaseAll(v.t_us, ekf);
    return;
  }
  if (!v.frame_ok) return;
  fuse(v.vo_orb, v.t_us, ekf);
  fuse(v.vo_planes, v.t_us, ekf);
  cloneFrame(v.t_us, ekf);
}

}  // namespace deepnav
