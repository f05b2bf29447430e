#include "drivers/parsers/wl_dvl_report.h"

#include <cmath>

namespace deepnav {

bool dvlSampleFromWlReport(const WlDvlReport& r, TimeUs t_us, DvlSample* s) {
  if (r.kind != WlDvlReport::Kind::kVelocity) return false;
  DvlSample out;
  out.t_us = t_us;
  const Eigen::Vector3d flu(1.0, -1.0, -1.0);  // x fwd, y right, z down -> FLU
  out.v_dvl_mps = Eigen::Vector3d(r.vx_mps, r.vy_mps, r.vz_mps).cwiseProduct(flu);
  out.valid = r.velocity_valid && r.status == 0;
  out.fom_mps = r.fom_mps;
  out.altitude_m = r.altitude_m;
  if (r.has_covariance) {
    Eigen::Matrix3d c;
    for (int i = 0; i < 9; ++i) c(i / 3, i % 3) = r.covariance_m2ps2[i];
    out.cov_v_dvl_mps2 = flu.asDiagonal() * c * flu.asDiagonal();
  }
  for (int i = 0; i < r.num_transducers && i < DvlSample::kBeams; ++i) {
    const WlDvlReport::Transducer& t = r.transducers[i];
    if (t.id < 0 || t.id >= DvlSample::kBeams) continue;
    out.beam_range_m[t.id] = t.distance_m;
    if (t.beam_valid) out.beam_valid_mask |= uint8_t(1u << t.id);
  }
  *s = out;
  return true;
}

}  // namespace deepnav
