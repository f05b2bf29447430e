// The health bit of failed vision pairs (a vision stage threw): set in the window the count rose, in the
// STATUS= words, cleared once no pair fails.
#include <gtest/gtest.h>

#include "board/service/health_monitor.h"
#include "board/service/status_text.h"

namespace deepnav {
namespace {

TEST(HealthVisionFailed, ABitInTheWindowThePairsFailedAndAWordInTheStatus) {
  HealthMonitor health;
  HealthSample s;
  s.loop.ticks = 10;
  health.update(s);  // reference
  s.loop.ticks = 20;
  s.vision_failures = 2;
  EXPECT_TRUE(health.update(s) & kHealthVisionFailed);
  EXPECT_TRUE(health.healthy());  // the loop runs on: the watchdog is still fed
  EXPECT_EQ(healthWords(health.bits()), "vision-failed");
  s.loop.ticks = 30;
  EXPECT_FALSE(health.update(s) & kHealthVisionFailed);
  EXPECT_EQ(healthWords(health.bits()), "ok");
}

}  // namespace
}  // namespace deepnav
