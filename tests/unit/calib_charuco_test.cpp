#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

#include "tools/sim/calib/charuco_images.h"
#include "vision/calib/charuco_view.h"
#include "vision/calib/stereo_charuco_calibration.h"

namespace deepnav {
namespace {

class CalibCharuco : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    renderer_ = new sim::CharucoImageRenderer();
    ASSERT_TRUE(renderer_->init(CharucoTarget{}, sim::simulatedCalibrationRig(), &error)) << error;
    pairs_ = new std::vector<CalibrationPairInput>(sim::makeCalibrationPairs(*renderer_, 7));
    result_ = new StereoCharucoResult();
    ok_ = calibrateStereoCharuco(*pairs_, CharucoTarget{}, result_, &error);
    error_ = error;
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete pairs_;
    delete result_;
  }
  static const CalibrationPairReport* report(const std::string& name) {
    for (const auto& r : result_->pairs)
      if (r.name == name) return &r;
    return nullptr;
  }
  static sim::CharucoImageRenderer* renderer_;
  static std::vector<CalibrationPairInput>* pairs_;
  static StereoCharucoResult* result_;
  static bool ok_;
  static std::string error_;
};

sim::CharucoImageRenderer* CalibCharuco::renderer_ = nullptr;
std::vector<CalibrationPairInput>* CalibCharuco::pairs_ = nullptr;
StereoCharucoResult* CalibCharuco::result_ = nullptr;
bool CalibCharuco::ok_ = false;
std::string CalibCharuco::error_;

TEST_F(CalibCharuco, RenderedCornersLieWhereTheBoardProjects) {
  // GIVEN the first pose rendered; THEN the detected ChArUco corners are the board corners projected
  // through the true camera (the generator and OpenCV agree on the board), to a fraction of a pixel.
  const auto board = makeCharucoBoard(CharucoTarget{});
  const sim::BoardPose pose = sim::calibrationPoses()[0];
  const CharucoView view = detectCharucoView((*pairs_)[0].left, board);
  ASSERT_GE(view.ids.size(), 30u);
  cv::Mat rvec;
  cv::Rodrigues(cv::Mat(pose.R_left_board), rvec);
  std::vector<cv::Point3f> object;
  for (int id : view.ids) object.push_back(board->chessboardCorners[id]);
  std::vector<cv::Point2f> projected;
  const StereoCalibration rig = sim::simulatedCalibrationRig();
  cv::projectPoints(object, rvec, cv::Mat(pose.p_board_in_left_m), rig.left.K, rig.left.dist, projected);
  double worst = 0.0;
  for (std::size_t i = 0; i < projected.size(); ++i) worst = std::max(worst, cv::norm(projected[i] - view.corners_px[i]));
  EXPECT_LT(worst, 0.25);
  EXPECT_LT(view.edge_width_px, 2.5);
}

TEST_F(CalibCharuco, RecoversSimulatedIntrinsicsAndExtrinsics) {
  ASSERT_TRUE(ok_) << error_;
  const StereoCalibration truth = sim::simulatedCalibrationRig();
  const StereoCalibration& est = result_->calibration;
  std::printf("ChArUco stereo calibration: %d pairs used, rms %.3f px (mono %.3f / %.3f px)\n", result_->pairs_used,
              result_->rms_px, result_->rms_left_mono_px, result_->rms_right_mono_px);
  for (bool right : {false, true}) {
    const CameraCalibration& e = right ? est.right : est.left;
    const CameraCalibration& t = right ? truth.right : truth.left;
    std::printf("  %s: fx %.2f (true %.2f) fy %.2f (%.2f) cx %.2f (%.2f) cy %.2f (%.2f) k1 %.4f (%.4f) k2 %.4f (%.4f)\n",
                right ? "right" : "left", e.K(0, 0), t.K(0, 0), e.K(1, 1), t.K(1, 1), e.K(0, 2), t.K(0, 2), e.K(1, 2),
                t.K(1, 2), e.dist.at<double>(0), t.dist.at<double>(0), e.dist.at<double>(1), t.dist.at<double>(1));
    // Tolerances: focal lengths 0.3 %, principal point 2 px, k1 0.01, k2 0.03.
    EXPECT_NEAR(e.K(0, 0), t.K(0, 0), 0.003 * t.K(0, 0));
    EXPECT_NEAR(e.K(1, 1), t.K(1, 1), 0.003 * t.K(1, 1));
    EXPECT_NEAR(e.K(0, 2), t.K(0, 2), 2.0);
    EXPECT_NEAR(e.K(1, 2), t.K(1, 2), 2.0);
    EXPECT_NEAR(e.dist.at<double>(0), t.dist.at<double>(0), 0.01);
    EXPECT_NEAR(e.dist.at<double>(1), t.dist.at<double>(1), 0.03);
  }
  // Extrinsics: rotation within 0.1 deg, baseline within 1 mm, translation direction within 0.2 deg.
  cv::Mat dR;
  cv::Rodrigues(cv::Mat(est.R * truth.R.t()), dR);
  const double rot_err_deg = cv::norm(dR) * 180.0 / CV_PI;
  const double baseline_err_m = std::abs(cv::norm(est.T) - cv::norm(truth.T));
  const double dir_err_deg =
      std::acos(std::min(1.0, est.T.dot(truth.T) / (cv::norm(est.T) * cv::norm(truth.T)))) * 180.0 / CV_PI;
  std::printf("  extrinsics: rotation error %.4f deg, baseline error %.2f mm, T direction error %.3f deg\n",
              rot_err_deg, baseline_err_m * 1e3, dir_err_deg);
  EXPECT_LT(rot_err_deg, 0.1);
  EXPECT_LT(baseline_err_m, 0.001);
  EXPECT_LT(dir_err_deg, 0.2);
  EXPECT_LT(result_->rms_px, 0.3);
}

