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
  if (!registrar_.registerPlanes(sets_[previous], sets_[next], &out->registration) || !out->registration.valid) {
    return false;
  }
  VoMeasurement& vo = out->vo;
  vo.valid = true;
  vo.source = VoSource::kPlanes;
  vo.t_reference_us = reference_us;
  vo.q_cama_camb = out->registration.q_cama_camb;
  vo.p_camb_in_cama_m = out->registration.p_camb_in_cama_m;
  vo.has_translation = out->registration.has_translation;
  vo.cov = out->registration.cov;
  vo.support = out->registration.matched_planes;
  return true;
}

}  // namespace deepnav
