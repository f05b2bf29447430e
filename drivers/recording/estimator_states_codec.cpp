#include "drivers/recording/estimator_states_codec.h"

#include <string>

#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/recording/stamped_header.h"
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

std::size_t encodeEstimatorStates(const EstimatorStates& e, std::uint8_t* out, std::size_t capacity) {
  cdr::CdrWriter w(out, capacity);
  writeStampedHeader(w, e.t_us, Topic::kEstimatorStates);
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
  TimeUs t_us = 0;
  if (!readStampedHeader(r, &t_us)) return false;
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
  e->t_us = t_us;
  return true;
}

}  // namespace deepnav
