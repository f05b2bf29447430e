// libFuzzer harness: arbitrary bytes as candump text and as raw CAN frames, through the NMEA 2000
// fast-packet assembler and the 127250/127251/127257 decoders; and the intact-frames property: three
// good candump lines after the input (split at LF or CR as `deepnav decode` does) are all decoded to
// their frames (intact_frames.h).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/candump_line.h"
#include "drivers/parsers/n2k_assembler.h"
#include "drivers/parsers/n2k_heading_pgns.h"
#include "tools/fuzz/intact_frames.h"

namespace {

void decode(deepnav::N2kAssembler* a, const deepnav::CanFrame& f) {
  using namespace deepnav;
  N2kMessage m;
  const char* why = "";
  if (a->add(f, &m, &why) != N2kAssembler::Result::kMessage) return;
  N2kVesselHeading h;
  N2kRateOfTurn r;
  N2kAttitude att;
  HeadingSample hs;
  AttitudeSample as;
  if (decodeN2kVesselHeading(m, &h, &why)) headingSampleFromN2k(h, 0, &hs);
  decodeN2kRateOfTurn(m, &r, &why);
  if (decodeN2kAttitude(m, &att, &why)) attitudeSampleFromN2k(att, 0, &as);
}

void checkIntactLines(const uint8_t* data, size_t size) {
  using namespace deepnav;
  const std::vector<std::string> lines = {"(1436509052.249713) can0 09F8027F#00FCFFFF0000FFFF",
                                          "can0  09F1128F   [8]  FF 4C 2E FF 7F FF 7F FD", "(1436509052.250000) can0 1F3#0102"};
  std::vector<std::string> frames;
  for (const std::string& l : lines) frames.push_back(l + "\n");
  fuzz::IntactFrames intact(data, size, frames, lines);
  const std::string_view text = intact.text();
  size_t begin = 0;
  for (size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != '\n' && text[i] != '\r') continue;
    const std::string_view line = text.substr(begin, std::min<size_t>(i - begin, 4096));
    CanFrame f;
    double t = 0;
    const char* why = "";
    size_t junk = 0;
    if (i - begin <= 4096 && parseCandumpLineAfterJunk(line, &f, &t, &why, &junk) == CandumpLine::kFrame) {
      // Blanks before a frame are not junk: the frame is compared from its first character.
      const size_t lead = std::min(line.find_first_not_of(" \t", junk), line.size());
      intact.delivered(begin + lead, line.substr(lead));
    }
    begin = i + 1;
  }
  intact.verify("n2k-candump");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  N2kAssembler text_assembler, raw_assembler;
  const uint32_t pgns[] = {127250, 127251, 127257, 129029};
  raw_assembler.setFastPacketPgns(pgns, 4);  // the heading PGNs also as fast packet
  std::string_view text(reinterpret_cast<const char*>(data), size);
  while (!text.empty()) {
    const size_t nl = text.find('\n');
    CanFrame f;
    double t = 0;
    const char* why = "";
    if (parseCandumpLine(text.substr(0, nl), &f, &t, &why) == CandumpLine::kFrame) decode(&text_assembler, f);
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
  // Raw frames: 4-byte identifier, 1 length byte, 8 data bytes.
  for (size_t i = 0; i + 13 <= size; i += 13) {
    CanFrame f;
    f.id = (uint32_t(data[i]) << 24 | uint32_t(data[i + 1]) << 16 | uint32_t(data[i + 2]) << 8 | data[i + 3]) & 0x1FFFFFFF;
    f.extended = true;
    f.dlc = data[i + 4] % 9;
    std::copy(data + i + 5, data + i + 13, f.data.begin());
    decode(&raw_assembler, f);
  }
  checkIntactLines(data, size);
  return 0;
}
