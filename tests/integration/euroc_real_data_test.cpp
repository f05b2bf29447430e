// Issue 19 item 5: real stereo and IMU data through deepnav. The start of EuRoC V1_01
// (../shared/data/euroc-v101-micro: 95 stereo pairs 752x480 at 20 Hz, the ADIS16448 at 200 Hz, the MAV
// sitting still on the floor) is imported, rectified with its own calibration, and run through the vision
// chain and the filter on board/euroc. Every threshold comes from the physics of a static rig or from the
// data itself; each test prints its figures (docs/euroc.md quotes them).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "board/cli/import_euroc_command.h"
#include "drivers/euroc/euroc_dataset.h"
#include "drivers/euroc/euroc_frames.h"
#include "tests/support/foreign_mcap_writer.h"
#include "tests/support/ros1_bag_writer.h"
#include "board/config/vehicle_setup.h"
#include "board/replay/bench_replay.h"
#include "drivers/replay/recording_reader.h"
#include "vision/stereo/elas_disparity.h"
#include "tests/support/source_paths.h"
#include "tests/support/temp_path.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;

using deepnav::testing::sharedDataDir;

const fs::path kBoard = fs::path(deepnav::testing::sourceDir()) / "board" / "euroc" / "board.yaml";
// The images end 4.70 s after the first sample; imu0 runs on through the 145 s flight.
constexpr double kImportSpan_s = 4.75;
// Local gravity at the ETH Zurich Vicon room (47.4 deg N, ~450 m): 9.807 m/s2 (WGS84 normal gravity).
constexpr double kLocalGravity_mps2 = 9.807;

struct Imported {
  fs::path dir;
  fs::path recording;
  std::vector<ImuSample> imu;
  std::vector<StereoFrame> frames;
};

// Imports once for the whole binary.
const Imported* importedData() {
  static Imported data;
  static bool done = false;
  static bool ok = false;
  if (done) return ok ? &data : nullptr;
  done = true;
  const fs::path source = sharedDataDir() / "euroc-v101-micro";
  if (!fs::exists(source / "mav0" / "cam0" / "data.csv")) return nullptr;
  data.dir = fs::path(deepnav::testing::tempPath("euroc_real"));
  fs::remove_all(data.dir);
  fs::create_directories(data.dir);
  data.recording = data.dir / "v101.mcap";
  ImportEurocOptions o;
  o.dir = source.string();
  o.out_path = data.recording.string();
  o.skip_missing_images = true;  // cam1/data.csv lists 4 images past the extract's end
  o.duration_s = kImportSpan_s;
  o.quiet = true;
  if (runImportEurocCommand(o) != 0) return nullptr;
  RecordingReader reader;
  std::string error;
  if (!reader.open(data.recording.string(), &error)) return nullptr;
  ok = reader.forEach(true, [&](const ReplayEvent& e) {
    if (e.kind == ReplayEvent::Kind::kInput) data.imu.push_back(std::get<ImuSample>(e.input));
    if (e.kind == ReplayEvent::Kind::kFrame) {
      StereoFrame f = *e.frame;
      f.left = e.frame->left.clone();
      f.right = e.frame->right.clone();
      data.frames.push_back(f);
    }
    return true;
  }, &error);
  return ok ? &data : nullptr;
}

// The import and the foreign copies (about 200 MB) go when the binary ends.
class RemoveImported : public ::testing::Environment {
 public:
  void TearDown() override {
    const Imported* data = importedData();
    std::error_code ec;
    if (data != nullptr) fs::remove_all(data->dir, ec);
  }
};
::testing::Environment* const kRemoveImported = ::testing::AddGlobalTestEnvironment(new RemoveImported);

