// Sample kinds are routed by type, in one way (docs/adding-a-sensor-kind.md): each kind reaches its
// topic, its ring and its counter, whatever the order of InputSample's alternatives.
#include <cstdint>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "board/config/vehicle_setup.h"
#include "board/loop/nav_core.h"
#include "drivers/buffers/live_inputs.h"
#include "drivers/recording/record_sink.h"
#include "drivers/recording/sample_codec.h"
#include "drivers/recording/topics.h"
#include "nav/types/input_sample.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

static_assert(kInputKind<ImuSample> == InputKind::kImu);
static_assert(kInputKind<DvlSample> == InputKind::kDvl);
static_assert(kInputKind<HeadingSample> == InputKind::kHeading);
static_assert(kInputKind<AttitudeSample> == InputKind::kAttitude);
static_assert(kInputKind<DepthSample> == InputKind::kDepth);
static_assert(kInputKind<VisionResult> == InputKind::kVision);
static_assert(static_cast<std::size_t>(InputKind::kCount) == std::variant_size_v<InputSample>);

// One sample of every kind, stamped 1000 + its kind, in InputSample's order.
template <typename... T>
std::vector<InputSample> oneOfEach(const std::variant<T...>*) {
  std::vector<InputSample> out;
  (out.push_back([] {
     T s{};
     s.t_us = 1000 + static_cast<TimeUs>(kInputKind<T>);
     return InputSample{s};
   }()),
   ...);
  return out;
}
std::vector<InputSample> oneOfEachKind() { return oneOfEach(static_cast<const InputSample*>(nullptr)); }

TEST(SampleRouting, KindFollowsTheTypeNotThePosition) {
  // GIVEN the same samples in InputSample and in a variant with the alternatives reversed
  using Reversed = std::variant<VisionResult, DepthSample, AttitudeSample, HeadingSample, DvlSample, ImuSample>;
  for (const InputSample& s : oneOfEachKind()) {
    const Reversed r = std::visit([](const auto& v) { return Reversed{v}; }, s);
    // THEN the kind read by type is the same, though every index differs
    EXPECT_NE(r.index(), s.index());
    const InputKind by_type = std::visit([](const auto& v) { return kInputKind<std::decay_t<decltype(v)>>; }, r);
    EXPECT_EQ(by_type, inputKind(s));
    EXPECT_EQ(static_cast<TimeUs>(inputKind(s)), sampleTimeUs(s) - 1000);
  }
}

TEST(SampleRouting, EveryKindIsRecordedOnItsOwnTopicAndReadBack) {
  const Topic expected[] = {Topic::kImu,      Topic::kDvlBottomTrack, Topic::kHeading,
                            Topic::kAttitude, Topic::kDepth,          Topic::kVisionResult};
  std::vector<std::uint8_t> buf(1 << 16);
  for (const InputSample& s : oneOfEachKind()) {
    const auto kind = static_cast<std::size_t>(inputKind(s));
    EXPECT_EQ(inputTopic(s), expected[kind]) << "kind " << kind;
    const std::size_t n = encodeInput(s, buf.data(), buf.size());
    ASSERT_GT(n, 0u);
    InputSample back;
    ASSERT_TRUE(decodeInput(inputTopic(s), buf.data(), n, &back));
    EXPECT_EQ(inputKind(back), inputKind(s));
    EXPECT_EQ(sampleTimeUs(back), sampleTimeUs(s));
    // AND no other topic reads it as an input
    EXPECT_FALSE(decodeInput(Topic::kNavSolution, buf.data(), n, &back));
  }
}

TEST(SampleRouting, OnlyDvlAndDepthHaveViewerCompanions) {
  std::vector<std::uint8_t> buf(1 << 16);
  for (const InputSample& s : oneOfEachKind()) {
    const InputKind kind = inputKind(s);
    const Topic companion = kind == InputKind::kDvl     ? Topic::kDvl
                            : kind == InputKind::kDepth ? Topic::kPressure
                                                        : Topic::kCount;
    EXPECT_EQ(inputCompanionTopic(s), companion);
    EXPECT_EQ(encodeInputCompanion(s, buf.data(), buf.size()) > 0, companion != Topic::kCount);
  }
}

TEST(SampleRouting, EverySensorKindHasOneRingVisitedInMergeOrder) {
  LiveInputs in;
  ASSERT_TRUE(in.allocate(LiveInputCapacities{}));
  // GIVEN one sample of each sensor kind pushed into the ring of its type (vision results queue apart)
  int pushed = 0;
  for (const InputSample& s : oneOfEachKind()) {
    std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (!std::is_same_v<T, VisionResult>) pushed += in.ring<T>().push(v);
        },
        s);
  }
  // THEN forEachSensorRing visits each ring once, the IMU's first, each holding only its own sample
  std::vector<TimeUs> fronts;
  in.forEachSensorRing([&](const auto& ring) {
    EXPECT_EQ(ring.size(), 1u);
    fronts.push_back(ring.front() ? ring.front()->t_us : -1);
  });
  EXPECT_EQ(pushed, static_cast<int>(std::variant_size_v<InputSample>) - 1);
  EXPECT_EQ(fronts.size(), std::variant_size_v<InputSample> - 1) << "a ring missing from forEachSensorRing";
  EXPECT_EQ(fronts, (std::vector<TimeUs>{1000, 1001, 1002, 1003, 1004}));
}

class CountingSink final : public RecordSink {
 public:
  void recordInput(const InputSample& s) override { kinds.push_back(inputKind(s)); }
  void recordSolution(const NavSolution&) override {}
  void recordFusion(const FusionDiagnostic&) override {}
  void recordEstimatorStates(const EstimatorStates&) override {}
  void recordFrame(const StereoFrame&, int) override {}
  std::vector<InputKind> kinds;
};

TEST(SampleRouting, NavCoreCountsEachKindUnderItsOwnName) {
  VehicleSetup setup;
  std::string error;
  ASSERT_TRUE(loadVehicleSetup(deepnav::testing::sourceDir() + "/board/sim/board.yaml", &setup, &error)) << error;
  CountingSink sink;
  NavCore core;
  ASSERT_TRUE(core.init(setup, &sink, &error)) << error;
  // WHEN one sample of each kind is consumed
  std::vector<InputKind> consumed;
  for (const InputSample& s : oneOfEachKind()) {
    core.consume(s);
    consumed.push_back(inputKind(s));
  }
  // THEN each is recorded once, in order, and counted once under its own kind
  EXPECT_EQ(sink.kinds, consumed);
  const InputCounters& c = core.counters();
  EXPECT_EQ(c.imu, 1u);
  EXPECT_EQ(c.dvl, 1u);
  EXPECT_EQ(c.heading, 1u);
  EXPECT_EQ(c.attitude, 1u);
  EXPECT_EQ(c.depth, 1u);
  EXPECT_EQ(c.vision, 1u);
}

}  // namespace
}  // namespace deepnav
