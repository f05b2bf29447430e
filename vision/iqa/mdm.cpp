#include "vision/iqa/mdm.h"

#include <algorithm>
#include <cmath>

namespace deepnav {
namespace {

constexpr int kLevels = 256;

// Octave 7 rgb2gray weights (ITU-R BT.601 as Octave spells them); the reference used these.
constexpr double kWeightR = 0.298936021293775390;
constexpr double kWeightG = 0.587043074451121360;
constexpr double kWeightB = 0.114020904255103250;

// x^64 by six squarings: exact enough and ~10x cheaper than std::pow.
double pow64(double x) {
  for (int i = 0; i < 6; ++i) x *= x;
  return x;
}

double pow8(double x) {
  x *= x;
  x *= x;
  return x * x;
}

// The paper's deviation feature from a histogram of 8-bit values: ((mean((J - mean
// J)^64))^(1/64))^(1/4) with J = I^8, and I = v/255 or its complement 1 - v/255.
double deviationFeature(const std::array<std::uint32_t, kLevels>& count, double total,
                        bool complement) {
  double moment_q[kLevels];
  double mean_q = 0.0;
  for (int v = 0; v < kLevels; ++v) {
    const double i = static_cast<double>(complement ? 255 - v : v) / 255.0;
    moment_q[v] = pow8(i);
    mean_q += count[v] * moment_q[v];
  }
  mean_q /= total;
  double mean_p = 0.0;
  for (int v = 0; v < kLevels; ++v) {
    if (count[v] != 0) mean_p += count[v] * pow64(moment_q[v] - mean_q);
  }
  mean_p /= total;
  return std::pow(std::pow(mean_p, 1.0 / 64.0), 0.25);
}

// Shannon entropy in bits of a 256-bin histogram (Octave's entropy(): empty bins skipped).
double entropyBits(const std::array<std::uint32_t, kLevels>& count, double total) {
  double bits = 0.0;
  for (std::uint32_t c : count) {
    if (c == 0) continue;
    const double p = c / total;
    bits -= p * std::log2(p);
  }
  return bits;
}

void countGrey(const cv::Mat& image, int step, MdmWorkspace* ws) {
  for (int y = 0; y < image.rows; y += step) {
    const std::uint8_t* row = image.ptr<std::uint8_t>(y);
    for (int x = 0; x < image.cols; x += step) ++ws->value_count[row[x]];
  }
  ws->grey_count = ws->value_count;
}

void countBgr(const cv::Mat& image, int step, MdmWorkspace* ws) {
  for (int y = 0; y < image.rows; y += step) {
    const std::uint8_t* row = image.ptr<std::uint8_t>(y);
    for (int x = 0; x < image.cols; x += step) {
      const std::uint8_t* p = row + 3 * x;
      ++ws->value_count[p[0]];
      ++ws->value_count[p[1]];
      ++ws->value_count[p[2]];
      const double grey = kWeightB * p[0] + kWeightG * p[1] + kWeightR * p[2];
      ++ws->grey_count[static_cast<int>(grey + 0.5)];  // im2uint8 rounds half up
    }
  }
}

}  // namespace

int mdmStep(int rows_px, int cols_px) {
  const int by_size = static_cast<int>(std::lround(std::min(rows_px, cols_px) / 512.0));
  return std::max(2, by_size);
}

bool computeMdm(const cv::Mat& image, MdmScore* out, MdmWorkspace* ws) {
  if (out == nullptr || ws == nullptr || image.empty()) return false;
  if (image.type() != CV_8UC1 && image.type() != CV_8UC3) return false;
  ws->value_count.fill(0);
  ws->grey_count.fill(0);
  const int step = mdmStep(image.rows, image.cols);
  if (image.channels() == 1) {
    countGrey(image, step, ws);
  } else {
    countBgr(image, step, ws);
  }
  const double pixels = static_cast<double>((image.rows + step - 1) / step) *
                        static_cast<double>((image.cols + step - 1) / step);
  const double values = pixels * image.channels();
  out->f1 = deviationFeature(ws->value_count, values, false);
  out->f2 = deviationFeature(ws->value_count, values, true);
  out->f3_bits = entropyBits(ws->grey_count, pixels);
  out->f3 = out->f3_bits / 8.0;
  out->score = (out->f1 + out->f2 + out->f3) / 3.0;
  return true;
}

}  // namespace deepnav
