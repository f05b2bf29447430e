#include "nav/ekf/stochastic_clone.h"

#include "nav/ekf/relative_pose_updater.h"
#include "nav/ekf/systematic_states.h"

namespace deepnav {

CloneStatus augmentClone(std::uint32_t id, int max_clones, FilterState* s) {
  if (s->n_clones >= max_clones || s->n_clones >= es::kMaxClones) return CloneStatus::kFull;
  if (findCloneSlot(*s, id) >= 0) return CloneStatus::kDuplicateId;
  // The new clone goes where the systematic block starts; that block moves behind it.
  const int o = s->sysOffset();
  const int ns = s->sys_layout.dim;
  relocateSystematic(o + es::kCloneDim, s);
  PoseClone& c = s->clones[static_cast<std::size_t>(s->n_clones)];
  c.id = id;
  c.t_us = s->t_us;
  c.p_robot_in_odom_m = s->x.p_robot_in_odom_m;
  c.q_odom_robot = s->x.q_odom_robot;
  auto& P = s->P;
  const int after = o + es::kCloneDim;  // columns of the systematic block, [after, after + ns)
  P.block(o, 0, 3, o) = P.block(es::kP, 0, 3, o);
  P.block(o + 3, 0, 3, o) = P.block(es::kTheta, 0, 3, o);
  P.block(o, after, 3, ns) = P.block(es::kP, after, 3, ns);
  P.block(o + 3, after, 3, ns) = P.block(es::kTheta, after, 3, ns);
  P.block(0, o, o, 6) = P.block(o, 0, 6, o).transpose();
  P.block(after, o, ns, 6) = P.block(o, after, 6, ns).transpose();
  P.block<3, 3>(o, o) = P.block<3, 3>(es::kP, es::kP);
  P.block<3, 3>(o, o + 3) = P.block<3, 3>(es::kP, es::kTheta);
  P.block<3, 3>(o + 3, o) = P.block<3, 3>(es::kTheta, es::kP);
  P.block<3, 3>(o + 3, o + 3) = P.block<3, 3>(es::kTheta, es::kTheta);
  ++s->n_clones;
  return CloneStatus::kOk;
}

CloneStatus marginaliseClone(std::uint32_t id, FilterState* s) {
  const int slot = findCloneSlot(*s, id);
  if (slot < 0) return CloneStatus::kUnknownId;
  const int n = s->dim();
  const int o = es::cloneOffset(slot);
  // Explicit loops: source and destination overlap, moving up/left by one clone block.
  for (int c = 0; c < n; ++c) {
    for (int r = o; r + es::kCloneDim < n; ++r) s->P(r, c) = s->P(r + es::kCloneDim, c);
  }
  for (int c = o; c + es::kCloneDim < n; ++c) {
    for (int r = 0; r < n - es::kCloneDim; ++r) s->P(r, c) = s->P(r, c + es::kCloneDim);
  }
  for (int i = slot; i + 1 < s->n_clones; ++i) {
    s->clones[static_cast<std::size_t>(i)] = s->clones[static_cast<std::size_t>(i + 1)];
  }
  --s->n_clones;
  return CloneStatus::kOk;
}

}  // namespace deepnav
