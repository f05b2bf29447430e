// OrbStereoOdometry on synthetic stereo pairs: textured planes at 1-3 m rendered by exact
// homographies into the DexROV rig (688x516, f = 700 px, baseline 0.30 m) along a known smooth
// trajectory, with sensor noise. GIVEN the rendered sequence WHEN the odometry runs THEN each
// relative pose, the chained trajectory, the covariance, the lost / relocalised states behave.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "base/so3.h"
#include "tests/support/synthetic_plane_scene.h"
#include "vision/orbvo/orb_stereo_odometry.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr TimeUs kFramePeriodUs = 100'000;  // 10 Hz

StereoRig rig() { return StereoRig{}; }

struct CameraPose {
  Eigen::Quaterniond q_world_cam = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_cam_in_world_m = Eigen::Vector3d::Zero();
};

// Smooth test trajectory: about 1-2 cm and 0.2-0.4 deg per frame.
CameraPose trajectoryPose(int k) {
  const double s = static_cast<double>(k);
  CameraPose pose;
  pose.p_cam_in_world_m = {0.25 * std::sin(0.08 * s), 0.08 * std::sin(0.13 * s),
                           0.15 * (1.0 - std::cos(0.06 * s))};
  const double yaw = 4.0 * kDeg * std::sin(0.07 * s);
  const double pitch = 3.0 * kDeg * (std::sin(0.05 * s + 0.5) - std::sin(0.5));
  const double roll = 2.0 * kDeg * std::sin(0.09 * s);
  // Camera frame: yaw about y (down), pitch about x (right), roll about z (forward).
  pose.q_world_cam = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()) *
                     Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ());
  return pose;
}

struct StereoImages {
  cv::Mat left, right;
};

StereoImages renderNoisy(const SyntheticPlaneScene& scene, const CameraPose& pose,
                         std::uint64_t seed) {
  StereoImages images;
  scene.render(rig(), pose.q_world_cam, pose.p_cam_in_world_m, 90, &images.left, &images.right);
  cv::RNG rng(seed);
  for (cv::Mat* image : {&images.left, &images.right}) {
    cv::Mat noise(image->size(), CV_16SC1);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.5);
    cv::Mat sum;
    image->convertTo(sum, CV_16SC1);
    sum += noise;
    sum.convertTo(*image, CV_8UC1);
  }
  return images;
}

// Truth of the relative pose of frame b in frame a.
CameraPose relativeTruth(const CameraPose& a, const CameraPose& b) {
  CameraPose rel;
  rel.q_world_cam = a.q_world_cam.conjugate() * b.q_world_cam;
  rel.p_cam_in_world_m = a.q_world_cam.conjugate() * (b.p_cam_in_world_m - a.p_cam_in_world_m);
  return rel;
}

struct FrameRecord {
  OrbVoOutput out;
  CameraPose truth_rel;
  double rotation_error_deg = 0.0;
  double translation_error_m = 0.0;
  // [dp; n], the output's convention
  Eigen::Matrix<double, 6, 1> error = Eigen::Matrix<double, 6, 1>::Zero();
};

struct SequenceRun {
  std::vector<FrameRecord> frames;
  CameraPose chained;  // chained relative poses from frame 0
};

const SyntheticPlaneScene& texturedScene() {
  static const SyntheticPlaneScene scene = makeOrbVoTestScene(7, 0.6);
  return scene;
}

// Relative pose errors of an output against the truth of frame b in frame a.
void relativeErrors(const OrbVoOutput& out, const CameraPose& a, const CameraPose& b,
                    double* translation_m, double* rotation_deg) {
  const CameraPose truth = relativeTruth(a, b);
  *translation_m = (out.p_camb_in_cama_m - truth.p_cam_in_world_m).norm();
  *rotation_deg = truth.q_world_cam.angularDistance(out.q_cama_camb) / kDeg;
}

SequenceRun runTextured50() {
  {
    SequenceRun r;
    const SyntheticPlaneScene& scene = texturedScene();
    OrbStereoOdometry vo;
    std::string error;
    if (!vo.init(OrbVoConfig(), rig(), &error)) return r;
    r.chained.q_world_cam.setIdentity();
    r.chained.p_cam_in_world_m.setZero();
    for (int k = 0; k < 50; ++k) {
      const StereoImages images = renderNoisy(scene, trajectoryPose(k), 100 + k);
      FrameRecord f;
      vo.process(k * kFramePeriodUs, images.left, images.right, &f.out);
      if (k > 0) {
        f.truth_rel = relativeTruth(trajectoryPose(k - 1), trajectoryPose(k));
        const Eigen::Matrix3d R_err = f.truth_rel.q_world_cam.toRotationMatrix().transpose() *
                                      f.out.q_cama_camb.toRotationMatrix();
        f.error.head<3>() = f.out.p_camb_in_cama_m - f.truth_rel.p_cam_in_world_m;
        f.error.tail<3>() = logSo3(R_err);
        f.rotation_error_deg = f.error.tail<3>().norm() / kDeg;
        f.translation_error_m = f.error.head<3>().norm();
        if (f.out.hasRelativePose()) {
          r.chained.p_cam_in_world_m += r.chained.q_world_cam * f.out.p_camb_in_cama_m;
          r.chained.q_world_cam = (r.chained.q_world_cam * f.out.q_cama_camb).normalized();
        }
      }
      r.frames.push_back(f);
    }
    return r;
  }
}

