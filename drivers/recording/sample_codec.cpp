#include "drivers/recording/sample_codec.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/cdr/ros_msg_codec.h"
#include "drivers/recording/stamped_header.h"
#include "nav/types/loop_stats.h"

namespace deepnav {
namespace {

using cdr::CdrReader;
using cdr::CdrWriter;

TimeUs fromStamp(const ros::Time& t) {
  return static_cast<TimeUs>(t.sec) * kUsPerS + static_cast<TimeUs>(t.nanosec / 1000);
}

bool readHeader(CdrReader& r, TimeUs* t_us) {
  ros::Time stamp;
  std::string frame_id;  // short frame names fit the small-string buffer: no allocation
  if (!r.i32(&stamp.sec) || !r.u32(&stamp.nanosec) || !r.string(&frame_id)) return false;
  *t_us = fromStamp(stamp);
  return true;
}

void writeVec3(CdrWriter& w, const Eigen::Vector3d& v) {
  w.f64(v.x());
  w.f64(v.y());
  w.f64(v.z());
}

bool readVec3(CdrReader& r, Eigen::Vector3d* v) { return r.f64(&v->x()) && r.f64(&v->y()) && r.f64(&v->z()); }

void writeQuat(CdrWriter& w, const Eigen::Quaterniond& q) {
  w.f64(q.x());
  w.f64(q.y());
  w.f64(q.z());
  w.f64(q.w());
}

bool readQuat(CdrReader& r, Eigen::Quaterniond* q) {
  return r.f64(&q->x()) && r.f64(&q->y()) && r.f64(&q->z()) && r.f64(&q->w());
}

template <typename Fn>
std::size_t finish(std::uint8_t* out, std::size_t capacity, Fn&& fn) {
  CdrWriter w(out, capacity);
  fn(w);
  return w.ok() ? w.size() : 0;
}

void writeImu(CdrWriter& w, const ImuSample& s) {
  writeStampedHeader(w, s.t_us, Topic::kImu);
  writeQuat(w, s.q_odom_imu);
  double cov[9] = {};
  if (s.has_orientation) {
    const double var = s.orientation_sigma_rad * s.orientation_sigma_rad;
    cov[0] = cov[4] = cov[8] = var;
  } else {
    cov[0] = -1.0;  // ROS convention: no orientation estimate
  }
  w.f64Array(cov, 9);
  writeVec3(w, s.w_imu_radps);
  const double zero[9] = {};
  w.f64Array(zero, 9);
  writeVec3(w, s.f_imu_mps2);
  w.f64Array(zero, 9);
}

bool readImu(CdrReader& r, ImuSample* s) {
  double cov[9];
  double ignored[9];
  if (!readHeader(r, &s->t_us) || !readQuat(r, &s->q_odom_imu) || !r.f64Array(cov, 9)) return false;
  s->has_orientation = cov[0] >= 0.0;
  s->orientation_sigma_rad = s->has_orientation ? std::sqrt(cov[0]) : 0.0;
  return readVec3(r, &s->w_imu_radps) && r.f64Array(ignored, 9) && readVec3(r, &s->f_imu_mps2) &&
         r.f64Array(ignored, 9);
}

void writeBottomTrack(CdrWriter& w, const DvlSample& s) {
  writeStampedHeader(w, s.t_us, Topic::kDvlBottomTrack);
  writeVec3(w, s.v_dvl_mps);
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> cov = s.cov_v_dvl_mps2;
  w.f64Array(cov.data(), 9);
  w.f64Array(s.beam_range_m.data(), DvlSample::kBeams);
  w.u8(s.beam_valid_mask);
  w.boolean(s.valid);
  w.f64(s.fom_mps);
  w.f64(s.altitude_m);
}

bool readBottomTrack(CdrReader& r, DvlSample* s) {
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> cov;
  if (!readHeader(r, &s->t_us) || !readVec3(r, &s->v_dvl_mps) || !r.f64Array(cov.data(), 9) ||
      !r.f64Array(s->beam_range_m.data(), DvlSample::kBeams) || !r.u8(&s->beam_valid_mask) ||
      !r.boolean(&s->valid) || !r.f64(&s->fom_mps) || !r.f64(&s->altitude_m)) {
    return false;
  }
  s->cov_v_dvl_mps2 = cov;
  return true;
}

void writeDvlTwist(CdrWriter& w, const DvlSample& s) {
  writeStampedHeader(w, s.t_us, Topic::kDvl);
  writeVec3(w, s.v_dvl_mps);
  writeVec3(w, Eigen::Vector3d::Zero());
  double cov[36] = {};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) cov[i * 6 + j] = s.cov_v_dvl_mps2(i, j);
  }
  if (!s.valid) cov[0] = -1.0;  // invalid ensemble: viewers should ignore it
  w.f64Array(cov, 36);
}

