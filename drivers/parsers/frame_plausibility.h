#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/nmea0183_heading.h"
#include "drivers/parsers/pd0_ensemble.h"
#include "drivers/parsers/wl_dvl_report.h"
#include "drivers/parsers/xbus_framer.h"
#include "drivers/parsers/xsens_mtdata2.h"

namespace deepnav {

// Limits of what one device can send from one frame to the next. A frame damaged by several bit
// errors can pass an 8- or 16-bit checksum (two flips of one bit position cancel in an XOR or a sum);
// these checks catch most such frames, none can catch a damage that keeps every field plausible.
// Steps are per frame at the device's own rate (scaled by the number of frames since the last accepted
// one, from the ensemble number / packet counter where the protocol has one, else by the frames
// framed in between): set them for the device's ping rate and the vehicle's dynamics.
struct PlausibilityLimits {
  double max_speed_mps = 10.0;          // a DVL velocity component beyond this is not a measurement
  // Per frame. The defaults fit a small vehicle and a DVL at 0.5-5 Hz: the real capture LA100204
  // (one ensemble per 1.5 s) has steps of 11 deg in heading and 12 deg in pitch.
  double max_velocity_step_mps = 1.0;
  double max_heading_step_deg = 45.0;
  double max_tilt_step_deg = 30.0;      // pitch/roll
  int max_frame_gap = 1000;             // a counter further ahead than this (or behind) is a damaged counter;
                                        // this many frames rejected in a row: start afresh
  double max_rate_of_turn_dpm = 3600.0; // NMEA ROT, deg/min
  double max_angular_rate_radps = 35.0; // IMU gyro (2000 deg/s)
  double max_specific_force_mps2 = 160.0;  // IMU accelerometer (16 g)
  double quaternion_norm_tolerance = 1e-3;
  // IMU/AHRS steps per frame of the device's counter (an MTi at 100 Hz). A work-class ROV's specific
  // force changes by under 1 m/s2 in 10 ms (thrusters spin up in tenths of a second; the MTi's output
  // is the velocity increment over the frame, which averages vibration), its rate by under 0.01 rad/s,
  // its attitude by under 0.3 deg; a flipped exponent or high mantissa bit in a damaged message whose
  // 8-bit sum still holds (1 in 256) multiplies a value by 2^k (fault_bit_errors_test). 0: not checked.
  double max_specific_force_step_mps2 = 4.0;
  double max_angular_rate_step_radps = 0.2;
  double max_orientation_step_deg = 2.0;
  int relock_after = 3;                 // consecutive layout mismatches that mean the device was reconfigured;
                                        // consecutive value rejections after which the reference is dropped
};

// Stream-level plausibility of checksum-valid frames of one sensor stream: structure locked to the
// first accepted frame (PD0 fixed leader; Xsens message id, length and data identifiers; relocked
// after `relock_after` frames of another structure in a row), physical ranges, and steps against the previous accepted frame. State only
// (no allocation after construction); one instance per stream.
class FramePlausibility {
 public:
  enum class Verdict { kAccepted, kLayoutChanged, kOutOfRange, kImplausibleStep, kCounterJump };

  explicit FramePlausibility(const PlausibilityLimits& limits = {}) : limits_(limits) {}
  void reset();

  Verdict checkPd0(const uint8_t* frame, size_t size, const Pd0Ensemble& e);
  Verdict checkXsens(const XbusMessage& m, const XsensMtData2& d);
  Verdict checkNmeaHeading(const Nmea0183HeadingRecord& r);
  Verdict checkWaterLinked(const WlDvlReport& r);
  // A frame that failed framing or its checksum: counts toward the gap of the next step check.
  void onRejectedFrame() { ++frames_since_accept_; }

  static const char* verdictName(Verdict v);

 private:
  static constexpr size_t kMaxLocked = 512;
  Verdict layoutVerdict(const uint8_t* bytes, size_t n, size_t frame_size);
  int gapFromCounter(uint32_t counter, uint32_t modulus);
  Verdict finish(Verdict v);
  bool xsensStepImplausible(const XsensMtData2& d, int gap) const;
  void keepXsensValues(const XsensMtData2& d);

  PlausibilityLimits limits_;
  std::array<uint8_t, kMaxLocked> locked_{};
  size_t locked_size_ = 0;
  size_t locked_frame_size_ = 0;
  std::array<uint8_t, kMaxLocked> candidate_{};  // a structure seen in the last frames, not yet taken
  size_t candidate_size_ = 0;
  size_t candidate_frame_size_ = 0;
  bool has_layout_ = false;
  int layout_mismatches_ = 0;
  int frames_since_accept_ = 0;
  int value_rejections_ = 0;  // consecutive range/step/counter rejections
  // Previous accepted values.
  bool has_previous_ = false;
  uint32_t counter_ = 0;
  double heading_deg_ = 0, pitch_deg_ = 0, roll_deg_ = 0;
  std::array<double, 4> velocity_mps_{};
  std::array<bool, 4> velocity_valid_{};
  // Xsens: the previous accepted message's IMU values (each only when that message carried it).
  bool has_acceleration_ = false, has_rate_ = false, has_quaternion_ = false;
  std::array<double, 3> acceleration_mps2_{}, rate_radps_{};
  std::array<double, 4> quaternion_{};
};

}  // namespace deepnav