TEST_F(CalibCharuco, BadViewsAreRejectedWithTheirReason) {
  const CalibrationPairReport* blurred = report("blurred");
  const CalibrationPairReport* duplicate = report("duplicate");
  const CalibrationPairReport* few = report("few_corners");
  ASSERT_TRUE(blurred && duplicate && few);
  EXPECT_FALSE(blurred->used);
  EXPECT_EQ(blurred->reason.rfind("blur:", 0), 0u) << blurred->reason;
  EXPECT_FALSE(duplicate->used);
  EXPECT_EQ(duplicate->reason.rfind("duplicate view of pose_0", 0), 0u) << duplicate->reason;
  EXPECT_FALSE(few->used);
  EXPECT_EQ(few->reason.rfind("too few corners", 0), 0u) << few->reason;
  // Every good pose is used, each with a small reprojection error.
  for (const auto& r : result_->pairs) {
    if (r.name.rfind("pose_", 0) != 0) continue;
    EXPECT_TRUE(r.used) << r.name << ": " << r.reason;
    EXPECT_LT(r.rms_left_px, 0.4) << r.name;
    EXPECT_LT(r.rms_right_px, 0.4) << r.name;
  }
  for (const auto& r : result_->pairs)
    std::printf("  %-12s %s corners %d/%d edge %.2f/%.2f px rms %.3f/%.3f px %s\n", r.name.c_str(),
                r.used ? "used    " : "rejected", r.corners_left, r.corners_right, r.edge_width_left_px,
                r.edge_width_right_px, r.rms_left_px, r.rms_right_px, r.reason.c_str());
}

TEST_F(CalibCharuco, TooFewUsablePairsIsAnError) {
  std::vector<CalibrationPairInput> few(pairs_->begin(), pairs_->begin() + 3);
  StereoCharucoResult result;
  std::string error;
  EXPECT_FALSE(calibrateStereoCharuco(few, CharucoTarget{}, &result, &error));
  EXPECT_NE(error.find("3 usable pairs out of 3"), std::string::npos) << error;
  EXPECT_EQ(result.pairs.size(), 3u);
}

TEST(CalibCharucoTarget, InconsistentTargetNamesTheField) {
  CharucoTarget t;
  std::string error;
  EXPECT_TRUE(validateCharucoTarget(t, &error)) << error;
  t.marker_m = 0.07;
  EXPECT_FALSE(validateCharucoTarget(t, &error));
  EXPECT_NE(error.find("marker_m"), std::string::npos) << error;
  t = CharucoTarget{};
  t.dictionary = "DICT_9X9_1";
  EXPECT_FALSE(validateCharucoTarget(t, &error));
  EXPECT_NE(error.find("dictionary"), std::string::npos) << error;
  t = CharucoTarget{};
  t.dictionary = "DICT_4X4_50";
  t.squares_x = 12;
  t.squares_y = 10;
  EXPECT_FALSE(validateCharucoTarget(t, &error));
  EXPECT_NE(error.find("needs 60"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
