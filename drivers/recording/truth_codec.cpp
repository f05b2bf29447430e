#include "drivers/recording/truth_codec.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/recording/stamped_header.h"
#include "drivers/recording/topics.h"

namespace deepnav {
namespace {

using cdr::CdrReader;
using cdr::CdrWriter;

constexpr int kMaxMapSidePx = 16384;  // a larger map is a corrupt message, not a camera

// geometry_msgs/Pose: position then orientation (x, y, z, w).
void writePose(CdrWriter& w, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  for (int i = 0; i < 3; ++i) w.f64(p[i]);
  w.f64(q.x());
  w.f64(q.y());
  w.f64(q.z());
  w.f64(q.w());
}

bool readPose(CdrReader& r, Eigen::Vector3d* p, Eigen::Quaterniond* q) {
  double v[7];
  for (double& x : v)
    if (!r.f64(&x)) return false;
  *p = Eigen::Vector3d(v[0], v[1], v[2]);
  *q = Eigen::Quaterniond(v[6], v[3], v[4], v[5]);
  return p->allFinite() && q->coeffs().allFinite();
}

// sensor_msgs/Image fields before the pixels.
void writeImageHead(CdrWriter& w, TimeUs t_us, Topic topic, const cv::Mat& m, const char* encoding, int bytes_per_px) {
  writeStampedHeader(w, t_us, topic);
  w.u32(static_cast<std::uint32_t>(m.rows));
  w.u32(static_cast<std::uint32_t>(m.cols));
  w.string(encoding);
  w.u8(0);  // little-endian
  const std::size_t row_bytes = static_cast<std::size_t>(m.cols) * bytes_per_px;
  w.u32(static_cast<std::uint32_t>(row_bytes));
  w.sequenceLength(row_bytes * static_cast<std::size_t>(m.rows));
}

// Reads the image fields; *pixels views rows * cols * bytes_per_px bytes with no row padding.
bool readImageHead(CdrReader& r, const char* encoding, int bytes_per_px, TimeUs* t_us, int* rows, int* cols,
                   const std::uint8_t** pixels) {
  std::uint32_t h = 0, w = 0, step = 0;
  std::uint8_t big = 0;
  std::string enc;
  std::size_t count = 0;
  if (!readStampedHeader(r, t_us) || !r.u32(&h) || !r.u32(&w) || !r.string(&enc) || !r.u8(&big) || !r.u32(&step) ||
      !r.u8SequenceView(pixels, &count))
    return false;
  if (enc != encoding || big != 0 || h == 0 || w == 0 || h > kMaxMapSidePx || w > kMaxMapSidePx) return false;
  if (step != w * static_cast<std::uint32_t>(bytes_per_px) || count != static_cast<std::size_t>(step) * h) return false;
  *rows = static_cast<int>(h);
  *cols = static_cast<int>(w);
  return true;
}

template <typename Fn>
std::size_t finish(std::uint8_t* out, std::size_t capacity, Fn&& fn) {
  CdrWriter w(out, capacity);
  fn(w);
  return w.ok() ? w.size() : 0;
}

// Depth rounded to kDepthMantissaBits significant bits (round half up on the bit pattern of a positive
// float): the zeroed low bits make the map compress about twice as well.
float roundDepth(float z) {
  if (!(z > 0.0f) || !std::isfinite(z)) return z;
  std::uint32_t bits = 0;
  std::memcpy(&bits, &z, 4);
  constexpr std::uint32_t kDrop = 24u - kDepthMantissaBits;
  bits = (bits + (1u << (kDrop - 1u))) & ~((1u << kDrop) - 1u);
  std::memcpy(&z, &bits, 4);
  return z;
}

constexpr int kTruthBlock = 256;  // pixels converted per write

bool isFloatMap(const cv::Mat& m) { return !m.empty() && m.type() == CV_32FC1; }

}  // namespace

std::size_t encodeFrameTruth(const FrameTruth& t, std::uint8_t* out, std::size_t capacity) {
  return finish(out, capacity, [&](CdrWriter& w) {
    writeStampedHeader(w, t.t_us, Topic::kFrameTruth);
    w.u64(t.sequence);
    writePose(w, t.p_robot_in_odom_m, t.q_odom_robot);
    writePose(w, t.p_left_cam_in_odom_m, t.q_odom_left_cam);
    writePose(w, t.p_right_cam_in_odom_m, t.q_odom_right_cam);
    w.sequenceLength(t.visible_marker_ids.size());
    for (const int id : t.visible_marker_ids) w.i32(id);
  });
}

bool decodeFrameTruth(const std::uint8_t* data, std::size_t size, FrameTruth* t) {
  CdrReader r(data, size);
  std::uint32_t n = 0;
  if (!readStampedHeader(r, &t->t_us) || !r.u64(&t->sequence) || !readPose(r, &t->p_robot_in_odom_m, &t->q_odom_robot) ||
      !readPose(r, &t->p_left_cam_in_odom_m, &t->q_odom_left_cam) ||
      !readPose(r, &t->p_right_cam_in_odom_m, &t->q_odom_right_cam) || !r.sequenceLength(&n, 4))
    return false;
  t->visible_marker_ids.resize(n);
  for (int& id : t->visible_marker_ids) {
    std::int32_t v = 0;
    if (!r.i32(&v)) return false;
    id = v;
  }
  return r.ok();
}

std::size_t encodeTruthDepth(const FrameTruth& t, std::uint8_t* out, std::size_t capacity) {
  if (!isFloatMap(t.depth_m)) return 0;
  return finish(out, capacity, [&](CdrWriter& w) {
    writeImageHead(w, t.t_us, Topic::kTruthDepth, t.depth_m, "32FC1", 4);
    // Converted in blocks on the stack and written a block at a time (a call per pixel cost more than
    // the conversion).
    std::array<float, kTruthBlock> block;
    for (int y = 0; y < t.depth_m.rows; ++y) {
      const float* row = t.depth_m.ptr<float>(y);
      for (int x0 = 0; x0 < t.depth_m.cols; x0 += kTruthBlock) {
        const int n = std::min(kTruthBlock, t.depth_m.cols - x0);
        for (int i = 0; i < n; ++i) block[i] = roundDepth(row[x0 + i]);
        w.f32Array(block.data(), n);
      }
    }
  });
}

std::size_t encodeTruthDisparity(const FrameTruth& t, std::uint8_t* out, std::size_t capacity) {
  if (!isFloatMap(t.disparity_px)) return 0;
  return finish(out, capacity, [&](CdrWriter& w) {
    writeImageHead(w, t.t_us, Topic::kTruthDisparity, t.disparity_px, "16UC1", 2);
    std::array<std::uint16_t, kTruthBlock> block;
    for (int y = 0; y < t.disparity_px.rows; ++y) {
      const float* row = t.disparity_px.ptr<float>(y);
      for (int x0 = 0; x0 < t.disparity_px.cols; x0 += kTruthBlock) {
        const int n = std::min(kTruthBlock, t.disparity_px.cols - x0);
        for (int i = 0; i < n; ++i) {
          const float px = row[x0 + i];
          const double d = px > 0.0f ? std::round(px * kTruthDisparityScale) : 0.0;
          // A positive disparity never rounds to 0 (which means "no surface").
          block[i] = static_cast<std::uint16_t>(px > 0.0f ? std::clamp(d, 1.0, 65535.0) : 0.0);
        }
        w.u16Array(block.data(), n);
      }
    }
  });
}

bool decodeTruthDepth(const std::uint8_t* data, std::size_t size, TimeUs* t_us, FrameTruth* t) {
  CdrReader r(data, size);
  int rows = 0, cols = 0;
  const std::uint8_t* pixels = nullptr;
  if (!readImageHead(r, "32FC1", 4, t_us, &rows, &cols, &pixels)) return false;
  t->depth_m.create(rows, cols, CV_32FC1);
  std::memcpy(t->depth_m.data, pixels, static_cast<std::size_t>(rows) * cols * 4);  // created continuous
  return true;
}

bool decodeTruthDisparity(const std::uint8_t* data, std::size_t size, TimeUs* t_us, FrameTruth* t) {
  CdrReader r(data, size);
  int rows = 0, cols = 0;
  const std::uint8_t* pixels = nullptr;
  if (!readImageHead(r, "16UC1", 2, t_us, &rows, &cols, &pixels)) return false;
  t->disparity_px.create(rows, cols, CV_32FC1);
  float* out = t->disparity_px.ptr<float>();
  const std::size_t n = static_cast<std::size_t>(rows) * cols;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint16_t v = 0;
    std::memcpy(&v, pixels + 2 * i, 2);  // little-endian host (checked in the header: is_bigendian = 0)
    out[i] = static_cast<float>(v / kTruthDisparityScale);
  }
  return true;
}

}  // namespace deepnav
