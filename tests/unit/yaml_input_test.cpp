// Issue 21: every YAML input (board, panel, stereo calibration, calibration target, simulator scenario) is
// read with a size limit and refuses repeated keys and a second document, with one message naming the file.
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "board/cli/calibrate_command.h"
#include "board/config/board_config.h"
#include "board/config/panel_file.h"
#include "board/config/stereo_calibration_file.h"
#include "board/config/text_file.h"
#include "board/config/yaml_document.h"
#include "tools/sim/scenario_loader.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;

const std::string kSource = deepnav::testing::sourceDir();

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "yaml_input_" + name;
  std::ofstream(path) << text;
  return path;
}

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

TEST(YamlInput, RepeatedKeysAreFoundAtAnyDepthWithTheirPath) {
  YAML::Node root;
  std::string error;
  EXPECT_FALSE(parseYamlDocument("faults:\n  - type: imu\n    params: {std: 1, std: 2}\n", "f.yaml", &root, &error));
  EXPECT_EQ(error, "f.yaml: line 3: key 'faults[0].params.std' repeats the one of line 3 (YAML keeps only one of "
                   "them): remove one");
  EXPECT_FALSE(parseYamlDocument("a: 1\n'a': 2\n", "q.yaml", &root, &error));  // quoting does not make it another
  EXPECT_TRUE(has(error, "line 2: key 'a' repeats the one of line 1")) << error;
  EXPECT_FALSE(parseYamlDocument("a: 1\n--- \nb: 2\n", "d.yaml", &root, &error));
  EXPECT_TRUE(has(error, "d.yaml: holds more than one YAML document")) << error;
  EXPECT_FALSE(parseYamlDocument("a: [1\n", "s.yaml", &root, &error));
  EXPECT_TRUE(has(error, "s.yaml: not valid YAML (line")) << error;
  // Lists may repeat values, maps in a list are separate maps, a key may repeat in another map.
  ASSERT_TRUE(parseYamlDocument("l: [1, 1]\nm: [{a: 1}, {a: 2}]\nx: {a: 1}\ny: {a: 2}\n", "ok.yaml", &root, &error))
      << error;
  EXPECT_EQ(root["m"][1]["a"].as<int>(), 2);
}

TEST(YamlInput, TextFilesAreReadUpToALimitAndNeverFromADirectory) {
  std::string text, error;
  EXPECT_FALSE(readTextFile("/dev/zero", "the input", &text, &error));
  EXPECT_EQ(error, "/dev/zero: the input is larger than 4 MiB, the limit for a text input (a wrong file, a device or "
                   "an endless stream?)");
  const std::string path = writeTemp("limit.txt", std::string(1025, 'x'));
  EXPECT_FALSE(readTextFile(path, "the input", &text, &error, 1024));
  EXPECT_TRUE(has(error, "larger than 1 KiB")) << error;
  EXPECT_TRUE(readTextFile(path, "the input", &text, &error, 1025)) << error;
  EXPECT_EQ(text.size(), 1025u);
  EXPECT_FALSE(readTextFile(::testing::TempDir(), "the input", &text, &error));
  EXPECT_TRUE(has(error, "is a directory, not the input")) << error;
  // A FIFO (what `--board <(...)` gives) is read to its end.
  const std::string fifo = ::testing::TempDir() + "yaml_input_fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << "loop:\n  rate_hz: 200\n"; });
  EXPECT_TRUE(readTextFile(fifo, "the input", &text, &error)) << error;
  writer.join();
  EXPECT_EQ(text, "loop:\n  rate_hz: 200\n");
  std::remove(fifo.c_str());
}

TEST(YamlInput, PanelFileRefusesRepeatedKeys) {
  PanelDescription panel;
  std::string error;
  EXPECT_FALSE(parsePanelDescription("dictionary: DICT_4X4_50\nmarker_size_m: 0.15\nmarker_size_m: 0.2\n",
                                     "panel.yaml", &panel, &error));
  EXPECT_TRUE(has(error, "panel.yaml: line 3: key 'marker_size_m' repeats the one of line 2")) << error;
  EXPECT_FALSE(parsePanelDescription("dictionary: DICT_BOGUS\nmarker_size_m: 0.15\n", "panel.yaml", &panel, &error));
  EXPECT_TRUE(has(error, "panel.yaml: key 'dictionary' is 'DICT_BOGUS', not an ArUco dictionary")) << error;
  EXPECT_FALSE(loadPanelDescription("/dev/zero", &panel, &error));
  EXPECT_TRUE(has(error, "/dev/zero: the panel description is larger than 4 MiB")) << error;
}

