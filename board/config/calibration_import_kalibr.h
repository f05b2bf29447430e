#pragma once
#include <string>

#include "board/config/calibration_import_common.h"

namespace deepnav {

// Kalibr's camchain.yaml (its wiki "yaml formats"): cam0 and cam1 with camera_model pinhole,
// intrinsics [fu fv pu pv], distortion_model radtan ([k1 k2 r1 r2], OpenCV's plumb_bob without k3) or
// equidistant ([k1 k2 k3 k4], Kannala-Brandt as cv::fisheye) or none, distortion_coeffs, resolution [w, h], and
// cam1.T_cn_cnm1 (4 x 4, takes cam0 coordinates to cam1: OpenCV's R, T with cam0 the left camera).
// An equidistant lens is rewritten as OpenCV's rational model (equidistantToRational) when that fits it
// within 0.1 px over the image, otherwise refused. Other keys (T_cam_imu, rostopic, ...) are ignored.
bool importKalibrCamchain(const std::string& path, ImportedCalibration* out, std::string* error);

// Largest difference between an equidistant lens and the rational model it is rewritten as (pixels).
constexpr double kMaxEquidistantFitErrorPx = 0.1;

}  // namespace deepnav
