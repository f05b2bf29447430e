#pragma once
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/stereo/sad16.h"

namespace deepnav {

// Histogram of |horizontal Sobel response| (0 .. 4 * 255), the image's gradient statistics.
using SobelHistogram = std::array<std::uint32_t, 1021>;

// ELAS descriptor image (Geiger et al. 2010): per pixel, 16 bytes of horizontal and
// vertical 3x3 Sobel responses sampled sparsely over a 9x9 window, each stored as
// saturate(gain * response + 128). The l1 distance of two descriptors is the matching cost.
// Sobel responses ignore the brightness offset between the two cameras; the gain (one for both
// views) removes their contrast, see descriptorGain().
class ElasDescriptorImage {
 public:
  static constexpr int kBytes = 16;

  bool allocate(int width_px, int height_px);
  // Step 1: Sobel responses of grey (CV_8UC1 of the allocated size); adds |gx| to *histogram.
  void computeGradients(const cv::Mat& grey, SobelHistogram* histogram);
  // Step 2: the descriptors, responses scaled by gain.
  void computeDescriptors(float gain);

  const std::uint8_t* at(int u_px, int v_px) const {
    return descriptors_.data() + (static_cast<std::size_t>(v_px) * width_px_ + u_px) * kBytes;
  }
  int width() const { return width_px_; }
  int height() const { return height_px_; }

 private:
  void gatherRow(int v_px);

  int width_px_ = 0;
  int height_px_ = 0;
  std::vector<std::int16_t> raw_gx_;  // d/du Sobel response
  std::vector<std::int16_t> raw_gy_;  // d/dv Sobel response
  std::vector<std::uint8_t> gx_;      // gain * d/du, offset 128, saturated
  std::vector<std::uint8_t> gy_;      // gain * d/dv, offset 128, saturated
  std::vector<std::uint8_t> descriptors_;
};

// l1 norm of a descriptor about "no gradient": how much texture a pixel has (inline: the dense
// matcher asks it for every pixel).
inline int descriptorTexture(const std::uint8_t* descriptor) {
  alignas(16) static constexpr std::uint8_t kFlat[16] = {128, 128, 128, 128, 128, 128, 128, 128,
                                                         128, 128, 128, 128, 128, 128, 128, 128};
  return sad16(descriptor, kFlat);
}

// Contrast normalisation: the gain mapping the 90th percentile of |gx| (over both views) to
// target, at most max_gain. Underwater contrast changes with turbidity, light and range; a fixed
// scale would leave low-contrast frames with tiny costs that the prior and the texture thresholds
// then dominate. fixed_gain > 0 bypasses it.
float descriptorGain(const SobelHistogram& histogram, float target, float max_gain,
                     float fixed_gain);

}  // namespace deepnav