void writeDepth(CdrWriter& w, const DepthSample& s) {
  writeStampedHeader(w, s.t_us, Topic::kDepth);
  w.f64(s.depth_m);
  w.f64(s.pressure_pa);
  w.f64(s.sigma_m);
}

bool readDepth(CdrReader& r, DepthSample* s) {
  return readHeader(r, &s->t_us) && r.f64(&s->depth_m) && r.f64(&s->pressure_pa) && r.f64(&s->sigma_m);
}

void writePressure(CdrWriter& w, const DepthSample& s) {
  writeStampedHeader(w, s.t_us, Topic::kPressure);
  w.f64(s.pressure_pa);
  w.f64(0.0);
}

void writeHeading(CdrWriter& w, const HeadingSample& s) {
  writeStampedHeader(w, s.t_us, Topic::kHeading);
  w.f64(s.heading_rad);
  w.boolean(s.is_true);
  w.f64(s.sigma_rad);
}

bool readHeading(CdrReader& r, HeadingSample* s) {
  return readHeader(r, &s->t_us) && r.f64(&s->heading_rad) && r.boolean(&s->is_true) && r.f64(&s->sigma_rad);
}

void writeAttitude(CdrWriter& w, const AttitudeSample& s) {
  writeStampedHeader(w, s.t_us, Topic::kAttitude);
  w.f64(s.roll_rad);
  w.f64(s.pitch_rad);
  w.f64(s.sigma_rad);
}

bool readAttitude(CdrReader& r, AttitudeSample* s) {
  return readHeader(r, &s->t_us) && r.f64(&s->roll_rad) && r.f64(&s->pitch_rad) && r.f64(&s->sigma_rad);
}

void writeMarker(CdrWriter& w, const MarkerObservation& m) {
  w.i32(m.id);
  for (const auto& c : m.corners_px) {
    w.f64(c.x());
    w.f64(c.y());
  }
  writeQuat(w, m.q_cam_marker);
  writeVec3(w, m.p_marker_in_cam_m);
  writeQuat(w, m.q_cam_marker_alt);
  writeVec3(w, m.p_marker_in_cam_alt_m);
  w.f64(m.reprojection_error_px);
  w.f64(m.reprojection_error_alt_px);
  w.boolean(m.ambiguous);
  w.f64(m.distance_m);
  w.f64(m.obliqueness_rad);
}

bool readMarker(CdrReader& r, MarkerObservation* m) {
  if (!r.i32(&m->id)) return false;
  for (auto& c : m->corners_px) {
    if (!r.f64(&c.x()) || !r.f64(&c.y())) return false;
  }
  return readQuat(r, &m->q_cam_marker) && readVec3(r, &m->p_marker_in_cam_m) && readQuat(r, &m->q_cam_marker_alt) &&
         readVec3(r, &m->p_marker_in_cam_alt_m) && r.f64(&m->reprojection_error_px) &&
         r.f64(&m->reprojection_error_alt_px) && r.boolean(&m->ambiguous) && r.f64(&m->distance_m) &&
         r.f64(&m->obliqueness_rad);
}

bool readVoSource(std::uint8_t raw, VoSource* source) {
  if (raw > static_cast<std::uint8_t>(VoSource::kPlanes)) return false;
  *source = static_cast<VoSource>(raw);
  return true;
}

void writeVo(CdrWriter& w, const VoMeasurement& m) {
  w.boolean(m.valid);
  w.u8(static_cast<std::uint8_t>(m.source));
  w.i64(m.t_reference_us);
  writeQuat(w, m.q_cama_camb);
  writeVec3(w, m.p_camb_in_cama_m);
  w.boolean(m.has_translation);
  for (int i = 0; i < 36; ++i) w.f64(m.cov.data()[i]);
  w.i32(m.support);
}

