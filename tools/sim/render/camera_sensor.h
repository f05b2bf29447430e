#pragma once
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "tools/sim/render/water_optics.h"
#include "tools/sim/sensors/camera_rig.h"

namespace deepnav::sim {

// From the irradiance on the sensor to the 8-bit image: the lens blur (3 x 3 Gaussian [1 2 1]/4 in
// each direction, replicated borders) giving I, sensor noise and analog gain g,
//   S = g (I + sqrt(read^2 + shot I) n),  n ~ N(0, 1),
// then 8 bits: round(255 clamp(S, 0, 1)). Linear, as machine-vision cameras are by default: a gamma
// curve after the blur moves the apparent edges of black-on-white markers by about half a pixel
// towards the black (measured with cv::aruco corners), a bias navigation would inherit. Noise values come from a table of
// normals drawn from the seed, read from an offset hashed from (frame key, row): deterministic, no
// random generator in the per-frame path. Buffers are allocated in init().
class CameraSensor {
 public:
  bool init(int width_px, int height_px, int channels, const WaterOptics& optics, std::uint64_t seed);
  // camera.sensor and camera.noise_model (after init; the default is the water preset's noise). With
  // kEmva1288 the noise of a frame of total gain g, exposure t and analogue gain a (exposureFor) is,
  // in full-scale units of the output S = g I (Q: full well, sigma_d: dark noise, both in electrons),
  //   var(S) = a^2 sigma_d^2 / Q^2 + a S / Q          (EMVA 1288 linear model, K = a / Q)
  // i.e. S = g (I + sqrt(read^2 + shot I) n) with read = (t_ref / t) sigma_d / Q and shot = (t_ref / t) / Q.
  void setSensor(SensorNoiseModel model, const CameraSensorConfig& sensor);
  // radiance: width * height * channels floats, row-major, channels interleaved (BGR or grey), linear.
  // image: preallocated CV_8UC1 / CV_8UC3 of the same size.
  void expose(const float* radiance, float gain, std::uint64_t frame_key, cv::Mat* image);

  // Auto exposure: the gain that brings the mean of a radiance image (every 4th pixel) to kTargetMean,
  // within [kMinGain, kMaxGain]. Computed per frame from the left view and used for both cameras (a
  // synchronised rig); stateless, so a frame does not depend on the frames before it.
  static constexpr float kTargetMean = 0.25f;  // 64 of 255
  static constexpr float kMinGain = 0.25f;
  static constexpr float kMaxGain = 24.0f;  // about 28 dB, a machine-vision camera's range
  float autoExposureGain(const float* radiance) const;

  // The AE's split of a total gain into exposure time and analogue gain (camera_rig.h, CameraSensorConfig).
  struct Exposure {
    float time_s = 0.0f;
    float analogue_gain = 1.0f;
  };
  Exposure exposureFor(float gain) const;

 private:
  void blurRow(const float* in, float* out) const;
  void exposeRow(const float* up, const float* mid, const float* down, const float* noise, float gain,
                 float read_var, float shot, std::uint8_t* out) const;

  int width_ = 0, height_ = 0, channels_ = 1;
  float read_var_ = 0.0f, shot_ = 0.0f;
  SensorNoiseModel noise_model_ = SensorNoiseModel::kWaterPreset;
  CameraSensorConfig sensor_{};
  std::vector<float> blurred_rows_;  // the horizontal pass
  std::vector<float> normals_;       // N(0, 1) table
};

}  // namespace deepnav::sim
