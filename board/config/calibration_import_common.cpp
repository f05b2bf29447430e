#include "board/config/calibration_import_common.h"

#include <cmath>

namespace deepnav {
namespace {

bool fail(const std::string& file, const std::string& key, const std::string& why, std::string* error) {
  if (error) *error = file + ": key '" + key + "' " + why;
  return false;
}

}  // namespace

bool checkCameraMatrix(const cv::Matx33d& K, const std::string& file, const std::string& key, std::string* error) {
  if (!cv::checkRange(cv::Mat(K))) return fail(file, key, "holds non-finite values", error);
  if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0))
    return fail(
        file, key,
        "focal lengths must be positive (fx " + std::to_string(K(0, 0)) + ", fy " + std::to_string(K(1, 1)) + ")",
        error);
  if (K(1, 0) != 0.0 || K(2, 0) != 0.0 || K(2, 1) != 0.0 || K(2, 2) != 1.0)
    return fail(file, key, "is not a camera matrix [fx s cx; 0 fy cy; 0 0 1]", error);
  return true;
}

bool checkRotation(const cv::Matx33d& R, const std::string& file, const std::string& key, std::string* error) {
  if (!cv::checkRange(cv::Mat(R))) return fail(file, key, "holds non-finite values", error);
  const double off = cv::norm(R.t() * R - cv::Matx33d::eye(), cv::NORM_INF);
  if (off > 1e-4)
    return fail(file, key, "is not a rotation: R^T R differs from the identity by " + std::to_string(off), error);
  if (cv::determinant(R) < 0.0) return fail(file, key, "is a reflection (determinant -1), not a rotation", error);
  return true;
}

bool checkBaseline(const cv::Vec3d& T, const std::string& file, const std::string& key, std::string* error) {
  if (!cv::checkRange(cv::Mat(T))) return fail(file, key, "holds non-finite values", error);
  if (!(cv::norm(T) > 1e-6)) return fail(file, key, "gives a baseline of 0 m between the two cameras", error);
  return true;
}

bool checkSameResolution(cv::Size left, cv::Size right, const std::string& file, const std::string& key,
                         std::string* error) {
  if (left.width < 16 || left.height < 16 || right.width < 16 || right.height < 16)
    return fail(file, key, "gives an image size below 16 x 16 px", error);
  if (left != right)
    return fail(file, key,
                "differs between the cameras: " + std::to_string(left.width) + " x " + std::to_string(left.height) +
                    " (left) and " + std::to_string(right.width) + " x " + std::to_string(right.height) +
                    " (right); deepnav rectifies pairs of one size",
                error);
  return true;
}

bool checkDistortion(const cv::Mat& dist, const std::string& file, const std::string& key, std::string* error) {
  const std::size_t n = dist.total();
  if (!(n == 4 || n == 5 || n == 8 || n == 12 || n == 14))
    return fail(
        file, key,
        "must hold 4, 5, 8, 12 or 14 coefficients (OpenCV order k1 k2 p1 p2 [k3 ...]), not " + std::to_string(n),
        error);
  if (!cv::checkRange(dist)) return fail(file, key, "holds non-finite values", error);
  return true;
}

bool readYamlNumbers(const YAML::Node& parent, const std::string& key, const std::string& file,
                     const std::string& prefix, std::size_t expected, std::vector<double>* out, std::string* error) {
  const std::string name = prefix.empty() ? key : prefix + "." + key;
  const YAML::Node node = parent[key];
  if (!node) return fail(file, name, "is missing", error);
  std::vector<double> values;
  // A flat list, or a list of rows (Kalibr writes 4 x 4 transforms as rows).
  const auto take = [&](const YAML::Node& v) {
    if (!v.IsScalar()) return false;
    try {
      values.push_back(v.as<double>());
    } catch (const YAML::Exception&) {
      return false;
    }
    return true;
  };
  bool ok = node.IsSequence();
  for (std::size_t i = 0; ok && i < node.size(); ++i) {
    if (!node[i].IsSequence()) {
      ok = take(node[i]);
      continue;
    }
    for (std::size_t j = 0; ok && j < node[i].size(); ++j) ok = take(node[i][j]);
  }
  if (!ok) return fail(file, name, "must be a list of numbers", error);
  if (values.size() != expected)
    return fail(file, name, "must hold " + std::to_string(expected) + " numbers, not " + std::to_string(values.size()),
                error);
  for (double v : values)
    if (!std::isfinite(v)) return fail(file, name, "holds non-finite values", error);
  *out = values;
  return true;
}

bool readYamlString(const YAML::Node& parent, const std::string& key, const std::string& file,
                    const std::string& prefix, std::string* out, std::string* error) {
  const std::string name = prefix.empty() ? key : prefix + "." + key;
  const YAML::Node node = parent[key];
  if (!node) return fail(file, name, "is missing", error);
  if (!node.IsScalar()) return fail(file, name, "must be a word", error);
  *out = node.Scalar();
  return true;
}

bool readYamlInt(const YAML::Node& parent, const std::string& key, const std::string& file, const std::string& prefix,
                 int* out, std::string* error) {
  const std::string name = prefix.empty() ? key : prefix + "." + key;
  const YAML::Node node = parent[key];
  if (!node) return fail(file, name, "is missing", error);
  try {
    *out = node.as<int>();
  } catch (const YAML::Exception&) {
    return fail(file, name, "must be an integer", error);
  }
  return true;
}

}  // namespace deepnav
