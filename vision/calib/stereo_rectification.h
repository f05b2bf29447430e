#pragma once
#include <string>

#include <opencv2/core.hpp>

#include "vision/calib/pinax_model.h"
#include "vision/calib/stereo_calibration.h"
#include "vision/markers/pinhole_intrinsics.h"

namespace deepnav {

// How the raw images are turned into a rectified pinhole pair.
enum class PortCorrection {
  kNone,   // plain pinhole rectification (cameras calibrated where they work: in air, dome port, or in water)
  kPinax,  // in-air calibration + flat port: PinAx virtual pinholes, then rectification
};

struct RectificationOptions {
  PortCorrection correction = PortCorrection::kNone;
  PinaxConfig pinax;   // used with kPinax
  double alpha = 0.0;  // cv::stereoRectify free scaling: 0 keeps only valid pixels, 1 keeps all
};

// Look-up tables of a rectified stereo pair: rectified pixel (u, v) -> raw pixel. Computed once at
// start-up; applied per frame by StereoRectifier.
struct StereoRectification {
  cv::Size image_size{0, 0};
  cv::Mat left_raw_px;          // CV_32FC2: exact raw position of each rectified pixel (tests, tools)
  cv::Mat right_raw_px;
  cv::Mat left_map_xy, left_map_frac;    // cv::convertMaps fixed-point form (CV_16SC2 + CV_16UC1)
  cv::Mat right_map_xy, right_map_frac;
  PinholeIntrinsics rectified;  // both rectified cameras
  double baseline_m = 0.0;      // right camera along +x of the rectified left camera
  cv::Matx33d R_rect_left = cv::Matx33d::eye();   // rectified left <- (virtual) left camera
  cv::Matx33d R_rect_right = cv::Matx33d::eye();
  double virtual_centre_z_m = 0.0;  // kPinax: virtual pinhole on each camera's axis (0 for kNone)
};

// Builds the maps. False with a message for bad calibrations (sizes, non-finite values) or ports.
bool computeStereoRectification(const StereoCalibration& calib, const RectificationOptions& options,
                                StereoRectification* out, std::string* error);

// Applies the maps (bilinear, fixed point, as cv::remap INTER_LINEAR on the cv::convertMaps form) into
// preallocated images: nothing is allocated per frame once the destination images have the right size
// and type (cv::remap itself allocates scratch images on every call).
class StereoRectifier {
 public:
  bool init(const StereoRectification& maps, std::string* error);
  // raw_* and rect_* have the calibrated size, CV_8UC1 or CV_8UC3; rect_* are preallocated with raw_*'s
  // type. False (nothing written) otherwise.
  bool rectify(const cv::Mat& raw_left, const cv::Mat& raw_right, cv::Mat& rect_left, cv::Mat& rect_right) const;
  const StereoRectification& maps() const { return maps_; }

 private:
  StereoRectification maps_;
};

}  // namespace deepnav
