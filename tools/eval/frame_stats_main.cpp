// deepnav-frame-stats: the statistics the navigation pipeline decides on (MDM f1-f3, ORB keypoints,
// tracked count, m_I, ELAS coverage; tools/sim/render/frame_statistics.h) for a folder of real images
// and for pairs rendered from a scenario, as a table (mean, std, median per statistic) and optionally a
// CSV of every frame.
//   deepnav-frame-stats --images DIR [--csv FILE]      every *.png / *.jpg of DIR in name order, monocular,
//                                                      or DIR/left + DIR/right as rectified pairs
//   deepnav-frame-stats --scenario FILE [--seed N] [--from-s A] [--to-s B] [--every-s S] [--channels 1|3]
// A missing folder is reported and skipped (exit 0), so scripts run where the data is absent.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tools/sim/render/frame_statistics.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"

namespace {

namespace fs = std::filesystem;
using deepnav::sim::FrameStatistics;

std::vector<std::string> imagesIn(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (entry.is_regular_file() && (ext == ".png" || ext == ".jpg" || ext == ".jpeg")) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct Table {
  std::vector<FrameStatistics> rows;
  std::vector<std::string> names;
};

void printTable(const std::string& title, const Table& t) {
  using deepnav::sim::summarise;
  const auto column = [&](auto get) {
    std::vector<double> v;
    for (const FrameStatistics& s : t.rows) v.push_back(get(s));
    return summarise(v);
  };
  struct Row {
    const char* name;
    deepnav::sim::StatisticSummary s;
  };
  const Row rows[] = {
      {"MDM f1", column([](const FrameStatistics& s) { return s.mdm.f1; })},
      {"MDM f2", column([](const FrameStatistics& s) { return s.mdm.f2; })},
      {"MDM f3", column([](const FrameStatistics& s) { return s.mdm.f3; })},
      {"ORB keypoints", column([](const FrameStatistics& s) { return static_cast<double>(s.orb_keypoints); })},
      {"ORB tracked (stereo VO)", column([](const FrameStatistics& s) { return static_cast<double>(s.orb_tracked_stereo); })},
      {"ORB tracked (2-D, F-RANSAC)", column([](const FrameStatistics& s) { return static_cast<double>(s.orb_tracked_2d); })},
      {"m_I", column([](const FrameStatistics& s) { return s.image_quality; })},
      {"ELAS coverage", column([](const FrameStatistics& s) { return s.elas_coverage; })},
  };
  std::printf("%s (%zu frames)\n| statistic | n | mean | std | median |\n| --- | --- | --- | --- | --- |\n", title.c_str(),
              t.rows.size());
  for (const Row& r : rows) {
    if (r.s.count == 0) {
      std::printf("| %s | 0 | n/a | | |\n", r.name);
    } else {
      std::printf("| %s | %d | %.3f | %.3f | %.3f |\n", r.name, r.s.count, r.s.mean, r.s.stddev, r.s.median);
    }
  }
}

void writeCsv(const std::string& path, const Table& t) {
  if (path.empty()) return;
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "%s: cannot write\n", path.c_str());
    return;
  }
  std::fprintf(f, "frame,mdm_f1,mdm_f2,mdm_f3,orb_keypoints,orb_tracked_stereo,orb_tracked_2d,m_I,elas_coverage\n");
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const FrameStatistics& s = t.rows[i];
    std::fprintf(f, "%s,%.5f,%.5f,%.5f,%d,%d,%d,%.5f,%.5f\n", t.names[i].c_str(), s.mdm.f1, s.mdm.f2, s.mdm.f3,
                 s.orb_keypoints, s.orb_tracked_stereo, s.orb_tracked_2d, s.image_quality, s.elas_coverage);
  }
  std::fclose(f);
}

