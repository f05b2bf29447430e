// FastCornerMap: the corner strength of FAST-9, and detection that gives, cell by cell and at any
// threshold from the strength's floor up, the corners of cv::FAST on the widened cell.
#include <gtest/gtest.h>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "tests/support/synthetic_plane_scene.h"
#include "vision/orbvo/fast_corner_map.h"

namespace deepnav {
namespace {

// cv::FAST on `cell` widened by the circle's radius, in image coordinates.
std::vector<cv::KeyPoint> openCvCorners(const cv::Mat& image, const cv::Rect& cell, int threshold) {
  const int r = FastCornerMap::kRadiusPx;
  const cv::Rect roi(cell.x - r, cell.y - r, cell.width + 2 * r, cell.height + 2 * r);
  std::vector<cv::KeyPoint> corners;
  cv::FAST(image(roi), corners, threshold, true, cv::FastFeatureDetector::TYPE_9_16);
  for (cv::KeyPoint& kp : corners) kp.pt += cv::Point2f(static_cast<float>(roi.x), static_cast<float>(roi.y));
  return corners;
}

void expectSameCorners(const std::vector<cv::KeyPoint>& expected, const std::vector<cv::KeyPoint>& got,
                       const std::string& where) {
  ASSERT_EQ(expected.size(), got.size()) << where;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(expected[i].pt, got[i].pt) << where << " corner " << i;
    EXPECT_EQ(expected[i].response, got[i].response) << where << " corner " << i;
  }
}

// A rendered 688x516 scene with sensor noise, and a dim copy: the extractor's usual input.
cv::Mat sceneImage(double contrast) { return renderOrbVoTestImage(5, contrast, 9); }

TEST(FastCornerMap, ReproducesOpenCvOnThisPlatform) {
  FastCornerMap map;
  map.init(688, 516);
  EXPECT_TRUE(map.exact());  // else the extractor pays cv::FAST per cell again
}

// One dark pixel with a bright arc of exactly 9 circle pixels 30 grey levels above it, the rest of the
// circle 10 above: the strength is 30 (the arc), a corner at thresholds below 30 only, with score 29.
TEST(FastCornerMap, StrengthIsTheBestArcOfNine) {
  cv::Mat image(21, 21, CV_8UC1, cv::Scalar(100));
  const int cx = 10, cy = 10;
  image.at<std::uint8_t>(cy, cx) = 50;
  const int circle[16][2] = {{0, 3}, {1, 3}, {2, 2}, {3, 1}, {3, 0}, {3, -1}, {2, -2}, {1, -3},
                             {0, -3}, {-1, -3}, {-2, -2}, {-3, -1}, {-3, 0}, {-3, 1}, {-2, 2}, {-1, 3}};
  for (int k = 0; k < 16; ++k) {
    image.at<std::uint8_t>(cy + circle[k][1], cx + circle[k][0]) = k >= 5 && k < 14 ? 80 : 60;
  }
  FastCornerMap map;
  map.init(image.cols, image.rows);
  map.compute(image, cv::Rect(3, 3, 15, 15), 1);
  EXPECT_EQ(map.strength().at<std::uint8_t>(cy, cx), 30);
  EXPECT_EQ(map.strength().at<std::uint8_t>(cy, cx + 4), 0);  // a flat neighbourhood
  std::vector<cv::KeyPoint> corners;
  const cv::Rect cell(5, 5, 11, 11);
  map.detect(cell, 29, &corners);
  ASSERT_FALSE(corners.empty());
  bool found = false;
  for (const cv::KeyPoint& kp : corners) found |= kp.pt == cv::Point2f(cx, cy) && kp.response == 29.0f;
  EXPECT_TRUE(found);
  map.detect(cell, 30, &corners);
  for (const cv::KeyPoint& kp : corners) EXPECT_NE(kp.pt, cv::Point2f(cx, cy));
  expectSameCorners(openCvCorners(image, cell, 29), [&] {
    std::vector<cv::KeyPoint> c;
    map.detect(cell, 29, &c);
    return c;
  }(), "synthetic corner");
}

// The extractor's grid (8 x 6 cells inside a 16 px border) on a rendered scene, its dim copy and the
// half-size level, at the thresholds the adaptive per-cell search uses.
TEST(FastCornerMap, SameCornersAsOpenCvCellByCell) {
  FastCornerMap map;
  map.init(688, 516);
  ASSERT_TRUE(map.exact());
  std::vector<cv::Mat> images = {sceneImage(0.6), sceneImage(0.1)};
  cv::Mat half;
  cv::resize(images[0], half, cv::Size(344, 258), 0.0, 0.0, cv::INTER_LINEAR);
  images.push_back(half);
  std::vector<cv::KeyPoint> got;
  int total = 0;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const cv::Mat& image = images[i];
    const int border = 16;
    const int w = image.cols - 2 * border, h = image.rows - 2 * border;
    map.compute(image, cv::Rect(border, border, w, h), 5);
    for (int gy = 0; gy < 6; ++gy) {
      for (int gx = 0; gx < 8; ++gx) {
        const cv::Rect cell(border + w * gx / 8, border + h * gy / 6, w * (gx + 1) / 8 - w * gx / 8,
                            h * (gy + 1) / 6 - h * gy / 6);
        for (int t : {5, 7, 12, 25, 40}) {
          const std::vector<cv::KeyPoint> expected = openCvCorners(image, cell, t);
          map.detect(cell, t, &got);
          expectSameCorners(expected, got,
                            "image " + std::to_string(i) + " cell " + std::to_string(gx) + "," +
                                std::to_string(gy) + " threshold " + std::to_string(t));
          total += static_cast<int>(got.size());
        }
      }
    }
  }
  EXPECT_GT(total, 10000);  // enough corners, and neighbours, for the non-maximum test to matter
}

