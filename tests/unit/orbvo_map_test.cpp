// VoMap: keyframe ring with eviction of the oldest, map points freed when no keyframe refers to
// them.
#include <gtest/gtest.h>

#include "vision/orbvo/vo_map.h"

namespace deepnav {
namespace {

TEST(OrbVoMap, EvictingTheOldestKeyframeFreesOnlyItsOwnPoints) {
  VoMap map;
  ASSERT_TRUE(map.init(3, 4, 10));
  // GIVEN keyframe 0 with two points, one of them also seen by keyframe 1
  Keyframe& kf0 = map.pushKeyframe();
  const int shared = map.createPoint(Eigen::Vector3d(1, 0, 2), OrbDescriptor{}, 0);
  const int own = map.createPoint(Eigen::Vector3d(0, 1, 2), OrbDescriptor{}, 0);
  kf0.map_point = {shared, own};
  map.addReference(shared);
  Keyframe& kf1 = map.pushKeyframe();
  kf1.map_point = {shared, -1};
  map.pushKeyframe();
  EXPECT_EQ(map.keyframeCount(), 3);
  EXPECT_EQ(map.mapPointCount(), 2);
  EXPECT_EQ(map.keyframe(2).id, 0);  // the oldest
  EXPECT_EQ(map.keyframe(0).id, 2);  // the newest
  // WHEN a fourth keyframe evicts keyframe 0
  map.pushKeyframe();
  // THEN its own point is freed and the shared one lives on
  EXPECT_EQ(map.keyframeCount(), 3);
  EXPECT_EQ(map.keyframe(2).id, 1);
  EXPECT_EQ(map.mapPointCount(), 1);
  EXPECT_TRUE(map.point(shared).alive);
  EXPECT_FALSE(map.point(own).alive);
  EXPECT_EQ(map.point(shared).references, 1);
}

TEST(OrbVoMap, PoolRefusesWhenFullAndReusesFreedPoints) {
  VoMap map;
  ASSERT_TRUE(map.init(3, 4, 2));
  const int a = map.createPoint(Eigen::Vector3d::Zero(), OrbDescriptor{}, 0);
  const int b = map.createPoint(Eigen::Vector3d::Zero(), OrbDescriptor{}, 0);
  EXPECT_GE(a, 0);
  EXPECT_GE(b, 0);
  EXPECT_EQ(map.createPoint(Eigen::Vector3d::Zero(), OrbDescriptor{}, 0), -1);
  map.releaseReference(a);
  EXPECT_EQ(map.mapPointCount(), 1);
  EXPECT_EQ(map.createPoint(Eigen::Vector3d::Ones(), OrbDescriptor{}, 1), a);
  map.clear();
  EXPECT_EQ(map.mapPointCount(), 0);
  EXPECT_EQ(map.keyframeCount(), 0);
}

}  // namespace
}  // namespace deepnav
