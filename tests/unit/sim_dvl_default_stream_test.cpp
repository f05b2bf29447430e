// The default DVL stream must not change with the sea-grade terms (all off by default): its FNV-1a hash
// over every field of the 601 ensembles of the default dive (seed 1) was recorded from the model before
// they were added (commit c8fce7c, same compiler flags).
#include <cstdint>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"
#include "tests/support/x86_64_reference.h"
#include "tests/support/source_paths.h"

namespace deepnav::sim {
namespace {

constexpr std::uint64_t kDefaultDvlHash = 0x31b35473744dc078ull;
constexpr std::uint64_t kDefaultDvlCount = 601;

struct Fnv1a {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  void number(double x) { bytes(&x, sizeof x); }
};

void hashSample(const DvlSample& s, Fnv1a* f) {
  f->bytes(&s.t_us, sizeof s.t_us);
  for (int i = 0; i < 3; ++i) f->number(s.v_dvl_mps[i]);
  for (double r : s.beam_range_m) f->number(r);
  f->bytes(&s.beam_valid_mask, 1);
  const unsigned char valid = s.valid;
  f->bytes(&valid, 1);
  f->number(s.fom_mps);
  for (int i = 0; i < 9; ++i) f->number(s.cov_v_dvl_mps2.data()[i]);
  f->number(s.altitude_m);
}

// Hash and count of the DVL stream of a scenario.
std::pair<std::uint64_t, std::uint64_t> dvlStreamHash(const Scenario& scenario, std::uint64_t seed) {
  SensorSimulator sim;
  std::string error;
  EXPECT_TRUE(sim.init(scenario, seed, &error)) << error;
  Fnv1a f;
  std::uint64_t count = 0;
  SimEvent e;
  while (sim.next(&e)) {
    if (e.stream != SimStream::kDvl) continue;
    hashSample(std::get<DvlSample>(e.sample), &f);
    ++count;
  }
  return {f.h, count};
}

TEST(SimDvlDefaultStream, BuiltInDefaultsGiveTheRecordedStream) {
  DEEPNAV_SKIP_UNLESS_X86_64_REFERENCE();
  const auto [hash, count] = dvlStreamHash(Scenario{}, 1);
  EXPECT_EQ(count, kDefaultDvlCount);
  EXPECT_EQ(hash, kDefaultDvlHash) << std::hex << hash;
}

TEST(SimDvlDefaultStream, DefaultFileAndGradeNoneGiveTheRecordedStream) {
  DEEPNAV_SKIP_UNLESS_X86_64_REFERENCE();
  Scenario from_file, grade_none;
  std::string error;
  ASSERT_TRUE(loadScenario(deepnav::testing::sourceDir() + "/tools/sim/scenarios/default.yaml", &from_file, &error))
      << error;
  ASSERT_TRUE(parseScenario("dvl: {grade: none}", "none.yaml", &grade_none, &error)) << error;
  EXPECT_EQ(dvlStreamHash(from_file, 1).first, kDefaultDvlHash);
  EXPECT_EQ(dvlStreamHash(grade_none, 1).first, kDefaultDvlHash);
  EXPECT_FALSE(from_file.dvl.usesBeamModel());
}

}  // namespace
}  // namespace deepnav::sim
