#include "drivers/parsers/pd0_dvl_sample.h"

#include <cmath>

#include <Eigen/Core>

namespace deepnav {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

// Instrument-frame (X stbd, Y fwd, Z up) velocity of the bottom from the four beam velocities.
bool beamToInstrument(const std::array<int16_t, 4>& b, double beam_angle_deg, Eigen::Vector3d* v_mps) {
  for (int16_t x : b) {
    if (x == Pd0Ensemble::kBadVelocity) return false;  // 3-beam solutions are not attempted
  }
  const double theta = beam_angle_deg * kDegToRad;
  const double a = 1.0 / (2.0 * std::sin(theta));
  const double c = 1.0 / (4.0 * std::cos(theta));
  *v_mps = Eigen::Vector3d(a * (b[0] - b[1]), a * (b[3] - b[2]), c * (b[0] + b[1] + b[2] + b[3])) * 1e-3;
  return true;
}

// Rotation instrument -> earth (E, N, U) from heading, pitch, roll (RDI's M matrix).
Eigen::Matrix3d instrumentToEarth(double heading_deg, double pitch_deg, double roll_deg) {
  const double ch = std::cos(heading_deg * kDegToRad), sh = std::sin(heading_deg * kDegToRad);
  const double cp = std::cos(pitch_deg * kDegToRad), sp = std::sin(pitch_deg * kDegToRad);
  const double cr = std::cos(roll_deg * kDegToRad), sr = std::sin(roll_deg * kDegToRad);
  Eigen::Matrix3d m;
  m << ch * cr + sh * sp * sr, sh * cp, ch * sr - sh * sp * cr,  //
      -sh * cr + ch * sp * sr, ch * cp, -sh * sr - ch * sp * cr,  //
      -cp * sr, sp, cp * cr;
  return m;
}

}  // namespace

bool pd0ToDvlSample(const Pd0Ensemble& e, TimeUs t_us, DvlSample* s) {
  if (!e.has_bottom_track || !e.has_fixed_leader || e.fixed.upFacing()) return false;
  const Pd0BottomTrack& bt = e.bottom_track;
  DvlSample out;
  out.t_us = t_us;
  const double beam_angle_deg = e.fixed.beamAngleDeg();
  int n_ranges = 0;
  double range_sum_m = 0.0;
  for (int i = 0; i < DvlSample::kBeams; ++i) {
    out.beam_range_m[i] = bt.range_cm[i] * 0.01;
    const bool beam_ok = bt.range_cm[i] > 0 && (e.fixed.frame() != 0 || bt.velocity_mmps[i] != Pd0Ensemble::kBadVelocity);
    if (beam_ok) {
      out.beam_valid_mask |= uint8_t(1u << i);
      range_sum_m += out.beam_range_m[i];
      ++n_ranges;
    }
  }
  if (n_ranges > 0) out.altitude_m = range_sum_m / n_ranges * std::cos(beam_angle_deg * kDegToRad);

  Eigen::Vector3d v_bottom_inst;  // bottom relative to the instrument, instrument frame
  bool have_velocity = false;
  if (e.fixed.frame() == 0) {
    have_velocity = beamToInstrument(bt.velocity_mmps, beam_angle_deg, &v_bottom_inst);
  } else {
    have_velocity = bt.velocity_mmps[0] != Pd0Ensemble::kBadVelocity && bt.velocity_mmps[1] != Pd0Ensemble::kBadVelocity &&
                    bt.velocity_mmps[2] != Pd0Ensemble::kBadVelocity;
    if (have_velocity) {
      const Eigen::Vector3d v(bt.velocity_mmps[0] * 1e-3, bt.velocity_mmps[1] * 1e-3, bt.velocity_mmps[2] * 1e-3);
      if (e.fixed.frame() == 3) {
        if (!e.has_variable_leader) return false;
        const Pd0VariableLeader& vl = e.variable;
        v_bottom_inst = instrumentToEarth(vl.heading_cdeg * 0.01, vl.pitch_cdeg * 0.01, vl.roll_cdeg * 0.01).transpose() * v;
      } else {
        v_bottom_inst = v;  // instrument, or ship (instrument rotated by the heading alignment EA)
      }
      if (bt.velocity_mmps[3] != Pd0Ensemble::kBadVelocity) out.fom_mps = std::abs(bt.velocity_mmps[3]) * 1e-3;
    }
  }
  if (have_velocity) {
    const Eigen::Vector3d v_dvl_inst = -v_bottom_inst;
    out.v_dvl_mps = Eigen::Vector3d(v_dvl_inst.y(), -v_dvl_inst.x(), v_dvl_inst.z());
  }
  out.valid = have_velocity && n_ranges >= 3 && e.variable.bit_result == 0;
  *s = out;
  return true;
}

}  // namespace deepnav
