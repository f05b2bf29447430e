#include "board/config/calibration_import_kalibr.h"

#include <cstdio>

#include "board/config/yaml_document.h"
#include "vision/calib/equidistant_to_rational.h"

namespace deepnav {
namespace {

// An equidistant lens as OpenCV's rational model, kept when the two differ by under 0.1 px over the image.
bool rewriteEquidistant(const cv::Vec4d& k, cv::Size size, const std::string& path, const std::string& cam,
                        CameraCalibration* out, std::vector<std::string>* notes, std::string* error) {
  EquidistantFit fit;
  std::string why;
  if (!equidistantToRational(out->K, k, size, &fit, &why)) {
    *error = path + ": key '" + cam + ".distortion_coeffs' (equidistant): " + why;
    return false;
  }
  if (fit.max_error_px > kMaxEquidistantFitErrorPx) {
    *error = path + ": key '" + cam + ".distortion_coeffs' (equidistant): the rational model fits this lens only to " +
             std::to_string(fit.max_error_px) +
             " px over the image (limit 0.1 px); deepnav rectifies with "
             "OpenCV's pinhole models and cannot use it";
    return false;
  }
  char text[240];
  std::snprintf(text, sizeof text,
                "%s: equidistant lens rewritten as OpenCV's rational model (k1 k2 k3 k4 k5 k6), largest difference "
                "%.4f px over the image (rays up to %.1f deg from the axis)",
                cam.c_str(), fit.max_error_px, fit.max_angle_deg);
  out->dist = fit.dist;
  notes->push_back(text);
  return true;
}

bool readCamera(const YAML::Node& root, const std::string& cam, const std::string& path, CameraCalibration* out,
                cv::Size* size, std::vector<std::string>* notes, std::string* error) {
  const YAML::Node node = root[cam];
  if (!node || !node.IsMap()) {
    *error = path + ": key '" + cam + "' is missing (a camchain.yaml holds cam0, cam1, ...)";
    return false;
  }
  std::string model, distortion;
  std::vector<double> intrinsics, coeffs, resolution;
  if (!readYamlString(node, "camera_model", path, cam, &model, error)) return false;
  if (model != "pinhole") {
    *error = path + ": key '" + cam + ".camera_model' is " + model +
             "; only pinhole is imported (omni, ds and eucm have no OpenCV equivalent)";
    return false;
  }
  if (!readYamlNumbers(node, "intrinsics", path, cam, 4, &intrinsics, error) ||
      !readYamlString(node, "distortion_model", path, cam, &distortion, error) ||
      !readYamlNumbers(node, "resolution", path, cam, 2, &resolution, error))
    return false;
  if (distortion != "radtan" && distortion != "equidistant" && distortion != "none") {
    *error = path + ": key '" + cam + ".distortion_model' is " + distortion + "; radtan, equidistant or none expected";
    return false;
  }
  // Kalibr's "none" has no coefficients (an empty list, or none at all).
  if (distortion == "none") {
    coeffs.assign(4, 0.0);
  } else if (!readYamlNumbers(node, "distortion_coeffs", path, cam, 4, &coeffs, error)) {
    return false;
  }
  out->K = cv::Matx33d(intrinsics[0], 0, intrinsics[2], 0, intrinsics[1], intrinsics[3], 0, 0, 1);
  *size = cv::Size(static_cast<int>(resolution[0]), static_cast<int>(resolution[1]));
  if (size->width < 16 || size->height < 16) {
    *error = path + ": key '" + cam + ".resolution' must be [width, height] of at least 16 x 16 px";
    return false;
  }
  if (!checkCameraMatrix(out->K, path, cam + ".intrinsics", error)) return false;
  if (distortion == "radtan" || distortion == "none") {
    out->dist = (cv::Mat_<double>(1, 5) << coeffs[0], coeffs[1], coeffs[2], coeffs[3], 0.0);
  } else if (!rewriteEquidistant(cv::Vec4d(coeffs[0], coeffs[1], coeffs[2], coeffs[3]), *size, path, cam, out, notes,
                                 error)) {
    return false;
  }
  return checkDistortion(out->dist, path, cam + ".distortion_coeffs", error);
}

}  // namespace

bool importKalibrCamchain(const std::string& path, ImportedCalibration* out, std::string* error) {
  std::string text;
  YAML::Node root;
  if (!loadYamlFile(path, "the Kalibr camchain", &text, &root, error)) return false;
  if (!root.IsMap()) {
    *error = path + ": expected a map with cam0 and cam1 (Kalibr camchain.yaml)";
    return false;
  }
  ImportedCalibration result;
  StereoCalibration& c = result.calibration;
  cv::Size size_left, size_right;
  if (!readCamera(root, "cam0", path, &c.left, &size_left, &result.notes, error) ||
      !readCamera(root, "cam1", path, &c.right, &size_right, &result.notes, error) ||
      !checkSameResolution(size_left, size_right, path, "cam1.resolution", error))
    return false;
  c.image_size = size_left;
  std::vector<double> T;
  if (!readYamlNumbers(root["cam1"], "T_cn_cnm1", path, "cam1", 16, &T, error)) return false;
  if (T[12] != 0.0 || T[13] != 0.0 || T[14] != 0.0 || T[15] != 1.0) {
    *error = path + ": key 'cam1.T_cn_cnm1' must end with the row [0, 0, 0, 1]";
    return false;
  }
  c.R = cv::Matx33d(T[0], T[1], T[2], T[4], T[5], T[6], T[8], T[9], T[10]);
  c.T = cv::Vec3d(T[3], T[7], T[11]);
  if (!checkRotation(c.R, path, "cam1.T_cn_cnm1", error) || !checkBaseline(c.T, path, "cam1.T_cn_cnm1", error))
    return false;
  if (root["cam2"]) result.notes.push_back("cam2 and beyond ignored: deepnav uses cam0 (left) and cam1 (right)");
  *out = result;
  return true;
}

}  // namespace deepnav
