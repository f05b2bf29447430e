#include "board/loop/scheduler.h"

#include <gtest/gtest.h>

namespace deepnav {
namespace {

const TaskSpec kTable[] = {
    {"nav", 100, 2000, false},
    {"output", 50, 500, false},
    {"stats", 1, 1000, false},
    {"vision", 10, 100000, true},
};

TEST(Scheduler, RunsEachTaskAtItsRate) {
  // GIVEN the default table WHEN 100 ticks (1 s) are walked THEN each loop task is due rate_hz times
  Scheduler s;
  std::string error;
  ASSERT_TRUE(s.init(kTable, 4, 0.5, &error)) << error;
  EXPECT_EQ(s.tickRateHz(), 100);
  EXPECT_EQ(s.periodUs(), 10000);
  int counts[4] = {};
  for (std::uint64_t tick = 0; tick < 100; ++tick) {
    for (int t = 0; t < 4; ++t) counts[t] += s.due(t, tick) ? 1 : 0;
  }
  EXPECT_EQ(counts[0], 100);
  EXPECT_EQ(counts[1], 50);
  EXPECT_EQ(counts[2], 1);
  EXPECT_EQ(counts[3], 0);  // the vision worker runs in its own thread
}

TEST(Scheduler, CountsOverrunsAndLateTicks) {
  Scheduler s;
  std::string error;
  ASSERT_TRUE(s.init(kTable, 4, 0.5, &error)) << error;
  s.recordRun(0, 1500);
  s.recordRun(0, 2500);  // over the 2000 us budget
  s.recordRun(3, 150000);
  s.recordTickStart(0, 1000);
  s.recordTickStart(10000, 16000);  // 6 ms late on a 10 ms period: late
  const LoopStats st = s.stats();
  EXPECT_EQ(st.runs[0], 2u);
  EXPECT_EQ(st.overruns[0], 1u);
  EXPECT_EQ(st.max_us[0], 2500);
  EXPECT_DOUBLE_EQ(st.mean_us[0], 2000.0);
  EXPECT_EQ(st.overruns[3], 1u);
  EXPECT_EQ(st.ticks, 2u);
  EXPECT_EQ(st.late_ticks, 1u);
  EXPECT_EQ(st.max_lateness_us, 6000);
  EXPECT_NE(formatLoopStats(st).find("late ticks 1"), std::string::npos);
}

TEST(Scheduler, RejectsRatesThatDoNotDivideTheTick) {
  const TaskSpec bad[] = {{"nav", 100, 2000, false}, {"odd", 30, 100, false}};
  Scheduler s;
  std::string error;
  EXPECT_FALSE(s.init(bad, 2, 0.5, &error));
  EXPECT_NE(error.find("task 'odd' rate 30 Hz does not divide the tick rate 100 Hz"), std::string::npos) << error;
  const TaskSpec zero[] = {{"nav", 0, 2000, false}};
  EXPECT_FALSE(s.init(zero, 1, 0.5, &error));
}

}  // namespace
}  // namespace deepnav
