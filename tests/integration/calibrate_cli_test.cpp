// `deepnav calibrate` as a user runs it: rendered ChArUco pairs written as PNGs, a target.yaml, the
// command line; the calibration file it writes holds the simulated rig and rectifies it.
#include <cstdio>
#include <filesystem>
#include <fstream>


#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "board/config/board_config.h"
#include "board/config/camera_rectification.h"
#include "board/config/stereo_calibration_file.h"
#include "tools/sim/calib/charuco_images.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_path.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;

const char* kTarget =
    "squares_x: 8\nsquares_y: 6\nsquare_m: 0.06\nmarker_m: 0.045\ndictionary: DICT_5X5_100\nmin_corners: 12\n";

using deepnav::testing::CliRun;
using deepnav::testing::runDeepnav;

class CalibrateCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each case in its own process, in parallel: one folder per process.
    dir_ = new fs::path(deepnav::testing::tempPath("calibrate_cli"));
    fs::remove_all(*dir_);
    fs::create_directories(*dir_ / "images");
    sim::CharucoImageRenderer renderer;
    std::string error;
    ASSERT_TRUE(renderer.init(CharucoTarget{}, sim::simulatedCalibrationRig(), &error)) << error;
    int index = 0;
    for (const auto& pair : sim::makeCalibrationPairs(renderer, 3)) {
      char prefix[16];
      std::snprintf(prefix, sizeof prefix, "%02d_", index++);  // the order they were taken in
      cv::imwrite((*dir_ / "images" / (prefix + pair.name + "_left.png")).string(), pair.left);
      cv::imwrite((*dir_ / "images" / (prefix + pair.name + "_right.png")).string(), pair.right);
    }
    std::ofstream(*dir_ / "target.yaml") << kTarget;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path* dir_;
};

fs::path* CalibrateCli::dir_ = nullptr;

TEST_F(CalibrateCli, WritesTheRigAndReportsEveryPair) {
  const fs::path out = *dir_ / "calibration.yaml";
  const CliRun r = runDeepnav("calibrate --target " + (*dir_ / "target.yaml").string() + " " +
                           (*dir_ / "images").string() + " --out " + out.string());
  std::printf("%s", r.out.c_str());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // Per-pair report with the rejected ones and their reasons, the overall error, camera_info.
  EXPECT_NE(r.out.find("14_blurred_left.png"), std::string::npos);
  EXPECT_NE(r.out.find("blur: edges"), std::string::npos);
  EXPECT_NE(r.out.find("duplicate view of 00_pose_0_left.png"), std::string::npos);
  EXPECT_NE(r.out.find("too few corners"), std::string::npos);
  EXPECT_NE(r.out.find("14 of 17 pairs used"), std::string::npos);
  EXPECT_NE(r.out.find("left camera_info:"), std::string::npos);
  EXPECT_NE(r.out.find("distortion_model: plumb_bob"), std::string::npos);
  // The file holds the simulated rig.
  StereoCalibration calib;
  std::string error;
  ASSERT_TRUE(readStereoCalibrationFile(out.string(), &calib, &error)) << error;
  const StereoCalibration truth = sim::simulatedCalibrationRig();
  EXPECT_EQ(calib.image_size, truth.image_size);
  EXPECT_NEAR(calib.left.K(0, 0), truth.left.K(0, 0), 0.003 * truth.left.K(0, 0));
  EXPECT_NEAR(calib.right.K(1, 1), truth.right.K(1, 1), 0.003 * truth.right.K(1, 1));
  EXPECT_NEAR(cv::norm(calib.T), cv::norm(truth.T), 0.001);
  // A board pointing at it, with a flat port, builds PinAx rectification maps at start-up.
  std::ofstream(*dir_ / "board.yaml") << "camera:\n  calibration_file: calibration.yaml\n  port:\n    model: flat\n"
                                          "    pinhole_to_glass_m: 0.004\n    glass_thickness_m: 0.012\n";
  BoardConfig config;
  ASSERT_TRUE(loadBoardConfig((*dir_ / "board.yaml").string(), &config, &error)) << error;
  StereoRectification rect;
  bool needed = false;
  ASSERT_TRUE(buildCameraRectification(config, dir_->string(), &rect, &needed, &error)) << error;
  EXPECT_TRUE(needed);
  EXPECT_GT(rect.virtual_centre_z_m, -0.01);
  EXPECT_GT(rect.rectified.fx_px, 1.3 * truth.left.K(0, 0));  // water narrows the view
}

