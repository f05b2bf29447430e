#pragma once
#include <opencv2/core.hpp>

namespace deepnav {

// One camera as calibrated: K, distortion (OpenCV order k1 k2 p1 p2 [k3 ...], "plumb_bob" for 5).
struct CameraCalibration {
  cv::Matx33d K = cv::Matx33d::eye();
  cv::Mat dist = cv::Mat::zeros(1, 5, CV_64F);
};

// A calibrated stereo pair (OpenCV convention): p_in_right = R * p_in_left + T (metres).
struct StereoCalibration {
  cv::Size image_size{0, 0};
  CameraCalibration left;
  CameraCalibration right;
  cv::Matx33d R = cv::Matx33d::eye();
  cv::Vec3d T{0.0, 0.0, 0.0};
};

}  // namespace deepnav
