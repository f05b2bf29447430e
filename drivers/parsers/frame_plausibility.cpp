#include "drivers/parsers/frame_plausibility.h"

#include <cmath>
#include <cstring>

#include "drivers/parsers/byte_order.h"

namespace deepnav {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

// Smallest signed difference of two angles in degrees.
double angleStepDeg(double a_deg, double b_deg) {
  double d = std::fmod(a_deg - b_deg, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d < -180.0) d += 360.0;
  return std::fabs(d);
}

}  // namespace

const char* FramePlausibility::verdictName(Verdict v) {
  switch (v) {
    case Verdict::kAccepted: return "accepted";
    case Verdict::kLayoutChanged: return "layout differs from the stream's (header, offsets, fixed leader or data identifiers)";
    case Verdict::kOutOfRange: return "value outside the device's range";
    case Verdict::kImplausibleStep: return "implausible step from the previous frame";
    case Verdict::kCounterJump: return "ensemble/packet counter does not follow the previous frame";
  }
  return "?";
}

void FramePlausibility::reset() {
  has_layout_ = false;
  has_previous_ = false;
  layout_mismatches_ = 0;
  frames_since_accept_ = 0;
  value_rejections_ = 0;
}

// The structure is taken once two frames in a row agree on it (a damaged first frame cannot set it),
// and replaced (a device reconfigured mid-stream) once relock_after frames in a row agree on another.
// Until the first structure is taken, frames are accepted unchecked.
FramePlausibility::Verdict FramePlausibility::layoutVerdict(const uint8_t* bytes, size_t n, size_t frame_size) {
  if (n > kMaxLocked) n = kMaxLocked;
  auto same = [&](const std::array<uint8_t, kMaxLocked>& ref, size_t ref_n, size_t ref_frame) {
    return n == ref_n && frame_size == ref_frame && std::memcmp(bytes, ref.data(), n) == 0;
  };
  if (has_layout_ && same(locked_, locked_size_, locked_frame_size_)) {
    layout_mismatches_ = 0;
    return Verdict::kAccepted;
  }
  if (layout_mismatches_ > 0 && same(candidate_, candidate_size_, candidate_frame_size_)) {
    ++layout_mismatches_;
  } else {
    std::memcpy(candidate_.data(), bytes, n);
    candidate_size_ = n;
    candidate_frame_size_ = frame_size;
    layout_mismatches_ = 1;
  }
  const int needed = has_layout_ ? limits_.relock_after : 2;
  if (layout_mismatches_ >= needed) {
    locked_ = candidate_;
    locked_size_ = candidate_size_;
    locked_frame_size_ = candidate_frame_size_;
    layout_mismatches_ = 0;
    if (has_layout_) has_previous_ = false;  // another configuration: values start afresh
    const bool first = !has_layout_;
    has_layout_ = true;
    return first ? Verdict::kAccepted : Verdict::kLayoutChanged;
  }
  return has_layout_ ? Verdict::kLayoutChanged : Verdict::kAccepted;
}

// Frames since the previous accepted one from the device's own counter (mod `modulus`), or -1
// when there is no previous one to compare with.
// A counter equal to or behind the previous one means the previous accepted frame was itself damaged
// (its counter hit) or the device restarted: start afresh from this frame (-1, no step check) rather
// than reject every good frame until the counter catches up.
int FramePlausibility::gapFromCounter(uint32_t counter, uint32_t modulus) {
  if (!has_previous_) return -1;
  const uint32_t ahead = (counter + modulus - counter_) % modulus;
  if (ahead == 0 || ahead > modulus / 2) {
    has_previous_ = false;
    return -1;
  }
  return int(ahead);
}

FramePlausibility::Verdict FramePlausibility::finish(Verdict v) {
  if (v == Verdict::kAccepted) {
    frames_since_accept_ = 0;
  } else {
    ++frames_since_accept_;
    // A run of value rejections: the reference itself is suspect (a damaged frame accepted before,
    // or a long outage): compare with nothing stale from the next frame on.
    if (v != Verdict::kLayoutChanged && ++value_rejections_ >= limits_.relock_after) has_previous_ = false;
    if (frames_since_accept_ > limits_.max_frame_gap) has_previous_ = false;
  }
  if (v == Verdict::kAccepted) value_rejections_ = 0;
  return v;
}

