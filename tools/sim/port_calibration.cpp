#include "tools/sim/port_calibration.h"

#include <cstdio>
#include <vector>

#include "board/config/board_overrides.h"
#include "board/config/stereo_calibration_file.h"

namespace deepnav::sim {
namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

StereoCalibration inAirCalibration(const CameraConfig& c) {
  StereoCalibration calib;
  calib.image_size = cv::Size(c.width_px, c.height_px);
  calib.left.K = cv::Matx33d(c.fx_px, 0.0, c.cx_px, 0.0, c.fy_px, c.cy_px, 0.0, 0.0, 1.0);
  calib.left.dist = cv::Mat::zeros(1, 5, CV_64F);
  calib.right = calib.left;
  calib.right.dist = cv::Mat::zeros(1, 5, CV_64F);
  calib.R = cv::Matx33d::eye();
  calib.T = cv::Vec3d(-c.baseline_m, 0.0, 0.0);  // p_right = p_left - baseline e_x
  return calib;
}

}  // namespace

bool describeSimulatedPort(const Scenario& scenario, VehicleSetup* setup, bool* described, std::string* error) {
  *described = false;
  const CameraConfig& c = scenario.camera;
  if (!c.enabled || !c.flat_port || !setup->config.camera.calibration_file.empty()) return true;
  StereoCalibrationInfo info;
  info.target = "deepnav-sim: the scenario's in-air pinhole pair (exact, no distortion)";
  // Name and text together: applyBoardOverrides keeps the text of an unchanged calibration_file.
  setup->config.camera.calibration_file = kSimulatedCalibrationName;
  setup->calibration_text = stereoCalibrationText(inAirCalibration(c), info);
  const std::vector<std::string> overrides = {
      std::string("camera.calibration_file=") + kSimulatedCalibrationName,
      "camera.port.model=flat",
      "camera.port.pinhole_to_glass_m=" + number(c.port.pinhole_to_glass_m),
      "camera.port.glass_thickness_m=" + number(c.port.glass_thickness_m),
      "camera.port.n_air=" + number(c.port.n_air),
      "camera.port.n_glass=" + number(c.port.n_glass),
      "camera.port.n_water=" + number(c.port.n_water),
  };
  if (!applyBoardOverrides(overrides, setup, error)) {
    if (error) *error = "sim: describing the flat port in the board: " + *error;
    return false;
  }
  *described = true;
  return true;
}

}  // namespace deepnav::sim
