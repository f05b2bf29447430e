#include "drivers/parsers/candump_line.h"

#include <charconv>

namespace deepnav {
namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string_view nextToken(std::string_view* s) {
  size_t i = 0;
  while (i < s->size() && ((*s)[i] == ' ' || (*s)[i] == '\t')) ++i;
  size_t j = i;
  while (j < s->size() && (*s)[j] != ' ' && (*s)[j] != '\t') ++j;
  const std::string_view token = s->substr(i, j - i);
  *s = s->substr(j);
  return token;
}

bool parseId(std::string_view hex, CanFrame* f) {
  if (hex.empty() || hex.size() > 8) return false;
  uint32_t id = 0;
  for (char c : hex) {
    const int v = hexValue(c);
    if (v < 0) return false;
    id = id * 16 + uint32_t(v);
  }
  f->extended = hex.size() > 3;
  if (f->extended ? id > 0x1FFFFFFF : id > 0x7FF) return false;
  f->id = id;
  return true;
}

bool parseByte(std::string_view hex, uint8_t* b) {
  if (hex.size() != 2 || hexValue(hex[0]) < 0 || hexValue(hex[1]) < 0) return false;
  *b = uint8_t(hexValue(hex[0]) * 16 + hexValue(hex[1]));
  return true;
}

}  // namespace

CandumpLine parseCandumpLine(std::string_view line, CanFrame* f, double* t_s, const char** error) {
  *f = CanFrame{};
  *t_s = 0;
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
  std::string_view rest = line;
  std::string_view tok = nextToken(&rest);
  if (tok.empty() || tok[0] == '#') return CandumpLine::kSkip;
  const auto invalid = [&](const char* why) { return *error = why, CandumpLine::kInvalid; };
  if (tok.front() == '(') {  // log format: (time) iface ID#DATA
    if (tok.back() != ')') return invalid("candump time stamp not closed");
    const auto r = std::from_chars(tok.data() + 1, tok.data() + tok.size() - 1, *t_s);
    if (r.ec != std::errc() || r.ptr != tok.data() + tok.size() - 1) return invalid("candump time stamp is not a number");
    nextToken(&rest);  // interface
    const std::string_view frame = nextToken(&rest);
    const size_t hash = frame.find('#');
    if (hash == std::string_view::npos || !parseId(frame.substr(0, hash), f)) return invalid("candump frame is not ID#DATA");
    std::string_view data = frame.substr(hash + 1);
    if (!data.empty() && data[0] == 'R') {
      f->rtr = true;
      return CandumpLine::kFrame;
    }
    if (data.size() % 2 != 0 || data.size() > 16) return invalid("candump data has an odd or too long hex string");
    f->dlc = uint8_t(data.size() / 2);
    for (int i = 0; i < f->dlc; ++i) {
      if (!parseByte(data.substr(2 * i, 2), &f->data[i])) return invalid("candump data is not hex");
    }
    return CandumpLine::kFrame;
  }
  // Default format: iface ID [n] b0 b1 ...
  if (!parseId(nextToken(&rest), f)) return invalid("candump identifier is not hex");
  const std::string_view dlc = nextToken(&rest);
  if (dlc.size() != 3 || dlc[0] != '[' || dlc[2] != ']' || dlc[1] < '0' || dlc[1] > '8') return invalid("candump length is not [0-8]");
  f->dlc = uint8_t(dlc[1] - '0');
  for (int i = 0; i < f->dlc; ++i) {
    if (!parseByte(nextToken(&rest), &f->data[i])) return invalid("candump data byte is not two hex digits");
  }
  if (!nextToken(&rest).empty()) return invalid("candump line has more bytes than its length");
  return CandumpLine::kFrame;
}

}  // namespace deepnav
