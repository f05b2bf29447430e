#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "tools/sim/sensors/camera_rig.h"
#include "vision/calib/flat_port.h"

namespace deepnav::sim {

// Renders a camera behind a flat port (vision/calib/flat_port.h) from a pinhole render taken at the
// same optical centre: each port pixel's ray is traced through the glass by Snell's law (in air, then
// glass, then water from a point on the outer surface), and the point where that water ray meets the
// scene is found on the pinhole render's depth map by fixed-point iteration (the ray starts a
// centimetre from the pinhole, so two or three steps converge; at depth edges the result is the
// pinhole render's surface, off by the millimetre parallax). The port image samples the pinhole image
// there (bilinear); the port depth is that point's z in the camera frame.
//
// The pinhole render must cover the port's narrower water view with at least the port's resolution:
// pinholeFor() scales the focal length by n_water / n_air (same size, same principal point).
class FlatPortResampler {
 public:
  bool init(const CameraConfig& port_camera, const FlatPort& port, std::string* error);

  // The helper pinhole camera to render at the same optical centre.
  static CameraConfig pinholeFor(const CameraConfig& port_camera, const FlatPort& port);

  // pinhole_image: CV_8U or CV_32F, 1 or 3 channels; pinhole_depth_m: CV_32F depth along the axis
  // (0 = open water), both of the pinhole camera's size. Outputs are written into preallocated
  // images of the port camera's size (port_image of pinhole_image's type, port_depth_m CV_32F);
  // nothing is allocated per frame. False on a size or type mismatch.
  bool resample(const cv::Mat& pinhole_image, const cv::Mat& pinhole_depth_m, cv::Mat& port_image,
                cv::Mat& port_depth_m);

  const CameraConfig& pinhole() const { return pinhole_; }

 private:
  struct WaterRay {
    float ox, oy, oz;  // start on the outer glass surface, camera frame (m)
    float dx, dy, dz;  // unit direction in water
  };
  CameraConfig port_camera_;
  CameraConfig pinhole_;
  std::vector<WaterRay> rays_;  // per port pixel, row-major
  cv::Mat map_px_;              // CV_32FC2 scratch: where each port pixel samples the pinhole image
};

}  // namespace deepnav::sim