bool readVo(CdrReader& r, VoMeasurement* m) {
  std::uint8_t source = 0;
  if (!r.boolean(&m->valid) || !r.u8(&source) || !readVoSource(source, &m->source) || !r.i64(&m->t_reference_us) ||
      !readQuat(r, &m->q_cama_camb) || !readVec3(r, &m->p_camb_in_cama_m) || !r.boolean(&m->has_translation)) {
    return false;
  }
  for (int i = 0; i < 36; ++i) {
    if (!r.f64(&m->cov.data()[i])) return false;
  }
  return r.i32(&m->support);
}

void writeVision(CdrWriter& w, const VisionResult& s) {
  writeStampedHeader(w, s.t_us, Topic::kVisionResult);
  w.u64(s.sequence);
  w.u32(s.processing_us);
  w.boolean(s.frame_ok);
  w.f64(s.mdm_f1);
  w.f64(s.mdm_f2);
  w.f64(s.mdm_f3);
  w.f64(s.image_quality);
  const auto n = static_cast<std::size_t>(std::clamp(s.marker_count, 0, VisionResult::kMaxMarkers));
  w.sequenceLength(n);
  for (std::size_t i = 0; i < n; ++i) writeMarker(w, s.markers[i]);
  w.i32(s.markers_dropped);
  w.i32(s.orb_tracked);
  w.u8(static_cast<std::uint8_t>(s.vo_selected));
  writeVo(w, s.vo_orb);
  writeVo(w, s.vo_planes);
  w.i32(s.planes);
  w.i32(s.map_frames);
  w.i32(s.map_voxels);
  w.boolean(s.map_ready);
  w.u32(s.orb_us);
  w.u32(s.planes_us);
  w.u32(s.map_us);
}

bool readVision(CdrReader& r, VisionResult* s) {
  std::uint32_t n = 0;
  if (!readHeader(r, &s->t_us) || !r.u64(&s->sequence) || !r.u32(&s->processing_us) || !r.boolean(&s->frame_ok) ||
      !r.f64(&s->mdm_f1) || !r.f64(&s->mdm_f2) || !r.f64(&s->mdm_f3) || !r.f64(&s->image_quality) ||
      !r.sequenceLength(&n, 4) || n > static_cast<std::uint32_t>(VisionResult::kMaxMarkers)) {
    return false;
  }
  s->marker_count = static_cast<std::int32_t>(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!readMarker(r, &s->markers[i])) return false;
  }
  std::uint8_t selected = 0;
  if (!r.i32(&s->markers_dropped) || !r.i32(&s->orb_tracked) || !r.u8(&selected) || !readVoSource(selected, &s->vo_selected) ||
      !readVo(r, &s->vo_orb) || !readVo(r, &s->vo_planes) || !r.i32(&s->planes) || !r.i32(&s->map_frames) ||
      !r.i32(&s->map_voxels) || !r.boolean(&s->map_ready)) {
    return false;
  }
  return r.u32(&s->orb_us) && r.u32(&s->planes_us) && r.u32(&s->map_us);
}

// The recording's row of each input kind: the topic it is recorded on (and replayed from), its writer
// and reader, and its viewer-only companion (DVL twist, pressure) where it has one. Rows are found by
// type (rowOf), so reordering InputSample changes nothing and a kind without a row does not compile.
template <typename T>
struct InputRow {
  Topic topic;
  void (*write)(CdrWriter&, const T&);
  bool (*read)(CdrReader&, T*);
  Topic companion_topic = Topic::kCount;
  void (*write_companion)(CdrWriter&, const T&) = nullptr;
};

constexpr InputRow<ImuSample> rowOf(const ImuSample*) { return {Topic::kImu, writeImu, readImu}; }
constexpr InputRow<DvlSample> rowOf(const DvlSample*) {
  return {Topic::kDvlBottomTrack, writeBottomTrack, readBottomTrack, Topic::kDvl, writeDvlTwist};
}
constexpr InputRow<HeadingSample> rowOf(const HeadingSample*) { return {Topic::kHeading, writeHeading, readHeading}; }
constexpr InputRow<AttitudeSample> rowOf(const AttitudeSample*) {
  return {Topic::kAttitude, writeAttitude, readAttitude};
}
constexpr InputRow<DepthSample> rowOf(const DepthSample*) {
  return {Topic::kDepth, writeDepth, readDepth, Topic::kPressure, writePressure};
}
constexpr InputRow<VisionResult> rowOf(const VisionResult*) {
  return {Topic::kVisionResult, writeVision, readVision};
}

