// The line `deepnav run` writes to the journal at stop: each driver that ran, with what it lost.
#include <gtest/gtest.h>

#include "board/service/driver_summary.h"

namespace deepnav {
namespace {

TEST(DriverSummary, NothingWhenNoDriverRan) { EXPECT_EQ(formatDriverSummary(SensorThreads::Status{}), ""); }

TEST(DriverSummary, NamesEachDriverThatRanWithItsLossesAndReopens) {
  SensorThreads::Status s;
  s.dvl_on = true;
  s.dvl.frames = 1200;
  s.dvl.bad_frames = 3;
  s.dvl.sink_refused = 1;
  s.dvl_reopens = 2;
  s.can_on = true;
  s.can.frames = 800;
  s.can_bus_state = "error-passive";
  s.can_tx_errors = 130;
  s.can_rx_errors = 7;
  s.depth_on = true;
  s.depth_reads = 300;
  s.depth_failures = 4;
  EXPECT_EQ(formatDriverSummary(s),
            "dvl 1200 frames, 3 bad, 1 refused, 2 reopens | can 800 frames, 0 bad, 0 refused, 0 reopens, bus "
            "error-passive, tx errors 130, rx errors 7 | depth 300 reads, 4 failed");
}

TEST(DriverSummary, AnAhrsAloneIsNamedAsTheAhrs) {
  SensorThreads::Status s;
  s.ahrs_on = true;
  s.ahrs.frames = 5;
  EXPECT_EQ(formatDriverSummary(s), "ahrs 5 frames, 0 bad, 0 refused, 0 reopens");
}

}  // namespace
}  // namespace deepnav
