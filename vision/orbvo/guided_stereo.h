#pragma once
#include <opencv2/core.hpp>

#include "vision/orbvo/orb_frame.h"
#include "vision/orbvo/stereo_feature_matcher.h"
#include "vision/orbvo/stereo_rig.h"
#include "vision/orbvo/vo_map.h"

namespace deepnav {

// Guided stereo: each feature of `frame` with a map point but no right match gets one from the
// ZSAD search (StereoFeatureMatcher::refineRightColumn) around the disparity d = fx b / z its map
// point predicts at `pose`, within config's depth range; its stereo point is triangulated again.
// The descriptor matching along the whole row loses many corners in low-contrast images; here the
// search spans a few pixels. Returns the number of features completed.
int completeStereo(const StereoFeatureMatcher& matcher, const StereoRig& rig,
                   const StereoMatchConfig& config, const cv::Mat& left_grey,
                   const cv::Mat& right_grey, const VoMap& map, const CameraPoseEstimate& pose,
                   OrbFrame* frame);

}  // namespace deepnav