#define REQUIRE_DATA()                                                                      \
  const Imported* data = importedData();                                                    \
  if (data == nullptr) GTEST_SKIP() << "no EuRoC data under " << sharedDataDir() << " (or the import failed)"

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// |v_left - v_right| of cross-checked ORB matches between the two images of a pair.
std::vector<double> rowOffsets(const cv::Mat& left, const cv::Mat& right) {
  auto orb = cv::ORB::create(1500);
  std::vector<cv::KeyPoint> kl, kr;
  cv::Mat dl, dr;
  orb->detectAndCompute(left, cv::noArray(), kl, dl);
  orb->detectAndCompute(right, cv::noArray(), kr, dr);
  std::vector<cv::DMatch> matches;
  cv::BFMatcher(cv::NORM_HAMMING, true).match(dl, dr, matches);
  std::vector<double> dy;
  for (const cv::DMatch& m : matches) {
    const cv::Point2f a = kl[static_cast<std::size_t>(m.queryIdx)].pt, b = kr[static_cast<std::size_t>(m.trainIdx)].pt;
    // A true stereo match lies to the left in the right image within the disparity range; the loose row
    // window (40 px) keeps the raw images' distorted matches too.
    if (m.distance < 40 && a.x - b.x > -2.0f && a.x - b.x < 128.0f && std::abs(a.y - b.y) < 40.0f) {
      dy.push_back(std::abs(a.y - b.y));
    }
  }
  return dy;
}

TEST(EurocRealData, ImportHoldsTheExtractAndItsOwnCalibrationRectifiesItsRows) {
  REQUIRE_DATA();
  // 95 pairs (cam1 lists 99 images, 4 past the extract's last file), 950 IMU samples = 4.75 s at 200 Hz.
  EXPECT_EQ(data->frames.size(), 95u);
  EXPECT_EQ(data->imu.size(), 950u);
  VehicleSetup setup;
  std::string error;
  ASSERT_TRUE(loadVehicleSetup(kBoard.string(), &setup, &error)) << error;
  ASSERT_TRUE(setup.rectify);
  StereoRectifier rectifier;
  ASSERT_TRUE(rectifier.init(setup.rectification, &error)) << error;
  std::vector<double> raw_dy, rect_dy;
  cv::Mat rl(480, 752, CV_8UC1), rr(480, 752, CV_8UC1);
  for (std::size_t k = 0; k < data->frames.size(); k += 10) {
    const StereoFrame& f = data->frames[k];
    for (double d : rowOffsets(f.left, f.right)) raw_dy.push_back(d);
    ASSERT_TRUE(rectifier.rectify(f.left, f.right, rl, rr));
    for (double d : rowOffsets(rl, rr)) rect_dy.push_back(d);
  }
  const double raw = median(raw_dy), rect = median(rect_dy);
  const auto within1 = [](const std::vector<double>& v) {
    return static_cast<double>(std::count_if(v.begin(), v.end(), [](double d) { return d <= 1.0; })) /
           static_cast<double>(v.size());
  };
  std::printf("[euroc] rectification (10 pairs): median |v_l - v_r| of ORB matches raw %.3f px (%zu matches, %.1f %% "
              "within 1 px), rectified %.3f px (%zu matches, %.1f %% within 1 px); rectified fx %.2f px, baseline "
              "%.4f m\n",
              raw, raw_dy.size(), 100.0 * within1(raw_dy), rect, rect_dy.size(), 100.0 * within1(rect_dy),
              setup.rectification.rectified.fx_px, setup.rectification.baseline_m);
  // Rectified with the right calibration, a match lies on the same row up to the keypoint quantisation of
  // ORB's pyramid (1 px at level 0, more above): the median under half a pixel, well under the raw one's.
  EXPECT_GT(rect_dy.size(), 500u);
  EXPECT_LT(rect, 0.5);
  EXPECT_LT(rect, 0.5 * raw);
  EXPECT_NEAR(setup.rectification.baseline_m, 0.110, 0.001);  // the VI-Sensor's 11 cm
}

