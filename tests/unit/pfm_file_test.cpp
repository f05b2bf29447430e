#include "drivers/files/pfm_file.h"

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

namespace deepnav {
namespace {

TEST(PfmFile, RoundTripWithInvalidPixelsAsInfinity) {
  cv::Mat d(3, 4, CV_32FC1);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) d.at<float>(y, x) = static_cast<float>(10 * y + x) + 0.25f;
  }
  d.at<float>(1, 2) = -1.0f;
  const std::string path = ::testing::TempDir() + "d.pfm";
  std::string error;
  ASSERT_TRUE(writePfm(path, d, &error)) << error;
  cv::Mat r;
  ASSERT_TRUE(readPfm(path, &r, &error)) << error;
  EXPECT_EQ(r.at<float>(0, 0), 0.25f);  // top row first in memory, bottom row first in the file
  EXPECT_EQ(r.at<float>(2, 3), 23.25f);
  EXPECT_TRUE(std::isinf(r.at<float>(1, 2)));
  std::ifstream raw(path, std::ios::binary);
  std::string header(16, '\0');
  raw.read(header.data(), 12);
  EXPECT_EQ(header.substr(0, 12), "Pf\n4 3\n-1.0\n");
}

TEST(PfmFile, GarbageIsRefused) {
  const std::string path = ::testing::TempDir() + "bad.pfm";
  std::ofstream(path) << "P5\n1 1\n255\n";
  cv::Mat r;
  std::string error;
  EXPECT_FALSE(readPfm(path, &r, &error));
  EXPECT_NE(error.find(path), std::string::npos);
}

}  // namespace
}  // namespace deepnav