// The three checks of the 50-frame run share one run (ctest starts the binary once per test).
void checkEachRelativeMotion(const SequenceRun& run) {
  EXPECT_EQ(run.frames[0].out.status, OrbVoStatus::kInitialised);
  double max_rot = 0.0, max_trans = 0.0, sum_rot = 0.0, sum_trans = 0.0;
  int min_tracked = 1 << 30;
  for (std::size_t k = 1; k < run.frames.size(); ++k) {
    const FrameRecord& f = run.frames[k];
    EXPECT_EQ(f.out.t_reference_us, static_cast<TimeUs>(k - 1) * kFramePeriodUs);
    max_rot = std::max(max_rot, f.rotation_error_deg);
    max_trans = std::max(max_trans, f.translation_error_m);
    sum_rot += f.rotation_error_deg;
    sum_trans += f.translation_error_m;
    min_tracked = std::min(min_tracked, f.out.tracked_features);
  }
  const double n = static_cast<double>(run.frames.size() - 1);
  std::printf(
      "per frame: rotation mean %.4f max %.4f deg, translation mean %.2f max %.2f mm, min tracked "
      "%d\n",
      sum_rot / n, max_rot, 1e3 * sum_trans / n, 1e3 * max_trans, min_tracked);
  EXPECT_LT(sum_rot / n, 0.1);
  EXPECT_LT(max_rot, 0.2);
  EXPECT_LT(sum_trans / n, 0.005);
  EXPECT_LT(max_trans, 0.01);
  EXPECT_GT(min_tracked, 100);
}

void checkChainedTrajectory(const SequenceRun& run) {
  const CameraPose truth = relativeTruth(trajectoryPose(0), trajectoryPose(49));
  const double position_error_m = (run.chained.p_cam_in_world_m - truth.p_cam_in_world_m).norm();
  const double rotation_error_deg =
      truth.q_world_cam.angularDistance(run.chained.q_world_cam) / kDeg;
  double path_m = 0.0;
  for (int k = 1; k < 50; ++k)
    path_m += (trajectoryPose(k).p_cam_in_world_m - trajectoryPose(k - 1).p_cam_in_world_m).norm();
  std::printf("after 50 frames (%.2f m of path): position error %.1f mm, rotation error %.3f deg\n",
              path_m, 1e3 * position_error_m, rotation_error_deg);
  EXPECT_LT(position_error_m, 0.03);
  EXPECT_LT(rotation_error_deg, 0.5);
  // The odometry's own world pose is the same chain.
  EXPECT_LT((run.frames.back().out.p_cam_in_world_m - run.chained.p_cam_in_world_m).norm(), 1e-6);
}

void checkCovarianceAgainstTheError(const SequenceRun& run) {
  // Normalised estimation error squared: 6 on average for a consistent 6-dof covariance.
  double nees_sum = 0.0;
  Eigen::Matrix<double, 6, 1> ratio_sum = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t k = 1; k < run.frames.size(); ++k) {
    const FrameRecord& f = run.frames[k];
    nees_sum += f.error.dot(f.out.cov.ldlt().solve(f.error));
    ratio_sum += (f.error.array().square() / f.out.cov.diagonal().array()).matrix();
  }
  const double n = static_cast<double>(run.frames.size() - 1);
  const double nees = nees_sum / n;
  Eigen::Matrix<double, 6, 1> sigma_ratio = (ratio_sum / n).array().sqrt();
  std::printf(
      "mean NEES %.2f (6 if consistent); rms error / sigma per axis: %.2f %.2f %.2f %.2f %.2f "
      "%.2f\n",
      nees, sigma_ratio(0), sigma_ratio(1), sigma_ratio(2), sigma_ratio(3), sigma_ratio(4),
      sigma_ratio(5));
  EXPECT_GT(nees, 0.6);
  EXPECT_LT(nees, 60.0);
  for (int i = 0; i < 6; ++i) {
    EXPECT_GT(sigma_ratio(i), 0.1) << "axis " << i;
    EXPECT_LT(sigma_ratio(i), 10.0) << "axis " << i;
  }
}

