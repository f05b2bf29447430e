#include "board/cli/decode_command.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "board/cli/decode_json.h"
#include "drivers/parsers/candump_line.h"
#include "drivers/parsers/frame_pump.h"
#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/n2k_assembler.h"
#include "drivers/parsers/pd0_framer.h"
#include "drivers/parsers/xbus_framer.h"
#include "drivers/parsers/wl_dvl_protocol.h"

namespace deepnav {
namespace {

constexpr const char* kFormats[] = {"pd0", "pd6", "wl-a50", "nmea0183", "n2k-candump", "xsens", nullptr};

struct Counts {
  long messages = 0, bad = 0, ignored = 0;
};

// Bad frames seen after the individual lines stopped: the byte range they cover and why.
struct BadRange {
  static constexpr int kReasons = 4;
  uint64_t first = 0, end = 0;  // stream offsets, end exclusive
  long count = 0, other_reasons = 0;
  const char* reason[kReasons] = {};
  long reason_count[kReasons] = {};
  void add(uint64_t offset, size_t skipped, const char* why);
};

void BadRange::add(uint64_t offset, size_t skipped, const char* why) {
  if (count == 0) first = offset;
  ++count;
  end = std::max(end, offset + std::max<size_t>(skipped, 1));
  for (int i = 0; i < kReasons; ++i) {
    if (reason[i] == nullptr) reason[i] = why;
    if (reason[i] == why || std::strcmp(reason[i], why) == 0) return void(++reason_count[i]);
  }
  ++other_reasons;
}

// Prints each decoded message, and the bad frames: the first kLines one line each, then one line per
// byte range, a range closing each time the bad-frame count doubles, so stderr stays a few KB whatever
// the input (10 MB of noise is about 25 range lines).
class Reporter {
 public:
  static constexpr long kLines = 100;
  explicit Reporter(std::string path) : path_(std::move(path)) {}
  void message(const std::string& json) {
    std::printf("%s\n", json.c_str());
    ++counts_.messages;
  }
  void bad(uint64_t offset, const char* reason, size_t skipped = 0) {
    ++counts_.bad;
    if (counts_.bad <= kLines) return line(offset, reason, skipped);
    range_.add(offset, skipped, reason);
    if (counts_.bad >= 2 * next_range_) flushRange();
  }
  void ignored() { ++counts_.ignored; }
  // Prints the open range and the summary line.
  void finish() {
    flushRange();
    std::fprintf(stderr, "deepnav decode: %s: %ld messages, %ld bad frames skipped, %ld other messages ignored\n", path_.c_str(),
                 counts_.messages, counts_.bad, counts_.ignored);
  }
  const Counts& counts() const { return counts_; }

 private:
  void line(uint64_t offset, const char* reason, size_t skipped) {
    const auto at = static_cast<unsigned long long>(offset);
    if (skipped > 0) {
      std::fprintf(stderr, "deepnav decode: %s: byte %llu: %s (%zu bytes skipped)\n", path_.c_str(), at, reason, skipped);
    } else {
      std::fprintf(stderr, "deepnav decode: %s: byte %llu: %s\n", path_.c_str(), at, reason);
    }
    if (counts_.bad == kLines) {
      std::fprintf(stderr, "deepnav decode: %s: further bad frames are counted per byte range\n", path_.c_str());
    }
  }
  void flushRange() {
    next_range_ = counts_.bad;
    if (range_.count == 0) return;
    std::string why;
    for (int i = 0; i < BadRange::kReasons && range_.reason[i] != nullptr; ++i) {
      why += (i > 0 ? ", " : "") + std::to_string(range_.reason_count[i]) + " " + range_.reason[i];
    }
    if (range_.other_reasons > 0) why += ", " + std::to_string(range_.other_reasons) + " other";
    std::fprintf(stderr, "deepnav decode: %s: bytes %llu-%llu: %ld bad frames (%s)\n", path_.c_str(),
                 static_cast<unsigned long long>(range_.first), static_cast<unsigned long long>(range_.end), range_.count,
                 why.c_str());
    range_ = BadRange{};
  }

