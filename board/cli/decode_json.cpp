#include "board/cli/decode_json.h"

#include <cmath>
#include <cstdio>

#include "drivers/parsers/n2k_heading_pgns.h"
#include "drivers/parsers/pd0_dvl_sample.h"

namespace deepnav {
namespace {

constexpr double kCdegToRad = M_PI / 18000.0;

// Builds one flat JSON line; keys are written as given (no escaping needed for our fixed keys).
class JsonLine {
 public:
  JsonLine& key(const char* k) {
    out_ += first_ ? "{\"" : ", \"";
    out_ += k;
    out_ += "\": ";
    first_ = false;
    return *this;
  }
  JsonLine& num(const char* k, double v) { return key(k).raw(number(v)); }
  JsonLine& integer(const char* k, int64_t v) { return key(k).raw(std::to_string(v)); }
  JsonLine& boolean(const char* k, bool v) { return key(k).raw(v ? "true" : "false"); }
  JsonLine& str(const char* k, const std::string& v) { return key(k).raw("\"" + v + "\""); }
  JsonLine& optional(const char* k, bool has, double v) { return key(k).raw(has ? number(v) : "null"); }
  template <typename It, typename F>
  JsonLine& array(const char* k, It begin, It end, F format) {
    std::string a = "[";
    for (It it = begin; it != end; ++it) a += (it == begin ? "" : ", ") + format(*it);
    return key(k).raw(a + "]");
  }
  JsonLine& raw(const std::string& v) {
    out_ += v;
    return *this;
  }
  std::string done() { return out_ + "}"; }
  static std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
  }

 private:
  std::string out_;
  bool first_ = true;
};

std::string mmps(int16_t v) { return v == Pd0Ensemble::kBadVelocity ? "null" : JsonLine::number(v * 1e-3); }

const char* pd0FrameName(int frame) {
  static const char* names[] = {"beam", "instrument", "ship", "earth"};
  return names[frame & 3];
}

}  // namespace

std::string pd0Json(const Pd0Ensemble& e, uint64_t offset) {
  JsonLine j;
  j.str("format", "pd0").integer("offset", int64_t(offset));
  if (e.has_variable_leader) {
    const Pd0VariableLeader& v = e.variable;
    char time[40];
    std::snprintf(time, sizeof time, "20%02u-%02u-%02uT%02u:%02u:%02u.%02u", v.rtc[0], v.rtc[1], v.rtc[2], v.rtc[3], v.rtc[4],
                  v.rtc[5], v.rtc[6]);
    j.integer("ensemble", v.ensemble_number).str("time", time);
    j.num("heading_rad", v.heading_cdeg * kCdegToRad).num("pitch_rad", v.pitch_cdeg * kCdegToRad);
    j.num("roll_rad", v.roll_cdeg * kCdegToRad).num("temperature_degc", v.temperature_cdegc * 0.01);
    j.num("salinity_ppt", v.salinity_ppt).num("speed_of_sound_mps", v.speed_of_sound_mps);
    j.num("transducer_depth_m", v.transducer_depth_dm * 0.1).integer("bit_result", v.bit_result);
    if (v.has_pressure) j.num("pressure_pa", v.pressure_dapa * 10.0);
  }
  if (e.has_fixed_leader) {
    j.integer("serial_number", e.fixed.serial_number).str("frame", pd0FrameName(e.fixed.frame()));
    j.num("beam_angle_rad", e.fixed.beamAngleDeg() * M_PI / 180).integer("cells", e.num_cells);
    j.num("cell_length_m", e.fixed.cell_length_cm * 0.01).num("bin1_distance_m", e.fixed.bin1_distance_cm * 0.01);
  }
  if (e.has_bottom_track) {
    const Pd0BottomTrack& b = e.bottom_track;
    j.array("bt_velocity_mps", b.velocity_mmps.begin(), b.velocity_mmps.end(), mmps);
    j.array("bt_range_m", b.range_cm.begin(), b.range_cm.end(), [](uint32_t r) { return JsonLine::number(r * 0.01); });
    j.array("bt_percent_good", b.percent_good.begin(), b.percent_good.end(), [](uint8_t p) { return std::to_string(p); });
    DvlSample s;
    if (pd0ToDvlSample(e, 0, &s)) {
      j.boolean("dvl_valid", s.valid);
      j.array("v_dvl_flu_mps", s.v_dvl_mps.data(), s.v_dvl_mps.data() + 3, [](double x) { return JsonLine::number(x); });
      j.num("altitude_m", s.altitude_m);
    }
  }
  if (e.has_velocity) {
    std::string rows = "[";
    for (int c = 0; c < e.num_cells; ++c) {
      rows += c ? ", [" : "[";
      for (int b = 0; b < 4; ++b) rows += (b ? ", " : "") + mmps(e.velocity_mmps[c][b]);
      rows += "]";
    }
    j.key("water_velocity_mps").raw(rows + "]");
  }
  return j.done();
}

