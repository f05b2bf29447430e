#include "board/config/board_config.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace deepnav {
namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(BoardConfig, EmptyFileGivesDeclaredDefaults) {
  const std::string path = writeTemp("empty.yaml", "");
  BoardConfig c{};
  std::string error;
  ASSERT_TRUE(loadBoardConfig(path, &c, &error)) << error;
  EXPECT_EQ(c.loop.rate_hz, 100);
  EXPECT_EQ(c.camera.width_px, 688);
  EXPECT_EQ(c.camera.height_px, 516);
  EXPECT_EQ(c.recording.options.compression, "zstd");
  EXPECT_TRUE(c.recording.enabled);
}

TEST(BoardConfig, ValuesOverrideDefaults) {
  const std::string path = writeTemp("ok.yaml", "loop:\n  rate_hz: 200\nrecording:\n  compression: lz4\n");
  BoardConfig c{};
  std::string error;
  ASSERT_TRUE(loadBoardConfig(path, &c, &error)) << error;
  EXPECT_EQ(c.loop.rate_hz, 200);
  EXPECT_EQ(c.recording.options.compression, "lz4");
}

struct BadCase {
  const char* yaml;
  const char* must_mention;
};

TEST(BoardConfig, BadInputNamesFileKeyAndAllowedRange) {
  const BadCase cases[] = {
      {"loop:\n  rate_hz: 5\n", "'loop.rate_hz' is 5, out of range; allowed: an integer in [10, 1000] (Hz)"},
      {"loop:\n  rate_hz: fast\n", "'loop.rate_hz' is 'fast'"},
      {"loop:\n  rate_hz: 100.5\n", "'loop.rate_hz'"},
      {"loop:\n  rat_hz: 100\n", "unknown key 'loop.rat_hz'"},
      {"lop:\n  rate_hz: 100\n", "unknown key 'lop'"},
      {"loop: 3\n", "unknown key 'loop' (a section: expected a map)"},
      {"recording:\n  compression: gzip\n", "one of zstd|lz4|none"},
      {"recording:\n  enabled: maybe\n", "true or false"},
      {"camera:\n  rate_hz: .nan\n", "'camera.rate_hz'"},
      {"loop: [1, 2\n", "not valid YAML"},
  };
  for (const auto& c : cases) {
    const std::string path = writeTemp("bad.yaml", c.yaml);
    BoardConfig config{};
    std::string error;
    EXPECT_FALSE(loadBoardConfig(path, &config, &error)) << c.yaml;
    EXPECT_NE(error.find(path), std::string::npos) << error;
    EXPECT_NE(error.find(c.must_mention), std::string::npos) << "got: " << error;
  }
}

TEST(BoardConfig, MissingFileIsAnError) {
  BoardConfig c{};
  std::string error;
  EXPECT_FALSE(loadBoardConfig("/nonexistent/board.yaml", &c, &error));
  EXPECT_NE(error.find("/nonexistent/board.yaml: cannot open"), std::string::npos);
}

TEST(BoardConfig, DeclaredDefaultsAreAllValid) {
  std::string error;
  EXPECT_TRUE(checkBoardDefaults(&error)) << error;
  EXPECT_GT(defaultBoardConfig().markers.covariance.pos_floor_m, 0.0);  // a default after the (empty) panel_file
}

TEST(BoardConfig, EveryParameterIsDocumented) {
  const std::string table = describeBoardParams();
  EXPECT_NE(table.find("`loop.rate_hz` | int | Hz | `100` | an integer in [10, 1000]"), std::string::npos)
      << table;
}

}  // namespace
}  // namespace deepnav

