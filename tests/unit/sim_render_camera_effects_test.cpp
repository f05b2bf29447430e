// The camera effects behind camera keys: motion blur (render/motion_blur.h) and the EMVA 1288 sensor
// noise following the auto exposure's analogue gain (render/camera_sensor.h).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tools/sim/render/camera_sensor.h"
#include "tools/sim/render/motion_blur.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"

namespace deepnav::sim {
namespace {

// Mean (I(u + 1) - I(u))^2 over the interior of a w x h grey image of floats or bytes: the edge energy,
// which a blur lowers (unlike the mean |gradient|, the total variation, which a monotone blur keeps).
template <typename T>
double horizontalEdgeEnergy(const T* image, int w, int h) {
  double sum = 0.0;
  int n = 0;
  for (int v = 2; v < h - 2; ++v) {
    for (int u = 10; u < w - 11; ++u, ++n) {
      const double d = double(image[v * w + u + 1]) - double(image[v * w + u]);
      sum += d * d;
    }
  }
  return sum / n;
}

CameraConfig smallCamera() {
  CameraConfig c;
  c.width_px = 200;
  c.height_px = 100;
  c.fx_px = c.fy_px = 200.0;
  c.cx_px = 100.0;
  c.cy_px = 50.0;
  return c;
}

// Vertical stripes, 16 px period, radiance 0.2 / 0.6.
std::vector<float> stripes(const CameraConfig& c) {
  std::vector<float> r(static_cast<std::size_t>(c.width_px) * c.height_px);
  for (int v = 0; v < c.height_px; ++v)
    for (int u = 0; u < c.width_px; ++u) r[static_cast<std::size_t>(v) * c.width_px + u] = (u / 8) % 2 ? 0.6f : 0.2f;
  return r;
}

TEST(SimRenderCameraBlur, LengthIsFocalTimesSpeedTimesExposureOverDepthAndBlurGrowsWithIt) {
  // GIVEN a striped image 1 m away and a camera moving sideways
  const CameraConfig c = smallCamera();
  MotionBlur blur;
  ASSERT_TRUE(blur.init(c, 1));
  const std::vector<float> depth(static_cast<std::size_t>(c.width_px) * c.height_px, 1.0f);
  const Eigen::Vector3d w = Eigen::Vector3d::Zero();
  struct Case {
    double v_mps, t_s;
  };
  const Case cases[] = {{0.0, 0.02}, {0.5, 0.02}, {1.0, 0.02}, {0.5, 0.04}, {2.0, 0.02}};
  std::vector<double> lengths, gradients;
  std::vector<std::vector<float>> images;
  for (const Case& k : cases) {
    std::vector<float> r = stripes(c);
    blur.apply(r.data(), depth.data(), Eigen::Vector3d(k.v_mps, 0.0, 0.0), w, static_cast<float>(k.t_s));
    lengths.push_back(blur.lastMaxLength_px());
    gradients.push_back(horizontalEdgeEnergy(r.data(), c.width_px, c.height_px));
    images.push_back(r);
  }
  // THEN the blur is fx v T / Z px long: 0, 2, 4, 4, 8 px
  const double expected[] = {0.0, 2.0, 4.0, 4.0, 8.0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(lengths[i], expected[i], 1e-4) << i;
  // AND the image's edges soften as speed or exposure grow
  EXPECT_NEAR(gradients[0], horizontalEdgeEnergy(stripes(c).data(), c.width_px, c.height_px), 1e-12);
  EXPECT_LT(gradients[1], gradients[0]);
  EXPECT_LT(gradients[2], gradients[1]);
  EXPECT_LT(gradients[4], gradients[2]);
  // AND twice the exposure blurs as twice the speed (to the rounding of the sample positions)
  for (std::size_t i = 0; i < images[2].size(); ++i) ASSERT_NEAR(images[2][i], images[3][i], 1e-5f) << i;
  // AND the mean radiance is kept (a box filter of a periodic signal, borders aside)
  double sharp = 0.0, moved = 0.0;
  for (int u = 40; u < 152; ++u) sharp += stripes(c)[50 * c.width_px + u], moved += images[4][50 * c.width_px + u];
  EXPECT_NEAR(moved, sharp, 1e-3 * sharp);
}

TEST(SimRenderCameraBlur, RotationBlursOpenWaterAndTheFlowFollowsTheModel) {
  // GIVEN open water (depth 0) and a camera yawing at 0.5 rad/s about its y axis for 20 ms
  const CameraConfig c = smallCamera();
  MotionBlur blur;
  ASSERT_TRUE(blur.init(c, 1));
  const std::vector<float> depth(static_cast<std::size_t>(c.width_px) * c.height_px, 0.0f);
  std::vector<float> r = stripes(c);
  blur.apply(r.data(), depth.data(), Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.5, 0.0), 0.02f);
  // THEN the longest flow is at the image's corners: fx (1 + x^2) w T with x = 0.5, plus the y term
  const double x = 0.5, y = 0.25;
  const double du = 200.0 * (1.0 + x * x) * 0.5 * 0.02, dv = 200.0 * x * y * 0.5 * 0.02;
  EXPECT_NEAR(blur.lastMaxLength_px(), std::hypot(du, dv), 1e-3);
  EXPECT_LT(horizontalEdgeEnergy(r.data(), c.width_px, c.height_px),
            0.5 * horizontalEdgeEnergy(stripes(c).data(), c.width_px, c.height_px));
}


TEST(SimRenderCameraBlur, MovingRigBlursTheRenderAndAStillRigRendersAsWithoutBlur) {
  Scenario plain;
  Scenario blurred;
  blurred.camera.motion_blur = true;
  StereoRenderer r_plain, r_blur;
  std::string error;
  ASSERT_TRUE(r_plain.init(plain, 1, 1, &error)) << error;
  ASSERT_TRUE(r_blur.init(blurred, 1, 1, &error)) << error;
  StereoFrame a, b;
  allocateStereoFrame(a, 688, 516, 1);
  allocateStereoFrame(b, 688, 516, 1);
  CameraTick tick = tickFacingFace(plain, 0, 1.2, -0.15, 1.3, 0.0, 0.0, 36'000'000);
  // GIVEN a still rig: the images are those of the renderer without blur, bit for bit
  ASSERT_TRUE(r_plain.render(tick, &a, nullptr));
  ASSERT_TRUE(r_blur.render(tick, &b, nullptr));
  EXPECT_EQ(cv::norm(a.left, b.left, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.right, b.right, cv::NORM_INF), 0.0);
  EXPECT_EQ(a.exposure_us, 0u);  // without the effect keys the frame carries no exposure (as before)
  EXPECT_GT(b.exposure_us, 0u);
  const double sharp = horizontalEdgeEnergy(b.left.ptr<std::uint8_t>(), 688, 516);
  // WHEN the rig sways sideways at 0.25 then 0.5 m/s
  double previous = sharp;
  for (double speed : {0.25, 0.5}) {
    tick.v_left_cam_mps = tick.v_right_cam_mps = Eigen::Vector3d(speed, 0.0, 0.0);
    ASSERT_TRUE(r_blur.render(tick, &b, nullptr));
    const double g = horizontalEdgeEnergy(b.left.ptr<std::uint8_t>(), 688, 516);
    // THEN the edges soften more with the speed (noise kept: the gradient keeps a floor)
    EXPECT_LT(g, previous) << speed;
    previous = g;
  }
  // (5.8 px of blur at 0.5 m/s, 20 ms, 1.2 m: the edge energy falls by a quarter; the noise's stays)
  EXPECT_LT(previous, 0.8 * sharp);
}

TEST(SimRenderCameraNoise, ExposureFirstThenAnalogueGain) {
  CameraSensor sensor;
  ASSERT_TRUE(sensor.init(64, 64, 1, waterOptics(WaterPreset::kModerate), 1));
  CameraSensorConfig cfg;  // t_ref 4 ms, t_max 20 ms
  sensor.setSensor(SensorNoiseModel::kEmva1288, cfg);
  EXPECT_NEAR(sensor.exposureFor(0.5f).time_s, 0.002f, 1e-7);
  EXPECT_NEAR(sensor.exposureFor(0.5f).analogue_gain, 1.0f, 1e-6);
  EXPECT_NEAR(sensor.exposureFor(5.0f).time_s, 0.020f, 1e-7);
  EXPECT_NEAR(sensor.exposureFor(20.0f).time_s, 0.020f, 1e-7);
  EXPECT_NEAR(sensor.exposureFor(20.0f).analogue_gain, 4.0f, 1e-5);
}

// Variance (DN^2) and mean of a flat exposure of radiance level / gain at the given total gain.
void flatFrameStatistics(CameraSensor& sensor, float gain, float level, double* mean, double* variance) {
  const int w = 512, h = 256;
  std::vector<float> radiance(static_cast<std::size_t>(w) * h, level / gain);
  cv::Mat image(h, w, CV_8UC1);
  sensor.expose(radiance.data(), gain, 0x1234u + static_cast<std::uint64_t>(gain * 100.0f), &image);
  cv::Scalar m, s;
  cv::meanStdDev(image, m, s);
  *mean = m[0];
  *variance = s[0] * s[0];
}

TEST(SimRenderCameraNoise, VarianceFollowsTheAnalogueGainAsEmva1288Says) {
  // GIVEN the EMVA 1288 model with the default sensor (Q = 22000 e-, dark noise 7 e-) and flat frames
  // whose output level is 0.3 of full scale at total gains 5 (20 ms, 0 dB) to 24 (20 ms, 13.6 dB)
  CameraSensor sensor;
  ASSERT_TRUE(sensor.init(512, 256, 1, waterOptics(WaterPreset::kModerate), 7));
  const CameraSensorConfig cfg;
  sensor.setSensor(SensorNoiseModel::kEmva1288, cfg);
  const double q = cfg.full_well_e, d = cfg.dark_noise_e, level = 0.3;
  double previous = 0.0;
  for (float gain : {5.0f, 10.0f, 24.0f}) {
    double mean = 0.0, variance = 0.0;
    flatFrameStatistics(sensor, gain, static_cast<float>(level), &mean, &variance);
    // THEN var = 255^2 (a^2 d^2 / Q^2 + a S / Q) + 1/12 (the 8-bit rounding), a = g / 5
    const double a = gain / 5.0;
    const double expected = 255.0 * 255.0 * (a * a * d * d / (q * q) + a * level / q) + 1.0 / 12.0;
    // 131072 pixels: the variance's own sampling error is sqrt(2 / N) = 0.4 %; the noise table's rows
    // overlap (65536 normals), so allow 5 %.
    EXPECT_NEAR(variance, expected, 0.05 * expected) << "gain " << gain;
    EXPECT_NEAR(mean, 255.0 * level, 0.1) << "gain " << gain;
    EXPECT_GT(variance, previous);
    previous = variance;
  }
}

TEST(SimRenderCameraNoise, WaterPresetNoiseIsTheDefaultAndUnchanged) {
  // The default keeps the preset's noise: var = g^2 (read^2 + shot I) at any exposure split.
  CameraSensor sensor;
  const WaterOptics optics = waterOptics(WaterPreset::kMurky);
  ASSERT_TRUE(sensor.init(512, 256, 1, optics, 7));
  const float gain = 8.0f, level = 0.3f;
  double mean = 0.0, variance = 0.0;
  flatFrameStatistics(sensor, gain, level, &mean, &variance);
  const double i = level / gain;
  const double expected =
      255.0 * 255.0 * gain * gain * (optics.read_noise * optics.read_noise + optics.shot_noise * i) + 1.0 / 12.0;
  EXPECT_NEAR(variance, expected, 0.05 * expected);
}

}  // namespace
}  // namespace deepnav::sim
