// vision/pipeline/modality_selector: the paper's threshold on m_I, with hysteresis, and the fixed modes.
#include <gtest/gtest.h>

#include "vision/pipeline/modality_selector.h"

namespace deepnav {
namespace {

TEST(ModalitySelector, ThresholdWithHysteresis) {
  // GIVEN the adaptive mode, threshold 0.45, hysteresis 0.02
  ModalitySelector s;
  ModalityConfig c;
  ASSERT_TRUE(s.init(c, nullptr));
  // THEN the first pair follows the bare threshold
  EXPECT_EQ(s.select(0.46), VoSource::kOrb);
  // AND a score just below the threshold does not leave ORB, one below threshold - h does
  EXPECT_EQ(s.select(0.44), VoSource::kOrb);
  EXPECT_EQ(s.select(0.429), VoSource::kPlanes);
  // AND on planes, a score just above the threshold stays on planes, one above threshold + h returns
  EXPECT_EQ(s.select(0.46), VoSource::kPlanes);
  EXPECT_EQ(s.select(0.471), VoSource::kOrb);
  // AND an unusable frame (negative score) selects nothing and forgets the state
  EXPECT_EQ(s.select(-1.0), VoSource::kNone);
  EXPECT_EQ(s.select(0.44), VoSource::kPlanes);
  EXPECT_TRUE(s.runOrb());
  EXPECT_TRUE(s.runPlanes(VoSource::kPlanes));
  EXPECT_FALSE(s.runPlanes(VoSource::kOrb));
}

TEST(ModalitySelector, FixedModesAndBadConfig) {
  ModalitySelector s;
  ModalityConfig c;
  for (const char* name : {"all", "orb", "planes", "none"}) {
    ASSERT_TRUE(parseVoMode(name, &c.mode)) << name;
    EXPECT_STREQ(toString(c.mode), name);
  }
  c.mode = VoMode::kAll;
  ASSERT_TRUE(s.init(c, nullptr));
  EXPECT_TRUE(s.runOrb());
  EXPECT_TRUE(s.runPlanes(VoSource::kOrb));  // both on every pair
  c.mode = VoMode::kNone;
  ASSERT_TRUE(s.init(c, nullptr));
  EXPECT_EQ(s.select(0.9), VoSource::kNone);
  EXPECT_FALSE(s.runPlanes(VoSource::kNone));
  c.mode = VoMode::kPlanes;
  ASSERT_TRUE(s.init(c, nullptr));
  EXPECT_EQ(s.select(0.9), VoSource::kPlanes);
  VoMode m;
  EXPECT_FALSE(parseVoMode("fast", &m));
  c.threshold = 1.5;
  std::string error;
  EXPECT_FALSE(s.init(c, &error));
  EXPECT_NE(error.find("vision.quality_threshold"), std::string::npos);
}

}  // namespace
}  // namespace deepnav
