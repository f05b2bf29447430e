#include "vision/planes/plane_odometry.h"

namespace deepnav {

bool PlaneOdometry::init(const PlaneOdometryConfig& config, const StereoGeometry& geometry, int rows, int cols,
                         int step_px, std::string* error) {
  config_ = config;
  has_previous_ = false;
  const bool ok = extractor_.init(config.extraction, geometry, rows, cols, step_px) &&
                  extractor_.allocatePlaneSet(&sets_[0]) && extractor_.allocatePlaneSet(&sets_[1]) &&
                  registrar_.init(config.registration);
  if (!ok && error) *error = "vision: plane extraction or registration parameters rejected";
  return ok;
}

bool PlaneOdometry::process(TimeUs t_us, const OrganizedCloud& cloud, PlaneOdometryOutput* out) {
  *out = PlaneOdometryOutput{};
  const int previous = current_;
  const int next = 1 - current_;
  out->planes = extractor_.extract(cloud, &sets_[next]);
  if (out->planes < 0) {
    has_previous_ = false;
    return false;
  }
  current_ = next;
  const bool chained = has_previous_ && t_us > previous_t_us_ && t_us - previous_t_us_ <= config_.max_gap_us;
  const TimeUs reference_us = previous_t_us_;
  has_previous_ = true;
  previous_t_us_ = t_us;
  if (!chained || out->planes == 0) return false;
  // Planes of a are the previous frame's, planes of b this frame's: the motion of b in a.
  const PlaneRegistrationResult& reg = out->registration;
  if (!registrar_.registerPlanes(sets_[previous], sets_[next], &out->registration)) return false;
  // With the registration's subspace mode every result that constrains a direction is a measurement (its
  // rotation is already the smallest one about the parallel normals).
  const bool subspace = config_.registration.subspace && (reg.rotation_dims > 0 || reg.translation_dims > 0);
  const bool partial = !subspace && config_.use_partial &&
                       reg.status == PlaneRegistrationStatus::kRotationUnobservable && reg.matched_planes >= 1;
  if (!reg.valid && !partial && !subspace) return false;
  VoMeasurement& vo = out->vo;
  vo.valid = true;
  vo.source = VoSource::kPlanes;
  vo.t_reference_us = reference_us;
  vo.q_cama_camb = reg.q_cama_camb;
  if (partial) {
    // Parallel planes fix the rotation but for the turn about their normal, which the q-method leaves
    // arbitrary (its variance there is the unobservable one): take the smallest rotation taking the
    // normal of b onto that of a, so the EKF linearises about a small angle.
    const PlaneMatch& m = reg.matches[0];
    vo.q_cama_camb = Eigen::Quaterniond::FromTwoVectors(sets_[next][m.b].n_in_cam, sets_[previous][m.a].n_in_cam);
  }
  vo.p_camb_in_cama_m = reg.p_camb_in_cama_m;
  vo.has_translation = reg.has_translation;
  vo.cov = reg.cov;
  vo.support = reg.matched_planes;
  return true;
}

}  // namespace deepnav