template <typename T, typename ReadFn>
bool readAs(CdrReader& r, InputSample* out, ReadFn read) {
  T sample{};
  if (!read(r, &sample) || !r.ok()) return false;
  *out = sample;
  return true;
}

// Decodes the message as kind T when T is the kind recorded on `topic`; false when it is not.
template <typename T>
bool decodeIfRecordedOn(Topic topic, CdrReader& r, InputSample* out, bool* ok) {
  constexpr InputRow<T> row = rowOf(static_cast<const T*>(nullptr));
  if (row.topic != topic) return false;
  *ok = readAs<T>(r, out, row.read);
  return true;
}

template <typename... T>
bool decodeAnyKind(Topic topic, CdrReader& r, InputSample* out, const std::variant<T...>*) {
  bool ok = false;
  (decodeIfRecordedOn<T>(topic, r, out, &ok) || ...);
  return ok;
}

void writePoseCov(CdrWriter& w, const Eigen::Matrix<double, 6, 6>& cov) {
  const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> row = cov;
  w.f64Array(row.data(), 36);
}

}  // namespace

Topic inputTopic(const InputSample& sample) {
  return std::visit([](const auto& s) { return rowOf(&s).topic; }, sample);
}

Topic inputCompanionTopic(const InputSample& sample) {
  return std::visit([](const auto& s) { return rowOf(&s).companion_topic; }, sample);
}

std::size_t encodeInput(const InputSample& sample, std::uint8_t* out, std::size_t capacity) {
  return finish(out, capacity,
                [&](CdrWriter& w) { std::visit([&w](const auto& s) { rowOf(&s).write(w, s); }, sample); });
}

std::size_t encodeInputCompanion(const InputSample& sample, std::uint8_t* out, std::size_t capacity) {
  return std::visit(
      [&](const auto& s) -> std::size_t {
        const auto row = rowOf(&s);
        if (row.write_companion == nullptr) return 0;
        return finish(out, capacity, [&](CdrWriter& w) { row.write_companion(w, s); });
      },
      sample);
}

bool decodeInput(Topic topic, const std::uint8_t* data, std::size_t size, InputSample* out) {
  CdrReader r(data, size);
  return decodeAnyKind(topic, r, out, static_cast<const InputSample*>(nullptr));
}

std::size_t encodeSolution(const NavSolution& s, std::uint8_t* out, std::size_t capacity) {
  return finish(out, capacity, [&](CdrWriter& w) {
    writeStampedHeader(w, s.t_us, Topic::kNavSolution);
    writeVec3(w, s.p_robot_in_odom_m);
    writeQuat(w, s.q_odom_robot);
    writeVec3(w, s.v_robot_in_odom_mps);
    writeVec3(w, s.w_robot_radps);
    writePoseCov(w, s.cov_pose);
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> cov_v = s.cov_v_mps2;
    w.f64Array(cov_v.data(), 9);
    w.u8(static_cast<std::uint8_t>(s.stage));
    w.u32(s.status);
    w.u32(s.faults);
    w.f64(s.image_quality);
    w.u32(s.rejected_total);
    w.u32(s.dropped_late_total);
  });
}

bool decodeSolution(const std::uint8_t* data, std::size_t size, NavSolution* s) {
  CdrReader r(data, size);
  Eigen::Matrix<double, 6, 6, Eigen::RowMajor> cov_pose;
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> cov_v;
  std::uint8_t stage = 0;
  if (!readHeader(r, &s->t_us) || !readVec3(r, &s->p_robot_in_odom_m) || !readQuat(r, &s->q_odom_robot) ||
      !readVec3(r, &s->v_robot_in_odom_mps) || !readVec3(r, &s->w_robot_radps) || !r.f64Array(cov_pose.data(), 36) ||
      !r.f64Array(cov_v.data(), 9) || !r.u8(&stage) || !r.u32(&s->status) || !r.u32(&s->faults) ||
      !r.f64(&s->image_quality) || !r.u32(&s->rejected_total) || !r.u32(&s->dropped_late_total)) {
    return false;
  }
  if (stage > static_cast<std::uint8_t>(NavStage::kOptimised)) return false;
  s->stage = static_cast<NavStage>(stage);
  s->cov_pose = cov_pose;
  s->cov_v_mps2 = cov_v;
  return r.ok();
}