TEST(EurocRealData, ElasDisparityIsDenseAndStaysPutOnTheStaticRig) {
  REQUIRE_DATA();
  VehicleSetup setup;
  std::string error;
  ASSERT_TRUE(loadVehicleSetup(kBoard.string(), &setup, &error)) << error;
  StereoRectifier rectifier;
  ASSERT_TRUE(rectifier.init(setup.rectification, &error)) << error;
  ElasParams params = ElasParams::robotics();
  params.num_disparities = 128;  // 0.37 m at fx 435 px and B 0.11 m: nearer than the floor in view
  ElasDisparity elas;
  ASSERT_TRUE(elas.init(params, 752, 480));
  cv::Mat rl(480, 752, CV_8UC1), rr(480, 752, CV_8UC1), first, d;
  std::vector<double> coverage, change;
  for (std::size_t k = 0; k < data->frames.size(); k += 10) {
    ASSERT_TRUE(rectifier.rectify(data->frames[k].left, data->frames[k].right, rl, rr));
    ASSERT_TRUE(elas.compute(rl, rr, &d));
    coverage.push_back(static_cast<double>(cv::countNonZero(d >= 0.0f)) / static_cast<double>(d.total()));
    if (first.empty()) {
      first = d.clone();
      continue;
    }
    std::vector<double> diff;
    for (int v = 0; v < d.rows; v += 4)
      for (int u = 0; u < d.cols; u += 4)
        if (d.at<float>(v, u) >= 0.0f && first.at<float>(v, u) >= 0.0f)
          diff.push_back(std::abs(d.at<float>(v, u) - first.at<float>(v, u)));
    change.push_back(median(diff));
  }
  const double mean_coverage = std::accumulate(coverage.begin(), coverage.end(), 0.0) / static_cast<double>(coverage.size());
  const double worst_change = *std::max_element(change.begin(), change.end());
  std::printf("[euroc] ELAS (robotics preset, 128 disparities) on %zu rectified pairs: coverage mean %.1f %%, "
              "min %.1f %%; median |d_k - d_0| worst %.3f px\n",
              coverage.size(), 100.0 * mean_coverage, 100.0 * *std::min_element(coverage.begin(), coverage.end()),
              worst_change);
  // The room is textured and lit: most of the view has a disparity.
  EXPECT_GT(*std::min_element(coverage.begin(), coverage.end()), 0.5);
  // Nothing moves: each pixel's disparity is the first pair's within ELAS's sub-pixel noise.
  EXPECT_LT(worst_change, 0.5);
}

// Mean of the IMU samples within [t0_us, t1_us).
void meanImu(const std::vector<ImuSample>& imu, TimeUs t0_us, TimeUs t1_us, Eigen::Vector3d* w, Eigen::Vector3d* f) {
  w->setZero();
  f->setZero();
  int n = 0;
  for (const ImuSample& s : imu) {
    if (s.t_us < t0_us || s.t_us >= t1_us) continue;
    *w += s.w_imu_radps;
    *f += s.f_imu_mps2;
    ++n;
  }
  *w /= n;
  *f /= n;
}

double angleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(EurocRealData, ImuSeesGravityUpAndAConstantRate) {
  REQUIRE_DATA();
  Eigen::Vector3d w_first, f_first, w_last, f_last, w_all, f_all;
  meanImu(data->imu, 0, 1'000'000, &w_first, &f_first);
  meanImu(data->imu, 3'750'000, 4'750'000, &w_last, &f_last);
  meanImu(data->imu, 0, 4'750'000, &w_all, &f_all);
  std::printf("[euroc] IMU (robot FLU): |f| %.4f m/s2 (local g %.3f), f/|f| [%.4f %.4f %.4f], tilt %.2f deg; "
              "mean rate [%.5f %.5f %.5f] rad/s; gravity direction first vs last second %.3f deg\n",
              f_all.norm(), kLocalGravity_mps2, f_all.x() / f_all.norm(), f_all.y() / f_all.norm(),
              f_all.z() / f_all.norm(), angleDeg(f_all, Eigen::Vector3d::UnitZ()), w_all.x(), w_all.y(), w_all.z(),
              angleDeg(f_first, f_last));
  // At rest the accelerometer reads gravity: its magnitude within 0.1 m/s2 (10 mg: the ADIS16448's
  // accelerometer bias before calibration can reach this, its noise averages to 0.2 mg over a second), and
  // pointing up in FLU (the body's x, rotated at import), the rig pitched by its stand, not upside down.
  EXPECT_NEAR(f_all.norm(), kLocalGravity_mps2, 0.1);
  EXPECT_GT(f_all.z() / f_all.norm(), std::cos(30.0 * M_PI / 180.0));
  // Nothing turns: the gravity direction of the last second is the first's within the gyro-free
  // accelerometer noise (2e-3 m/s2/sqrt(Hz) over 1 s: 0.01 deg) and the rotor vibration's bias.
  EXPECT_LT(angleDeg(f_first, f_last), 0.2);
}