TEST(OrbVoOdometry, FiftyFramesRelativeMotionsChainAndCovariance) {
  const SequenceRun run = runTextured50();
  ASSERT_EQ(run.frames.size(), 50u);
  for (std::size_t k = 1; k < run.frames.size(); ++k) {
    ASSERT_EQ(run.frames[k].out.status, OrbVoStatus::kOk) << "frame " << k;
  }
  {
    SCOPED_TRACE("each relative motion");
    checkEachRelativeMotion(run);
  }
  {
    SCOPED_TRACE("chained trajectory");
    checkChainedTrajectory(run);
  }
  {
    SCOPED_TRACE("covariance");
    checkCovarianceAgainstTheError(run);
  }
}

TEST(OrbVoOdometry, LowTextureImageGivesFewTrackedFeatures) {
  // GIVEN a map built on a textured scene, WHEN the same geometry comes back almost without texture
  // (contrast 3 % of the usual one, the look of a silted or backscattered view)
  const SyntheticPlaneScene bland = makeOrbVoTestScene(7, 0.02);
  OrbStereoOdometry vo;
  std::string error;
  ASSERT_TRUE(vo.init(OrbVoConfig(), rig(), &error)) << error;
  OrbVoOutput out;
  int textured_tracked = 0;
  for (int k = 0; k < 6; ++k) {
    const StereoImages images = renderNoisy(texturedScene(), trajectoryPose(k), 300 + k);
    vo.process(k * kFramePeriodUs, images.left, images.right, &out);
    textured_tracked = out.tracked_features;
  }
  ASSERT_EQ(out.status, OrbVoStatus::kOk);
  for (int k = 6; k < 9; ++k) {
    const StereoImages images = renderNoisy(bland, trajectoryPose(k), 300 + k);
    vo.process(k * kFramePeriodUs, images.left, images.right, &out);
    // THEN few features are tracked and the frame is reported lost, without a relative pose
    std::printf("bland frame %d: %d features, %d stereo, %d tracked (textured: %d), %s\n", k,
                out.left_features, out.stereo_points, out.tracked_features, textured_tracked,
                toString(out.status));
    EXPECT_LT(out.tracked_features, 20);
    EXPECT_EQ(out.status, OrbVoStatus::kLost);
    EXPECT_FALSE(out.hasRelativePose());
  }
  EXPECT_GT(textured_tracked, 200);
}

TEST(OrbVoOdometry, RelocalisesAfterBlankFramesNearAKeyframe) {
  OrbStereoOdometry vo;
  std::string error;
  ASSERT_TRUE(vo.init(OrbVoConfig(), rig(), &error)) << error;
  OrbVoOutput out;
  // GIVEN 25 tracked frames
  for (int k = 0; k < 25; ++k) {
    const StereoImages images = renderNoisy(texturedScene(), trajectoryPose(k), 400 + k);
    vo.process(k * kFramePeriodUs, images.left, images.right, &out);
    ASSERT_TRUE(k == 0 || out.status == OrbVoStatus::kOk) << "frame " << k;
  }
  const int keyframes = out.keyframes;
  ASSERT_GE(keyframes, 2);
  // WHEN the cameras see nothing for 4 frames (grey water, sensor noise)
  for (int k = 25; k < 29; ++k) {
    cv::Mat blank(rig().height_px, rig().width_px, CV_8UC1, cv::Scalar(90));
    StereoImages images{blank.clone(), blank.clone()};
    cv::RNG rng(500 + k);
    for (cv::Mat* image : {&images.left, &images.right}) {
      cv::Mat noise(image->size(), CV_8UC1);
      rng.fill(noise, cv::RNG::UNIFORM, 0, 4);
      *image += noise;
    }
    vo.process(k * kFramePeriodUs, images.left, images.right, &out);
    EXPECT_EQ(out.status, OrbVoStatus::kLost) << "blank frame " << k;
    EXPECT_EQ(out.tracked_features, 0);
  }
  // AND the vehicle comes back near where it was at frame 12, by then long behind it
  CameraPose back = trajectoryPose(12);
  back.p_cam_in_world_m += Eigen::Vector3d(0.02, -0.01, 0.015);
  back.q_world_cam = back.q_world_cam *
                     Eigen::Quaterniond(Eigen::AngleAxisd(1.0 * kDeg, Eigen::Vector3d::UnitY()));
  {
    const StereoImages images = renderNoisy(texturedScene(), back, 600);
    vo.process(29 * kFramePeriodUs, images.left, images.right, &out);
  }
  // THEN it relocalises, and the relative pose spans the gap from the last tracked frame (24)
  ASSERT_EQ(out.status, OrbVoStatus::kRelocalised);
  EXPECT_EQ(out.t_reference_us, 24 * kFramePeriodUs);
  double translation_m = 0.0;
  double rotation_deg = 0.0;
  relativeErrors(out, trajectoryPose(24), back, &translation_m, &rotation_deg);
  std::printf("relocalised: %d tracked, error %.2f mm, %.4f deg over %.3f m\n",
              out.tracked_features, 1e3 * translation_m, rotation_deg,
              (trajectoryPose(24).p_cam_in_world_m - back.p_cam_in_world_m).norm());
  EXPECT_LT(translation_m, 0.01);
  EXPECT_LT(rotation_deg, 0.2);
  EXPECT_GT(out.tracked_features, 100);
  // AND tracking goes on from there
  CameraPose previous = back;
  for (int k = 30; k < 33; ++k) {
    CameraPose pose = trajectoryPose(12 + (k - 29));
    pose.p_cam_in_world_m += Eigen::Vector3d(0.02, -0.01, 0.015);
    pose.q_world_cam = pose.q_world_cam *
                       Eigen::Quaterniond(Eigen::AngleAxisd(1.0 * kDeg, Eigen::Vector3d::UnitY()));
    const StereoImages images = renderNoisy(texturedScene(), pose, 600 + k);
    vo.process(k * kFramePeriodUs, images.left, images.right, &out);
    ASSERT_EQ(out.status, OrbVoStatus::kOk) << "frame " << k;
    relativeErrors(out, previous, pose, &translation_m, &rotation_deg);
    EXPECT_LT(translation_m, 0.01);
    EXPECT_LT(rotation_deg, 0.2);
    previous = pose;
  }
}