TEST(YamlInput, StereoCalibrationRefusesRepeatedKeys) {
  StereoCalibration calibration;
  std::string error;
  // OpenCV's FileStorage keeps the first of the two without a word.
  EXPECT_FALSE(parseStereoCalibrationText("%YAML:1.0\n---\nimage_width: 688\nimage_width: 640\n", "calib.yaml",
                                          &calibration, &error));
  EXPECT_TRUE(has(error, "calib.yaml: line 4: key 'image_width' repeats the one of line 3")) << error;
  EXPECT_FALSE(readStereoCalibrationFile("/dev/zero", &calibration, &error));
  EXPECT_TRUE(has(error, "/dev/zero: the stereo calibration file is larger than 4 MiB")) << error;
  const std::string dexrov = kSource + "/board/sim-dexrov/dexrov_in_air_calibration.yaml";
  EXPECT_TRUE(readStereoCalibrationFile(dexrov, &calibration, &error)) << error;
}

TEST(YamlInput, CalibrationTargetRefusesRepeatedKeysAndEndlessFiles) {
  CharucoTarget target;
  std::string error;
  const std::string path = writeTemp("target.yaml", "squares_x: 8\nsquares_x: 9\n");
  EXPECT_FALSE(loadCharucoTarget(path, &target, &error));
  EXPECT_TRUE(has(error, path + ": line 2: key 'squares_x' repeats the one of line 1")) << error;
  EXPECT_FALSE(loadCharucoTarget("/dev/zero", &target, &error));
  EXPECT_TRUE(has(error, "/dev/zero: the calibration target is larger than 4 MiB")) << error;
}

TEST(YamlInput, ScenarioRefusesRepeatedKeysSecondDocumentsAndEndlessFiles) {
  sim::Scenario s;
  std::string error;
  EXPECT_FALSE(sim::parseScenario("duration_s: 5\nduration_s: 10\n", "dive.yaml", &s, &error));
  EXPECT_EQ(error, "dive.yaml: line 2: key 'duration_s' repeats the one of line 1 (YAML keeps only one of them): "
                   "remove one");
  EXPECT_FALSE(sim::parseScenario("duration_s: 5\n---\nduration_s: 10\n", "dive.yaml", &s, &error));
  EXPECT_TRUE(has(error, "dive.yaml: holds more than one YAML document")) << error;
  EXPECT_FALSE(sim::loadScenario("/dev/zero", &s, &error));  // was std::bad_alloc after gigabytes
  EXPECT_TRUE(has(error, "/dev/zero: the scenario file is larger than 4 MiB")) << error;
  EXPECT_FALSE(sim::loadScenario(::testing::TempDir(), &s, &error));
  EXPECT_TRUE(has(error, "is a directory, not the scenario file")) << error;
}

// The stricter loader must not refuse anything we ship.
TEST(YamlInput, EveryShippedBoardPanelAndScenarioStillLoads) {
  int boards = 0, scenarios = 0;
  for (const auto& dir : fs::directory_iterator(kSource + "/board")) {
    const fs::path board = dir.path() / "board.yaml";
    if (!fs::exists(board)) continue;
    BoardConfig c;
    std::string error;
    EXPECT_TRUE(loadBoardConfig(board.string(), &c, &error)) << error;
    ++boards;
    const fs::path panel = dir.path() / "panel.yaml";
    PanelDescription p;
    if (fs::exists(panel)) {
      EXPECT_TRUE(loadPanelDescription(panel.string(), &p, &error)) << error;
    }
  }
  for (const auto& file : fs::directory_iterator(kSource + "/tools/sim/scenarios")) {
    if (file.path().extension() != ".yaml") continue;
    sim::Scenario s;
    std::string error;
    EXPECT_TRUE(sim::loadScenario(file.path().string(), &s, &error)) << error;
    ++scenarios;
  }
  EXPECT_GE(boards, 4);
  EXPECT_GE(scenarios, 10);
}

}  // namespace
}  // namespace deepnav
