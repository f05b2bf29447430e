#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "vision/iqa/image_quality_score.h"
#include "vision/iqa/mdm.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

using deepnav::testing::sharedDataDir;

TEST(Mdm, MatchesAuthorsReferenceCode) {
  const std::filesystem::path data = sharedDataDir();
  std::ifstream file(data / "iqa" / "mdm_reference.txt");
  if (!file) GTEST_SKIP() << "no MDM reference under " << data;
  MdmWorkspace ws;
  int checked = 0;
  for (std::string line; std::getline(file, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name;
    double f1 = 0, f2 = 0, f3_bits = 0;
    ASSERT_TRUE(fields >> name >> f1 >> f2 >> f3_bits) << line;
    const cv::Mat image = cv::imread((data / name).string(), cv::IMREAD_COLOR);
    if (image.empty()) GTEST_SKIP() << "missing " << name;
    MdmScore score;
    ASSERT_TRUE(computeMdm(image, &score, &ws));
    EXPECT_NEAR(score.f1, f1, 1e-3) << name;
    EXPECT_NEAR(score.f2, f2, 1e-3) << name;
    EXPECT_NEAR(score.f3_bits, f3_bits, 1e-3) << name;
    EXPECT_NEAR(score.f3, f3_bits / 8.0, 1e-3 / 8.0) << name;
    EXPECT_NEAR(score.score, (score.f1 + score.f2 + score.f3) / 3.0, 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(Mdm, FlatImageHasNoContrastAndNoEntropy) {
  // GIVEN a uniform grey image WHEN scored THEN every deviation and the entropy vanish.
  const cv::Mat flat(100, 120, CV_8UC1, cv::Scalar(90));
  MdmWorkspace ws;
  MdmScore score;
  ASSERT_TRUE(computeMdm(flat, &score, &ws));
  EXPECT_DOUBLE_EQ(score.f1, 0.0);
  EXPECT_DOUBLE_EQ(score.f2, 0.0);
  EXPECT_DOUBLE_EQ(score.f3_bits, 0.0);
}

TEST(Mdm, LowContrastScoresBelowFullRange) {
  // GIVEN a ramp over the full range and the same ramp squeezed into [100, 140]
  cv::Mat full(64, 256, CV_8UC1), squeezed(64, 256, CV_8UC1);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 256; ++x) {
      full.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(x);
      squeezed.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(100 + x * 40 / 255);
    }
  }
  MdmWorkspace ws;
  MdmScore a, b;
  ASSERT_TRUE(computeMdm(full, &a, &ws));
  ASSERT_TRUE(computeMdm(squeezed, &b, &ws));
  // THEN the squeezed ramp scores lower on every feature (entropy of 128 vs 41 levels: 7 vs ~5.4
  // bits)
  EXPECT_LT(b.f1, a.f1);
  EXPECT_LT(b.f2, a.f2);
  EXPECT_NEAR(a.f3_bits, 7.0, 1e-9);  // step 2 keeps the 128 even levels, uniformly
  EXPECT_LT(b.f3_bits, a.f3_bits);
  EXPECT_LT(b.score, a.score);
}

TEST(Mdm, RejectsEmptyAndUnsupportedImages) {
  MdmWorkspace ws;
  MdmScore score;
  EXPECT_FALSE(computeMdm(cv::Mat(), &score, &ws));
  EXPECT_FALSE(computeMdm(cv::Mat(10, 10, CV_32FC1, cv::Scalar(0.5)), &score, &ws));
  EXPECT_FALSE(computeMdm(cv::Mat(10, 10, CV_8UC1), nullptr, &ws));
}

TEST(Mdm, StepFollowsImageSize) {
  EXPECT_EQ(mdmStep(288, 384), 2);
  EXPECT_EQ(mdmStep(516, 688), 2);
  EXPECT_EQ(mdmStep(1536, 2048), 3);
  EXPECT_EQ(mdmStep(2048, 2048), 4);
}

TEST(ImageQualityScore, AveragesMdmFeaturesAndOrbRatio) {
  MdmScore mdm;
  mdm.f1 = 0.9;
  mdm.f2 = 0.8;
  mdm.f3 = 0.7;
  EXPECT_NEAR(imageQualityScore(mdm, 50, 200), (0.9 + 0.8 + 0.7 + 0.25) / 4.0, 1e-12);
  EXPECT_NEAR(imageQualityScore(mdm, 500, 200), (0.9 + 0.8 + 0.7 + 1.0) / 4.0, 1e-12);
  EXPECT_NEAR(imageQualityScore(mdm, 10, 0), (0.9 + 0.8 + 0.7) / 4.0, 1e-12);
}

}  // namespace
}  // namespace deepnav