TEST(EurocRealData, ReplayOnTheBoardHoldsTheStaticRigToMillimetres) {
  REQUIRE_DATA();
  ReplayOptions o;
  o.input_path = data->recording.string();
  o.out_dir = (data->dir / "replay").string();
  o.board_path = kBoard.string();
  o.progress = false;
  ReplaySummary s;
  std::string error;
  ASSERT_TRUE(runBenchReplay(o, &s, &error)) << error;
  ReplaySummary imu_only;
  o.out_dir = (data->dir / "replay_imu_only").string();
  o.overrides = {"vision.vo_mode=none"};
  ASSERT_TRUE(runBenchReplay(o, &imu_only, &error)) << error;

  // Stage 2 from the alignment (200 IMU samples: 1 s), ORB VO on every pair from then on.
  EXPECT_NEAR(s.stage2_at_s, 0.995, 0.01);
  std::vector<double> tracked;
  for (const FrameStat& f : s.frame_stats) tracked.push_back(f.orb_tracked);
  const double min_tracked = *std::min_element(tracked.begin(), tracked.end());
  const double mean_tracked = std::accumulate(tracked.begin(), tracked.end(), 0.0) / static_cast<double>(tracked.size());
  // Drift: the largest distance from the start over the run (the rig does not move).
  double drift = 0.0, drift_imu = 0.0, yaw_change = 0.0, tilt_change = 0.0;
  const StampedPose& p0 = s.estimate.front();
  for (const StampedPose& p : s.estimate) {
    drift = std::max(drift, (p.p_robot_in_odom_m - p0.p_robot_in_odom_m).norm());
    const Eigen::Vector3d x0 = p0.q_odom_robot * Eigen::Vector3d::UnitX(), x = p.q_odom_robot * Eigen::Vector3d::UnitX();
    yaw_change = std::max(yaw_change, std::abs(std::atan2(x.y(), x.x()) - std::atan2(x0.y(), x0.x())) * 180.0 / M_PI);
    tilt_change = std::max(tilt_change, angleDeg(p.q_odom_robot.conjugate() * Eigen::Vector3d::UnitZ(),
                                                 p0.q_odom_robot.conjugate() * Eigen::Vector3d::UnitZ()));
  }
  for (const StampedPose& p : imu_only.estimate) {
    drift_imu = std::max(drift_imu, (p.p_robot_in_odom_m - imu_only.estimate.front().p_robot_in_odom_m).norm());
  }
  Eigen::Vector3d w_all, f_all;
  meanImu(data->imu, 0, 4'750'000, &w_all, &f_all);
  const Eigen::Vector3d bias_error = s.estimator_states.b_gyro_radps - w_all;
  std::printf("[euroc] replay: %llu pairs, stage 2 at %.3f s, ORB tracked per pair mean %.0f min %.0f; VO offered %u "
              "fused %u rejected %u; drift over %.2f s: %.1f mm with VO, %.1f mm IMU alone; yaw change %.3f deg, "
              "tilt change %.3f deg; gyro bias [%.5f %.5f %.5f] rad/s (sigma %.5f %.5f %.5f), minus the data's mean "
              "rate [%.5f %.5f %.5f]; accel bias [%.4f %.4f %.4f] m/s2\n",
              static_cast<unsigned long long>(s.frames), s.stage2_at_s, mean_tracked, min_tracked, s.vo.measurements,
              s.vo.accepted, s.vo.rejected, s.estimate.back().t_s - p0.t_s, 1e3 * drift, 1e3 * drift_imu, yaw_change,
              tilt_change, s.estimator_states.b_gyro_radps.x(), s.estimator_states.b_gyro_radps.y(),
              s.estimator_states.b_gyro_radps.z(), s.estimator_states.b_gyro_sigma_radps.x(),
              s.estimator_states.b_gyro_sigma_radps.y(), s.estimator_states.b_gyro_sigma_radps.z(), bias_error.x(),
              bias_error.y(), bias_error.z(), s.estimator_states.b_accel_mps2.x(), s.estimator_states.b_accel_mps2.y(),
              s.estimator_states.b_accel_mps2.z());
  // The same view in every pair: every pair keeps more features than the ORB VO's keyframe threshold (80).
  EXPECT_GE(min_tracked, 80.0);
  // One VO result per stage-2 pair (76 pairs from 0.995 s) but the first (no reference yet) and the
  // three beyond the delay window, and most of them fused. (A consistent 3-sigma gate refuses 0.3 %; the
  // 10 of 72 it refuses here are printed and discussed in docs/euroc.md, not asserted away.)
  EXPECT_GE(s.vo.measurements, 70u);
  EXPECT_GT(2 * s.vo.accepted, s.vo.measurements);
  // Static rig: the VO holds the position to millimetres, where the IMU alone drifts by decimetres
  // (its accelerometer bias 0.03 m/s2 integrates to 0.2 m in 3.7 s).
  EXPECT_LT(drift, 0.010);
  EXPECT_GT(drift_imu, 10.0 * drift);
  // Attitude: the rig does not turn; the gyro's noise integrates to 0.2 deg over the run.
  EXPECT_LT(yaw_change, 0.5);
  EXPECT_LT(tilt_change, 0.5);
  // Gyro bias: the rig is static, so the data's mean rate is the bias (plus Earth's 7e-5 rad/s); the
  // filter's estimate agrees with it within 3 of its own sigmas on each axis. (The extract carries no
  // state_groundtruth_estimate0/data.csv, so the dataset's own bias estimate cannot be compared.)
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(bias_error[i]), 3.0 * s.estimator_states.b_gyro_sigma_radps[i]) << i;
}

