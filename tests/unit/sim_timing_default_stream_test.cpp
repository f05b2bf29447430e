// The default scenarios must keep producing, bit for bit, the streams they produced before the
// sea-grade error terms (compass deviation and panel field, attitude biases, depth scale / quantisation /
// drift, per-stream timing, and the other sensors' terms) were added: every new term is off by default
// and draws from its own sub-stream. The hashes below were recorded with the simulator of commit c8fce7c
// (a build of that commit's tools/sim with this file's hashStreams), whole dives, two seeds.
#include <array>
#include <cstdint>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "sim_test_events.h"
#include "tools/sim/scenario_loader.h"
#include "tests/support/x86_64_reference.h"
#include "tests/support/source_paths.h"

namespace deepnav::sim {
namespace {

using StreamHashes = std::array<std::uint64_t, kSimStreamCount>;

// FNV-1a (64 bit) over every number of every event of each stream (test::flatten's order).
StreamHashes hashStreams(const Scenario& scenario, std::uint64_t seed) {
  StreamHashes h;
  h.fill(0xcbf29ce484222325ull);
  SensorSimulator sim;
  std::string error;
  EXPECT_TRUE(sim.init(scenario, seed, &error)) << error;
  SimEvent e;
  while (sim.next(&e)) {
    std::uint64_t& hs = h[static_cast<int>(e.stream)];
    for (double v : test::flatten(e)) {
      unsigned char bytes[sizeof(double)];
      std::memcpy(bytes, &v, sizeof(double));
      for (unsigned char b : bytes) hs = (hs ^ b) * 0x100000001b3ull;
    }
  }
  return h;
}

struct Recorded {
  const char* scenario;
  std::uint64_t seed;
  StreamHashes hashes;  // ground truth, imu, dvl, compass, attitude, depth, camera
};

// default, clear, murky and no-markers differ only in what the renderer sees: their streams are equal.
constexpr StreamHashes kDefault1{0xc5583b12e17b6c83ull, 0x2b0b63ea43245642ull, 0x38970ad1ae2ce1b3ull,
                                 0x6c4a5dbdc0f265a1ull, 0xf4c39a08897a1cf1ull, 0xd5792675e19e9e63ull,
                                 0x4d1d38edd1d6c191ull};
constexpr StreamHashes kDefault7{0x41cc7dbfda34aa1eull, 0x2d2a18ab29ce050full, 0x26a2a0353802153aull,
                                 0x6e2b3300f3e69701ull, 0x2130e8e5647f75a6ull, 0xc24a9023ebba719aull,
                                 0x4d1d38edd1d6c191ull};
const Recorded kRecorded[] = {
    {"default", 1, kDefault1},
    {"default", 7, kDefault7},
    {"clear", 1, kDefault1},
    {"murky", 7, kDefault7},
    {"no-markers", 1, kDefault1},
    {"flat-port", 1, {0xa6d1ed50650b4ee7ull, 0x24879f1d4bfa27faull, 0x9f7b27cc17fce71eull, 0xdc9835ae26520af7ull,
                      0xa9b92c99391d1ff8ull, 0x99774b135bf3648bull, 0xdfe585e21298ea5aull}},
    {"flat-port", 7, {0x7aea21821ff99a30ull, 0xb1b3d872d0d20f4full, 0x9359d6805c0e71cdull, 0x0cbeffdf870d84eeull,
                      0x44ae8c07fe82101dull, 0xc6af2307afe2b830ull, 0xdfe585e21298ea5aull}},
};

TEST(SimTimingDefaultStream, DefaultScenarioStreamsAreBitIdenticalToBeforeTheSeaGradeTerms) {
  DEEPNAV_SKIP_UNLESS_X86_64_REFERENCE();
  for (const Recorded& r : kRecorded) {
    Scenario s;
    std::string error;
    ASSERT_TRUE(loadScenario(deepnav::testing::sourceDir() + "/tools/sim/scenarios/" + r.scenario + ".yaml", &s,
                             &error))
        << error;
    const StreamHashes h = hashStreams(s, r.seed);
    for (int i = 0; i < kSimStreamCount; ++i)
      EXPECT_EQ(h[i], r.hashes[i]) << r.scenario << " seed " << r.seed << ": stream "
                                   << streamName(static_cast<SimStream>(i)) << " changed";
  }
}

}  // namespace
}  // namespace deepnav::sim
