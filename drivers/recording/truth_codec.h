#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/recording/frame_truth.h"

namespace deepnav {

// CDR encoding of the simulator's per-frame ground truth (FrameTruth) on three topics:
//   /truth/frame      deepnav_msgs/FrameTruth: poses and visible marker ids
//   /truth/depth      sensor_msgs/Image "32FC1": depth in metres, 0 = no surface (open water), rounded to
//                     16 significant bits (relative error <= 1.5e-5: 0.015 mm at 1 m), which halves its
//                     compressed size
//   /truth/disparity  sensor_msgs/Image "16UC1": round(disparity_px * kTruthDisparityScale), 0 = no
//                     surface; saturates at 65535 (511.99 px, i.e. depth below fx * B / 512)
// 16-bit disparity halves the largest message of the recording and compresses far better than floats;
// its 1/128 px step (error <= 1/256 px) is two orders of magnitude below any matcher's error.
// Encoders write into a caller buffer and return the size, 0 when it is too small; decoders are
// bounds-checked and return false on a malformed message.
constexpr double kTruthDisparityScale = 128.0;  // stored units per pixel of disparity
constexpr unsigned kDepthMantissaBits = 16;      // significant bits kept of each depth: relative error <= 2^-16

std::size_t encodeFrameTruth(const FrameTruth& t, std::uint8_t* out, std::size_t capacity);
std::size_t encodeTruthDepth(const FrameTruth& t, std::uint8_t* out, std::size_t capacity);
std::size_t encodeTruthDisparity(const FrameTruth& t, std::uint8_t* out, std::size_t capacity);

// Fills the stamp, sequence, poses and ids of *t (maps untouched).
bool decodeFrameTruth(const std::uint8_t* data, std::size_t size, FrameTruth* t);
// Fill t->depth_m / t->disparity_px (CV_32FC1, reallocated only when the size changes); the stamp of
// the message goes to *t_us.
bool decodeTruthDepth(const std::uint8_t* data, std::size_t size, TimeUs* t_us, FrameTruth* t);
bool decodeTruthDisparity(const std::uint8_t* data, std::size_t size, TimeUs* t_us, FrameTruth* t);

}  // namespace deepnav
