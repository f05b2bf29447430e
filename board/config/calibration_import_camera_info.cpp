#include "board/config/calibration_import_camera_info.h"

#include <cstdio>

#include "board/config/calibration_import_kalibr.h"
#include "board/config/yaml_document.h"
#include "vision/calib/equidistant_to_rational.h"

namespace deepnav {
namespace {

struct CameraInfoFile {
  cv::Size size;
  CameraCalibration camera;
  cv::Matx33d R_rect = cv::Matx33d::eye();
  cv::Matx34d P = cv::Matx34d::zeros();
};

// {rows, cols, data} of the expected shape (cols = 0: 1 x N or N x 1 of any length).
bool readMatrix(const YAML::Node& root, const std::string& key, const std::string& path, int rows, int cols,
                cv::Mat* out, std::string* error) {
  const YAML::Node node = root[key];
  const std::string shape = cols > 0 ? std::to_string(rows) + " x " + std::to_string(cols) : "1 x N";
  if (!node) {
    *error = path + ": key '" + key + "' is missing";
    return false;
  }
  int r = 0, c = 0;
  std::vector<double> data;
  if (!node.IsMap()) {
    *error = path + ": key '" + key + "' must be a matrix {rows, cols, data}";
    return false;
  }
  if (!readYamlInt(node, "rows", path, key, &r, error) || !readYamlInt(node, "cols", path, key, &c, error))
    return false;
  const bool shape_ok = cols > 0 ? (r == rows && c == cols) : ((r == 1 || c == 1) && r * c > 0);
  if (!shape_ok) {
    *error =
        path + ": key '" + key + "' is " + std::to_string(r) + " x " + std::to_string(c) + ", " + shape + " expected";
    return false;
  }
  if (!readYamlNumbers(node, "data", path, key, static_cast<std::size_t>(r * c), &data, error)) return false;
  *out = cv::Mat(data, true).reshape(1, cols > 0 ? r : 1);
  return true;
}

bool readDistortion(const YAML::Node& root, const std::string& path, CameraInfoFile* f, std::vector<std::string>* notes,
                    std::string* error) {
  std::string model;
  cv::Mat D;
  if (!readYamlString(root, "distortion_model", path, "", &model, error) ||
      !readMatrix(root, "distortion_coefficients", path, 1, 0, &D, error))
    return false;
  const std::size_t n = D.total();
  const std::size_t expected = model == "plumb_bob"             ? 5
                               : model == "rational_polynomial" ? 8
                               : model == "equidistant"         ? 4
                                                                : 0;
  if (expected == 0) {
    *error = path + ": key 'distortion_model' is " + model + "; plumb_bob, rational_polynomial or equidistant expected";
    return false;
  }
  if (n != expected) {
    *error = path + ": key 'distortion_coefficients' holds " + std::to_string(n) + " numbers; " + model + " has " +
             std::to_string(expected);
    return false;
  }
  if (model != "equidistant") {
    f->camera.dist = D.clone();
    return checkDistortion(f->camera.dist, path, "distortion_coefficients", error);
  }
  EquidistantFit fit;
  std::string why;
  const cv::Vec4d k(D.at<double>(0), D.at<double>(1), D.at<double>(2), D.at<double>(3));
  if (!equidistantToRational(f->camera.K, k, f->size, &fit, &why) || fit.max_error_px > kMaxEquidistantFitErrorPx) {
    *error = path + ": key 'distortion_coefficients' (equidistant): " +
             (why.empty() ? "the rational model fits this lens only to " + std::to_string(fit.max_error_px) +
                                " px over the image (limit 0.1 px)"
                          : why);
    return false;
  }
  char text[200];
  std::snprintf(text, sizeof text,
                "%s: equidistant lens rewritten as OpenCV's rational model, largest difference %.4f px", path.c_str(),
                fit.max_error_px);
  notes->push_back(text);
  f->camera.dist = fit.dist;
  return true;
}

bool readCameraInfo(const std::string& path, CameraInfoFile* f, std::vector<std::string>* notes, std::string* error) {
  std::string text;
  YAML::Node root;
  if (!loadYamlFile(path, "the camera_info file", &text, &root, error)) return false;
  if (!root.IsMap()) {
    *error = path + ": expected a camera_info map (image_width, image_height, camera_matrix, ...)";
    return false;
  }
  cv::Mat K, R, P;
  if (!readYamlInt(root, "image_width", path, "", &f->size.width, error) ||
      !readYamlInt(root, "image_height", path, "", &f->size.height, error) ||
      !readMatrix(root, "camera_matrix", path, 3, 3, &K, error))
    return false;
  f->camera.K = cv::Matx33d(K);
  if (!checkCameraMatrix(f->camera.K, path, "camera_matrix", error) || !readDistortion(root, path, f, notes, error) ||
      !readMatrix(root, "rectification_matrix", path, 3, 3, &R, error) ||
      !readMatrix(root, "projection_matrix", path, 3, 4, &P, error))
    return false;
  f->R_rect = cv::Matx33d(R);
  f->P = cv::Matx34d(P);
  if (!checkRotation(f->R_rect, path, "rectification_matrix", error)) return false;
  if (!(f->P(0, 0) > 0.0) || !(f->P(1, 1) > 0.0)) {
    *error = path + ": key 'projection_matrix' focal lengths must be positive (an uncalibrated camera has P = 0)";
    return false;
  }
  return true;
}

}  // namespace

bool importCameraInfoPair(const std::string& left_path, const std::string& right_path, ImportedCalibration* out,
                          std::string* error) {
  ImportedCalibration result;
  CameraInfoFile left, right;
  if (!readCameraInfo(left_path, &left, &result.notes, error) ||
      !readCameraInfo(right_path, &right, &result.notes, error) ||
      !checkSameResolution(left.size, right.size, right_path, "image_width', 'image_height", error))
    return false;
  if (left.P(0, 3) != 0.0) {
    *error = left_path + ": key 'projection_matrix' has Tx = " + std::to_string(left.P(0, 3)) +
             "; the left camera's is 0 (give the left camera's file first)";
    return false;
  }
  const double fx = right.P(0, 0), fy = right.P(1, 1);
  const cv::Vec3d t_rect(right.P(0, 3) / fx, right.P(1, 3) / fy, right.P(2, 3));
  if (!(right.P(0, 3) < 0.0)) {
    *error = right_path + ": key 'projection_matrix' has Tx = " + std::to_string(right.P(0, 3)) +
             "; the right camera of a stereo pair has Tx = -fx * baseline < 0" +
             (right.P(0, 3) > 0.0 ? " (the files may be swapped: left first)" : " (baseline 0)");
    return false;
  }
  StereoCalibration& c = result.calibration;
  c.image_size = left.size;
  c.left = left.camera;
  c.right = right.camera;
  c.R = right.R_rect.t() * left.R_rect;
  c.T = right.R_rect.t() * t_rect;
  if (!checkBaseline(c.T, right_path, "projection_matrix", error)) return false;
  *out = result;
  return true;
}

}  // namespace deepnav
