#pragma once
// Builders of well-formed sensor frames for tests: PD0 ensembles, NMEA 0183 sentences, Water Linked
// sentences, Xsens Xbus MTData2 messages. Each follows the format's specification independently of
// the parsers under test (checksums computed here).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

namespace deepnav::test {

inline void putLe16(std::vector<uint8_t>* v, size_t at, uint16_t x) {
  (*v)[at] = uint8_t(x & 0xFF);
  (*v)[at + 1] = uint8_t(x >> 8);
}

// PD0 ensemble: header, fixed leader (59 bytes), variable leader (65 bytes), bottom track (85 bytes).
struct Pd0Spec {
  uint8_t frame = 1;  // EX bits 3-4: 0 beam, 1 instrument, 2 ship, 3 earth
  uint16_t ensemble = 1;
  uint16_t heading_cdeg = 0;
  int16_t pitch_cdeg = 0, roll_cdeg = 0;
  int16_t bt_velocity_mmps[4] = {0, 0, 0, 0};
  uint16_t bt_range_cm[4] = {1000, 1000, 1000, 1000};
  uint16_t beam_angle_bits = 2;  // 30 deg
};

inline std::vector<uint8_t> buildPd0(const Pd0Spec& s) {
  const size_t fixed = 59, variable = 65, bt = 85;
  const size_t header = 6 + 2 * 3;
  const size_t length = header + fixed + variable + bt;
  std::vector<uint8_t> e(length + 2, 0);
  e[0] = e[1] = 0x7F;
  putLe16(&e, 2, uint16_t(length));
  e[5] = 3;
  putLe16(&e, 6, uint16_t(header));
  putLe16(&e, 8, uint16_t(header + fixed));
  putLe16(&e, 10, uint16_t(header + fixed + variable));
  uint8_t* f = e.data() + header;  // fixed leader, ID 0x0000
  f[2] = 51, f[3] = 2;
  const uint16_t sysconfig = uint16_t(0x0040 | 0x0008 | (s.beam_angle_bits << 8));  // 600 kHz-ish, convex, down
  f[4] = uint8_t(sysconfig & 0xFF), f[5] = uint8_t(sysconfig >> 8);
  f[8] = 4, f[9] = 0;  // 4 beams, no cells
  f[25] = uint8_t(s.frame << 3);
  uint8_t* v = e.data() + header + fixed;  // variable leader, ID 0x0080
  v[0] = 0x80;
  v[2] = uint8_t(s.ensemble & 0xFF), v[3] = uint8_t(s.ensemble >> 8);
  v[14] = 0xDC, v[15] = 0x05;  // 1500 m/s
  v[18] = uint8_t(s.heading_cdeg & 0xFF), v[19] = uint8_t(s.heading_cdeg >> 8);
  v[20] = uint8_t(uint16_t(s.pitch_cdeg) & 0xFF), v[21] = uint8_t(uint16_t(s.pitch_cdeg) >> 8);
  v[22] = uint8_t(uint16_t(s.roll_cdeg) & 0xFF), v[23] = uint8_t(uint16_t(s.roll_cdeg) >> 8);
  uint8_t* b = e.data() + header + fixed + variable;  // bottom track, ID 0x0600
  b[1] = 0x06;
  for (int i = 0; i < 4; ++i) {
    b[16 + 2 * i] = uint8_t(s.bt_range_cm[i] & 0xFF), b[17 + 2 * i] = uint8_t(s.bt_range_cm[i] >> 8);
    const uint16_t vel = uint16_t(s.bt_velocity_mmps[i]);
    b[24 + 2 * i] = uint8_t(vel & 0xFF), b[25 + 2 * i] = uint8_t(vel >> 8);
    b[40 + i] = 100;
  }
  uint32_t sum = 0;
  for (size_t i = 0; i < length; ++i) sum += e[i];
  putLe16(&e, length, uint16_t(sum));
  return e;
}

// "$" + body + "*hh\r\n" with the XOR checksum.
inline std::string nmeaSentence(const std::string& body) {
  uint8_t x = 0;
  for (char c : body) x ^= uint8_t(c);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", x);
  return "$" + body + tail;
}

// Water Linked sentence: body + "*hh\r\n" with the CRC-8 (poly 0x07), computed bit by bit here.
inline std::string wlSentence(const std::string& body) {
  uint8_t crc = 0;
  for (char c : body) {
    crc ^= uint8_t(c);
    for (int b = 0; b < 8; ++b) crc = (crc & 0x80) ? uint8_t((crc << 1) ^ 0x07) : uint8_t(crc << 1);
  }
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02x\r\n", crc);
  return body + tail;
}

inline void putBeF32(std::vector<uint8_t>* v, float f) {
  uint32_t bits;
  std::memcpy(&bits, &f, 4);
  for (int i = 3; i >= 0; --i) v->push_back(uint8_t(bits >> (8 * i)));
}

// Xbus MTData2 with packet counter, quaternion (w,x,y,z), acceleration and rate of turn (float32, ENU).
inline std::vector<uint8_t> buildMtData2(uint16_t counter, const float q[4], const float acc[3], const float gyr[3]) {
  std::vector<uint8_t> p;
  // push_back rather than insert of an initializer list: g++ 12 -O3 warns falsely on the latter.
  const auto put = [&p](std::initializer_list<uint8_t> bytes) {
    for (uint8_t b : bytes) p.push_back(b);
  };
  put({0x10, 0x20, 2, uint8_t(counter >> 8), uint8_t(counter & 0xFF)});
  put({0x20, 0x10, 16});
  for (int i = 0; i < 4; ++i) putBeF32(&p, q[i]);
  put({0x40, 0x20, 12});
  for (int i = 0; i < 3; ++i) putBeF32(&p, acc[i]);
  put({0x80, 0x20, 12});
  for (int i = 0; i < 3; ++i) putBeF32(&p, gyr[i]);
  std::vector<uint8_t> m = {0xFA, 0xFF, 0x36, uint8_t(p.size())};
  for (uint8_t b : p) m.push_back(b);
  uint8_t sum = 0;
  for (size_t i = 1; i < m.size(); ++i) sum = uint8_t(sum + m[i]);
  m.push_back(uint8_t(0x100 - sum));
  return m;
}

}  // namespace deepnav::test
