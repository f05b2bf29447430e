#include "board/config/stereo_calibration_file.h"

#include <opencv2/core/persistence.hpp>

#include "board/config/text_file.h"
#include "board/config/yaml_document.h"

namespace deepnav {
namespace {

// Reads a matrix field of the expected shape (cols = 0: a 1 x N or N x 1 vector of any length).
bool readMatrix(const cv::FileStorage& fs, const std::string& path, const char* name, int rows, int cols,
                cv::Mat* out, std::string* error) {
  const cv::FileNode node = fs[name];
  if (node.empty()) {
    if (error) *error = path + ": field '" + name + "' is missing";
    return false;
  }
  cv::Mat m;
  try {
    node >> m;
  } catch (const cv::Exception&) {
    m.release();
  }
  const bool shape_ok = cols > 0 ? (m.rows == rows && m.cols == cols) : (m.rows == 1 || m.cols == 1);
  if (m.empty() || !shape_ok || m.channels() != 1) {
    if (error)
      *error = path + ": field '" + name + "' must be an opencv-matrix of " +
               (cols > 0 ? std::to_string(rows) + " x " + std::to_string(cols) : std::string("1 x N")) + " numbers";
    return false;
  }
  m.convertTo(*out, CV_64F);
  if (!cv::checkRange(*out)) {
    if (error) *error = path + ": field '" + name + "' holds non-finite values";
    return false;
  }
  return true;
}

bool readInt(const cv::FileStorage& fs, const std::string& path, const char* name, int* out, std::string* error) {
  const cv::FileNode node = fs[name];
  if (node.empty() || !node.isInt()) {
    if (error) *error = path + ": field '" + name + "' must be an integer";
    return false;
  }
  *out = static_cast<int>(node);
  return true;
}

}  // namespace

namespace {

void writeFields(cv::FileStorage& fs, const StereoCalibration& c, const StereoCalibrationInfo& info) {
  fs.writeComment("deepnav stereo calibration (deepnav calibrate): p_in_right = R * p_in_left + T, metres");
  fs << "image_width" << c.image_size.width << "image_height" << c.image_size.height;
  fs << "camera_matrix_left" << cv::Mat(c.left.K) << "distortion_coefficients_left" << c.left.dist;
  fs << "camera_matrix_right" << cv::Mat(c.right.K) << "distortion_coefficients_right" << c.right.dist;
  fs << "R" << cv::Mat(c.R) << "T" << cv::Mat(c.T);
  fs << "rms_px" << info.rms_px << "pairs_used" << info.pairs_used << "target" << info.target;
}

bool readFields(const cv::FileStorage& fs, const std::string& path, StereoCalibration* c, std::string* error) {
  StereoCalibration out;
  cv::Mat K1, D1, K2, D2, R, T;
  if (!readInt(fs, path, "image_width", &out.image_size.width, error) ||
      !readInt(fs, path, "image_height", &out.image_size.height, error) ||
      !readMatrix(fs, path, "camera_matrix_left", 3, 3, &K1, error) ||
      !readMatrix(fs, path, "distortion_coefficients_left", 1, 0, &D1, error) ||
      !readMatrix(fs, path, "camera_matrix_right", 3, 3, &K2, error) ||
      !readMatrix(fs, path, "distortion_coefficients_right", 1, 0, &D2, error) ||
      !readMatrix(fs, path, "R", 3, 3, &R, error) || !readMatrix(fs, path, "T", 3, 1, &T, error))
    return false;
  out.left.K = cv::Matx33d(K1);
  out.left.dist = D1.reshape(1, 1).clone();
  out.right.K = cv::Matx33d(K2);
  out.right.dist = D2.reshape(1, 1).clone();
  out.R = cv::Matx33d(R);
  out.T = cv::Vec3d(T);
  *c = out;
  return true;
}

}  // namespace

bool writeStereoCalibrationFile(const std::string& path, const StereoCalibration& c, const StereoCalibrationInfo& info,
                                std::string* error) {
  try {
    cv::FileStorage fs(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
    if (!fs.isOpened()) {
      if (error) *error = path + ": cannot write the calibration file";
      return false;
    }
    writeFields(fs, c, info);
  } catch (const cv::Exception& e) {
    if (error) *error = path + ": cannot write the calibration file: " + e.what();
    return false;
  }
  return true;
}

std::string stereoCalibrationText(const StereoCalibration& c, const StereoCalibrationInfo& info) {
  cv::FileStorage fs(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  writeFields(fs, c, info);
  return fs.releaseAndGetString();
}

bool readStereoCalibrationFile(const std::string& path, StereoCalibration* c, std::string* error) {
  std::string text;
  return readTextFile(path, "the stereo calibration file", &text, error) &&
         parseStereoCalibrationText(text, path, c, error);
}

bool parseStereoCalibrationText(const std::string& text, const std::string& name, StereoCalibration* c,
                                std::string* error) {
  // OpenCV keeps the first of two equal keys without a word; its "%YAML:1.0" directive is not YAML 1.2.
  const std::size_t directive = text.rfind("%YAML:", 0) == 0 ? text.find('\n') : 0;
  if (!checkYamlKeysUnique(text.substr(directive == std::string::npos ? text.size() : directive), name, error)) {
    return false;
  }
  cv::FileStorage fs;
  try {
    if (text.empty() || !fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML)) {
      if (error) *error = name + ": empty or unreadable stereo calibration";
      return false;
    }
  } catch (const cv::Exception& e) {
    if (error) *error = name + ": not an OpenCV YAML calibration (" + e.err + ")";
    return false;
  }
  return readFields(fs, name, c, error);
}

}  // namespace deepnav
