#include "vision/cloud/area_halving.h"

#include <cstdint>

namespace deepnav {

namespace {

// One channel: a plain stride-2 loop the compiler vectorises (about as fast as cv::resize's SIMD path).
void halveRow(const std::uint8_t* top, const std::uint8_t* bottom, int out_cols, std::uint8_t* out) {
  for (int x = 0; x < out_cols; ++x) {
    // At most 4 * 255 + 2: 16-bit lanes hold it, twice as many per vector as 32-bit ones.
    const std::uint16_t sum =
        static_cast<std::uint16_t>(top[2 * x] + top[2 * x + 1] + bottom[2 * x] + bottom[2 * x + 1] + 2);
    out[x] = static_cast<std::uint8_t>(sum >> 2);
  }
}

void halveRowChannels(const std::uint8_t* top, const std::uint8_t* bottom, int out_cols, int cn,
                      std::uint8_t* out) {
  for (int x = 0; x < out_cols; ++x) {
    for (int c = 0; c < cn; ++c) {
      const int a = 2 * x * cn + c;  // channel c of the left input pixel
      const unsigned sum = top[a] + top[a + cn] + bottom[a] + bottom[a + cn];
      out[x * cn + c] = static_cast<std::uint8_t>((sum + 2u) >> 2);
    }
  }
}

}  // namespace

bool halveByArea(const cv::Mat& full, cv::Mat* half) {
  if (full.depth() != CV_8U || full.rows % 2 != 0 || full.cols % 2 != 0 || half->type() != full.type() ||
      half->rows != full.rows / 2 || half->cols != full.cols / 2) {
    return false;
  }
  const int cn = full.channels();
  for (int y = 0; y < half->rows; ++y) {
    const std::uint8_t* top = full.ptr<std::uint8_t>(2 * y);
    const std::uint8_t* bottom = full.ptr<std::uint8_t>(2 * y + 1);
    std::uint8_t* out = half->ptr<std::uint8_t>(y);
    if (cn == 1) {
      halveRow(top, bottom, half->cols, out);
    } else {
      halveRowChannels(top, bottom, half->cols, cn, out);
    }
  }
  return true;
}

}  // namespace deepnav
