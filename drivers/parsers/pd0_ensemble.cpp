#include "drivers/parsers/pd0_ensemble.h"

#include <algorithm>

#include "drivers/parsers/byte_order.h"

namespace deepnav {
namespace {

constexpr uint16_t kFixedLeaderId = 0x0000;
constexpr uint16_t kVariableLeaderId = 0x0080;
constexpr uint16_t kVelocityId = 0x0100;
constexpr uint16_t kCorrelationId = 0x0200;
constexpr uint16_t kEchoIntensityId = 0x0300;
constexpr uint16_t kPercentGoodId = 0x0400;
constexpr uint16_t kBottomTrackId = 0x0600;

bool decodeFixedLeader(const uint8_t* p, size_t n, Pd0FixedLeader* f) {
  if (n < 42) return false;
  f->firmware_version = p[2];
  f->firmware_revision = p[3];
  f->system_config = readLe16(p + 4);
  f->lag_length = p[7];
  f->num_beams = p[8];
  f->num_cells = p[9];
  f->pings_per_ensemble = readLe16(p + 10);
  f->cell_length_cm = readLe16(p + 12);
  f->blank_after_transmit_cm = readLe16(p + 14);
  f->profiling_mode = p[16];
  f->low_corr_threshold = p[17];
  f->code_repetitions = p[18];
  f->percent_good_min = p[19];
  f->error_velocity_max_mmps = readLe16(p + 20);
  f->coord_transform = p[25];
  f->heading_alignment_cdeg = readLeI16(p + 26);
  f->heading_bias_cdeg = readLeI16(p + 28);
  f->sensor_source = p[30];
  f->sensors_available = p[31];
  f->bin1_distance_cm = readLe16(p + 32);
  f->transmit_pulse_length_cm = readLe16(p + 34);
  f->ref_layer_start_cell = p[36];
  f->ref_layer_end_cell = p[37];
  f->false_target_threshold = p[38];
  f->transmit_lag_distance_cm = readLe16(p + 40);
  if (n >= 58) f->serial_number = readLe32(p + 54);
  return true;
}

bool decodeVariableLeader(const uint8_t* p, size_t n, Pd0VariableLeader* v) {
  if (n < 34) return false;
  v->ensemble_number = readLe16(p + 2) | (uint32_t(p[11]) << 16);
  std::copy(p + 4, p + 11, v->rtc.begin());
  v->bit_result = readLe16(p + 12);
  v->speed_of_sound_mps = readLe16(p + 14);
  v->transducer_depth_dm = readLe16(p + 16);
  v->heading_cdeg = readLe16(p + 18);
  v->pitch_cdeg = readLeI16(p + 20);
  v->roll_cdeg = readLeI16(p + 22);
  v->salinity_ppt = readLe16(p + 24);
  v->temperature_cdegc = readLeI16(p + 26);
  v->mpt_minutes = p[28];
  v->mpt_seconds = p[29];
  v->mpt_hundredths = p[30];
  v->heading_std_deg = p[31];
  v->pitch_std_ddeg = p[32];
  v->roll_std_ddeg = p[33];
  if (n >= 42) std::copy(p + 34, p + 42, v->adc.begin());
  if (n >= 46) v->error_status = readLe32(p + 42);
  v->has_pressure = n >= 56;
  if (v->has_pressure) {
    v->pressure_dapa = readLe32(p + 48);
    v->pressure_variance_dapa = readLe32(p + 52);
  }
  return true;
}

bool decodeBottomTrack(const uint8_t* p, size_t n, Pd0BottomTrack* b) {
  if (n < 44) return false;
  b->pings_per_ensemble = readLe16(p + 2);
  b->delay_before_reacquire = readLe16(p + 4);
  b->corr_mag_min = p[6];
  b->eval_amp_min = p[7];
  b->percent_good_min = p[8];
  b->mode = p[9];
  b->error_velocity_max_mmps = readLe16(p + 10);
  for (int i = 0; i < 4; ++i) {
    b->range_cm[i] = readLe16(p + 16 + 2 * i);
    if (n >= 81) b->range_cm[i] |= uint32_t(p[77 + i]) << 16;
    b->velocity_mmps[i] = readLeI16(p + 24 + 2 * i);
    b->correlation[i] = p[32 + i];
    b->eval_amplitude[i] = p[36 + i];
    b->percent_good[i] = p[40 + i];
  }
  return true;
}

// A profile data type: 2-byte ID, then cells x 4 beams of `width` bytes.
template <typename T>
bool decodeProfile(const uint8_t* p, size_t n, int cells, std::array<std::array<T, 4>, Pd0Ensemble::kMaxCells>* out) {
  const size_t width = sizeof(T);
  if (n < 2 + size_t(cells) * 4 * width) return false;
  for (int c = 0; c < cells; ++c) {
    for (int b = 0; b < 4; ++b) {
      const uint8_t* q = p + 2 + (size_t(c) * 4 + b) * width;
      (*out)[c][b] = width == 2 ? T(readLeI16(q)) : T(q[0]);
    }
  }
  return true;
}

}  // namespace

double Pd0FixedLeader::beamAngleDeg() const {
  switch ((system_config >> 8) & 3) {
    case 0: return 15.0;
    case 1: return 20.0;
    case 2: return 30.0;
    default: return 25.0;  // "other": Explorer/Pathfinder-class heads use 25 or 30 deg; 25 is documented
  }
}

bool decodePd0Ensemble(const uint8_t* d, size_t size, Pd0Ensemble* out, const char** error) {
  *out = Pd0Ensemble{};
  if (size < 8 || d[0] != 0x7F || d[1] != 0x7F) return *error = "not a PD0 ensemble", false;
  const size_t length = readLe16(d + 2);  // checksum excluded
  if (length + 2 != size) return *error = "PD0 length field disagrees with the frame size", false;
  out->num_data_types = d[5];
  const size_t n_types = d[5];
  if (6 + 2 * n_types > length) return *error = "PD0 data type table runs past the ensemble", false;
  // Each data type extends to the next offset (or to the checksum); offsets must increase.
  for (size_t i = 0; i < n_types; ++i) {
    const size_t begin = readLe16(d + 6 + 2 * i);
    const size_t end = i + 1 < n_types ? readLe16(d + 8 + 2 * i) : length;
    if (begin < 6 + 2 * n_types || begin + 2 > end || end > length) {
      return *error = "PD0 data type offset out of range", false;
    }
    const uint8_t* p = d + begin;
    const size_t n = end - begin;
    switch (readLe16(p)) {
      case kFixedLeaderId:
        if (!decodeFixedLeader(p, n, &out->fixed)) return *error = "PD0 fixed leader too short", false;
        if (out->fixed.num_beams != 4) return *error = "PD0 beam count is not 4 (unsupported)", false;
        out->has_fixed_leader = true;
        out->num_cells = std::min<int>(out->fixed.num_cells, Pd0Ensemble::kMaxCells);
        break;
      case kVariableLeaderId:
        if (!decodeVariableLeader(p, n, &out->variable)) return *error = "PD0 variable leader too short", false;
        out->has_variable_leader = true;
        break;
      case kBottomTrackId:
        if (!decodeBottomTrack(p, n, &out->bottom_track)) return *error = "PD0 bottom track too short", false;
        out->has_bottom_track = true;
        break;
      case kVelocityId:
        if (!out->has_fixed_leader) return *error = "PD0 velocity before the fixed leader", false;
        if (!decodeProfile(p, n, out->num_cells, &out->velocity_mmps)) return *error = "PD0 velocity too short", false;
        out->has_velocity = true;
        break;
      case kCorrelationId:
        if (!out->has_fixed_leader) return *error = "PD0 correlation before the fixed leader", false;
        if (!decodeProfile(p, n, out->num_cells, &out->correlation)) return *error = "PD0 correlation too short", false;
        out->has_correlation = true;
        break;
      case kEchoIntensityId:
        if (!out->has_fixed_leader) return *error = "PD0 echo intensity before the fixed leader", false;
        if (!decodeProfile(p, n, out->num_cells, &out->echo_intensity)) return *error = "PD0 echo intensity too short", false;
        out->has_echo_intensity = true;
        break;
      case kPercentGoodId:
        if (!out->has_fixed_leader) return *error = "PD0 percent good before the fixed leader", false;
        if (!decodeProfile(p, n, out->num_cells, &out->percent_good)) return *error = "PD0 percent good too short", false;
        out->has_percent_good = true;
        break;
      default:
        break;  // other data types (e.g. status, navigation) are not used
    }
  }
  return true;
}

}  // namespace deepnav
