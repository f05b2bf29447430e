// deepnav-figures: the report's pictures of one stereo pair of a recording, as the stage-2 plane VO sees
// it: left and right images, the dense disparity, the cloud filtered by the stage-1 workspace map with
// its extracted planes (image overlay and CSV for a 3-D view), and the map's occupied voxels (CSV).
//   deepnav-figures DIVE.mcap --time-s 75 [--workspace DIR] --out DIR
// The cloud is placed in the map with the recorded true pose (the map of the same dive lives in the
// odometry frame of the replay, which the EKF keeps within centimetres of the truth).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "board/config/vehicle_setup.h"
#include "board/replay/bench_replay.h"
#include "board/replay/workspace_files.h"
#include "drivers/replay/recording_reader.h"
#include "vision/pipeline/vision_pipeline.h"

namespace {

using namespace deepnav;

struct Picked {
  bool found = false;
  StereoFrame frame;
  bool has_truth = false;
  TruthSample truth;
};

bool pickFrame(RecordingReader& reader, TimeUs t_us, Picked* out, std::string* error) {
  return reader.forEach(true, [&](const ReplayEvent& e) {
    if (e.kind == ReplayEvent::Kind::kTruth && (!out->has_truth || e.t_us <= t_us)) {
      out->truth = e.truth;
      out->has_truth = true;
    }
    if (e.kind != ReplayEvent::Kind::kFrame || e.t_us < t_us) return true;
    out->frame.t_us = e.frame->t_us;
    out->frame.left = e.frame->left.clone();
    out->frame.right = e.frame->right.clone();
    out->found = true;
    return false;
  }, error);
}

cv::Mat colourDisparity(const cv::Mat& disparity_px, double max_px) {
  cv::Mat scaled, colour;
  disparity_px.convertTo(scaled, CV_8U, 255.0 / max_px);
  cv::applyColorMap(scaled, colour, cv::COLORMAP_TURBO);
  colour.setTo(cv::Scalar(0, 0, 0), disparity_px < 0);
  return colour;
}

// Left image (grey) with each plane's cells painted in its own colour; filtered-out points stay grey.
cv::Mat planeOverlay(const cv::Mat& left, const PlaneExtractor& extractor, int step_full_px) {
  cv::Mat grey = left.channels() == 1 ? left : cv::Mat();
  if (left.channels() == 3) cv::cvtColor(left, grey, cv::COLOR_BGR2GRAY);
  cv::Mat out;
  cv::cvtColor(grey, out, cv::COLOR_GRAY2BGR);
  const cv::Mat& labels = extractor.labels();
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c) {
      const int label = labels.at<std::uint8_t>(r, c);
      if (label == 0 || label == 255) continue;
      const cv::Scalar colour((label * 67) % 256, (label * 151) % 256, (label * 29 + 128) % 256);
      const cv::Rect cell(c * step_full_px, r * step_full_px, step_full_px, step_full_px);
      cv::Mat roi = out(cell & cv::Rect(0, 0, out.cols, out.rows));
      cv::addWeighted(roi, 0.4, cv::Mat(roi.size(), roi.type(), colour), 0.6, 0.0, roi);
    }
  }
  return out;
}

bool writeCloudCsv(const std::string& path, const OrganizedCloud& cloud, const PlaneExtractor& extractor) {
  std::ofstream out(path);
  out << "x_m,y_m,z_m,plane\n";
  const cv::Mat& labels = extractor.labels();
  for (int r = 0; r < cloud.rows(); ++r) {
    for (int c = 0; c < cloud.cols(); ++c) {
      const cv::Vec3f& p = cloud.row(r)[c];
      if (!OrganizedCloud::isValid(p)) continue;
      const int label = labels.empty() ? 0 : labels.at<std::uint8_t>(r, c);
      out << p[0] << ',' << p[1] << ',' << p[2] << ',' << (label == 255 ? 0 : label) << '\n';
    }
  }
  return static_cast<bool>(out);
}

