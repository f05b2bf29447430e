#include "board/config/camera_rectification.h"

#include <filesystem>

#include "board/config/stereo_calibration_file.h"
#include "board/config/text_file.h"

namespace deepnav {

RectificationOptions rectificationOptions(const BoardConfig& config) {
  RectificationOptions o;
  const auto& port = config.camera.port;
  o.correction = port.model == "flat" ? PortCorrection::kPinax : PortCorrection::kNone;
  o.pinax = port.pinax;
  return o;
}

bool buildCameraRectificationFromText(const BoardConfig& config, const std::string& calibration_text,
                                      const std::string& name, StereoRectification* out, std::string* error) {
  StereoCalibration calibration;
  if (!parseStereoCalibrationText(calibration_text, name, &calibration, error)) return false;
  if (calibration.image_size.width != config.camera.width_px ||
      calibration.image_size.height != config.camera.height_px) {
    if (error)
      *error = name + ": calibrated for " + std::to_string(calibration.image_size.width) + " x " +
               std::to_string(calibration.image_size.height) + " px images, the board's camera gives " +
               std::to_string(config.camera.width_px) + " x " + std::to_string(config.camera.height_px) +
               " (camera.width_px, camera.height_px)";
    return false;
  }
  std::string rect_error;
  if (!computeStereoRectification(calibration, rectificationOptions(config), out, &rect_error)) {
    if (error) *error = name + ": " + rect_error + (config.camera.port.model == "flat" ? " (camera.port.*)" : "");
    return false;
  }
  return true;
}

bool buildCameraRectification(const BoardConfig& config, const std::string& board_dir, StereoRectification* out,
                              bool* needed, std::string* error) {
  *needed = !config.camera.calibration_file.empty();
  if (!*needed) return true;
  const std::string path = (std::filesystem::path(board_dir) / config.camera.calibration_file).string();
  std::string text;
  return readTextFile(path, "the stereo calibration (camera.calibration_file)", &text, error) &&
         buildCameraRectificationFromText(config, text, path, out, error);
}

}  // namespace deepnav