namespace deepnav {
namespace {

TEST(BoardConfig, MountingRotationsLeverArmsAndDurations) {
  const std::string path = writeTemp("ekf.yaml",
                                     "ekf:\n  dvl_rotation_deg: [0, 0, 45]\n  p_dvl_in_robot_m: [0.2, 0, -0.4]\n"
                                     "  timeout_dvl_s: 0.6\n");
  BoardConfig c{};
  std::string error;
  ASSERT_TRUE(loadBoardConfig(path, &c, &error)) << error;
  const Eigen::Vector3d x_dvl_in_robot = c.ekf.q_robot_dvl * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(x_dvl_in_robot.x(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(x_dvl_in_robot.y(), std::sqrt(0.5), 1e-12);
  EXPECT_EQ(c.ekf.p_dvl_in_robot_m, Eigen::Vector3d(0.2, 0, -0.4));
  EXPECT_EQ(c.ekf.timeout_dvl_us, 600000);
  const std::string bad = writeTemp("ekf_bad.yaml", "ekf:\n  p_dvl_in_robot_m: [0.2, 0]\n");
  EXPECT_FALSE(loadBoardConfig(bad, &c, &error));
  EXPECT_NE(error.find("'ekf.p_dvl_in_robot_m' is '[0.2, 0]'; allowed: a list of 3 numbers"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav

#include "board/config/board_overrides.h"
#include "board/config/vehicle_setup.h"
#include "board/loop/nav_core.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

TEST(BoardConfig, MarkersEnabledKeySwitchesTheWholeMarkerChain) {
  // GIVEN the simulator's board (it names a panel) WHEN loaded as is THEN markers are on: detected by
  // the vision worker and used by the loop
  VehicleSetup setup;
  std::string error;
  const std::string board = deepnav::testing::sourceDir() + "/board/sim/board.yaml";
  ASSERT_TRUE(loadVehicleSetup(board, &setup, &error)) << error;
  EXPECT_TRUE(setup.config.markers.enabled);
  EXPECT_TRUE(visionConfig(setup).detect_markers);
  NavCore on;
  ASSERT_TRUE(on.init(setup, nullptr, &error)) << error;
  EXPECT_TRUE(on.hasPanel());
  // WHEN overridden as the dead-reckoning run does THEN neither detects nor uses markers
  ASSERT_TRUE(applyBoardOverrides({"markers.enabled=false", "vision.vo_mode=none"}, &setup, &error)) << error;
  EXPECT_FALSE(setup.config.markers.enabled);
  EXPECT_TRUE(setup.has_panel);  // the description is still known (the recording keeps it)
  EXPECT_FALSE(visionConfig(setup).detect_markers);
  NavCore off;
  ASSERT_TRUE(off.init(setup, nullptr, &error)) << error;
  EXPECT_FALSE(off.hasPanel());
  // AND a bad value names the key
  EXPECT_FALSE(applyBoardOverrides({"markers.enabled=sometimes"}, &setup, &error));
  EXPECT_NE(error.find("markers.enabled"), std::string::npos) << error;
  // AND `deepnav config --list` documents it
  EXPECT_NE(describeBoardParams().find("`markers.enabled` | bool | - | `true` | true or false"), std::string::npos);
}

// Issue 21: what yaml-cpp accepts silently is refused, naming the file, the key and the line.
TEST(BoardConfig, RepeatedKeysSectionsDottedKeysAndSecondDocumentsAreRefused) {
  const BadCase cases[] = {
      // The first one used to win: refused in one order, accepted in the other.
      {"loop:\n  rate_hz: 5\n  rate_hz: 100\n", "line 3: key 'loop.rate_hz' repeats the one of line 2"},
      {"loop:\n  rate_hz: 100\n  rate_hz: 5\n", "line 3: key 'loop.rate_hz' repeats the one of line 2"},
      {"loop: {rate_hz: 100, rate_hz: 200}\n", "key 'loop.rate_hz' repeats the one of line 1"},
      // The second section used to be ignored.
      {"loop:\n  rate_hz: 100\ncamera:\n  rate_hz: 5\nloop:\n  budget_us: 3000\n",
       "line 5: key 'loop' repeats the one of line 1"},
      // Passed the unknown-key check and was never applied.
      {"loop.rate_hz: 5\n", "key 'loop.rate_hz' (line 1) is written with a dot; nest it instead"},
      {"loop:\n  rate_hz: 100\nrecording:\n  chunk.size_kib: 64\n", "key 'chunk.size_kib' (line 4) is written with a dot"},
      // Everything after the separator used to be ignored.
      {"loop:\n  rate_hz: 100\n---\nloop:\n  rate_hz: 5\n", "holds more than one YAML document"},
  };
  for (const auto& c : cases) {
    const std::string path = writeTemp("bad_structure.yaml", c.yaml);
    BoardConfig config{};
    std::string error;
    EXPECT_FALSE(loadBoardConfig(path, &config, &error)) << c.yaml;
    EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
    EXPECT_NE(error.find(c.must_mention), std::string::npos) << "got: " << error;
  }
}

TEST(BoardConfig, DocumentMarkersAndEqualKeysInOtherMapsStayValid) {
  const char* good[] = {
      "---\nloop:\n  rate_hz: 200\n",
      "loop:\n  rate_hz: 200\n...\n",
      // The same key name in two sections is two keys.
      "loop:\n  rate_hz: 200\ncamera:\n  rate_hz: 5\n",
  };
  for (const char* yaml : good) {
    BoardConfig c{};
    std::string error;
    EXPECT_TRUE(loadBoardConfig(writeTemp("good_structure.yaml", yaml), &c, &error)) << yaml << error;
    EXPECT_EQ(c.loop.rate_hz, 200) << yaml;
  }
}

TEST(BoardConfig, DirectoryIsRefused) {
  BoardConfig c{};
  std::string error;
  const std::string dir = ::testing::TempDir();
  EXPECT_FALSE(loadBoardConfig(dir, &c, &error));
  EXPECT_EQ(error, dir + ": is a directory, not the board file");
}

TEST(BoardConfig, EndlessOrHugeInputIsRefusedAtTheLimit) {
  BoardConfig c{};
  std::string error;
  EXPECT_FALSE(loadBoardConfig("/dev/zero", &c, &error));
  EXPECT_EQ(error.rfind("/dev/zero: the board file is larger than 4 MiB", 0), 0u) << error;
  // A regular file one byte over the limit (a comment, so that only the size is wrong).
  const std::string path = ::testing::TempDir() + "huge_board.yaml";
  {
    std::ofstream out(path);
    out << "#" << std::string(4 * 1024 * 1024, 'x');
  }
  EXPECT_FALSE(loadBoardConfig(path, &c, &error));
  EXPECT_NE(error.find(path + ": the board file is larger than 4 MiB"), std::string::npos) << error;
  std::remove(path.c_str());
}

// OpenCV's SGBM throws when the searched range (rounded up to 16) reaches the matched width
// (board/config/dense_stereo_range.h): 512 px at scale 1/2 is 256 px wide.
TEST(BoardConfig, DenseDisparityRangeMustFitTheImageWidth) {
  const std::string camera = "camera:\n  width_px: 512\n  height_px: 384\n  cx_px: 255.5\n  cy_px: 191.5\n";
  const struct {
    const char* vision;
    bool valid;
  } cases[] = {
      {"vision:\n  dense_method: sgbm\n  dense_disparities: 256\n", false},
      {"vision:\n  dense_method: sgbm-wls\n  dense_disparities: 241\n", false},  // searched as 256
      {"vision:\n  dense_method: sgbm\n  dense_disparities: 240\n", true},
      {"vision:\n  dense_method: elas\n  dense_disparities: 256\n", false},
      {"vision:\n  dense_method: elas\n  dense_disparities: 255\n", true},
      {"vision:\n  dense_method: sgbm\n  dense_disparities: 256\n  dense_scale_down: 1\n", true},
  };
  for (const auto& k : cases) {
    BoardConfig c{};
    std::string error;
    const std::string yaml = camera + k.vision;
    EXPECT_EQ(loadBoardConfig(writeTemp("dense.yaml", yaml), &c, &error), k.valid) << yaml << error;
    if (k.valid) continue;
    EXPECT_NE(error.find("key 'vision.dense_disparities'"), std::string::npos) << error;
    EXPECT_NE(error.find("'camera.width_px' (512 px"), std::string::npos) << error;
  }
  BoardConfig c{};
  std::string error;
  EXPECT_FALSE(loadBoardConfig(writeTemp("odd.yaml", "camera:\n  width_px: 511\n  cx_px: 255\n"), &c, &error));
  EXPECT_NE(error.find("must be multiples of 'vision.dense_scale_down' (2)"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
