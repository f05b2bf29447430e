#include "drivers/parsers/pd6_sentence.h"

#include <cmath>

#include "drivers/parsers/nmea0183_sentence.h"

namespace deepnav {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

struct Layout {
  const char* tag;
  Pd6Record::Kind kind;
  int numbers;       // numeric fields after the tag
  bool has_status;   // a trailing A/V
};

constexpr Layout kLayouts[] = {
    {"SA", Pd6Record::Kind::kSA, 3, false}, {"TS", Pd6Record::Kind::kTS, 5, false},
    {"WI", Pd6Record::Kind::kWI, 4, true},  {"WS", Pd6Record::Kind::kWS, 3, true},
    {"WE", Pd6Record::Kind::kWE, 3, true},  {"WD", Pd6Record::Kind::kWD, 5, false},
    {"BI", Pd6Record::Kind::kBI, 4, true},  {"BS", Pd6Record::Kind::kBS, 3, true},
    {"BE", Pd6Record::Kind::kBE, 3, true},  {"BD", Pd6Record::Kind::kBD, 5, false},
};

int splitFields(std::string_view s, std::array<std::string_view, 8>* f) {
  int n = 0;
  while (n < 8) {
    const size_t c = s.find(',');
    std::string_view field = s.substr(0, c);
    while (!field.empty() && field.front() == ' ') field.remove_prefix(1);  // PD6 pads fields to fixed width
    while (!field.empty() && field.back() == ' ') field.remove_suffix(1);
    (*f)[n++] = field;
    if (c == std::string_view::npos) return n;
    s = s.substr(c + 1);
  }
  return -1;  // too many fields
}

}  // namespace

const char* pd6KindName(Pd6Record::Kind kind) {
  for (const Layout& l : kLayouts) {
    if (l.kind == kind) return l.tag;
  }
  return "?";
}

bool parsePd6Line(std::string_view line, Pd6Record* out, const char** error) {
  *out = Pd6Record{};
  if (line.size() < 4 || line[0] != ':') return *error = "not a PD6 line", false;
  std::array<std::string_view, 8> f{};
  const int n = splitFields(line.substr(1), &f);
  if (n < 0) return *error = "PD6 line has too many fields", false;
  const Layout* layout = nullptr;
  for (const Layout& l : kLayouts) {
    if (f[0] == l.tag) layout = &l;
  }
  if (layout == nullptr) return *error = "unknown PD6 line", false;
  const int first = layout->kind == Pd6Record::Kind::kTS ? 2 : 1;  // TS: field 1 is the time string
  if (n != first + layout->numbers + (layout->has_status ? 1 : 0)) return *error = "PD6 line has the wrong number of fields", false;
  out->kind = layout->kind;
  out->num_values = layout->numbers;
  for (int i = 0; i < layout->numbers; ++i) {
    double v = 0;
    if (!nmeaDouble(f[first + i], &v)) return *error = "PD6 field is not a number", false;
    out->value[i] = v;
    out->value_valid[i] = v != -32768.0;
  }
  if (layout->has_status) {
    const std::string_view s = f[first + layout->numbers];
    if (s != "A" && s != "V") return *error = "PD6 status is not A or V", false;
    out->status_good = s == "A";
  }
  switch (out->kind) {
    case Pd6Record::Kind::kSA:
      for (int i = 0; i < 3; ++i) out->value[i] *= kDegToRad;
      if (std::abs(out->value[0]) > M_PI || std::abs(out->value[1]) > M_PI || out->value[2] < 0 || out->value[2] > 2 * M_PI) {
        return *error = "PD6 SA attitude out of range", false;
      }
      break;
    case Pd6Record::Kind::kTS:
      if (f[1].size() != 14) return *error = "PD6 TS time is not YYMMDDHHmmsshh", false;
      for (char c : f[1]) {
        if (c < '0' || c > '9') return *error = "PD6 TS time is not YYMMDDHHmmsshh", false;
      }
      out->time = f[1];
      if (out->value[4] < 0 || out->value[4] > 999) return *error = "PD6 TS built-in test result out of range", false;
      out->bit = int(out->value[4]);  // values: salinity ppt, temperature degC, depth m, speed of sound m/s
      out->num_values = 4;
      break;
    case Pd6Record::Kind::kWD:
    case Pd6Record::Kind::kBD:
      break;  // already metres and seconds
    default:
      for (int i = 0; i < out->num_values; ++i) {
        if (out->value_valid[i]) out->value[i] *= 1e-3;  // mm/s -> m/s
      }
  }
  return true;
}

bool Pd6DvlAssembler::add(const Pd6Record& r, TimeUs t_us, DvlSample* sample) {
  if (r.kind == Pd6Record::Kind::kBI) {
    pending_ = DvlSample{};
    pending_.t_us = t_us;
    const bool ok = r.status_good && r.value_valid[0] && r.value_valid[1] && r.value_valid[2];
    if (ok) pending_.v_dvl_mps = Eigen::Vector3d(r.value[1], -r.value[0], r.value[2]);
    if (ok && r.value_valid[3]) pending_.fom_mps = std::abs(r.value[3]);
    pending_.valid = ok;
    have_velocity_ = true;
    return false;
  }
  if (r.kind != Pd6Record::Kind::kBD || !have_velocity_) return false;
  have_velocity_ = false;
  pending_.altitude_m = r.value[3];
  if (r.value[3] <= 0) pending_.valid = false;
  *sample = pending_;
  return true;
}

}  // namespace deepnav
