#pragma once
#include <string>
#include <vector>

#include "vision/calib/charuco_target.h"
#include "vision/calib/charuco_view.h"
#include "vision/calib/stereo_view_calibration.h"

namespace deepnav {

using StereoCharucoResult = StereoCalibrationResult;

// calibrateStereoViews with ChArUco views (detectCharucoView) and the target's screening thresholds.
// False with a message for an invalid target, fewer than 4 usable pairs or a failed optimisation.
bool calibrateStereoCharuco(const std::vector<CalibrationPairInput>& pairs, const CharucoTarget& target,
                            StereoCharucoResult* result, std::string* error);

}  // namespace deepnav
