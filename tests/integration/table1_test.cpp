// deepnav-table1's evaluation on a short rendered dive (the vehicle holding 2 m from the panel's left
// face, cameras pitched down to the seabed, moderate water): the
// GT row must be exact and its planes must register with a small rotation error; the matchers must
// be sane. The full Table I on the default dive is in tools/eval/README.md.
#include "tools/eval/table1.h"

#include <gtest/gtest.h>

#include "tests/support/test_dive.h"

namespace deepnav {
namespace {

TEST(Table1, ShortDiveGivesAnExactGtRowAndSaneMatchers) {
  // GIVEN a 3 s rendered dive (31 stereo pairs with truth maps) that starts 2 m from the left face
  // and at the face's depth, cameras pitched 25 deg down: the face and the seabed in view (two planes).
  const std::string dive = testing::makeTestDive(
      "table1", 3.0, 7, true,
      {{"start_distance_m: 8.0", "start_distance_m: 2.0"},
       {"start_depth_m: 998.0", "start_depth_m: 998.5"},
       {"mount_rpy_deg: [0.0, 0.0, 0.0]   # [-360, 360] zero:", "mount_rpy_deg: [0.0, 25.0, 0.0]   # [-360, 360] zero:"}});
  eval::Table1Options o;
  o.eval_from_s = 0.5;
  o.map_every = 5;          // stage-1 map from the pairs at 0, 0.5, 1.0, ... s
  o.max_frames = 10;
  // The board's dense chain at half size with 96 disparities (the board's default is 128, for the dive's
  // closer dwells): the face ~1.4 m from the camera is at ~75 px, and a shorter range leaves SGBM a
  // narrower unmatched band at the left border.
  o.num_disparities = 96;
  // WHEN Table I is computed
  eval::Table1Result r;
  std::string error;
  ASSERT_TRUE(eval::runTable1(dive, o, &r, &error)) << error;
  // THEN every row scored the same pairs
  EXPECT_GE(r.map_frames, 5);
  for (const eval::Table1Row& row : r.rows) EXPECT_EQ(row.frames, 10) << row.name;
  // the true disparity is exact and complete
  const eval::Table1Row& gt = r.rows[eval::kRowGt];
  EXPECT_EQ(gt.d1_mean, 0.0);
  EXPECT_EQ(gt.coverage_mean, 1.0);
  // its planes exist and register with a small error (the true motion is a slow drift)
  EXPECT_GE(gt.planes_mean, 1.0);
  EXPECT_GE(gt.registered, 1);
  EXPECT_LT(gt.rot_err_mean_deg, 0.5);
  // the matchers are right on most pixels of this textured, distant view
  EXPECT_LT(r.rows[eval::kRowElas].d1_mean, 0.25);
  EXPECT_LT(r.rows[eval::kRowSgbm].d1_mean, 0.35);
  EXPECT_GT(r.rows[eval::kRowElas].coverage_mean, 0.6);
  // the filter only removes points: coverage never grows
  EXPECT_LE(r.rows[eval::kRowElasFilter].coverage_mean, r.rows[eval::kRowElas].coverage_mean);
  EXPECT_LE(r.rows[eval::kRowSgbmFilter].coverage_mean, r.rows[eval::kRowSgbm].coverage_mean);
  // and the report names every row
  const std::string table = eval::table1Markdown(r);
  for (const char* name : {"| GT |", "| ELAS |", "| SGBM |", "| ELAS+Filter |", "| SGBM+Filter |"})
    EXPECT_NE(table.find(name), std::string::npos) << name;
  EXPECT_NE(eval::table1Json(r).find("\"rot_err_mean_deg\""), std::string::npos);
}

}  // namespace
}  // namespace deepnav
