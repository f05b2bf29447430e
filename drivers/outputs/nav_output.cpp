#include "drivers/outputs/nav_output.h"

#include <algorithm>
#include <cmath>

namespace deepnav {

void eulerZyxRad(const Eigen::Quaterniond& q_in, double* roll_rad, double* pitch_rad, double* yaw_rad) {
  const Eigen::Quaterniond q = q_in.normalized();
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  *roll_rad = std::atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y));
  *pitch_rad = std::asin(std::clamp(2.0 * (w * y - z * x), -1.0, 1.0));
  *yaw_rad = std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
}

}  // namespace deepnav