std::string pd6Json(const Pd6Record& r, uint64_t offset) {
  static const char* kNames[][5] = {
      {"pitch_rad", "roll_rad", "heading_rad", "", ""},
      {"salinity_ppt", "temperature_degc", "transducer_depth_m", "speed_of_sound_mps", ""},
      {"x_mps", "y_mps", "z_mps", "error_mps", ""},
      {"transverse_mps", "longitudinal_mps", "normal_mps", "", ""},
      {"east_mps", "north_mps", "up_mps", "", ""},
      {"east_m", "north_m", "up_m", "range_to_bottom_m", "time_since_good_s"},
  };
  const int kind = int(r.kind);
  const int layout = kind <= 1 ? kind : 2 + (kind - 2) % 4;  // W* and B* lines share layouts
  JsonLine j;
  j.str("format", "pd6").integer("offset", int64_t(offset)).str("type", pd6KindName(r.kind));
  if (r.kind == Pd6Record::Kind::kTS) j.str("time", std::string(r.time)).integer("bit", r.bit);
  for (int i = 0; i < r.num_values; ++i) j.optional(kNames[layout][i], r.value_valid[i], r.value[i]);
  const bool velocity = layout >= 2 && layout <= 4;
  if (velocity) j.boolean("status_good", r.status_good);
  return j.done();
}

std::string wlDvlJson(const WlDvlReport& r, uint64_t offset) {
  JsonLine j;
  j.str("format", "wl-a50").integer("offset", int64_t(offset));
  const auto num = [](double x) { return JsonLine::number(x); };
  if (r.kind == WlDvlReport::Kind::kVelocity) {
    j.str("type", "velocity").num("vx_mps", r.vx_mps).num("vy_mps", r.vy_mps).num("vz_mps", r.vz_mps);
    j.boolean("velocity_valid", r.velocity_valid).num("altitude_m", r.altitude_m).num("fom_mps", r.fom_mps);
    if (r.has_covariance) j.array("covariance_m2ps2", r.covariance_m2ps2.begin(), r.covariance_m2ps2.end(), num);
    j.num("time_of_validity_s", r.time_of_validity_us * 1e-6).num("time_of_transmission_s", r.time_of_transmission_us * 1e-6);
    j.num("time_since_last_s", r.time_since_last_ms * 1e-3).integer("status", r.status);
  } else if (r.kind == WlDvlReport::Kind::kDeadReckoning) {
    j.str("type", "position_local").num("ts_s", r.ts_s).num("x_m", r.x_m).num("y_m", r.y_m).num("z_m", r.z_m);
    j.num("pos_std_m", r.pos_std_m).num("roll_rad", r.roll_rad).num("pitch_rad", r.pitch_rad).num("yaw_rad", r.yaw_rad);
    j.integer("status", r.status);
  } else {
    j.str("type", "transducer");
  }
  if (r.num_transducers > 0) {
    std::string a = "[";
    for (int i = 0; i < r.num_transducers; ++i) {
      const auto& t = r.transducers[i];
      JsonLine o;
      o.integer("id", t.id).num("velocity_mps", t.velocity_mps).num("distance_m", t.distance_m);
      o.num("rssi_dbm", t.rssi_dbm).num("nsd_dbm", t.nsd_dbm).boolean("beam_valid", t.beam_valid);
      a += (i ? ", " : "") + o.done();
    }
    j.key("transducers").raw(a + "]");
  }
  return j.done();
}

