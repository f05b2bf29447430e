#include "board/cli/import_euroc_command.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include <opencv2/imgcodecs.hpp>

#include "board/config/euroc_mounting.h"
#include "board/config/recording_options.h"
#include "board/config/stereo_calibration_file.h"
#include "board/config/vehicle_setup.h"
#include "drivers/euroc/euroc_dataset.h"
#include "drivers/euroc/euroc_frames.h"
#include "drivers/recording/recording_writer.h"

namespace deepnav {
namespace {

const char* kEurocTarget = "EuRoC sensor.yaml (T_BS, pinhole, radial-tangential)";

bool loadImage(const std::string& path, const cv::Size& size, cv::Mat* into, std::string* error) {
  const cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.empty()) {
    if (error) *error = path + ": cannot read the image";
    return false;
  }
  if (image.type() != CV_8UC1 || image.size() != size) {
    if (error)
      *error = path + ": " + std::to_string(image.cols) + "x" + std::to_string(image.rows) + " with " +
               std::to_string(image.channels()) + " channel(s), expected 8-bit grey " + std::to_string(size.width) +
               "x" + std::to_string(size.height) + " (sensor.yaml resolution)";
    return false;
  }
  image.copyTo(*into);
  return true;
}

std::int64_t firstTimeNs(const EurocDataset& d) {
  std::int64_t t0 = std::min(d.pairs.front().t_ns, d.imu_rows.front().t_ns);
  if (!d.truth.empty()) t0 = std::min(t0, d.truth.front().t_ns);
  return t0;
}

// The setup whose texts go into the recording: the --board one (its camera must match the data), or only
// the imported calibration (replay then needs --board).
bool recordingSetup(const ImportEurocOptions& o, const EurocDataset& d, const std::string& calibration_text,
                    VehicleSetup* setup, RecordingOptions* recording, std::string* error) {
  if (o.board_path.empty()) {
    setup->calibration_text = calibration_text;
    *recording = RecordingOptions{};
    recording->image_width_px = d.cam0.width_px;
    recording->image_height_px = d.cam0.height_px;
    return true;
  }
  if (!loadVehicleSetup(o.board_path, setup, error)) return false;
  const BoardConfig::Camera& c = setup->config.camera;
  if (c.width_px != d.cam0.width_px || c.height_px != d.cam0.height_px || c.channels != 1) {
    if (error)
      *error = o.board_path + ": camera.width_px/height_px/channels are " + std::to_string(c.width_px) + "x" +
               std::to_string(c.height_px) + "x" + std::to_string(c.channels) + ", the EuRoC images " +
               std::to_string(d.cam0.width_px) + "x" + std::to_string(d.cam0.height_px) + "x1";
    return false;
  }
  *recording = recordingOptions(setup->config);
  recording->record_images = true;
  return true;
}

std::map<std::string, std::string> eurocMetadata(const EurocDataset& d, std::int64_t t0_ns) {
  return {{"source", d.mav_dir},
          {"t0_ns", std::to_string(t0_ns)},
          {"pairs", std::to_string(d.pairs.size())},
          {"cam0_unpaired", std::to_string(d.cam0_unpaired)},
          {"cam1_unpaired", std::to_string(d.cam1_unpaired)},
          {"cam0_missing", std::to_string(d.cam0_missing)},
          {"cam1_missing", std::to_string(d.cam1_missing)},
          {"imu_samples", std::to_string(d.imu_rows.size())},
          {"truth_samples", std::to_string(d.truth.size())},
          {"R_robot_body", "[0 0 1; 0 -1 0; 1 0 0] (robot FLU: forward = z_B, left = -y_B, up = x_B)"}};
}

// Merges the three time-sorted streams into the recording (ties: IMU, then truth, then the pair).
bool writeStreams(const EurocDataset& d, std::int64_t t0_ns, RecordingWriter* w, std::string* error) {
  StereoFrame frame;
  if (!allocateStereoFrame(frame, d.cam0.width_px, d.cam0.height_px, 1)) {
    if (error) *error = "cannot allocate a stereo frame";
    return false;
  }
  const cv::Size size(d.cam0.width_px, d.cam0.height_px);
  const Eigen::Matrix3d R_body_imu = d.imu.T_body_sensor.linear();
  std::size_t i = 0, p = 0, g = 0;
  const std::int64_t kEnd = INT64_MAX;
  while (i < d.imu_rows.size() || p < d.pairs.size() || g < d.truth.size()) {
    const std::int64_t ti = i < d.imu_rows.size() ? d.imu_rows[i].t_ns : kEnd;
    const std::int64_t tg = g < d.truth.size() ? d.truth[g].t_ns : kEnd;
    const std::int64_t tp = p < d.pairs.size() ? d.pairs[p].t_ns : kEnd;
    if (ti <= tg && ti <= tp) {
      w->recordInput(eurocImuSample(d.imu_rows[i++], R_body_imu, t0_ns));
    } else if (tg <= tp) {
      w->recordTruth(eurocTruthSample(d.truth[g++], t0_ns));
    } else {
      const EurocStereoPair& pair = d.pairs[p];
      if (!loadImage(pair.left_path, size, &frame.left, error) || !loadImage(pair.right_path, size, &frame.right, error)) {
        return false;
      }
      frame.t_us = eurocTimeUs(pair.t_ns, t0_ns);
      frame.sequence = p++;
      frame.rectified = false;
      w->recordFrame(frame, -1);
    }
  }
  return true;
}

void printSummary(const ImportEurocOptions& o, const EurocDataset& d, const EurocMounting& m) {
  const double span_s = 1e-9 * static_cast<double>(d.imu_rows.back().t_ns - d.imu_rows.front().t_ns);
  std::printf("%s: %zu stereo pairs (%d cam0 and %d cam1 images without a twin left out), %zu IMU samples over "
              "%.2f s, %zu ground-truth samples\n",
              o.out_path.c_str(), d.pairs.size(), d.cam0_unpaired, d.cam1_unpaired, d.imu_rows.size(), span_s,
              d.truth.size());
  if (d.cam0_missing + d.cam1_missing > 0)
    std::printf("listed images without a file, skipped: %d cam0, %d cam1\n", d.cam0_missing, d.cam1_missing);
  const cv::Matx33d& K0 = m.calibration.left.K;
  std::printf("stereo: %dx%d, fu %.3f fv %.3f cu %.3f cv %.3f (cam0), baseline %.4f m\n", d.cam0.width_px,
              d.cam0.height_px, K0(0, 0), K0(1, 1), K0(0, 2), K0(1, 2), m.baseline_m);
  std::printf("board mounting (robot frame FLU: forward = z_B, left = -y_B, up = x_B):\n");
  std::printf("  camera.p_cam_in_robot_m: [%.4f, %.4f, %.4f]\n", m.p_cam_in_robot_m.x(), m.p_cam_in_robot_m.y(),
              m.p_cam_in_robot_m.z());
  std::printf("  camera.rotation_deg: [%.3f, %.3f, %.3f]\n", m.camera_rotation_deg.x(), m.camera_rotation_deg.y(),
              m.camera_rotation_deg.z());
  std::printf("  ekf.p_imu_in_robot_m: [%.4f, %.4f, %.4f]\n", m.p_imu_in_robot_m.x(), m.p_imu_in_robot_m.y(),
              m.p_imu_in_robot_m.z());
  std::printf("  camera.rate_hz: %g\n", d.cam0.rate_hz);
}

bool importEuroc(const ImportEurocOptions& o, std::string* error) {
  EurocDataset d;
  EurocReadOptions read;
  read.skip_missing_images = o.skip_missing_images;
  read.duration_s = o.duration_s;
  if (!readEurocDataset(o.dir, read, &d, error)) return false;
  const EurocMounting m = eurocMounting(d.cam0, d.cam1, d.imu);
  StereoCalibrationInfo info;
  info.target = kEurocTarget;
  if (!o.calibration_out.empty() && !writeStereoCalibrationFile(o.calibration_out, m.calibration, info, error)) {
    return false;
  }
  VehicleSetup setup;
  RecordingOptions recording;
  if (!recordingSetup(o, d, stereoCalibrationText(m.calibration, info), &setup, &recording, error)) return false;
  RecordingWriter writer;
  if (!writer.open(o.out_path, recording, error)) return false;
  if (o.board_path.empty()) {
    writer.recordMetadata(kCalibrationMetadata, {{"yaml", setup.calibration_text}});
  } else {
    for (const auto& [name, values] : recordingMetadata(setup)) writer.recordMetadata(name, values);
  }
  const std::int64_t t0_ns = firstTimeNs(d);
  writer.recordMetadata("deepnav.euroc", eurocMetadata(d, t0_ns));
  if (!writeStreams(d, t0_ns, &writer, error)) return false;
  if (writer.failures() > 0) {
    if (error) *error = o.out_path + ": " + std::to_string(writer.failures()) + " messages could not be written";
    return false;
  }
  if (!writer.close(error)) return false;
  if (!o.quiet) printSummary(o, d, m);
  return true;
}

}  // namespace

int runImportEurocCommand(const ImportEurocOptions& options) {
  std::string error;
  if (!importEuroc(options, &error)) {
    std::fprintf(stderr, "deepnav import euroc: %s\n", error.empty() ? "failed (no reason given)" : error.c_str());
    return 1;
  }
  return 0;
}

}  // namespace deepnav