FramePlausibility::Verdict FramePlausibility::checkPd0(const uint8_t* /*frame*/, size_t /*size*/, const Pd0Ensemble& e) {
  // Locked: the head's identity and configuration from the fixed leader (firmware, system
  // configuration, beams, cells, pings, cell length, coordinate transform, serial number). Not the
  // whole leader: some heads update fields such as the bin 1 distance with the speed of sound (the
  // real capture LA100204 does), and not the header: one head may interleave ensembles with and
  // without bottom track.
  if (e.has_fixed_leader) {
    const Pd0FixedLeader& f = e.fixed;
    std::array<uint8_t, 16> id{};
    id[0] = f.firmware_version, id[1] = f.firmware_revision;
    id[2] = uint8_t(f.system_config), id[3] = uint8_t(f.system_config >> 8);
    id[4] = f.num_beams, id[5] = f.num_cells;
    id[6] = uint8_t(f.pings_per_ensemble), id[7] = uint8_t(f.pings_per_ensemble >> 8);
    id[8] = uint8_t(f.cell_length_cm), id[9] = uint8_t(f.cell_length_cm >> 8);
    id[10] = f.coord_transform;
    for (int i = 0; i < 4; ++i) id[size_t(11 + i)] = uint8_t(f.serial_number >> (8 * i));
    const Verdict layout = layoutVerdict(id.data(), 15, 0);
    if (layout != Verdict::kAccepted) return finish(layout);
  }
  if (!e.has_variable_leader) return finish(Verdict::kAccepted);

  const Pd0VariableLeader& v = e.variable;
  const int gap = gapFromCounter(v.ensemble_number, 1u << 24);
  if (gap > limits_.max_frame_gap) return finish(Verdict::kCounterJump);
  const double heading_deg = v.heading_cdeg / 100.0, pitch_deg = v.pitch_cdeg / 100.0, roll_deg = v.roll_cdeg / 100.0;
  if (v.heading_cdeg >= 36000 || std::fabs(pitch_deg) > 90.0 || std::fabs(roll_deg) > 90.0 ||
      v.speed_of_sound_mps < 1400 || v.speed_of_sound_mps > 1600 || v.temperature_cdegc < -500 ||
      v.temperature_cdegc > 4500 || v.salinity_ppt > 45) {
    return finish(Verdict::kOutOfRange);
  }
  std::array<double, 4> vel{};
  std::array<bool, 4> valid{};
  if (e.has_bottom_track) {
    for (int i = 0; i < 4; ++i) {
      const int16_t mmps = e.bottom_track.velocity_mmps[i];
      valid[i] = mmps != Pd0Ensemble::kBadVelocity;
      vel[i] = mmps / 1000.0;
      if (valid[i] && std::fabs(vel[i]) > limits_.max_speed_mps) return finish(Verdict::kOutOfRange);
      if (e.bottom_track.percent_good[i] > 100) return finish(Verdict::kOutOfRange);
    }
  }
  if (gap > 0) {
    const double g = gap;
    if (angleStepDeg(heading_deg, heading_deg_) > limits_.max_heading_step_deg * g ||
        std::fabs(pitch_deg - pitch_deg_) > limits_.max_tilt_step_deg * g ||
        std::fabs(roll_deg - roll_deg_) > limits_.max_tilt_step_deg * g) {
      return finish(Verdict::kImplausibleStep);
    }
    for (int i = 0; i < 4; ++i) {
      if (valid[i] && velocity_valid_[i] && std::fabs(vel[i] - velocity_mps_[i]) > limits_.max_velocity_step_mps * g) {
        return finish(Verdict::kImplausibleStep);
      }
    }
  }
  has_previous_ = true;
  counter_ = v.ensemble_number;
  heading_deg_ = heading_deg, pitch_deg_ = pitch_deg, roll_deg_ = roll_deg;
  velocity_mps_ = vel;
  velocity_valid_ = valid;
  return finish(Verdict::kAccepted);
}

FramePlausibility::Verdict FramePlausibility::checkXsens(const XbusMessage& m, const XsensMtData2& d) {
  // Locked: message id, payload length and each packet's data identifier and size.
  std::array<uint8_t, 3 + 3 * 32> sig{};
  size_t n = 0;
  sig[n++] = m.message_id;
  sig[n++] = uint8_t(m.payload_size >> 8);
  sig[n++] = uint8_t(m.payload_size);
  for (size_t p = 0; p + 3 <= m.payload_size && n + 3 <= sig.size();) {
    sig[n++] = m.payload[p], sig[n++] = m.payload[p + 1], sig[n++] = m.payload[p + 2];
    p += 3 + m.payload[p + 2];
  }
  const Verdict layout = layoutVerdict(sig.data(), n, m.payload_size);
  if (layout != Verdict::kAccepted) return finish(layout);

  int gap = -1;
  if (d.has_packet_counter) {
    gap = gapFromCounter(d.packet_counter, 1u << 16);
    if (gap > limits_.max_frame_gap) return finish(Verdict::kCounterJump);
  }
  if (d.has_quaternion) {
    const auto& q = d.quaternion;
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(std::fabs(norm - 1.0) <= limits_.quaternion_norm_tolerance)) return finish(Verdict::kOutOfRange);
  }
  auto norm3 = [](const std::array<double, 3>& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); };
  if (d.has_rate_of_turn && !(norm3(d.rate_of_turn_radps) <= limits_.max_angular_rate_radps)) return finish(Verdict::kOutOfRange);
  if (d.has_acceleration && !(norm3(d.acceleration_mps2) <= limits_.max_specific_force_mps2)) return finish(Verdict::kOutOfRange);
  if (d.has_euler) {
    for (double a : d.euler_rad) {
      if (!(std::fabs(a) <= M_PI + 1e-6)) return finish(Verdict::kOutOfRange);
    }
  }
  if (gap > 0 && xsensStepImplausible(d, gap)) return finish(Verdict::kImplausibleStep);
  has_previous_ = d.has_packet_counter;
  counter_ = d.packet_counter;
  keepXsensValues(d);
  return finish(Verdict::kAccepted);
}