// The same extract as EuRoC's own ROS bags publish it: /cam0/image_raw and /cam1/image_raw
// (sensor_msgs/Image mono8) and /imu0 (sensor_msgs/Imu in the IMU's frame, x up, y right, z forward),
// stamped with the dataset's time to the microsecond (the deepnav recording's t_us after its t0_ns).
template <typename Writer>
void writeAsRos(const EurocDataset& d, std::int64_t t0_us, Writer& w) {
  const auto stampNs = [&](std::int64_t t_ns) { return (t0_us + eurocTimeUs(t_ns, d.imu_rows.front().t_ns)) * 1000; };
  const auto header = [&](std::int64_t t_ns, const char* frame) {
    ros::Header h;
    const std::int64_t ns = stampNs(t_ns);
    h.stamp.sec = static_cast<std::int32_t>(ns / 1'000'000'000);
    h.stamp.nanosec = static_cast<std::uint32_t>(ns % 1'000'000'000);
    h.frame_id = frame;
    return h;
  };
  const auto image = [&](const std::string& path, std::int64_t t_ns, const char* frame) {
    const cv::Mat m = cv::imread(path, cv::IMREAD_UNCHANGED);
    ros::Image i;
    i.header = header(t_ns, frame);
    i.width = static_cast<std::uint32_t>(m.cols);
    i.height = static_cast<std::uint32_t>(m.rows);
    i.encoding = "mono8";
    i.step = i.width;
    i.data.assign(m.data, m.data + m.total());
    return i;
  };
  std::size_t p = 0;
  for (const EurocImuRow& r : d.imu_rows) {
    while (p < d.pairs.size() && d.pairs[p].t_ns < r.t_ns) {
      w.write("/cam0/image_raw", image(d.pairs[p].left_path, d.pairs[p].t_ns, "cam0"), stampNs(d.pairs[p].t_ns));
      w.write("/cam1/image_raw", image(d.pairs[p].right_path, d.pairs[p].t_ns, "cam1"), stampNs(d.pairs[p].t_ns));
      ++p;
    }
    ros::Imu m;
    m.header = header(r.t_ns, "imu4");
    m.orientation_covariance[0] = -1.0;  // a plain IMU
    m.angular_velocity = {r.w_sensor_radps.x(), r.w_sensor_radps.y(), r.w_sensor_radps.z()};
    m.linear_acceleration = {r.f_sensor_mps2.x(), r.f_sensor_mps2.y(), r.f_sensor_mps2.z()};
    w.write("/imu0", m, stampNs(r.t_ns));
  }
}

// The IMU's frame to the robot's is R_robot_body = [0 0 1; 0 -1 0; 1 0 0] = Rz(0) Ry(-90 deg) Rx(180 deg).
const char* kEurocTopicMap =
    "topics:\n"
    "  /imu0: {sensor: imu, rotation_deg: [180, -90, 0]}\n"
    "  /cam0/image_raw: {sensor: camera_left}\n"
    "  /cam1/image_raw: {sensor: camera_right}\n";

TEST(EurocRealData, AsARos2McapAndAsARos1BagItGivesTheSameTrajectory) {
  REQUIRE_DATA();
  EurocDataset d;
  EurocReadOptions read;
  read.skip_missing_images = true;
  read.duration_s = kImportSpan_s;
  std::string error;
  ASSERT_TRUE(readEurocDataset((sharedDataDir() / "euroc-v101-micro").string(), read, &d, &error)) << error;
  const std::int64_t t0_us = eurocTimeUs(d.imu_rows.front().t_ns, 0);  // 1403715273262143 us
  const fs::path mcap = data->dir / "v101_ros2.mcap", bag = data->dir / "v101_ros1.bag", map = data->dir / "map.yaml";
  {
    testing::ForeignMcapWriter w(mcap.string());
    writeAsRos(d, t0_us, w);
    w.close();
  }
  testsupport::Ros1BagWriter b;
  ASSERT_TRUE(b.open(bag.string(), testsupport::Ros1BagWriter::Compression::kLz4));
  writeAsRos(d, t0_us, b);
  ASSERT_TRUE(b.close());
  std::ofstream(map) << kEurocTopicMap;

  const auto run = [&](const fs::path& input, const std::string& topics, const char* out) {
    ReplayOptions o;
    o.input_path = input.string();
    o.topics_path = topics;
    o.out_dir = (data->dir / out).string();
    o.board_path = kBoard.string();
    o.progress = false;
    ReplaySummary s;
    std::string e;
    EXPECT_TRUE(runBenchReplay(o, &s, &e)) << e;
    return s;
  };
  const ReplaySummary own = run(data->recording, "", "own");
  const ReplaySummary ros2 = run(mcap, map.string(), "ros2");
  const ReplaySummary ros1 = run(bag, map.string(), "ros1");
  for (const ReplaySummary* s : {&ros2, &ros1}) {
    const char* what = s == &ros2 ? "ROS 2 MCAP" : "ROS 1 bag (lz4)";
    ASSERT_EQ(s->estimate.size(), own.estimate.size()) << what;
    EXPECT_EQ(s->frames, own.frames) << what;
    EXPECT_EQ(s->inputs.imu, own.inputs.imu) << what;
    EXPECT_EQ(s->vo.accepted, own.vo.accepted) << what;
    double worst_m = 0.0, worst_deg = 0.0, worst_dt_s = 0.0;
    for (std::size_t i = 0; i < own.estimate.size(); ++i) {
      const StampedPose &a = own.estimate[i], &b = s->estimate[i];
      worst_dt_s = std::max(worst_dt_s, std::abs(b.t_s - 1e-6 * static_cast<double>(t0_us) - a.t_s));
      worst_m = std::max(worst_m, (b.p_robot_in_odom_m - a.p_robot_in_odom_m).norm());
      worst_deg = std::max(worst_deg, a.q_odom_robot.angularDistance(b.q_odom_robot) * 180.0 / M_PI);
    }
    std::printf("[euroc] %s: %zu ticks, %llu pairs, VO fused %u; against the deepnav import: largest position "
                "difference %.3g m, attitude %.3g deg, time %.3g s\n",
                what, s->estimate.size(), static_cast<unsigned long long>(s->frames), s->vo.accepted, worst_m, worst_deg,
                worst_dt_s);
    // The same samples and images: the same trajectory up to the rounding of the IMU's rotation (applied as
    // the mounting's quaternion here, as an exact axis permutation at import). The ticks keep to multiples
    // of the 5 ms loop period on each recording's clock: the dataset's clock (t0 = ...273.262143 s) puts
    // them 2.857 ms after the import's (t0 = 0), the same IMU sample's state at each.
    EXPECT_LT(worst_dt_s, 0.005) << what;
    EXPECT_LT(worst_m, 1e-6) << what;
    EXPECT_LT(worst_deg, 1e-6) << what;
  }
}

}  // namespace
}  // namespace deepnav