// nav_msgs/Odometry: ROS puts the twist in the child (robot) frame.
static std::size_t encodeOdometryMsg(TimeUs t_us, Topic topic, const Eigen::Vector3d& p, const Eigen::Quaterniond& q,
                                     const Eigen::Matrix<double, 6, 6>& cov_pose, const Eigen::Vector3d& v_odom,
                                     const Eigen::Vector3d& w_robot, const Eigen::Matrix3d& cov_v_odom,
                                     std::uint8_t* out, std::size_t capacity) {
  return finish(out, capacity, [&](CdrWriter& w) {
    writeStampedHeader(w, t_us, topic);
    w.string("base_link");
    writeVec3(w, p);
    writeQuat(w, q);
    writePoseCov(w, cov_pose);
    const Eigen::Matrix3d R = q.toRotationMatrix();
    writeVec3(w, R.transpose() * v_odom);
    writeVec3(w, w_robot);
    Eigen::Matrix<double, 6, 6> cov_twist = Eigen::Matrix<double, 6, 6>::Zero();
    cov_twist.topLeftCorner<3, 3>() = R.transpose() * cov_v_odom * R;
    writePoseCov(w, cov_twist);
  });
}

std::size_t encodeOdometry(const NavSolution& s, std::uint8_t* out, std::size_t capacity) {
  return encodeOdometryMsg(s.t_us, Topic::kOdometry, s.p_robot_in_odom_m, s.q_odom_robot, s.cov_pose,
                           s.v_robot_in_odom_mps, s.w_robot_radps, s.cov_v_mps2, out, capacity);
}

std::size_t encodeTruth(const TruthSample& s, std::uint8_t* out, std::size_t capacity) {
  return encodeOdometryMsg(s.t_us, Topic::kTruth, s.p_robot_in_odom_m, s.q_odom_robot,
                           Eigen::Matrix<double, 6, 6>::Zero(), s.v_robot_in_odom_mps, s.w_robot_radps,
                           Eigen::Matrix3d::Zero(), out, capacity);
}

bool decodeTruth(const std::uint8_t* data, std::size_t size, TruthSample* s) {
  ros::Odometry odom;
  if (!ros::decode(data, size, &odom)) return false;
  s->t_us = fromStamp(odom.header.stamp);
  const auto& p = odom.pose.pose.position;
  const auto& q = odom.pose.pose.orientation;
  s->p_robot_in_odom_m = Eigen::Vector3d(p.x, p.y, p.z);
  s->q_odom_robot = Eigen::Quaterniond(q.w, q.x, q.y, q.z);
  const auto& v = odom.twist.twist.linear;
  const auto& w = odom.twist.twist.angular;
  s->v_robot_in_odom_mps = s->q_odom_robot.toRotationMatrix() * Eigen::Vector3d(v.x, v.y, v.z);
  s->w_robot_radps = Eigen::Vector3d(w.x, w.y, w.z);
  return s->p_robot_in_odom_m.allFinite() && s->q_odom_robot.coeffs().allFinite();
}

std::size_t encodeStereoInfo(const StereoFrame& f, std::uint8_t* out, std::size_t capacity) {
  return finish(out, capacity, [&](CdrWriter& w) {
    writeStampedHeader(w, f.t_us, Topic::kStereoInfo);
    w.u32(f.exposure_us);
    w.u64(f.sequence);
    w.boolean(f.rectified);
  });
}

bool decodeStereoInfo(const std::uint8_t* data, std::size_t size, StereoFrame* f) {
  CdrReader r(data, size);
  return readHeader(r, &f->t_us) && r.u32(&f->exposure_us) && r.u64(&f->sequence) && r.boolean(&f->rectified) &&
         r.ok();
}

std::size_t encodeImage(const StereoFrame& f, bool left, std::uint8_t* out, std::size_t capacity) {
  const cv::Mat& img = left ? f.left : f.right;
  return finish(out, capacity, [&](CdrWriter& w) {
    writeStampedHeader(w, f.t_us, left ? Topic::kLeftImage : Topic::kRightImage);
    w.u32(static_cast<std::uint32_t>(img.rows));
    w.u32(static_cast<std::uint32_t>(img.cols));
    w.string(img.channels() == 3 ? "bgr8" : "mono8");
    w.u8(0);
    const std::size_t row_bytes = static_cast<std::size_t>(img.cols) * img.elemSize();
    w.u32(static_cast<std::uint32_t>(row_bytes));
    w.sequenceLength(row_bytes * static_cast<std::size_t>(img.rows));
    for (int y = 0; y < img.rows; ++y) w.u8Array(img.ptr<std::uint8_t>(y), row_bytes);
  });
}

