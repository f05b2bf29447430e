#include "board/cli/import_calibration_command.h"

#include <cmath>
#include <cstdio>

#include <opencv2/calib3d.hpp>

#include "board/config/calibration_import_camera_info.h"
#include "board/config/calibration_import_kalibr.h"
#include "board/config/calibration_import_opencv.h"
#include "board/config/stereo_calibration_file.h"
#include "vision/calib/stereo_rectification.h"

namespace deepnav {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

bool parseImageSize(const std::string& text, cv::Size* size) {
  int w = 0, h = 0;
  char tail = 0;
  if (text.empty()) return true;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16) return false;
  *size = cv::Size(w, h);
  return true;
}

bool importAny(const ImportCalibrationOptions& o, ImportedCalibration* out, std::string* error) {
  const std::size_t n = o.inputs.size();
  if (o.format == "kalibr") {
    if (n != 1) {
      *error = "--format kalibr takes one file (camchain.yaml)";
      return false;
    }
    return importKalibrCamchain(o.inputs[0], out, error);
  }
  if (o.format == "camera-info") {
    if (n != 2) {
      *error = "--format camera-info takes two files: the left camera's then the right camera's";
      return false;
    }
    return importCameraInfoPair(o.inputs[0], o.inputs[1], out, error);
  }
  if (o.format == "opencv") {
    cv::Size size(0, 0);
    if (n < 1 || n > 2) {
      *error = "--format opencv takes one or two files (intrinsics.yml extrinsics.yml, or one with all)";
      return false;
    }
    if (!parseImageSize(o.image_size, &size)) {
      *error = "--image-size '" + o.image_size + "': WIDTHxHEIGHT in pixels expected, e.g. 640x480";
      return false;
    }
    return importOpenCvStereo(o.inputs, size, out, error);
  }
  *error = "--format '" + o.format + "': kalibr, opencv or camera-info expected";
  return false;
}

std::string distortionText(const cv::Mat& dist) {
  std::string text = dist.total() <= 5 ? "plumb_bob [" : "rational [";
  char value[32];
  for (std::size_t i = 0; i < dist.total(); ++i) {
    std::snprintf(value, sizeof value, "%s%.6g", i ? " " : "", dist.at<double>(static_cast<int>(i)));
    text += value;
  }
  return text + "]";
}

void printImported(const ImportCalibrationOptions& o, const ImportedCalibration& imported,
                   const StereoRectification& rect) {
  const StereoCalibration& c = imported.calibration;
  std::printf("imported %s calibration:", o.format.c_str());
  for (const std::string& in : o.inputs) std::printf(" %s", in.c_str());
  std::printf("\n  resolution %d x %d px\n", c.image_size.width, c.image_size.height);
  for (int side = 0; side < 2; ++side) {
    const CameraCalibration& cam = side == 0 ? c.left : c.right;
    std::printf("  %-5s fx %.3f fy %.3f cx %.3f cy %.3f px, distortion %s\n", side == 0 ? "left" : "right", cam.K(0, 0),
                cam.K(1, 1), cam.K(0, 2), cam.K(1, 2), distortionText(cam.dist).c_str());
  }
  cv::Vec3d rvec;
  cv::Rodrigues(c.R, rvec);
  std::printf("  baseline %.4f m, T [%.4f %.4f %.4f] m, rotation between the cameras %.3f deg\n", cv::norm(c.T), c.T[0],
              c.T[1], c.T[2], cv::norm(rvec) * kRadToDeg);
  std::printf("  rectified: f %.3f px, cx %.3f cy %.3f px, baseline %.4f m\n", rect.rectified.fx_px,
              rect.rectified.cx_px, rect.rectified.cy_px, rect.baseline_m);
  for (const std::string& note : imported.notes) std::printf("  note: %s\n", note.c_str());
}

}  // namespace

int runImportCalibrationCommand(const ImportCalibrationOptions& o) {
  ImportedCalibration imported;
  std::string error;
  if (!importAny(o, &imported, &error)) {
    std::fprintf(stderr, "deepnav import calibration: %s\n", error.c_str());
    return 2;
  }
  // What the board will do with it at start-up: a calibration deepnav cannot rectify is refused here.
  StereoRectification rect;
  if (!computeStereoRectification(imported.calibration, RectificationOptions{}, &rect, &error)) {
    std::fprintf(stderr, "deepnav import calibration: %s\n", error.c_str());
    return 2;
  }
  printImported(o, imported, rect);
  StereoCalibrationInfo info;
  info.target = "imported (" + o.format + "):";
  for (const std::string& in : o.inputs) info.target += " " + in;
  if (!writeStereoCalibrationFile(o.out_path, imported.calibration, info, &error)) {
    std::fprintf(stderr, "deepnav import calibration: %s\n", error.c_str());
    return 2;
  }
  std::printf("calibration written to %s (point camera.calibration_file of the board at it)\n", o.out_path.c_str());
  return 0;
}

}  // namespace deepnav
