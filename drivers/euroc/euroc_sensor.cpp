#include "drivers/euroc/euroc_sensor.h"

#include <cmath>
#include <vector>

#include "drivers/euroc/euroc_yaml.h"

namespace deepnav {
namespace {

// A rotation written with 10-12 significant digits is orthonormal to ~1e-9; 1e-6 catches a mistyped entry.
constexpr double kOrthonormalTolerance = 1e-6;

bool readTransform(const EurocYaml& y, const std::string& path, Eigen::Isometry3d* T, std::string* error) {
  double rows = 0.0, cols = 0.0;
  if (!y.number("T_BS.rows", &rows, error) || !y.number("T_BS.cols", &cols, error)) return false;
  if (rows != 4.0 || cols != 4.0) {
    if (error) *error = path + ": key 'T_BS' is " + std::to_string(rows) + "x" + std::to_string(cols) + ", expected 4x4";
    return false;
  }
  std::vector<double> d;
  if (!y.numbers("T_BS.data", 16, &d, error)) return false;
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) M(r, c) = d[static_cast<std::size_t>(4 * r + c)];
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  const bool last_row = M(3, 0) == 0.0 && M(3, 1) == 0.0 && M(3, 2) == 0.0 && M(3, 3) == 1.0;
  const double ortho = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!last_row || ortho > kOrthonormalTolerance || R.determinant() < 0.0) {
    if (error)
      *error = path + ": key 'T_BS.data' is not a rigid transform (last row 0 0 0 1, R orthonormal with det +1; "
                      "|R^T R - I| = " + std::to_string(ortho) + ")";
    return false;
  }
  T->setIdentity();
  T->linear() = R;
  T->translation() = M.block<3, 1>(0, 3);
  return true;
}

bool requireText(const EurocYaml& y, const std::string& path, const std::string& key, const std::string& expected,
                 std::string* error) {
  std::string v;
  if (!y.text(key, &v, error)) return false;
  if (v == expected) return true;
  if (error) *error = path + ": key '" + key + "' is '" + v + "': only '" + expected + "' is supported";
  return false;
}

bool positive(const std::string& path, const std::string& key, double v, std::string* error) {
  if (v > 0.0) return true;
  if (error) *error = path + ": key '" + key + "' must be positive";
  return false;
}

}  // namespace

bool readEurocCamera(const std::string& path, EurocCamera* cam, std::string* error) {
  EurocYaml y;
  if (!y.load(path, error) || !requireText(y, path, "sensor_type", "camera", error) ||
      !requireText(y, path, "camera_model", "pinhole", error) ||
      !requireText(y, path, "distortion_model", "radial-tangential", error) ||
      !readTransform(y, path, &cam->T_body_sensor, error) || !y.number("rate_hz", &cam->rate_hz, error) ||
      !positive(path, "rate_hz", cam->rate_hz, error)) {
    return false;
  }
  std::vector<double> v;
  if (!y.numbers("resolution", 2, &v, error)) return false;
  if (v[0] < 1.0 || v[1] < 1.0 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) || v[0] > 16384 || v[1] > 16384) {
    if (error) *error = path + ": key 'resolution' must be two whole numbers of pixels in [1, 16384]";
    return false;
  }
  cam->width_px = static_cast<int>(v[0]);
  cam->height_px = static_cast<int>(v[1]);
  if (!y.numbers("intrinsics", 4, &v, error)) return false;
  for (std::size_t i = 0; i < 4; ++i) cam->intrinsics[i] = v[i];
  if (!positive(path, "intrinsics (fu)", v[0], error) || !positive(path, "intrinsics (fv)", v[1], error)) return false;
  if (!y.numbers("distortion_coefficients", 4, &v, error)) return false;
  for (std::size_t i = 0; i < 4; ++i) cam->distortion[i] = v[i];
  return true;
}

bool readEurocImuInfo(const std::string& path, EurocImuInfo* imu, std::string* error) {
  EurocYaml y;
  return y.load(path, error) && requireText(y, path, "sensor_type", "imu", error) &&
         readTransform(y, path, &imu->T_body_sensor, error) && y.number("rate_hz", &imu->rate_hz, error) &&
         positive(path, "rate_hz", imu->rate_hz, error) &&
         y.number("gyroscope_noise_density", &imu->gyro_noise_density_radps_rthz, error) &&
         y.number("gyroscope_random_walk", &imu->gyro_random_walk_radps2_rthz, error) &&
         y.number("accelerometer_noise_density", &imu->accel_noise_density_mps2_rthz, error) &&
         y.number("accelerometer_random_walk", &imu->accel_random_walk_mps3_rthz, error);
}

}  // namespace deepnav
