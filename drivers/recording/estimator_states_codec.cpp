#include "drivers/recording/estimator_states_codec.h"

#include <string>

#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/recording/topics.h"

namespace deepnav {
namespace {

template <std::size_t N>
void writeArray(cdr::CdrWriter& w, const std::array<double, N>& a) {
  for (double v : a) w.f64(v);
}

template <std::size_t N>
bool readArray(cdr::CdrReader& r, std::array<double, N>* a) {
  for (double& v : *a) {
    if (!r.f64(&v)) return false;
  }
  return true;
}

}  // namespace

// Header as sample_codec.cpp writes it: builtin_interfaces/Time (floor division keeps nanosec >= 0).
std::size_t encodeEstimatorStates(const EstimatorStates& e, std::uint8_t* out, std::size_t capacity) {
  cdr::CdrWriter w(out, capacity);
  TimeUs sec = e.t_us / kUsPerS, rem = e.t_us % kUsPerS;
  if (rem < 0) {
    rem += kUsPerS;
    --sec;
  }
  w.i32(static_cast<std::int32_t>(sec));
  w.u32(static_cast<std::uint32_t>(rem * 1000));
  w.string(topicInfo(Topic::kEstimatorStates).frame_id);
  writeArray(w, e.gyro_bias_radps);
  writeArray(w, e.gyro_bias_sigma_radps);
  writeArray(w, e.accel_bias_mps2);
  writeArray(w, e.accel_bias_sigma_mps2);
  w.boolean(e.dvl_scale_estimated);
  w.f64(e.dvl_scale);
  w.f64(e.dvl_scale_sigma);
  w.boolean(e.dvl_misalignment_estimated);
  writeArray(w, e.dvl_misalignment_rad);
  writeArray(w, e.dvl_misalignment_sigma_rad);
  w.boolean(e.heading_bias_estimated);
  w.f64(e.heading_bias_rad);
  w.f64(e.heading_bias_sigma_rad);
  w.boolean(e.heading_deviation_estimated);
  writeArray(w, e.heading_deviation_rad);
  writeArray(w, e.heading_deviation_sigma_rad);
  w.boolean(e.dvl_bias_estimated);
  writeArray(w, e.dvl_bias_mps);
  writeArray(w, e.dvl_bias_sigma_mps);
  return w.ok() ? w.size() : 0;
}

bool decodeEstimatorStates(const std::uint8_t* data, std::size_t size, EstimatorStates* e) {
  cdr::CdrReader r(data, size);
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  std::string frame_id;
  if (!r.i32(&sec) || !r.u32(&nanosec) || !r.string(&frame_id) || nanosec >= 1000000000u) return false;
  const bool ok = readArray(r, &e->gyro_bias_radps) && readArray(r, &e->gyro_bias_sigma_radps) &&
                  readArray(r, &e->accel_bias_mps2) && readArray(r, &e->accel_bias_sigma_mps2) &&
                  r.boolean(&e->dvl_scale_estimated) && r.f64(&e->dvl_scale) && r.f64(&e->dvl_scale_sigma) &&
                  r.boolean(&e->dvl_misalignment_estimated) && readArray(r, &e->dvl_misalignment_rad) &&
                  readArray(r, &e->dvl_misalignment_sigma_rad) && r.boolean(&e->heading_bias_estimated) &&
                  r.f64(&e->heading_bias_rad) && r.f64(&e->heading_bias_sigma_rad) &&
                  r.boolean(&e->heading_deviation_estimated) && readArray(r, &e->heading_deviation_rad) &&
                  readArray(r, &e->heading_deviation_sigma_rad) && r.boolean(&e->dvl_bias_estimated) &&
                  readArray(r, &e->dvl_bias_mps) && readArray(r, &e->dvl_bias_sigma_mps);
  if (!ok) return false;
  e->t_us = static_cast<TimeUs>(sec) * kUsPerS + static_cast<TimeUs>(nanosec / 1000);
  return true;
}

}  // namespace deepnav
