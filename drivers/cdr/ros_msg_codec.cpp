#include "drivers/cdr/ros_msg_codec.h"

namespace deepnav::ros {

using cdr::CdrReader;
using cdr::CdrWriter;

// Encoding ------------------------------------------------------------------------------------

void encodeFields(CdrWriter& w, const Time& m) {
  w.i32(m.sec);
  w.u32(m.nanosec);
}

void encodeFields(CdrWriter& w, const Header& m) {
  encodeFields(w, m.stamp);
  w.string(m.frame_id);
}

void encodeFields(CdrWriter& w, const Vector3& m) {
  w.f64(m.x);
  w.f64(m.y);
  w.f64(m.z);
}

void encodeFields(CdrWriter& w, const Point& m) {
  w.f64(m.x);
  w.f64(m.y);
  w.f64(m.z);
}

void encodeFields(CdrWriter& w, const Quaternion& m) {
  w.f64(m.x);
  w.f64(m.y);
  w.f64(m.z);
  w.f64(m.w);
}

void encodeFields(CdrWriter& w, const Pose& m) {
  encodeFields(w, m.position);
  encodeFields(w, m.orientation);
}

void encodeFields(CdrWriter& w, const PoseWithCovariance& m) {
  encodeFields(w, m.pose);
  w.f64Array(m.covariance.data(), m.covariance.size());
}

void encodeFields(CdrWriter& w, const Twist& m) {
  encodeFields(w, m.linear);
  encodeFields(w, m.angular);
}

void encodeFields(CdrWriter& w, const TwistWithCovariance& m) {
  encodeFields(w, m.twist);
  w.f64Array(m.covariance.data(), m.covariance.size());
}

void encodeFields(CdrWriter& w, const TwistWithCovarianceStamped& m) {
  encodeFields(w, m.header);
  encodeFields(w, m.twist);
}

void encodeFields(CdrWriter& w, const Imu& m) {
  encodeFields(w, m.header);
  encodeFields(w, m.orientation);
  w.f64Array(m.orientation_covariance.data(), m.orientation_covariance.size());
  encodeFields(w, m.angular_velocity);
  w.f64Array(m.angular_velocity_covariance.data(), m.angular_velocity_covariance.size());
  encodeFields(w, m.linear_acceleration);
  w.f64Array(m.linear_acceleration_covariance.data(), m.linear_acceleration_covariance.size());
}

void encodeFields(CdrWriter& w, const ImageView& m) {
  static const Header kNoHeader;
  encodeFields(w, m.header != nullptr ? *m.header : kNoHeader);
  w.u32(m.height);
  w.u32(m.width);
  w.string(m.encoding);
  w.u8(m.is_bigendian);
  w.u32(m.step);
  w.u8Sequence(m.data, m.size);
}

void encodeFields(CdrWriter& w, const Image& m) {
  encodeFields(w, ImageView{&m.header, m.height, m.width, m.encoding, m.is_bigendian, m.step,
                            m.data.data(), m.data.size()});
}

void encodeFields(CdrWriter& w, const FluidPressure& m) {
  encodeFields(w, m.header);
  w.f64(m.fluid_pressure);
  w.f64(m.variance);
}

void encodeFields(CdrWriter& w, const Odometry& m) {
  encodeFields(w, m.header);
  w.string(m.child_frame_id);
  encodeFields(w, m.pose);
  encodeFields(w, m.twist);
}

void encodeFields(CdrWriter& w, const TwistStamped& m) {
  encodeFields(w, m.header);
  encodeFields(w, m.twist);
}

void encodeFields(CdrWriter& w, const CompressedImage& m) {
  encodeFields(w, m.header);
  w.string(m.format);
  w.u8Sequence(m.data.data(), m.data.size());
}

void encodeFields(CdrWriter& w, const MagneticField& m) {
  encodeFields(w, m.header);
  encodeFields(w, m.magnetic_field);
  w.f64Array(m.magnetic_field_covariance.data(), m.magnetic_field_covariance.size());
}

// Decoding ------------------------------------------------------------------------------------

bool decodeFields(CdrReader& r, Time* m) { return r.i32(&m->sec) && r.u32(&m->nanosec); }

bool decodeFields(CdrReader& r, Header* m) {
  return decodeFields(r, &m->stamp) && r.string(&m->frame_id);
}

bool decodeFields(CdrReader& r, Vector3* m) { return r.f64(&m->x) && r.f64(&m->y) && r.f64(&m->z); }

bool decodeFields(CdrReader& r, Point* m) { return r.f64(&m->x) && r.f64(&m->y) && r.f64(&m->z); }

bool decodeFields(CdrReader& r, Quaternion* m) {
  return r.f64(&m->x) && r.f64(&m->y) && r.f64(&m->z) && r.f64(&m->w);
}

bool decodeFields(CdrReader& r, Pose* m) {
  return decodeFields(r, &m->position) && decodeFields(r, &m->orientation);
}

bool decodeFields(CdrReader& r, PoseWithCovariance* m) {
  return decodeFields(r, &m->pose) && r.f64Array(m->covariance.data(), m->covariance.size());
}

bool decodeFields(CdrReader& r, Twist* m) {
  return decodeFields(r, &m->linear) && decodeFields(r, &m->angular);
}

bool decodeFields(CdrReader& r, TwistWithCovariance* m) {
  return decodeFields(r, &m->twist) && r.f64Array(m->covariance.data(), m->covariance.size());
}

bool decodeFields(CdrReader& r, TwistWithCovarianceStamped* m) {
  return decodeFields(r, &m->header) && decodeFields(r, &m->twist);
}

bool decodeFields(CdrReader& r, Imu* m) {
  return decodeFields(r, &m->header) && decodeFields(r, &m->orientation) &&
         r.f64Array(m->orientation_covariance.data(), m->orientation_covariance.size()) &&
         decodeFields(r, &m->angular_velocity) &&
         r.f64Array(m->angular_velocity_covariance.data(), m->angular_velocity_covariance.size()) &&
         decodeFields(r, &m->linear_acceleration) &&
         r.f64Array(m->linear_acceleration_covariance.data(),
                    m->linear_acceleration_covariance.size());
}

bool decodeFields(CdrReader& r, Image* m) {
  const uint8_t* pixels = nullptr;
  size_t size = 0;
  if (!decodeFields(r, &m->header) || !r.u32(&m->height) || !r.u32(&m->width) ||
      !r.string(&m->encoding) || !r.u8(&m->is_bigendian) || !r.u32(&m->step) ||
      !r.u8SequenceView(&pixels, &size)) {
    return false;
  }
  m->data.assign(pixels, pixels + size);
  return true;
}

bool decodeFields(CdrReader& r, FluidPressure* m) {
  return decodeFields(r, &m->header) && r.f64(&m->fluid_pressure) && r.f64(&m->variance);
}

bool decodeFields(CdrReader& r, Odometry* m) {
  return decodeFields(r, &m->header) && r.string(&m->child_frame_id) && decodeFields(r, &m->pose) &&
         decodeFields(r, &m->twist);
}

bool decodeFields(CdrReader& r, TwistStamped* m) {
  return decodeFields(r, &m->header) && decodeFields(r, &m->twist);
}

bool decodeFields(CdrReader& r, CompressedImage* m) {
  const uint8_t* bytes = nullptr;
  size_t size = 0;
  if (!decodeFields(r, &m->header) || !r.string(&m->format) || !r.u8SequenceView(&bytes, &size)) return false;
  m->data.assign(bytes, bytes + size);
  return true;
}

bool decodeFields(CdrReader& r, MagneticField* m) {
  return decodeFields(r, &m->header) && decodeFields(r, &m->magnetic_field) &&
         r.f64Array(m->magnetic_field_covariance.data(), m->magnetic_field_covariance.size());
}

}  // namespace deepnav::ros