std::string nmeaHeadingJson(const Nmea0183HeadingRecord& r, uint64_t offset) {
  static const char* kTypes[] = {"HDT", "HDM", "HDG", "ROT"};
  JsonLine j;
  j.str("format", "nmea0183").integer("offset", int64_t(offset)).str("talker", std::string(r.talker));
  j.str("sentence", kTypes[int(r.kind)]);
  if (r.kind == Nmea0183HeadingRecord::Kind::kRot) {
    j.optional("rate_radps", r.has_rate, r.rate_radps).boolean("valid", r.rate_valid);
    return j.done();
  }
  j.optional("heading_rad", r.has_heading, r.heading_rad);
  if (r.kind == Nmea0183HeadingRecord::Kind::kHdg) {
    j.optional("deviation_rad", r.has_deviation, r.deviation_rad).optional("variation_rad", r.has_variation, r.variation_rad);
  }
  j.str("reference", r.kind == Nmea0183HeadingRecord::Kind::kHdt ? "true" : "magnetic");
  return j.done();
}

std::string n2kJson(const N2kMessage& m, uint64_t offset, double t_s) {
  JsonLine j;
  j.str("format", "n2k").integer("offset", int64_t(offset));
  if (t_s >= 0) j.num("t_s", t_s);
  j.integer("prio", m.priority).integer("src", m.source).integer("dst", m.destination).integer("pgn", m.pgn);
  const char* why = "";
  if (m.pgn == kPgnVesselHeading) {
    N2kVesselHeading h;
    if (decodeN2kVesselHeading(m, &h, &why)) {
      static const char* kRef[] = {"true", "magnetic", "error", "null"};
      j.str("description", "Vessel Heading").integer("sid", h.sid).optional("heading_rad", h.has_heading, h.heading_rad);
      j.optional("deviation_rad", h.has_deviation, h.deviation_rad).optional("variation_rad", h.has_variation, h.variation_rad);
      return j.str("reference", kRef[h.reference]).done();
    }
  } else if (m.pgn == kPgnRateOfTurn) {
    N2kRateOfTurn r;
    if (decodeN2kRateOfTurn(m, &r, &why)) {
      return j.str("description", "Rate of Turn").integer("sid", r.sid).optional("rate_radps", r.has_rate, r.rate_radps).done();
    }
  } else if (m.pgn == kPgnAttitude) {
    N2kAttitude a;
    if (decodeN2kAttitude(m, &a, &why)) {
      j.str("description", "Attitude").integer("sid", a.sid).optional("yaw_rad", a.has_yaw, a.yaw_rad);
      return j.optional("pitch_rad", a.has_pitch, a.pitch_rad).optional("roll_rad", a.has_roll, a.roll_rad).done();
    }
  }
  std::string hex;
  char b[4];
  for (size_t i = 0; i < m.size; ++i) {
    std::snprintf(b, sizeof b, i ? " %02X" : "%02X", m.data[i]);
    hex += b;
  }
  return j.str("data", hex).done();
}

std::string xsensJson(uint8_t message_id, const XsensMtData2* d, size_t payload_bytes, uint64_t offset) {
  JsonLine j;
  j.str("format", "xsens").integer("offset", int64_t(offset)).integer("message_id", message_id);
  if (d == nullptr) return j.integer("payload_bytes", int64_t(payload_bytes)).done();
  const auto num = [](double x) { return JsonLine::number(x); };
  if (d->has_packet_counter) j.integer("packet_counter", d->packet_counter);
  if (d->has_sample_time_fine) j.num("sample_time_fine_s", d->sample_time_fine * 1e-4);
  static const char* kFrames[] = {"ENU", "NED", "NWU", "?"};
  if (d->has_quaternion) {
    j.array("quaternion_wxyz", d->quaternion.begin(), d->quaternion.end(), num).str("quaternion_frame", kFrames[d->quaternion_frame & 3]);
  }
  if (d->has_euler) j.array("euler_rpy_rad", d->euler_rad.begin(), d->euler_rad.end(), num);
  if (d->has_acceleration) j.array("acceleration_mps2", d->acceleration_mps2.begin(), d->acceleration_mps2.end(), num);
  if (d->has_rate_of_turn) j.array("rate_of_turn_radps", d->rate_of_turn_radps.begin(), d->rate_of_turn_radps.end(), num);
  if (d->has_magnetic_field) j.array("magnetic_field", d->magnetic_field.begin(), d->magnetic_field.end(), num);
  if (d->has_status_word) j.integer("status_word", d->status_word);
  return j.done();
}

}  // namespace deepnav