bool writeVoxelsCsv(const std::string& path, const WorkspaceMap& map) {
  std::ofstream out(path);
  out << "x_m,y_m,z_m\n";
  const octomap::OcTree& tree = map.octree();
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    if (!tree.isNodeOccupied(*it)) continue;
    out << it.getX() << ',' << it.getY() << ',' << it.getZ() << '\n';
  }
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"deepnav-figures: pictures of one stereo pair through the plane VO chain"};
  std::string recording, workspace, out_dir;
  double time_s = 60.0;
  app.add_option("recording", recording, "simulated dive (MCAP)")->required()->check(CLI::ExistingFile);
  app.add_option("--time-s", time_s, "dive time of the pair (s from the recording's start)");
  app.add_option("--workspace", workspace, "saved workspace (deepnav replay --workspace-out)");
  app.add_option("--out", out_dir, "output directory")->required();
  CLI11_PARSE(app, argc, argv);

  std::string error;
  RecordingReader reader;
  VehicleSetup setup;
  if (!reader.open(recording, &error) || !loadReplaySetup("", reader, recording, &setup, &error)) {
    std::fprintf(stderr, "deepnav-figures: %s\n", error.c_str());
    return 1;
  }
  TimeUs first_us = -1;
  reader.forEach(true, [&](const ReplayEvent& e) { first_us = e.t_us; return false; }, &error);
  Picked picked;
  if (!pickFrame(reader, first_us + sToUs(time_s), &picked, &error) || !picked.found) {
    std::fprintf(stderr, "deepnav-figures: %s: no stereo pair at %.1f s %s\n", recording.c_str(), time_s, error.c_str());
    return 1;
  }
  VisionPipelineConfig vc = visionConfig(setup);
  VisionPipeline pipeline;
  if (!pipeline.init(vc, &error) || (!workspace.empty() && !loadWorkspace(workspace, &pipeline.workspace(), &error))) {
    std::fprintf(stderr, "deepnav-figures: %s\n", error.c_str());
    return 1;
  }
  std::filesystem::create_directories(out_dir);
  StereoCloud& dense = pipeline.dense();
  OrganizedCloud cloud;
  dense.allocateCloud(&cloud);
  if (!dense.compute(picked.frame.left, picked.frame.right, &cloud)) {
    std::fprintf(stderr, "deepnav-figures: dense stereo failed on the pair\n");
    return 1;
  }
  int removed = 0;
  if (!workspace.empty() && picked.has_truth) {
    Eigen::Isometry3d T_odom_robot = Eigen::Isometry3d::Identity();
    T_odom_robot.linear() = picked.truth.q_odom_robot.toRotationMatrix();
    T_odom_robot.translation() = picked.truth.p_robot_in_odom_m;
    const Eigen::Isometry3d T_odom_cam = T_odom_robot * robotFromCamera(setup.config);
    removed = pipeline.workspace().filterInMapFrame(T_odom_cam, &cloud);
    writeVoxelsCsv(out_dir + "/octomap_voxels.csv", pipeline.workspace().map());
  }
  PlaneExtractor extractor;
  PlaneSet planes;
  const int n = extractor.init(vc.planes.extraction, dense.geometry(), dense.rows(), dense.cols(), vc.dense.cloud_step_px) &&
                        extractor.allocatePlaneSet(&planes)
                    ? extractor.extract(cloud, &planes)
                    : -1;
  cv::imwrite(out_dir + "/left.png", picked.frame.left);
  cv::imwrite(out_dir + "/right.png", picked.frame.right);
  cv::imwrite(out_dir + "/disparity.png", colourDisparity(dense.disparity(), vc.dense.num_disparities));
  cv::imwrite(out_dir + "/planes.png", planeOverlay(picked.frame.left, extractor, dense.stepPx()));
  writeCloudCsv(out_dir + "/cloud_planes.csv", cloud, extractor);
  std::printf("pair at %.2f s: %d cloud points kept (%d removed by the map), %d planes; written to %s\n",
              usToS(picked.frame.t_us - first_us), cloud.countValid(), removed, n, out_dir.c_str());
  return 0;
}
