#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace deepnav {

// Fields of one Teledyne RDI PD0 ensemble, as stored (raw integers; units in the names). Layout from
// the RDI "WorkHorse Commands and Output Data Format" manual: header 0x7F7F, fixed leader 0x0000,
// variable leader 0x0080, velocity 0x0100, correlation 0x0200, echo intensity 0x0300, percent good
// 0x0400, bottom track 0x0600. Unknown data types are skipped.
struct Pd0FixedLeader {
  uint8_t firmware_version = 0;
  uint8_t firmware_revision = 0;
  uint16_t system_config = 0;     // bits 0-2 frequency, 3 convex, 7 up-facing, 8-9 beam angle
  uint8_t lag_length = 0;
  uint8_t num_beams = 0;
  uint8_t num_cells = 0;
  uint16_t pings_per_ensemble = 0;
  uint16_t cell_length_cm = 0;
  uint16_t blank_after_transmit_cm = 0;
  uint8_t profiling_mode = 0;
  uint8_t low_corr_threshold = 0;
  uint8_t code_repetitions = 0;
  uint8_t percent_good_min = 0;
  uint16_t error_velocity_max_mmps = 0;
  uint8_t coord_transform = 0;    // EX: bits 3-4 frame (0 beam, 1 instrument, 2 ship, 3 earth)
  int16_t heading_alignment_cdeg = 0;
  int16_t heading_bias_cdeg = 0;
  uint8_t sensor_source = 0;
  uint8_t sensors_available = 0;
  uint16_t bin1_distance_cm = 0;
  uint16_t transmit_pulse_length_cm = 0;
  uint8_t ref_layer_start_cell = 0;
  uint8_t ref_layer_end_cell = 0;
  uint8_t false_target_threshold = 0;
  uint16_t transmit_lag_distance_cm = 0;
  uint32_t serial_number = 0;     // bytes 54-57 (0 on firmware that does not send them)
  double beamAngleDeg() const;    // from system_config bits 8-9
  int frame() const { return (coord_transform >> 3) & 3; }
  bool upFacing() const { return (system_config & 0x80) != 0; }
};

struct Pd0VariableLeader {
  uint32_t ensemble_number = 0;   // including the roll-over MSB (byte 11)
  std::array<uint8_t, 7> rtc{};   // year (2 digits), month, day, hour, minute, second, hundredths
  uint16_t bit_result = 0;
  uint16_t speed_of_sound_mps = 0;
  uint16_t transducer_depth_dm = 0;
  uint16_t heading_cdeg = 0;
  int16_t pitch_cdeg = 0;
  int16_t roll_cdeg = 0;
  uint16_t salinity_ppt = 0;
  int16_t temperature_cdegc = 0;
  uint8_t mpt_minutes = 0;
  uint8_t mpt_seconds = 0;
  uint8_t mpt_hundredths = 0;
  uint8_t heading_std_deg = 0;
  uint8_t pitch_std_ddeg = 0;     // 0.1 deg
  uint8_t roll_std_ddeg = 0;
  std::array<uint8_t, 8> adc{};
  uint32_t error_status = 0;
  bool has_pressure = false;      // bytes 48-55 present
  uint32_t pressure_dapa = 0;     // deca-pascals
  uint32_t pressure_variance_dapa = 0;
};

struct Pd0BottomTrack {
  uint16_t pings_per_ensemble = 0;
  uint16_t delay_before_reacquire = 0;
  uint8_t corr_mag_min = 0;
  uint8_t eval_amp_min = 0;
  uint8_t percent_good_min = 0;
  uint8_t mode = 0;
  uint16_t error_velocity_max_mmps = 0;
  std::array<uint32_t, 4> range_cm{};        // LSB (bytes 16-23) + MSB (bytes 77-80 when present)
  std::array<int16_t, 4> velocity_mmps{};    // in the EX frame; -32768 = bad
  std::array<uint8_t, 4> correlation{};
  std::array<uint8_t, 4> eval_amplitude{};
  std::array<uint8_t, 4> percent_good{};
};

struct Pd0Ensemble {
  static constexpr int kMaxCells = 255;
  static constexpr int16_t kBadVelocity = -32768;
  uint8_t num_data_types = 0;
  bool has_fixed_leader = false;
  bool has_variable_leader = false;
  bool has_velocity = false;
  bool has_correlation = false;
  bool has_echo_intensity = false;
  bool has_percent_good = false;
  bool has_bottom_track = false;
  int num_beams = 4;  // profile arrays hold 4 beams per cell
  int num_cells = 0;
  Pd0FixedLeader fixed;
  Pd0VariableLeader variable;
  Pd0BottomTrack bottom_track;
  std::array<std::array<int16_t, 4>, kMaxCells> velocity_mmps{};
  std::array<std::array<uint8_t, 4>, kMaxCells> correlation{};
  std::array<std::array<uint8_t, 4>, kMaxCells> echo_intensity{};
  std::array<std::array<uint8_t, 4>, kMaxCells> percent_good{};
};

// Decodes one checksum-verified ensemble (header to checksum included). Every offset is checked
// against the ensemble and every data type against its own extent; on failure *error names the
// first problem and false is returned.
bool decodePd0Ensemble(const uint8_t* data, size_t size, Pd0Ensemble* out, const char** error);

}  // namespace deepnav