int runImages(const fs::path& dir, const deepnav::StereoRig& rig, Table* t) {
  if (!fs::is_directory(dir)) {
    std::printf("%s: not found, skipped\n", dir.string().c_str());
    return 0;
  }
  deepnav::sim::FrameStatisticsRunner runner;
  std::string error;
  if (!runner.init(rig, &error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const bool pairs = fs::is_directory(dir / "left") && fs::is_directory(dir / "right");
  const std::vector<std::string> files = imagesIn(pairs ? dir / "left" : dir);
  const std::vector<std::string> rights = pairs ? imagesIn(dir / "right") : std::vector<std::string>{};
  for (std::size_t i = 0; i < files.size(); ++i) {
    FrameStatistics s;
    const cv::Mat image = deepnav::sim::toRigFormat(cv::imread(files[i], cv::IMREAD_COLOR), rig.width_px, rig.height_px);
    bool ok = false;
    if (pairs && i < rights.size()) {
      const cv::Mat right = deepnav::sim::toRigFormat(cv::imread(rights[i], cv::IMREAD_COLOR), rig.width_px, rig.height_px);
      ok = runner.stereo(static_cast<deepnav::TimeUs>(i) * 100000, image, right, &s);
    } else {
      ok = runner.mono(image, &s);
    }
    if (!ok) continue;
    t->rows.push_back(s);
    t->names.push_back(fs::path(files[i]).filename().string());
  }
  return 0;
}

struct RenderRange {
  std::string scenario;
  std::uint64_t seed = 1;
  double from_s = 0.0, to_s = -1.0, every_s = 1.0;
  int channels = 1;
};

int runScenario(const RenderRange& r, Table* t) {
  using namespace deepnav::sim;
  Scenario scenario;
  std::string error;
  SensorSimulator sim;
  StereoRenderer renderer;
  if (!loadScenario(r.scenario, &scenario, &error) || !sim.init(scenario, r.seed, &error) ||
      !renderer.init(scenario, r.seed, r.channels, &error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  if (scenario.camera.flat_port) {
    std::fprintf(stderr, "%s: a flat port gives raw images; the statistics need a rectified pair\n", r.scenario.c_str());
    return 1;
  }
  deepnav::StereoRig rig;
  rig.fx_px = scenario.camera.fx_px, rig.fy_px = scenario.camera.fy_px;
  rig.cx_px = scenario.camera.cx_px, rig.cy_px = scenario.camera.cy_px;
  rig.baseline_m = scenario.camera.baseline_m;
  rig.width_px = scenario.camera.width_px, rig.height_px = scenario.camera.height_px;
  FrameStatisticsRunner runner;
  if (!runner.init(rig, &error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  deepnav::StereoFrame frame;
  deepnav::allocateStereoFrame(frame, rig.width_px, rig.height_px, r.channels);
  const double to_s = r.to_s < 0.0 ? scenario.duration_s : r.to_s;
  for (double t_s = r.from_s; t_s <= to_s + 1e-9; t_s += r.every_s) {
    const auto t_us = static_cast<deepnav::TimeUs>(std::llround(t_s * 1e6));
    if (!renderer.render(sim.cameraAt(t_us), &frame, nullptr)) return 1;
    FrameStatistics s;
    if (!runner.stereo(t_us, frame.left, frame.right, &s)) return 1;
    t->rows.push_back(s);
    char name[32];
    std::snprintf(name, sizeof name, "t=%.2f", t_s);
    t->names.push_back(name);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Pipeline statistics (MDM, ORB, m_I, ELAS coverage) of real images or rendered pairs"};
  std::string images, csv;
  RenderRange range;
  deepnav::StereoRig rig;  // the simulated rig's format (688 x 516) for real images
  app.add_option("--images", images, "folder of images (monocular) or with left/ and right/ (pairs)");
  app.add_option("--scenario", range.scenario, "render pairs of this scenario's dive");
  app.add_option("--seed", range.seed, "seed of the dive");
  app.add_option("--from-s", range.from_s, "first instant, s");
  app.add_option("--to-s", range.to_s, "last instant, s (default: the dive's end)");
  app.add_option("--every-s", range.every_s, "spacing of the rendered pairs, s")->check(CLI::PositiveNumber);
  app.add_option("--channels", range.channels, "rendered images: 1 grey or 3 BGR")->check(CLI::IsMember({1, 3}));
  app.add_option("--csv", csv, "write every frame's statistics here");
  CLI11_PARSE(app, argc, argv);
  if (images.empty() == range.scenario.empty()) {
    std::fprintf(stderr, "give --images DIR or --scenario FILE\n");
    return 2;
  }
  Table t;
  const int rc = images.empty() ? runScenario(range, &t) : runImages(images, rig, &t);
  if (rc != 0) return rc;
  if (t.rows.empty()) return 0;
  printTable(images.empty() ? range.scenario : images, t);
  writeCsv(csv, t);
  return 0;
}
