#include <cmath>

#include "drivers/parsers/json_scan.h"
#include "drivers/parsers/wl_dvl_protocol.h"

namespace deepnav {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

bool num(std::string_view o, std::string_view key, double* v) {
  std::string_view text;
  return JsonScan::member(o, key, &text) && JsonScan::number(text, v);
}

bool transducers(std::string_view array, WlDvlReport* out) {
  std::string_view rest, element;
  if (!JsonScan::arrayBegin(array, &rest)) return false;
  while (JsonScan::arrayNext(&rest, &element)) {
    if (out->num_transducers == int(out->transducers.size())) return false;
    WlDvlReport::Transducer& t = out->transducers[out->num_transducers++];
    double id = -1;
    std::string_view valid;
    if (!num(element, "id", &id) || id < 0 || id > 3 || !num(element, "velocity", &t.velocity_mps) ||
        !num(element, "distance", &t.distance_m) || !num(element, "rssi", &t.rssi_dbm) || !num(element, "nsd", &t.nsd_dbm) ||
        !JsonScan::member(element, "beam_valid", &valid) || !JsonScan::boolean(valid, &t.beam_valid)) {
      return false;
    }
    t.id = int(id);
  }
  return true;
}

bool covariance(std::string_view rows, WlDvlReport* out) {
  std::string_view rest, row, row_rest, cell;
  if (!JsonScan::arrayBegin(rows, &rest)) return false;
  int n = 0;
  while (JsonScan::arrayNext(&rest, &row)) {
    if (!JsonScan::arrayBegin(row, &row_rest)) return false;
    while (JsonScan::arrayNext(&row_rest, &cell)) {
      if (n == 9 || !JsonScan::number(cell, &out->covariance_m2ps2[n++])) return false;
    }
  }
  return n == 9;
}

}  // namespace

WlDecode parseWlDvlJson(std::string_view text, WlDvlReport* out, const char** error) {
  *out = WlDvlReport{};
  const auto invalid = [&](const char* why) { return *error = why, WlDecode::kInvalid; };
  if (!JsonScan::isObject(text)) return invalid("not a JSON object");
  std::string_view type_text, type;
  if (!JsonScan::member(text, "type", &type_text) || !JsonScan::string(type_text, &type)) return invalid("JSON report without \"type\"");
  double status = 0;
  if (type == "velocity") {
    std::string_view valid, array;
    double tov = 0, tot = 0;
    if (!num(text, "vx", &out->vx_mps) || !num(text, "vy", &out->vy_mps) || !num(text, "vz", &out->vz_mps) ||
        !num(text, "fom", &out->fom_mps) || !num(text, "altitude", &out->altitude_m) ||
        !JsonScan::member(text, "velocity_valid", &valid) || !JsonScan::boolean(valid, &out->velocity_valid) ||
        !num(text, "status", &status)) {
      return invalid("JSON velocity report misses a field");
    }
    num(text, "time", &out->time_since_last_ms);
    if (num(text, "time_of_validity", &tov) && !wlMicros(tov, &out->time_of_validity_us)) return invalid("JSON time_of_validity out of range");
    if (num(text, "time_of_transmission", &tot) && !wlMicros(tot, &out->time_of_transmission_us)) {
      return invalid("JSON time_of_transmission out of range");
    }
    if (JsonScan::member(text, "covariance", &array)) {
      if (!covariance(array, out)) return invalid("JSON covariance is not a 3x3 array");
      out->has_covariance = true;
    }
    if (JsonScan::member(text, "transducers", &array) && !transducers(array, out)) return invalid("JSON transducers are malformed");
    out->kind = WlDvlReport::Kind::kVelocity;
    if (!wlStatusValue(status, &out->status)) return invalid("JSON status is not a small integer");
    return WlDecode::kDecoded;
  }
  if (type == "position_local") {
    double roll = 0, pitch = 0, yaw = 0;
    if (!num(text, "ts", &out->ts_s) || !num(text, "x", &out->x_m) || !num(text, "y", &out->y_m) ||
        !num(text, "z", &out->z_m) || !num(text, "std", &out->pos_std_m) || !num(text, "roll", &roll) ||
        !num(text, "pitch", &pitch) || !num(text, "yaw", &yaw) || !num(text, "status", &status)) {
      return invalid("JSON position_local report misses a field");
    }
    out->kind = WlDvlReport::Kind::kDeadReckoning;
    out->roll_rad = roll * kDegToRad, out->pitch_rad = pitch * kDegToRad, out->yaw_rad = yaw * kDegToRad;
    if (!wlStatusValue(status, &out->status)) return invalid("JSON status is not a small integer");
    return WlDecode::kDecoded;
  }
  return WlDecode::kOtherSentence;
}

}  // namespace deepnav