bool decodeImageInto(const std::uint8_t* data, std::size_t size, bool left, StereoFrame* f) {
  CdrReader r(data, size);
  TimeUs t_us = 0;
  std::uint32_t rows = 0, cols = 0, step = 0;
  std::uint8_t big = 0;
  std::string encoding;
  const std::uint8_t* pixels = nullptr;
  std::size_t count = 0;
  if (!readHeader(r, &t_us) || !r.u32(&rows) || !r.u32(&cols) || !r.string(&encoding) || !r.u8(&big) ||
      !r.u32(&step) || !r.u8SequenceView(&pixels, &count)) {
    return false;
  }
  cv::Mat& img = left ? f->left : f->right;
  const int channels = encoding == "bgr8" ? 3 : (encoding == "mono8" ? 1 : 0);
  if (channels == 0 || static_cast<int>(rows) != img.rows || static_cast<int>(cols) != img.cols ||
      channels != img.channels()) {
    return false;
  }
  const std::size_t row_bytes = static_cast<std::size_t>(cols) * static_cast<std::size_t>(channels);
  if (step < row_bytes || count < static_cast<std::size_t>(step) * (rows - 1) + row_bytes) return false;
  for (std::uint32_t y = 0; y < rows; ++y) {
    std::memcpy(img.ptr<std::uint8_t>(static_cast<int>(y)), pixels + static_cast<std::size_t>(y) * step, row_bytes);
  }
  return true;
}

std::size_t encodeLoopStats(TimeUs t_us, const LoopStats& s, std::uint8_t* out, std::size_t capacity) {
  return finish(out, capacity, [&](CdrWriter& w) {
    writeStampedHeader(w, t_us, Topic::kLoopStats);
    const auto n = static_cast<std::size_t>(s.task_count);
    w.sequenceLength(n);
    for (std::size_t i = 0; i < n; ++i) w.string(s.names[i]);
    w.sequenceLength(n);
    for (std::size_t i = 0; i < n; ++i) w.u64(s.runs[i]);
    w.sequenceLength(n);
    for (std::size_t i = 0; i < n; ++i) w.u64(s.overruns[i]);
    w.sequenceLength(n);
    for (std::size_t i = 0; i < n; ++i) w.f64(s.mean_us[i]);
    w.sequenceLength(n);
    for (std::size_t i = 0; i < n; ++i) w.i64(s.max_us[i]);
    w.u64(s.ticks);
    w.u64(s.late_ticks);
    w.i64(s.max_lateness_us);
  });
}

bool peekImageSize(const std::uint8_t* data, std::size_t size, int* rows, int* cols, int* channels) {
  CdrReader r(data, size);
  TimeUs t_us = 0;
  std::uint32_t h = 0, w = 0;
  std::string encoding;
  if (!readHeader(r, &t_us) || !r.u32(&h) || !r.u32(&w) || !r.string(&encoding)) return false;
  *channels = encoding == "bgr8" ? 3 : (encoding == "mono8" ? 1 : 0);
  constexpr std::uint32_t kMaxSide = 16384;
  if (*channels == 0 || h == 0 || w == 0 || h > kMaxSide || w > kMaxSide) return false;
  *rows = static_cast<int>(h);
  *cols = static_cast<int>(w);
  return true;
}

bool sameBits(const NavSolution& a, const NavSolution& b) {
  auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  return a.t_us == b.t_us && same(a.p_robot_in_odom_m, b.p_robot_in_odom_m) &&
         same(a.q_odom_robot.coeffs(), b.q_odom_robot.coeffs()) && same(a.v_robot_in_odom_mps, b.v_robot_in_odom_mps) &&
         same(a.w_robot_radps, b.w_robot_radps) && same(a.cov_pose, b.cov_pose) && same(a.cov_v_mps2, b.cov_v_mps2) &&
         a.stage == b.stage && a.status == b.status && a.faults == b.faults &&
         same(a.image_quality, b.image_quality) && a.rejected_total == b.rejected_total &&
         a.dropped_late_total == b.dropped_late_total;
}

}  // namespace deepnav
