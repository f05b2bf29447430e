#include "drivers/outputs/nav_datagram.h"

#include <cstring>

#include "drivers/mcap/crc32.h"

namespace deepnav {
namespace {

constexpr std::size_t kCrcOffset = kNavDatagramSize - 4;

class Writer {
 public:
  explicit Writer(std::uint8_t* b) : b_(b) {}
  template <typename T>
  void put(T v) {
    std::uint64_t bits = 0;
    static_assert(sizeof(T) <= 8);
    std::memcpy(&bits, &v, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) b_[at_++] = static_cast<std::uint8_t>(bits >> (8 * i));
  }

 private:
  std::uint8_t* b_;
  std::size_t at_ = 0;
};

class Reader {
 public:
  explicit Reader(const std::uint8_t* b) : b_(b) {}
  template <typename T>
  T get() {
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) bits |= static_cast<std::uint64_t>(b_[at_++]) << (8 * i);
    T v;
    std::memcpy(&v, &bits, sizeof(T));
    return v;
  }

 private:
  const std::uint8_t* b_;
  std::size_t at_ = 0;
};

constexpr int kCounterCount = 14;

void countersOf(const NavOutput& o, std::uint64_t* v) {
  const NavCounters& c = o.counters;
  const std::uint64_t all[kCounterCount] = {o.solution.rejected_total, o.solution.dropped_late_total, c.ticks,
                                            c.late_ticks, c.nav_overruns, c.vision_overruns, c.recorder_drops,
                                            c.inputs_refused, c.imu, c.dvl, c.depth, c.heading, c.attitude, c.vision};
  std::memcpy(v, all, sizeof all);
}

void setCounters(const std::uint64_t* v, NavOutput* o) {
  NavCounters& c = o->counters;
  o->solution.rejected_total = static_cast<std::uint32_t>(v[0]);
  o->solution.dropped_late_total = static_cast<std::uint32_t>(v[1]);
  std::uint64_t* fields[] = {&c.ticks, &c.late_ticks, &c.nav_overruns, &c.vision_overruns, &c.recorder_drops,
                             &c.inputs_refused, &c.imu, &c.dvl, &c.depth, &c.heading, &c.attitude, &c.vision};
  for (int i = 2; i < kCounterCount; ++i) *fields[i - 2] = v[i];
}

}  // namespace

void encodeNavDatagram(const NavOutput& out, std::uint8_t* buffer) {
  const NavSolution& s = out.solution;
  Writer w(buffer);
  for (char ch : {'D', 'N', 'A', 'V'}) w.put<std::uint8_t>(static_cast<std::uint8_t>(ch));
  w.put<std::uint16_t>(kNavDatagramVersion);
  w.put<std::uint16_t>(static_cast<std::uint16_t>(kNavDatagramSize));
  w.put<std::uint32_t>(out.sequence);
  w.put<std::int64_t>(s.t_us);
  w.put<std::uint8_t>(static_cast<std::uint8_t>(s.stage));
  for (int i = 0; i < 3; ++i) w.put<std::uint8_t>(0);
  w.put<std::uint32_t>(s.status);
  w.put<std::uint32_t>(s.faults);
  w.put<std::uint32_t>(out.health);
  for (int i = 0; i < 3; ++i) w.put<double>(s.p_robot_in_odom_m[i]);
  for (double q : {s.q_odom_robot.x(), s.q_odom_robot.y(), s.q_odom_robot.z(), s.q_odom_robot.w()}) w.put<double>(q);
  for (int i = 0; i < 3; ++i) w.put<double>(s.v_robot_in_odom_mps[i]);
  for (int i = 0; i < 3; ++i) w.put<double>(s.w_robot_radps[i]);
  for (int i = 0; i < 6; ++i) w.put<double>(s.cov_pose(i, i));
  for (int i = 0; i < 3; ++i) w.put<double>(s.cov_v_mps2(i, i));
  w.put<double>(s.image_quality);
  std::uint64_t counters[kCounterCount];
  countersOf(out, counters);
  for (std::uint64_t v : counters) w.put<std::uint64_t>(v);
  w.put<std::uint32_t>(mcap::crc32(buffer, kCrcOffset));
}

bool decodeNavDatagram(const std::uint8_t* data, std::size_t size, NavOutput* out, std::string* error) {
  auto fail = [&](const char* why) {
    if (error) *error = std::string("nav datagram: ") + why;
    return false;
  };
  if (size != kNavDatagramSize) return fail("wrong size");
  if (std::memcmp(data, "DNAV", 4) != 0) return fail("bad magic");
  Reader r(data + 4);
  if (r.get<std::uint16_t>() != kNavDatagramVersion) return fail("unknown version");
  if (r.get<std::uint16_t>() != kNavDatagramSize) return fail("length field disagrees");
  Reader crc_reader(data + kCrcOffset);
  if (crc_reader.get<std::uint32_t>() != mcap::crc32(data, kCrcOffset)) return fail("CRC mismatch");
  NavOutput o;
  NavSolution& s = o.solution;
  o.sequence = r.get<std::uint32_t>();
  s.t_us = r.get<std::int64_t>();
  s.stage = static_cast<NavStage>(r.get<std::uint8_t>());
  for (int i = 0; i < 3; ++i) r.get<std::uint8_t>();
  s.status = r.get<std::uint32_t>();
  s.faults = r.get<std::uint32_t>();
  o.health = r.get<std::uint32_t>();
  for (int i = 0; i < 3; ++i) s.p_robot_in_odom_m[i] = r.get<double>();
  s.q_odom_robot.x() = r.get<double>();
  s.q_odom_robot.y() = r.get<double>();
  s.q_odom_robot.z() = r.get<double>();
  s.q_odom_robot.w() = r.get<double>();
  for (int i = 0; i < 3; ++i) s.v_robot_in_odom_mps[i] = r.get<double>();
  for (int i = 0; i < 3; ++i) s.w_robot_radps[i] = r.get<double>();
  for (int i = 0; i < 6; ++i) s.cov_pose(i, i) = r.get<double>();
  for (int i = 0; i < 3; ++i) s.cov_v_mps2(i, i) = r.get<double>();
  s.image_quality = r.get<double>();
  std::uint64_t counters[kCounterCount];
  for (std::uint64_t& v : counters) v = r.get<std::uint64_t>();
  setCounters(counters, &o);
  *out = o;
  return true;
}

}  // namespace deepnav
