#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "base/marker_observation.h"

namespace deepnav {

// Planar pose ambiguity: a small marker seen nearly head-on has two poses (IPPE's two solutions,
// the marker tilted either way about the line of sight) that fit its corners about equally, and the
// one with the lower error is then a coin toss. With a prediction of the marker's rotation in the
// camera (predictedCameraMarkerPose() from the filter's robot pose and the fixed panel), keep the
// solution closer to it: swaps the best and alternative solutions (poses, errors, distance,
// obliqueness) of an ambiguous observation when the alternative is closer in angle. Returns true
// when it swapped. A non-ambiguous observation is left as it is. The ambiguous flag stays set: the
// prediction chose, the image did not, so the covariance model still treats the pose as ambiguous.
bool preferSolutionNear(const Eigen::Quaterniond& q_cam_marker_predicted, MarkerObservation* obs);

}  // namespace deepnav
