#include "nav/ekf/gate_reset.h"

#include <algorithm>

#include "nav/ekf/ekf_config.h"

namespace deepnav {
namespace {

void raise(int i, double variance, FilterState* s) {
  const int n = s->dim();
  const double v = std::max(s->P(i, i), variance);
  s->P.row(i).head(n).setZero();
  s->P.col(i).head(n).setZero();
  s->P(i, i) = v;
}

void raiseBlock(int offset, int count, double sigma, FilterState* s) {
  for (int i = offset; i < offset + count; ++i) raise(i, sigma * sigma, s);
}

}  // namespace

void resetObservedStates(NavSource source, const EkfConfig& c, FilterState* s) {
  switch (source) {
    case kSrcDvl:
      raiseBlock(es::kV, 3, c.init_vel_sigma_mps, s);
      raiseBlock(es::kBa, 3, c.init_accel_bias_sigma_mps2, s);
      break;
    case kSrcDepth:
      raise(es::kP + 2, c.init_pos_sigma_m * c.init_pos_sigma_m, s);
      raise(es::kV + 2, c.init_vel_sigma_mps * c.init_vel_sigma_mps, s);
      break;
    case kSrcHeading:
      raise(es::kTheta + 2, c.init_yaw_sigma_rad * c.init_yaw_sigma_rad, s);
      raiseBlock(es::kBg, 3, c.init_gyro_bias_sigma_radps, s);
      break;
    case kSrcAttitude:
      raiseBlock(es::kTheta, 2, c.init_roll_pitch_sigma_rad, s);
      break;
    case kSrcMarkers:
      raiseBlock(es::kP, 3, c.init_pos_sigma_m, s);
      raiseBlock(es::kTheta, 2, c.init_roll_pitch_sigma_rad, s);
      raise(es::kTheta + 2, c.init_yaw_sigma_rad * c.init_yaw_sigma_rad, s);
      break;
    default:
      break;
  }
}

}  // namespace deepnav
