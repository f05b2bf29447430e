#pragma once
#include <string>
#include <vector>

#include "vision/calib/checkerboard_target.h"
#include "vision/calib/stereo_view_calibration.h"

namespace deepnav {

// calibrateStereoViews with checkerboard views (detectCheckerboardView): every view must hold the whole
// board; the right view is numbered as the left one (checkerboardAlignPair). False with a message
// for an invalid target, fewer than 4 usable pairs or a failed optimisation.
bool calibrateStereoCheckerboard(const std::vector<CalibrationPairInput>& pairs, const CheckerboardTarget& target,
                                 StereoCalibrationResult* result, std::string* error);

}  // namespace deepnav