// Steps from the previous accepted message, `gap` frames of the device's counter ago (PlausibilityLimits).
bool FramePlausibility::xsensStepImplausible(const XsensMtData2& d, int gap) const {
  auto step3 = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  };
  const double f_limit = limits_.max_specific_force_step_mps2 * gap;
  const double w_limit = limits_.max_angular_rate_step_radps * gap;
  if (d.has_acceleration && has_acceleration_ && f_limit > 0 && step3(d.acceleration_mps2, acceleration_mps2_) > f_limit) {
    return true;
  }
  if (d.has_rate_of_turn && has_rate_ && w_limit > 0 && step3(d.rate_of_turn_radps, rate_radps_) > w_limit) return true;
  if (d.has_quaternion && has_quaternion_ && limits_.max_orientation_step_deg > 0) {
    // Angle between the two orientations: 2 acos(|q1 . q2|) for unit quaternions (either sign).
    double dot = 0.0;
    for (int i = 0; i < 4; ++i) dot += d.quaternion[size_t(i)] * quaternion_[size_t(i)];
    const double angle_deg = 2.0 * std::acos(std::min(1.0, std::fabs(dot))) * kRadToDeg;
    if (angle_deg > limits_.max_orientation_step_deg * gap) return true;
  }
  return false;
}

void FramePlausibility::keepXsensValues(const XsensMtData2& d) {
  has_acceleration_ = d.has_acceleration;
  has_rate_ = d.has_rate_of_turn;
  has_quaternion_ = d.has_quaternion;
  if (d.has_acceleration) acceleration_mps2_ = d.acceleration_mps2;
  if (d.has_rate_of_turn) rate_radps_ = d.rate_of_turn_radps;
  if (d.has_quaternion) quaternion_ = d.quaternion;
}

FramePlausibility::Verdict FramePlausibility::checkNmeaHeading(const Nmea0183HeadingRecord& r) {
  // Frames framed since the previous accepted one; damaged line ends can merge two sentences, so one
  // more is allowed.
  const int gap = has_previous_ ? frames_since_accept_ + 2 : -1;
  if (r.has_rate && !(std::fabs(r.rate_radps * kRadToDeg * 60.0) <= limits_.max_rate_of_turn_dpm)) {
    return finish(Verdict::kOutOfRange);
  }
  if (!r.has_heading) return finish(Verdict::kAccepted);
  const double heading_deg = r.heading_rad * kRadToDeg;
  if (!(heading_deg >= 0.0 && heading_deg < 360.0)) return finish(Verdict::kOutOfRange);
  if (gap > 0 && angleStepDeg(heading_deg, heading_deg_) > limits_.max_heading_step_deg * gap) {
    return finish(Verdict::kImplausibleStep);
  }
  has_previous_ = true;
  heading_deg_ = heading_deg;
  return finish(Verdict::kAccepted);
}

FramePlausibility::Verdict FramePlausibility::checkWaterLinked(const WlDvlReport& r) {
  if (r.kind != WlDvlReport::Kind::kVelocity) return finish(Verdict::kAccepted);
  const int gap = has_previous_ ? frames_since_accept_ + 2 : -1;
  const std::array<double, 3> v{r.vx_mps, r.vy_mps, r.vz_mps};
  for (double c : v) {
    if (!(std::fabs(c) <= limits_.max_speed_mps)) return finish(Verdict::kOutOfRange);
  }
  if (!(r.altitude_m >= -1.0 && r.altitude_m < 1000.0) || !(r.fom_mps >= 0.0 && r.fom_mps <= limits_.max_speed_mps)) {
    return finish(Verdict::kOutOfRange);
  }
  if (r.has_covariance) {
    for (int i = 0; i < 3; ++i) {
      if (!(r.covariance_m2ps2[size_t(4 * i)] >= 0.0)) return finish(Verdict::kOutOfRange);
    }
  }
  if (gap > 0 && r.velocity_valid && velocity_valid_[0]) {
    for (int i = 0; i < 3; ++i) {
      if (std::fabs(v[size_t(i)] - velocity_mps_[size_t(i)]) > limits_.max_velocity_step_mps * gap) {
        return finish(Verdict::kImplausibleStep);
      }
    }
  }
  has_previous_ = true;
  for (int i = 0; i < 3; ++i) velocity_mps_[size_t(i)] = v[size_t(i)];
  velocity_valid_[0] = r.velocity_valid;
  return finish(Verdict::kAccepted);
}

}  // namespace deepnav
