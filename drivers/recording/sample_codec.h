#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/recording/topics.h"
#include "nav/types/input_sample.h"
#include "nav/types/nav_solution.h"
#include "nav/types/truth_sample.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

struct LoopStats;

// CDR encoding of deepnav's samples as the ROS 2 messages of their topics (topics.h), and back.
// Encoders write into a caller buffer and never allocate; they return the size, or 0 when the buffer
// is too small. Decoders are bounds-checked and return false on a malformed message. Every field the
// loop uses survives the round trip bit for bit.

// The topic an input sample is recorded on (the replayed one for DVL and depth).
Topic inputTopic(const InputSample& sample);

std::size_t encodeInput(const InputSample& sample, std::uint8_t* out, std::size_t capacity);
// The viewer-only companion of a DVL or depth sample (/dvl twist, /pressure); 0 for other samples.
std::size_t encodeInputCompanion(const InputSample& sample, std::uint8_t* out, std::size_t capacity);
// The topic of that companion; Topic::kCount for a sample without one.
Topic inputCompanionTopic(const InputSample& sample);
std::size_t encodeSolution(const NavSolution& s, std::uint8_t* out, std::size_t capacity);
std::size_t encodeOdometry(const NavSolution& s, std::uint8_t* out, std::size_t capacity);
std::size_t encodeTruth(const TruthSample& s, std::uint8_t* out, std::size_t capacity);
std::size_t encodeStereoInfo(const StereoFrame& f, std::uint8_t* out, std::size_t capacity);
std::size_t encodeImage(const StereoFrame& f, bool left, std::uint8_t* out, std::size_t capacity);
std::size_t encodeLoopStats(TimeUs t_us, const LoopStats& s, std::uint8_t* out, std::size_t capacity);

// Input topics only (IMU, bottom track, depth, heading, attitude, vision result).
bool decodeInput(Topic topic, const std::uint8_t* data, std::size_t size, InputSample* out);
bool decodeSolution(const std::uint8_t* data, std::size_t size, NavSolution* out);
bool decodeTruth(const std::uint8_t* data, std::size_t size, TruthSample* out);
bool decodeStereoInfo(const std::uint8_t* data, std::size_t size, StereoFrame* out);
// Copies the pixels into frame->left or ->right, which must already have the image's size and type
// (frames come from the preallocated pool); false when they differ or the message is malformed.
bool decodeImageInto(const std::uint8_t* data, std::size_t size, bool left, StereoFrame* frame);

// Size and channels of an encoded sensor_msgs/Image (mono8 or bgr8), without decoding the pixels.
bool peekImageSize(const std::uint8_t* data, std::size_t size, int* rows, int* cols, int* channels);

// Equality of every bit of two solutions (replay must reproduce the recording exactly).
bool sameBits(const NavSolution& a, const NavSolution& b);

}  // namespace deepnav