TEST_F(CalibrateCli, BadTargetFileNamesTheField) {
  const fs::path images = *dir_ / "images";
  struct Case {
    const char* yaml;
    const char* expected;
  } cases[] = {
      {"squares_x: 8\nsquares_y: 6\nsquare_m: 0.06\ndictionary: DICT_5X5_100\n", "key 'marker_m' is missing"},
      {"squares_x: 8\nsquares_y: 6\nsquare_m: 0.06\nmarker_m: 0.08\ndictionary: DICT_5X5_100\n", "marker_m must be"},
      {"squares_x: eight\nsquares_y: 6\nsquare_m: 0.06\nmarker_m: 0.045\ndictionary: DICT_5X5_100\n",
       "key 'squares_x' is 'eight'"},
      {"squares_x: 8\nsquares_y: 6\nsquare_m: 0.06\nmarker_m: 0.045\ndictionary: DICT_5X5_100\nsquare_size: 1\n",
       "square_size"},
      {"squares_x: 8\nsquares_y: 6\nsquare_m: 0.06\nmarker_m: 0.045\ndictionary: DICT_FOO\n", "dictionary 'DICT_FOO'"},
      {"squares_x: [8\n", "not valid YAML"},
  };
  for (const Case& c : cases) {
    const fs::path target = *dir_ / "bad_target.yaml";
    std::ofstream(target) << c.yaml;
    const CliRun r = runDeepnav("calibrate --target " + target.string() + " " + images.string() + " --out " +
                             (*dir_ / "unused.yaml").string());
    EXPECT_EQ(r.exit_code, 2) << c.yaml;
    EXPECT_NE(r.out.find(c.expected), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("bad_target.yaml"), std::string::npos) << r.out;
  }
}

TEST_F(CalibrateCli, BadCalibrationFileNamesTheField) {
  const fs::path path = *dir_ / "broken_calibration.yaml";
  std::ofstream(path) << "%YAML:1.0\n---\nimage_width: 688\nimage_height: 516\n";
  StereoCalibration calib;
  std::string error;
  EXPECT_FALSE(readStereoCalibrationFile(path.string(), &calib, &error));
  EXPECT_NE(error.find("field 'camera_matrix_left' is missing"), std::string::npos) << error;
  // A calibration of another image size is refused against the board's camera.
  ASSERT_TRUE(writeStereoCalibrationFile((*dir_ / "calibration.yaml").string(), sim::simulatedCalibrationRig(),
                                         StereoCalibrationInfo{}, &error)) << error;
  std::ofstream(*dir_ / "board_small.yaml") << "camera:\n  width_px: 640\n  height_px: 480\n"
                                                "  calibration_file: calibration.yaml\n";
  BoardConfig config;
  ASSERT_TRUE(loadBoardConfig((*dir_ / "board_small.yaml").string(), &config, &error)) << error;
  StereoRectification rect;
  bool needed = false;
  EXPECT_FALSE(buildCameraRectification(config, dir_->string(), &rect, &needed, &error));
  EXPECT_NE(error.find("camera.width_px"), std::string::npos) << error;
}

TEST_F(CalibrateCli, UnpairedImageIsAnError) {
  const fs::path lone = *dir_ / "lone";
  fs::create_directories(lone);
  fs::copy_file(*dir_ / "images" / "00_pose_0_left.png", lone / "view_left.png", fs::copy_options::overwrite_existing);
  const CliRun r = runDeepnav("calibrate --target " + (*dir_ / "target.yaml").string() + " " + lone.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("no matching right image"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace deepnav
