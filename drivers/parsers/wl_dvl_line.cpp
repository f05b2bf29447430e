#include "drivers/parsers/wl_dvl_protocol.h"

namespace deepnav {

WlDecode parseWlDvlLine(std::string_view line, WlDvlReport* out, const char** error, size_t* junk_bytes) {
  *junk_bytes = 0;
  const auto parse = [&](std::string_view s) {
    return !s.empty() && s[0] == '{' ? parseWlDvlJson(s, out, error) : parseWlDvlSerialLine(s, out, error);
  };
  const WlDecode d = parse(line);
  if (d != WlDecode::kInvalid) return d;
  const size_t at = line.rfind("wr");
  if (at == 0 || at == std::string_view::npos) return d;
  const char* first_error = *error;
  const WlDecode retry = parseWlDvlSerialLine(line.substr(at), out, error);
  if (retry == WlDecode::kInvalid) return *error = first_error, d;
  *junk_bytes = at;
  return retry;
}

}  // namespace deepnav
