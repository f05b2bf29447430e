#include "board/cli/decode_command.h"

#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "board/cli/decode_json.h"
#include "drivers/parsers/candump_line.h"
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

class Reporter {
 public:
  explicit Reporter(std::string path) : path_(std::move(path)) {}
  void message(const std::string& json) {
    std::printf("%s\n", json.c_str());
    ++counts_.messages;
  }
  void bad(uint64_t offset, const char* reason, size_t skipped = 0) {
    if (skipped > 0) {
      std::fprintf(stderr, "deepnav decode: %s: byte %llu: %s (%zu bytes skipped)\n", path_.c_str(),
                   static_cast<unsigned long long>(offset), reason, skipped);
    } else {
      std::fprintf(stderr, "deepnav decode: %s: byte %llu: %s\n", path_.c_str(), static_cast<unsigned long long>(offset), reason);
    }
    ++counts_.bad;
  }
  void ignored() { ++counts_.ignored; }
  const Counts& counts() const { return counts_; }

 private:
  std::string path_;
  Counts counts_;
};

// Streams the file through `framer` in 64 KiB reads; calls on_frame for each complete frame.
template <typename Framer>
bool pump(std::ifstream& in, Framer* framer, Reporter* rep, const std::function<void(const RawFrame&)>& on_frame) {
  std::vector<char> chunk(65536);
  size_t have = 0, used = 0;
  while (true) {
    RawFrame f;
    FrameError e;
    const FrameStatus st = framer->next(&f, &e);
    if (st == FrameStatus::kFrame) {
      on_frame(f);
    } else if (st == FrameStatus::kBad) {
      rep->bad(e.offset, e.reason, e.skipped);
    } else {
      if (used == have) {
        in.read(chunk.data(), std::streamsize(chunk.size()));
        have = size_t(in.gcount());
        used = 0;
        if (have == 0) return true;
      }
      used += framer->push(reinterpret_cast<const uint8_t*>(chunk.data()) + used, have - used);
    }
  }
}

void decodePd0(std::ifstream& in, Reporter* rep) {
  Pd0Framer framer;
  framer.init(65535);
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

void decodeLines(std::ifstream& in, Reporter* rep, std::string_view starts, bool restart,
                 const std::function<void(std::string_view, uint64_t)>& on_line) {
  LineFramer framer;
  framer.init(starts, 4096, restart);
  pump(in, &framer, rep, [&](const RawFrame& f) { on_line(std::string_view(reinterpret_cast<const char*>(f.data), f.size), f.offset); });
}

void decodeNmea(std::ifstream& in, Reporter* rep) {
  decodeLines(in, rep, "$!", true, [&](std::string_view line, uint64_t offset) {
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
  decodeLines(in, rep, ":", true, [&](std::string_view line, uint64_t offset) {
    Pd6Record r;
    const char* why = "";
    if (!parsePd6Line(line, &r, &why)) return rep->bad(offset, why, line.size());
    rep->message(pd6Json(r, offset));
  });
}

void decodeWaterLinked(std::ifstream& in, Reporter* rep) {
  decodeLines(in, rep, "w{", false, [&](std::string_view line, uint64_t offset) {
    WlDvlReport r;
    const char* why = "";
    const WlDecode d = line[0] == '{' ? parseWlDvlJson(line, &r, &why) : parseWlDvlSerialLine(line, &r, &why);
    if (d == WlDecode::kInvalid) return rep->bad(offset, why, line.size());
    if (d == WlDecode::kOtherSentence) return rep->ignored();
    rep->message(wlDvlJson(r, offset));
  });
}

void decodeCandump(std::ifstream& in, Reporter* rep) {
  N2kAssembler assembler;
  std::string line;
  uint64_t offset = 0;
  while (std::getline(in, line)) {
    const uint64_t here = offset;
    offset += line.size() + 1;
    CanFrame frame;
    double t_s = -1;
    const char* why = "";
    const CandumpLine c = parseCandumpLine(line, &frame, &t_s, &why);
    if (c == CandumpLine::kSkip) continue;
    if (c == CandumpLine::kInvalid) {
      rep->bad(here, why, line.size());
      continue;
    }
    if (t_s == 0) t_s = -1;  // default candump format has no time stamps
    N2kMessage m;
    const N2kAssembler::Result r = assembler.add(frame, &m, &why);
    if (r == N2kAssembler::Result::kError) rep->bad(here, why, line.size());
    if (r == N2kAssembler::Result::kMessage) rep->message(n2kJson(m, here, t_s));
  }
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
  std::fprintf(stderr, "deepnav decode: %s: %ld messages, %ld bad frames skipped, %ld other messages ignored\n", path.c_str(),
               rep.counts().messages, rep.counts().bad, rep.counts().ignored);
  return 0;
}

}  // namespace deepnav
