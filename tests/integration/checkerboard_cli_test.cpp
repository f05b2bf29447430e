// `deepnav calibrate` on a real checkerboard set and `deepnav import calibration`, as a user runs them
// (issue 19 items 3-4). The real set is OpenCV's stereo sample as Debian's opencv-doc ships it
// (/usr/share/doc/opencv-doc/examples/data/left01..14.jpg, right01..14.jpg; skipped when absent); its
// square size is not published: 25 mm is assumed, which scales T and nothing else.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "board/config/board_config.h"
#include "board/config/camera_rectification.h"
#include "board/config/stereo_calibration_file.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_path.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;

const fs::path kOpencvDocData = "/usr/share/doc/opencv-doc/examples/data";

using deepnav::testing::CliRun;
using deepnav::testing::runDeepnav;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(deepnav::testing::tempPath("checkerboard_cli"));
  fs::create_directories(dir);
  return dir / name;
}

TEST(CheckerboardCli, CalibratesTheOpencvDocSetToASubPixelErrorAndTheBoardRectifiesWithIt) {
  if (!fs::exists(kOpencvDocData / "left01.jpg"))
    GTEST_SKIP() << kOpencvDocData << " absent (apt-get install opencv-doc)";
  const fs::path target = scratch("target.yaml");
  std::ofstream(target) << "type: checkerboard\ninner_corners: [9, 6]\nsquare_m: 0.025\n";
  std::string images;
  for (int i = 1; i <= 14; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "left%02d.jpg", i);
    if (!fs::exists(kOpencvDocData / name)) continue;  // no left10/right10 in the set
    images += ' ';
    images += (kOpencvDocData / name).string();
  }
  const fs::path out = scratch("calibration.yaml");
  const CliRun r = runDeepnav("calibrate --target " + target.string() + images + " --out " + out.string());
  std::printf("%s", r.out.c_str());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("13 of 13 pairs used"), std::string::npos);
  double rms = 99.0;
  const std::size_t at = r.out.find("reprojection error ");
  ASSERT_NE(at, std::string::npos);
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "reprojection error %lf px", &rms), 1);
  EXPECT_LT(rms, 0.5);  // sub-pixel (the bound of CheckerboardOpencvDoc in calib_checkerboard_test.cpp)
  // The file names the checkerboard and a board with the sample's 640 x 480 camera rectifies with it.
  std::ifstream file(out);
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_NE(text.str().find("checkerboard 9 x 6 inner corners, square 0.0250 m"), std::string::npos);
  BoardConfig config;
  config.camera.width_px = 640;
  config.camera.height_px = 480;
  StereoRectification rect;
  std::string error;
  ASSERT_TRUE(buildCameraRectificationFromText(config, text.str(), out.string(), &rect, &error)) << error;
  EXPECT_NEAR(rect.baseline_m, 0.083, 0.002);  // 3.3 squares of the assumed 25 mm
}

TEST(CalibImportCli, ImportsAKalibrCamchainAndNamesABadKey) {
  const fs::path camchain = scratch("camchain.yaml");
  std::ofstream(camchain) << "cam0:\n  camera_model: pinhole\n  intrinsics: [458.654, 457.296, 367.215, 248.375]\n"
                             "  distortion_model: radtan\n  distortion_coeffs: [-0.28340811, 0.07395907, 0.00019359, "
                             "1.76187114e-05]\n  resolution: [752, 480]\n"
                             "cam1:\n  T_cn_cnm1:\n  - [1.0, 0.0, 0.0, -0.11]\n  - [0.0, 1.0, 0.0, 0.0]\n"
                             "  - [0.0, 0.0, 1.0, 0.0]\n  - [0.0, 0.0, 0.0, 1.0]\n  camera_model: pinhole\n"
                             "  intrinsics: [457.587, 456.134, 379.999, 255.238]\n  distortion_model: radtan\n"
                             "  distortion_coeffs: [-0.28368365, 0.07451284, -0.00010473, -3.55590700e-05]\n"
                             "  resolution: [752, 480]\n";
  const fs::path out = scratch("imported.yaml");
  CliRun r = runDeepnav("import calibration --format kalibr " + camchain.string() + " --out " + out.string());
  std::printf("%s", r.out.c_str());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("baseline 0.1100 m"), std::string::npos);
  StereoCalibration c;
  std::string error;
  ASSERT_TRUE(readStereoCalibrationFile(out.string(), &c, &error)) << error;
  EXPECT_DOUBLE_EQ(c.T[0], -0.11);
  // A resolution mismatch: exit code 2 and one line naming the file and the key.
  std::ifstream in(camchain);
  std::stringstream text;
  text << in.rdbuf();
  std::string bad = text.str();
  bad.replace(bad.rfind("[752, 480]"), 10, "[640, 480]");
  std::ofstream(camchain) << bad;
  r = runDeepnav("import calibration --format kalibr " + camchain.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "deepnav import calibration: " + camchain.string() +
                       ": key 'cam1.resolution' differs between the cameras: 752 x 480 (left) and 640 x 480 (right); "
                       "deepnav rectifies pairs of one size\n");
}

}  // namespace
}  // namespace deepnav