// A row of cells computed in one go, each with its own floor (blocks across two cells take the lower
// one), gives in every cell cv::FAST's corners at that cell's floor and above; cells of uneven widths,
// narrower than a block, and floors that differ by a lot between neighbours.
TEST(FastCornerMap, RowOfCellsGivesEachCellItsCorners) {
  FastCornerMap map;
  map.init(688, 516);
  ASSERT_TRUE(map.exact());
  const cv::Mat image = sceneImage(0.6);
  const std::vector<int> x_edges = {19, 100, 181, 190, 203, 260, 341, 422, 503, 584, 668};
  const std::vector<int> floors = {20, 5, 40, 9, 25, 12, 7, 30, 18, 11};
  std::vector<cv::KeyPoint> got;
  int total = 0;
  for (int y0 : {19, 100, 416}) {
    const int y1 = y0 + 81;
    map.computeCells(image, y0, y1, x_edges.data(), floors.data(), static_cast<int>(floors.size()));
    for (std::size_t c = 0; c < floors.size(); ++c) {
      const cv::Rect cell(x_edges[c], y0, x_edges[c + 1] - x_edges[c], y1 - y0);
      for (int t : {floors[c], floors[c] + 3, 40}) {
        const std::vector<cv::KeyPoint> expected = openCvCorners(image, cell, t);
        map.detect(cell, t, &got);
        expectSameCorners(expected, got,
                          "row " + std::to_string(y0) + " cell " + std::to_string(c) + " threshold " +
                              std::to_string(t));
        total += static_cast<int>(got.size());
      }
    }
  }
  EXPECT_GT(total, 2000);
}

// An image within the init area but wider than the init width needs more blocks per row than were sized:
// refused with an error, not written past the buffer.
TEST(FastCornerMap, WiderThanTheInitWidthIsRefused) {
  FastCornerMap map;
  map.init(64, 64);
  cv::Mat wide(20, 400, CV_8UC1);
  cv::RNG(5).fill(wide, cv::RNG::UNIFORM, 0, 256);
  EXPECT_THROW(map.compute(wide, cv::Rect(3, 3, wide.cols - 6, wide.rows - 6), 5), cv::Exception);
  EXPECT_NO_THROW(map.compute(wide, cv::Rect(3, 3, 90, wide.rows - 6), 5));
}

// A cell touching the image's 3 px margin, a 1-pixel-wide cell and cells whose width is not a multiple
// of 16 (the vector scan's tail), on noise where neighbours often tie.
TEST(FastCornerMap, OddCellsAndTiesOnNoise) {
  cv::Mat image(64, 75, CV_8UC1);
  cv::RNG(17).fill(image, cv::RNG::UNIFORM, 0, 4);
  image *= 50;
  FastCornerMap map;
  map.init(image.cols, image.rows);
  map.compute(image, cv::Rect(3, 3, image.cols - 6, image.rows - 6), 1);
  std::vector<cv::KeyPoint> got;
  for (const cv::Rect& cell : {cv::Rect(3, 3, 69, 58), cv::Rect(10, 7, 1, 40), cv::Rect(4, 9, 33, 17),
                               cv::Rect(40, 30, 17, 31)}) {
    for (int t : {1, 20, 60}) {
      map.detect(cell, t, &got);
      expectSameCorners(openCvCorners(image, cell, t), got, "cell x " + std::to_string(cell.x));
    }
  }
}

// Areas narrower than 16 px take the scalar formulation; it must give the vector one's strengths (every
// value above the floor, both polarities) and the same corners as cv::FAST on narrow cells.
TEST(FastCornerMap, ScalarStrengthsEqualTheVectorOnes) {
  cv::Mat image(60, 70, CV_8UC1);
  cv::RNG(23).fill(image, cv::RNG::UNIFORM, 0, 256);
  FastCornerMap map;
  map.init(image.cols, image.rows);
  const int floor = 1;
  map.compute(image, cv::Rect(3, 3, image.cols - 6, image.rows - 6), floor);
  const cv::Mat vector_strength = map.strength().clone();
  std::vector<cv::KeyPoint> got;
  int above_floor = 0;
  for (int x = 3; x < image.cols - 3; x += 8) {
    const cv::Rect strip(x, 3, std::min(8, image.cols - 3 - x), image.rows - 6);  // scalar: < 16 px
    map.compute(image, strip, floor);
    for (int y = strip.y; y < strip.y + strip.height; ++y) {
      for (int u = strip.x; u < strip.x + strip.width; ++u) {
        const int v = vector_strength.at<std::uint8_t>(y, u);
        if (v <= floor && map.strength().at<std::uint8_t>(y, u) <= floor) continue;
        ++above_floor;
        ASSERT_EQ(map.strength().at<std::uint8_t>(y, u), v) << "pixel " << u << "," << y;
      }
    }
    map.detect(strip, 30, &got);
    expectSameCorners(openCvCorners(image, strip, 30), got, "strip x " + std::to_string(x));
  }
  EXPECT_GT(above_floor, 1000);
}

TEST(FastCornerMap, DetectDoesNotAllocateWithinCapacity) {
  const cv::Mat image = sceneImage(0.6);
  FastCornerMap map;
  map.init(image.cols, image.rows);
  map.compute(image, cv::Rect(19, 19, 80, 80), 5);
  std::vector<cv::KeyPoint> got;
  got.reserve(4096);
  const cv::KeyPoint* data = got.data();
  map.detect(cv::Rect(19, 19, 80, 80), 5, &got);
  EXPECT_FALSE(got.empty());
  EXPECT_EQ(got.data(), data);
}

}  // namespace
}  // namespace deepnav
