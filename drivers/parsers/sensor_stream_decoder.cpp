#include "drivers/parsers/sensor_stream_decoder.h"

#include "drivers/parsers/nmea0183_heading.h"
#include "drivers/parsers/pd0_dvl_sample.h"
#include "drivers/parsers/pd0_ensemble.h"
#include "drivers/parsers/wl_dvl_protocol.h"
#include "drivers/parsers/xsens_mtdata2.h"

namespace deepnav {
namespace {

struct ProtocolName {
  SensorProtocol protocol;
  const char* name;
};
constexpr ProtocolName kNames[] = {{SensorProtocol::kPd0, "pd0"},
                                   {SensorProtocol::kPd6, "pd6"},
                                   {SensorProtocol::kWlA50, "wl-a50"},
                                   {SensorProtocol::kNmea0183, "nmea0183"},
                                   {SensorProtocol::kXsens, "xsens"}};

}  // namespace

bool parseSensorProtocol(std::string_view name, SensorProtocol* protocol) {
  for (const ProtocolName& p : kNames) {
    if (name == p.name) return *protocol = p.protocol, true;
  }
  return false;
}

const char* sensorProtocolName(SensorProtocol protocol) {
  for (const ProtocolName& p : kNames) {
    if (p.protocol == protocol) return p.name;
  }
  return "?";
}

SensorStreamDecoder::SensorStreamDecoder() = default;
SensorStreamDecoder::~SensorStreamDecoder() = default;

bool SensorStreamDecoder::init(SensorProtocol protocol, const PlausibilityLimits& limits) {
  protocol_ = protocol;
  counters_ = {};
  plausible_ = FramePlausibility(limits);
  pd6_ = {};
  switch (protocol) {
    case SensorProtocol::kPd0:
      ensemble_ = std::make_unique<Pd0Ensemble>();
      return pd0_.init(8192);
    case SensorProtocol::kPd6: return lines_.init(":", 120);
    case SensorProtocol::kWlA50: return lines_.init("w{", 4096, true, "{");
    case SensorProtocol::kNmea0183: return lines_.init("$!", 120);
    case SensorProtocol::kXsens: return xbus_.init(2048);
  }
  return false;
}

size_t SensorStreamDecoder::push(const uint8_t* data, size_t n) {
  switch (protocol_) {
    case SensorProtocol::kPd0: return pd0_.push(data, n);
    case SensorProtocol::kXsens: return xbus_.push(data, n);
    default: return lines_.push(data, n);
  }
}

bool SensorStreamDecoder::next(RawFrame* frame, FrameError* error) {
  while (true) {
    FrameStatus st;
    switch (protocol_) {
      case SensorProtocol::kPd0: st = pd0_.next(frame, error); break;
      case SensorProtocol::kXsens: st = xbus_.next(frame, error); break;
      default: st = lines_.next(frame, error); break;
    }
    if (st == FrameStatus::kFrame) return true;
    if (st == FrameStatus::kNeedMore) return false;
    ++counters_.bad_frames;
    counters_.bytes_skipped += error->skipped;
    plausible_.onRejectedFrame();
  }
}

void SensorStreamDecoder::feed(const uint8_t* data, size_t n, TimeUs t_us, SampleSink* sink) {
  size_t used = 0;
  while (true) {
    RawFrame frame;
    FrameError error;
    while (next(&frame, &error)) onFrame(frame, t_us, sink);
    if (used == n) return;
    used += push(data + used, n - used);
  }
}

void SensorStreamDecoder::deliver(bool accepted) {
  ++counters_.samples;
  if (!accepted) ++counters_.sink_refused;
}

// A checksum-valid frame that is not plausible in this stream is counted bad and gives no sample.
bool SensorStreamDecoder::plausibleFrame(FramePlausibility::Verdict v) {
  if (v == FramePlausibility::Verdict::kAccepted) return true;
  ++counters_.bad_frames;
  ++counters_.implausible;
  return false;
}

void SensorStreamDecoder::onFrame(const RawFrame& f, TimeUs t_us, SampleSink* sink) {
  const char* why = "";
  const std::string_view line(reinterpret_cast<const char*>(f.data), f.size);
  bool ok = true;
  bool used = false;
  switch (protocol_) {
    case SensorProtocol::kPd0: {
      DvlSample s;
      ok = decodePd0Ensemble(f.data, f.size, ensemble_.get(), &why);
      if (ok && !plausibleFrame(plausible_.checkPd0(f.data, f.size, *ensemble_))) return;
      if (ok && pd0ToDvlSample(*ensemble_, t_us, &s)) deliver(sink->onDvl(s)), used = true;
      break;
    }
    case SensorProtocol::kPd6: {
      Pd6Record r;
      DvlSample s;
      ok = parsePd6Line(line, &r, &why);
      if (ok && pd6_.add(r, t_us, &s)) deliver(sink->onDvl(s)), used = true;
      used = used || ok;  // the other lines complete the ensemble
      break;
    }
    case SensorProtocol::kWlA50: {
      WlDvlReport r;
      DvlSample s;
      size_t junk = 0;
      const WlDecode d = parseWlDvlLine(line, &r, &why, &junk);
      if (junk > 0) ++counters_.bad_frames, counters_.bytes_skipped += junk;
      ok = d != WlDecode::kInvalid;
      if (d == WlDecode::kDecoded && !plausibleFrame(plausible_.checkWaterLinked(r))) return;
      if (d == WlDecode::kDecoded && dvlSampleFromWlReport(r, t_us, &s)) deliver(sink->onDvl(s)), used = true;
      break;
    }
    case SensorProtocol::kNmea0183: {
      Nmea0183Sentence s;
      Nmea0183HeadingRecord r;
      HeadingSample h;
      ok = parseNmea0183Sentence(line, true, &s, &why);
      const NmeaDecode d = ok ? decodeNmea0183Heading(s, &r, &why) : NmeaDecode::kInvalid;
      ok = d != NmeaDecode::kInvalid;
      if (d == NmeaDecode::kDecoded && !plausibleFrame(plausible_.checkNmeaHeading(r))) return;
      if (d == NmeaDecode::kDecoded && headingSampleFromNmea(r, t_us, &h)) deliver(sink->onHeading(h)), used = true;
      break;
    }
    case SensorProtocol::kXsens: {
      XbusMessage m;
      XsensMtData2 d;
      ok = splitXbusFrame(f.data, f.size, &m);
      if (ok && m.message_id == kXbusMtData2) {
        ok = decodeXsensMtData2(m.payload, m.payload_size, &d, &why);
        if (ok && !plausibleFrame(plausible_.checkXsens(m, d))) return;
        ImuSample imu;
        AttitudeSample att;
        if (ok && imuSampleFromXsens(d, t_us, &imu)) deliver(sink->onImu(imu)), used = true;
        if (ok && attitudeSampleFromXsens(d, t_us, &att)) deliver(sink->onAttitude(att)), used = true;
      }
      break;
    }
  }
  if (!ok) {
    ++counters_.bad_frames;
    plausible_.onRejectedFrame();
    return;
  }
  ++counters_.frames;
  if (!used) ++counters_.ignored;
}

}  // namespace deepnav
