#include "vision/orbvo/guided_stereo.h"

namespace deepnav {

int completeStereo(const StereoFeatureMatcher& matcher, const StereoRig& rig,
                   const StereoMatchConfig& config, const cv::Mat& left_grey,
                   const cv::Mat& right_grey, const VoMap& map, const CameraPoseEstimate& pose,
                   OrbFrame* frame) {
  int added = 0;
  for (std::size_t j = 0; j < frame->map_point.size(); ++j) {
    const int m = frame->map_point[j];
    if (m < 0 || frame->u_right_px[j] >= 0.0f) continue;
    const Eigen::Vector3d p_in_cam_m =
        pose.R_cam_world * map.point(m).p_in_world_m + pose.p_world_in_cam_m;
    if (p_in_cam_m.z() < config.min_depth_m || p_in_cam_m.z() > config.max_depth_m) continue;
    const OrbFeature& f = frame->features[j];
    const double predicted_disparity_px = rig.fx_px * rig.baseline_m / p_in_cam_m.z();
    double u_right = 0.0;
    if (!matcher.refineRightColumn(left_grey, right_grey, f.u_px, f.v_px,
                                   f.u_px - predicted_disparity_px, &u_right)) {
      continue;
    }
    const double disparity_px = f.u_px - u_right;
    if (disparity_px <= 0.0) continue;
    frame->u_right_px[j] = static_cast<float>(u_right);
    frame->p_in_cam_m[j] = triangulateStereo(rig, f.u_px, f.v_px, disparity_px);
    ++added;
  }
  return added;
}

}  // namespace deepnav