  std::string path_;
  Counts counts_;
  BadRange range_;
  long next_range_ = kLines;  // bad-frame count when the open range started
};

// Streams the file through `framer` in 64 KiB reads; calls on_frame for each complete frame. At the end
// of the file the framer frames what it holds without waiting for more.
template <typename Framer>
void pump(std::ifstream& in, Framer* framer, Reporter* rep, const std::function<void(const RawFrame&)>& on_frame) {
  std::vector<char> chunk(65536);
  size_t have = 0, used = 0;
  const auto read_more = [&](Framer* fr) {
    if (used == have) {
      in.read(chunk.data(), std::streamsize(chunk.size()));
      have = size_t(in.gcount());
      used = 0;
      if (have == 0) return false;
    }
    used += fr->push(reinterpret_cast<const uint8_t*>(chunk.data()) + used, have - used);
    return true;
  };
  frameToEnd(framer, read_more, on_frame, [rep](const FrameError& e) { rep->bad(e.offset, e.reason, e.skipped); });
}

// Splits the file at LF or CR (a bare CR ends a line too) in 64 KiB reads; a line longer than
// max_bytes is reported and skipped.
void forEachLine(std::ifstream& in, size_t max_bytes, Reporter* rep,
                 const std::function<void(std::string_view, uint64_t)>& on_line) {
  std::vector<char> chunk(65536);
  std::string line;
  uint64_t offset = 0, line_offset = 0;
  bool too_long = false;
  const auto end_line = [&] {
    if (too_long) rep->bad(line_offset, "line too long", size_t(offset - line_offset));
    if (!too_long && !line.empty()) on_line(line, line_offset);
    line.clear();
    too_long = false;
  };
  while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0) {
    const size_t n = size_t(in.gcount());
    for (size_t i = 0; i < n; ++i, ++offset) {
      const char c = chunk[i];
      if (c == '\n' || c == '\r') {
        end_line();
        line_offset = offset + 1;
      } else if (line.size() < max_bytes) {
        line.push_back(c);
      } else {
        too_long = true;
      }
    }
  }
  end_line();
}

void decodePd0(std::ifstream& in, Reporter* rep) {
  Pd0Framer framer;
  framer.init(65535);
  framer.waitForCertainty();  // a file: waiting for bytes costs no latency
  auto e = std::make_unique<Pd0Ensemble>();
  pump(in, &framer, rep, [&](const RawFrame& f) {
    const char* why = "";
    if (decodePd0Ensemble(f.data, f.size, e.get(), &why)) {
      rep->message(pd0Json(*e, f.offset));
    } else {
      rep->bad(f.offset, why, f.size);
    }
  });
}

void decodeXsens(std::ifstream& in, Reporter* rep) {
  XbusFramer framer;
  framer.init(65535);
  framer.waitForCertainty();  // a file: waiting for bytes costs no latency
  pump(in, &framer, rep, [&](const RawFrame& f) {
    XbusMessage m;
    if (!splitXbusFrame(f.data, f.size, &m)) return rep->bad(f.offset, "Xbus frame inconsistent", f.size);
    if (m.message_id != kXbusMtData2) return rep->message(xsensJson(m.message_id, nullptr, m.payload_size, f.offset));
    XsensMtData2 d;
    const char* why = "";
    if (decodeXsensMtData2(m.payload, m.payload_size, &d, &why)) {
      rep->message(xsensJson(m.message_id, &d, m.payload_size, f.offset));
    } else {
      rep->bad(f.offset, why, f.size);
    }
  });
}

void decodeLines(std::ifstream& in, Reporter* rep, std::string_view starts, std::string_view whole_line_starts,
                 const std::function<void(std::string_view, uint64_t)>& on_line) {
  LineFramer framer;
  framer.init(starts, 4096, true, whole_line_starts);
  pump(in, &framer, rep, [&](const RawFrame& f) { on_line(std::string_view(reinterpret_cast<const char*>(f.data), f.size), f.offset); });
}

void decodeNmea(std::ifstream& in, Reporter* rep) {
  decodeLines(in, rep, "$!", "", [&](std::string_view line, uint64_t offset) {
    Nmea0183Sentence s;
    Nmea0183HeadingRecord r;
    const char* why = "";
    if (!parseNmea0183Sentence(line, false, &s, &why)) return rep->bad(offset, why, line.size());
    const NmeaDecode d = decodeNmea0183Heading(s, &r, &why);
    if (d == NmeaDecode::kInvalid) return rep->bad(offset, why, line.size());
    if (d == NmeaDecode::kOtherSentence) return rep->ignored();
    rep->message(nmeaHeadingJson(r, offset));
  });
}

void decodePd6(std::ifstream& in, Reporter* rep) {
  decodeLines(in, rep, ":", "", [&](std::string_view line, uint64_t offset) {
    Pd6Record r;
    const char* why = "";
    if (!parsePd6Line(line, &r, &why)) return rep->bad(offset, why, line.size());
    rep->message(pd6Json(r, offset));
  });
}

void decodeWaterLinked(std::ifstream& in, Reporter* rep) {
  decodeLines(in, rep, "w{", "{", [&](std::string_view line, uint64_t offset) {
    WlDvlReport r;
    const char* why = "";
    size_t junk = 0;
    const WlDecode d = parseWlDvlLine(line, &r, &why, &junk);
    if (d == WlDecode::kInvalid) return rep->bad(offset, why, line.size());
    if (junk > 0) rep->bad(offset, "bytes before a Water Linked sentence", junk);
    offset += junk;
    if (d == WlDecode::kOtherSentence) return rep->ignored();
    rep->message(wlDvlJson(r, offset));
  });
}

void decodeCandump(std::ifstream& in, Reporter* rep) {
  N2kAssembler assembler;
  forEachLine(in, 4096, rep, [&](std::string_view line, uint64_t here) {
    CanFrame frame;
    double t_s = -1;
    const char* why = "";
    size_t junk = 0;
    const CandumpLine c = parseCandumpLineAfterJunk(line, &frame, &t_s, &why, &junk);
    if (c == CandumpLine::kSkip) return;
    if (c == CandumpLine::kInvalid) return rep->bad(here, why, line.size());
    if (junk > 0) rep->bad(here, "bytes before a candump frame", junk);
    if (t_s == 0) t_s = -1;  // default candump format has no time stamps
    N2kMessage m;
    const N2kAssembler::Result r = assembler.add(frame, &m, &why);
    if (r == N2kAssembler::Result::kError) rep->bad(here + junk, why, line.size() - junk);
    if (r == N2kAssembler::Result::kMessage) rep->message(n2kJson(m, here + junk, t_s));
  });
}

}  // namespace

const char* const* decodeFormats() { return kFormats; }

int runDecodeCommand(const std::string& format, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "deepnav decode: %s: cannot open the file\n", path.c_str());
    return 1;
  }
  Reporter rep(path);
  if (format == "pd0") {
    decodePd0(in, &rep);
  } else if (format == "pd6") {
    decodePd6(in, &rep);
  } else if (format == "wl-a50") {
    decodeWaterLinked(in, &rep);
  } else if (format == "nmea0183") {
    decodeNmea(in, &rep);
  } else if (format == "n2k-candump") {
    decodeCandump(in, &rep);
  } else if (format == "xsens") {
    decodeXsens(in, &rep);
  } else {
    std::fprintf(stderr, "deepnav decode: unknown format '%s' (pd0, pd6, wl-a50, nmea0183, n2k-candump, xsens)\n", format.c_str());
    return 2;
  }
  rep.finish();
  return 0;
}

}  // namespace deepnav