TEST(OrbVoOdometry, StartsANewMapWhenLostForTooLong) {
  OrbVoConfig config;
  config.reset_after_lost_frames = 2;
  OrbStereoOdometry vo;
  std::string error;
  ASSERT_TRUE(vo.init(config, rig(), &error)) << error;
  OrbVoOutput out;
  for (int k = 0; k < 3; ++k) {
    const StereoImages images = renderNoisy(texturedScene(), trajectoryPose(k), 700 + k);
    vo.process(k * kFramePeriodUs, images.left, images.right, &out);
  }
  ASSERT_EQ(out.status, OrbVoStatus::kOk);
  // GIVEN two blank frames, WHEN a scene never seen before appears (nothing to relocalise against)
  const cv::Mat blank(rig().height_px, rig().width_px, CV_8UC1, cv::Scalar(90));
  for (int k = 3; k < 5; ++k) {
    vo.process(k * kFramePeriodUs, blank, blank, &out);
    EXPECT_EQ(out.status, OrbVoStatus::kLost);
  }
  const SyntheticPlaneScene other = makeOrbVoTestScene(99, 0.6);
  const StereoImages first = renderNoisy(other, trajectoryPose(0), 800);
  vo.process(5 * kFramePeriodUs, first.left, first.right, &out);
  // THEN a new map starts there and tracking resumes in it
  EXPECT_EQ(out.status, OrbVoStatus::kInitialised);
  EXPECT_EQ(out.keyframes, 1);
  const StereoImages second = renderNoisy(other, trajectoryPose(1), 801);
  vo.process(6 * kFramePeriodUs, second.left, second.right, &out);
  ASSERT_EQ(out.status, OrbVoStatus::kOk);
  EXPECT_EQ(out.t_reference_us, 5 * kFramePeriodUs);
  double translation_m = 0.0;
  double rotation_deg = 0.0;
  relativeErrors(out, trajectoryPose(0), trajectoryPose(1), &translation_m, &rotation_deg);
  EXPECT_LT(translation_m, 0.01);
  EXPECT_LT(rotation_deg, 0.2);
}

TEST(OrbVoOdometry, RejectsBadConfigurationAndFrames) {
  OrbStereoOdometry vo;
  std::string error;
  OrbVoConfig config;
  config.local_keyframes = 1;
  EXPECT_FALSE(vo.init(config, rig(), &error));
  EXPECT_NE(error.find("local_keyframes"), std::string::npos) << error;
  ASSERT_TRUE(vo.init(OrbVoConfig(), rig(), &error)) << error;
  OrbVoOutput out;
  cv::Mat small(100, 100, CV_8UC1, cv::Scalar(0));
  EXPECT_FALSE(vo.process(0, small, small, &out));
  EXPECT_EQ(out.status, OrbVoStatus::kLost);
  StereoFrame raw;
  raw.left = cv::Mat(rig().height_px, rig().width_px, CV_8UC1, cv::Scalar(0));
  raw.right = raw.left;
  raw.rectified = false;
  EXPECT_FALSE(vo.process(raw, &out));
}

}  // namespace
}  // namespace deepnav
