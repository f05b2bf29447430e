#pragma once
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

namespace deepnav {

// MDM: no-reference contrast quality of one image (Ziaei Nafchi & Cheriet, "Efficient No-Reference
// Quality Assessment and Classification Model for Contrast Distorted Images", IEEE Trans.
// Broadcasting 2018), computed exactly as the authors' MDM.m does (checked against their code run
// in Octave, /work/shared/data/iqa/mdm_reference.txt):
//   - subsample both axes with step max(2, round(min(h, w) / 512)), starting at the first pixel;
//   - f1 = (mean((I^8 - mean(I^8))^64))^(1/64), then f1^(1/4), with I in [0, 1] taken over every
//     sample of every colour channel pooled together (the paper's moments with q = 8, p = 64);
//   - f2 = the same on the complement 1 - I;
//   - f3 = entropy in bits of the 256-bin grey histogram, the grey level being Octave's rgb2gray
//     (0.298936 R + 0.587043 G + 0.114021 B, rounded) for colour input; the paper uses f3 / 8.
struct MdmScore {
  double f1 = 0.0;       // dark-side contrast deviation, [0, 1]
  double f2 = 0.0;       // bright-side contrast deviation (on 1 - I), [0, 1]
  double f3_bits = 0.0;  // grey-level entropy, [0, 8] bits
  double f3 = 0.0;       // f3_bits / 8, [0, 1]
  double score = 0.0;    // mean(f1, f2, f3), [0, 1]; higher = better contrast
};

// Scratch for computeMdm. Since the inputs are 8-bit, every statistic MDM needs is a function of
// two 256-bin histograms (pooled channel values and grey levels), so the workspace is fixed-size
// and valid for any image size: no allocation at all, not even on the first call.
struct MdmWorkspace {
  std::array<std::uint32_t, 256> value_count{};  // samples of all channels, by 8-bit value
  std::array<std::uint32_t, 256> grey_count{};   // grey levels of the subsampled pixels
};

// image: CV_8UC1 (grey) or CV_8UC3 (BGR, OpenCV order), any size >= 1x1, any step.
// Returns false (and leaves *out untouched) for an empty image or another type.
bool computeMdm(const cv::Mat& image, MdmScore* out, MdmWorkspace* ws);

// Subsampling step of MDM.m: max(2, round(min(h, w) / 512)).
int mdmStep(int rows_px, int cols_px);

}  // namespace deepnav
