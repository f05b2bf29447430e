// StereoFeatureMatcher: row-band ORB matching with subpixel ZSAD refinement on rectified pairs of
// known disparity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "tests/support/synthetic_plane_scene.h"
#include "vision/orbvo/grid_orb_extractor.h"
#include "vision/orbvo/stereo_feature_matcher.h"

namespace deepnav {
namespace {

struct Pair {
  cv::Mat left, right;
};

// A fronto-parallel textured wall at depth_m filling the view, seen by the default rig.
Pair wallPair(double depth_m, double extra_right_shift_v_px = 0.0) {
  SyntheticPlaneScene scene;
  TexturedPlane wall;
  wall.texel_m = 0.0015 * depth_m;
  wall.texture = makeSyntheticTexture(1000, 800, 21, 0.6);
  wall.p_origin_in_world_m = {-0.75 * depth_m, -0.6 * depth_m, depth_m};
  scene.addPlane(wall);
  Pair pair;
  scene.render(StereoRig{}, Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 90, &pair.left,
               &pair.right);
  if (extra_right_shift_v_px != 0.0) {
    const cv::Matx23d shift(1.0, 0.0, 0.0, 0.0, 1.0, extra_right_shift_v_px);
    cv::warpAffine(pair.right, pair.right, shift, pair.right.size(), cv::INTER_LINEAR,
                   cv::BORDER_REPLICATE);
  }
  return pair;
}

struct Matched {
  std::vector<OrbFeature> left;
  std::vector<float> u_right_px;
  std::vector<Eigen::Vector3d> p_in_cam_m;
  int matches = 0;
};

Matched matchPair(const Pair& pair) {
  GridOrbExtractor left_extractor, right_extractor;
  OrbExtractorConfig right_config;
  right_config.max_features_per_cell *= 2;
  EXPECT_TRUE(left_extractor.init(OrbExtractorConfig(), 688, 516));
  EXPECT_TRUE(right_extractor.init(right_config, 688, 516));
  std::vector<OrbFeature> right;
  std::vector<OrbDescriptor> left_desc, right_desc;
  Matched m;
  left_extractor.extract(pair.left, &m.left, &left_desc);
  right_extractor.extract(pair.right, &right, &right_desc);
  StereoFeatureMatcher matcher;
  EXPECT_TRUE(matcher.init(StereoMatchConfig(), StereoRig{}, right_extractor.capacity(), 1.2));
  m.matches = matcher.match(pair.left, pair.right, m.left, left_desc, right, right_desc,
                            &m.u_right_px, &m.p_in_cam_m);
  return m;
}

TEST(OrbVoStereoMatcher, RecoversTheDisparityOfAWallToSubpixel) {
  // GIVEN a wall at 2 m: disparity fx b / z = 700 * 0.3 / 2 = 105 px everywhere
  const Matched m = matchPair(wallPair(2.0));
  // THEN the features that can be seen by both cameras are matched, with the right disparity
  int visible = 0;
  double sum_sq = 0.0;
  int gross = 0;
  for (std::size_t i = 0; i < m.left.size(); ++i) {
    if (m.left[i].u_px > 105.0 + 20.0) ++visible;
    if (m.u_right_px[i] < 0.0f) continue;
    const double error_px = (m.left[i].u_px - m.u_right_px[i]) - 105.0;
    if (std::abs(error_px) > 1.0) {
      ++gross;
      continue;
    }
    sum_sq += error_px * error_px;
    EXPECT_NEAR(m.p_in_cam_m[i].z(), 2.0, 0.03);
  }
  const double rms_px = std::sqrt(sum_sq / std::max(1, m.matches - gross));
  std::printf("wall at 2 m: %d matches of %d visible features, disparity rms %.3f px, %d gross\n",
              m.matches, visible, rms_px, gross);
  EXPECT_GT(m.matches, visible / 2);
  EXPECT_LT(rms_px, 0.15);
  EXPECT_LE(gross, m.matches / 100);
}

TEST(OrbVoStereoMatcher, RowsOutOfTheBandAreNotMatched) {
  // GIVEN a right image 6 px lower than it should be (a broken rectification)
  const Matched m = matchPair(wallPair(2.0, 6.0));
  // THEN almost nothing passes the +-2 px band (coarse levels have a wider band)
  int level0 = 0;
  for (std::size_t i = 0; i < m.left.size(); ++i)
    level0 += m.left[i].level == 0 && m.u_right_px[i] >= 0.0f;
  EXPECT_LT(level0, 5);
}

TEST(OrbVoStereoMatcher, ParabolaRefinementFindsAFractionalShift) {
  // GIVEN a right image that is the left one moved left by 10.3 px
  cv::Mat left = makeSyntheticTexture(688, 516, 5, 0.6);
  cv::Mat right;
  const cv::Matx23d shift(1.0, 0.0, -10.3, 0.0, 1.0, 0.0);
  cv::warpAffine(left, right, shift, left.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  StereoFeatureMatcher matcher;
  ASSERT_TRUE(matcher.init(StereoMatchConfig(), StereoRig{}, 10, 1.2));
  std::vector<double> errors_px;
  for (int v = 40; v < 480; v += 37) {
    for (int u = 60; u < 640; u += 41) {
      double u_right = 0.0;
      // WHEN refined from a guess one pixel off
      if (!matcher.refineRightColumn(left, right, u, v, u - 11.0, &u_right)) continue;
      errors_px.push_back(std::abs(u_right - (u - 10.3)));
    }
  }
  // THEN the subpixel column comes back within a tenth of a pixel (the bilinear shift of this noisy
  // texture is itself not exact: the finest noise is near the sampling limit)
  ASSERT_GT(errors_px.size(), 100u);
  std::sort(errors_px.begin(), errors_px.end());
  EXPECT_LT(errors_px[errors_px.size() / 2], 0.1);
  EXPECT_LT(errors_px[errors_px.size() * 9 / 10], 0.3);
}

}  // namespace
}  // namespace deepnav
