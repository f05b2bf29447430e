#pragma once
#include <string>

#include "board/config/calibration_import_common.h"

namespace deepnav {

// A pair of ROS camera_info YAML files (camera_calibration_parsers, as written by the ROS stereo
// calibrator): image_width, image_height, camera_matrix, distortion_model (plumb_bob, rational_polynomial
// or equidistant), distortion_coefficients, rectification_matrix and projection_matrix, each matrix as
// {rows, cols, data}. The extrinsics are not stored as such; they follow from the rectification:
// R_i rotates camera i into the common rectified frame and the right projection's fourth column holds
// Tx = -fx' B (fx' its focal length, B the baseline), so p_right = R2^T (R1 p_left + t) with
// t = (P2[0][3] / fx', P2[1][3] / fy', P2[2][3]): R = R2^T R1, T = R2^T t.
bool importCameraInfoPair(const std::string& left_path, const std::string& right_path, ImportedCalibration* out,
                          std::string* error);

}  // namespace deepnav
