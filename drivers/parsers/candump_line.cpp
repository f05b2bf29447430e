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

// Start of the interface token two tokens before the last "[" (default format), or npos.
size_t defaultFormatStart(std::string_view line) {
  size_t i = line.rfind('[');
  if (i == std::string_view::npos) return i;
  for (int token = 0; token < 2; ++token) {
    while (i > 0 && (line[i - 1] == ' ' || line[i - 1] == '\t')) --i;
    if (i == 0) return std::string_view::npos;
    while (i > 0 && line[i - 1] != ' ' && line[i - 1] != '\t') --i;
  }
  return i;
}

size_t afterLastStrayByte(std::string_view line) {
  for (size_t i = line.size(); i > 0; --i) {
    const auto c = uint8_t(line[i - 1]);
    if ((c < 0x20 && c != '\t' && c != '\r') || c >= 0x7F) return i;
  }
  return std::string_view::npos;
}

}  // namespace

CandumpLine parseCandumpLineAfterJunk(std::string_view line, CanFrame* f, double* t_s, const char** error,
                                      size_t* junk_bytes) {
  *junk_bytes = 0;
  const CandumpLine c = parseCandumpLine(line, f, t_s, error);
  if (c == CandumpLine::kFrame || (c == CandumpLine::kSkip && line.find('#') == std::string_view::npos)) return c;
  // A comment ('#' first) may be a stray '#' glued before a frame: it is searched like a bad line.
  const char* first_error = *error;
  for (const size_t at : {afterLastStrayByte(line), line.rfind('('), defaultFormatStart(line)}) {
    if (at == 0 || at >= line.size()) continue;
    if (parseCandumpLine(line.substr(at), f, t_s, error) == CandumpLine::kFrame) return *junk_bytes = at, CandumpLine::kFrame;
  }
  *error = first_error;
  return c;
}

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
    // Nothing follows the frame in the log format: text after it is another line glued on.
    if (!nextToken(&rest).empty()) return invalid("candump log line has text after the frame");
    std::string_view data = frame.substr(hash + 1);
    if (!data.empty() && data[0] == 'R') {
      if (data.size() > 2 || (data.size() == 2 && (data[1] < '0' || data[1] > '8'))) return invalid("candump remote frame is not R or R0-R8");
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
