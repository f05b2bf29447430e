#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// ELAS descriptor image (Geiger et al. 2010): per pixel, 16 bytes of horizontal and
// vertical 3x3 Sobel responses sampled sparsely over a 9x9 window, each stored as
// saturate(response / 2^shift + 128). The l1 distance of two descriptors is the matching cost.
// Sobel responses ignore the brightness offset between the two cameras.
class ElasDescriptorImage {
 public:
  static constexpr int kBytes = 16;

  bool allocate(int width_px, int height_px);
  // grey: CV_8UC1 of the allocated size.
  void compute(const cv::Mat& grey, int sobel_shift);

  const std::uint8_t* at(int u_px, int v_px) const {
    return descriptors_.data() + (static_cast<std::size_t>(v_px) * width_px_ + u_px) * kBytes;
  }
  int width() const { return width_px_; }
  int height() const { return height_px_; }

 private:
  void computeSobel(const cv::Mat& grey, int sobel_shift);
  void gatherRow(int v_px);

  int width_px_ = 0;
  int height_px_ = 0;
  std::vector<std::uint8_t> gx_;  // d/du response, offset 128
  std::vector<std::uint8_t> gy_;  // d/dv response, offset 128
  std::vector<std::uint8_t> descriptors_;
};

// l1 norm of a descriptor about "no gradient": how much texture a pixel has.
int descriptorTexture(const std::uint8_t* descriptor);

}  // namespace deepnav
