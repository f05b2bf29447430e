#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "board/config/calibration_import_common.h"

namespace deepnav {

// OpenCV stereo YAML as OpenCV's stereo_calib sample writes it (cv::FileStorage, %YAML:1.0): M1 D1 M2 D2
// (intrinsics.yml) and R T (extrinsics.yml, p_right = R p_left + T, in the unit of the square size given to
// the calibration: metres expected), in one file or spread over several (a key in two files is refused).
// R1 R2 P1 P2 Q are ignored (deepnav rectifies by itself). The sample stores no image size: image_width
// and image_height from the files if present, else image_size (width 0: none given) or an error.
bool importOpenCvStereo(const std::vector<std::string>& paths, cv::Size image_size, ImportedCalibration* out,
                        std::string* error);

}  // namespace deepnav
