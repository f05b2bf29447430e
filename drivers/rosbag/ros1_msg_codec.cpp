#include "drivers/rosbag/ros1_msg_codec.h"

#include <array>
#include <bit>
#include <limits>

#include "drivers/mcap/byte_cursor.h"

namespace deepnav::rosbag {
namespace {

using Cursor = mcap::ByteCursor;  // bounds-checked little-endian reads, no alignment

bool f64(Cursor& c, double* v) {
  uint64_t bits = 0;
  if (!c.u64(&bits)) return false;
  *v = std::bit_cast<double>(bits);
  return true;
}

template <size_t N>
bool f64s(Cursor& c, std::array<double, N>* a) {
  for (double& v : *a) {
    if (!f64(c, &v)) return false;
  }
  return true;
}

bool vector3(Cursor& c, ros::Vector3* v) { return f64(c, &v->x) && f64(c, &v->y) && f64(c, &v->z); }

bool quaternion(Cursor& c, ros::Quaternion* q) {
  return f64(c, &q->x) && f64(c, &q->y) && f64(c, &q->z) && f64(c, &q->w);
}

bool twist(Cursor& c, ros::Twist* t) { return vector3(c, &t->linear) && vector3(c, &t->angular); }

bool header(Cursor& c, ros::Header* h) {
  uint32_t seq = 0;
  uint32_t sec = 0;
  uint32_t nsec = 0;
  if (!c.u32(&seq) || !c.u32(&sec) || !c.u32(&nsec) || !c.string(&h->frame_id)) return false;
  if (nsec >= 1000000000u || sec > uint32_t(std::numeric_limits<int32_t>::max())) return false;
  h->stamp.sec = int32_t(sec);
  h->stamp.nanosec = nsec;
  return true;
}

bool bytes(Cursor& c, std::vector<uint8_t>* out) {
  uint32_t n = 0;
  const uint8_t* p = nullptr;
  if (!c.u32(&n) || !c.bytes(n, &p)) return false;
  out->assign(p, p + n);
  return true;
}

}  // namespace

bool decodeRos1(const uint8_t* data, size_t size, ros::Image* msg) {
  Cursor c(data, size);
  return header(c, &msg->header) && c.u32(&msg->height) && c.u32(&msg->width) &&
         c.string(&msg->encoding) && c.u8(&msg->is_bigendian) && c.u32(&msg->step) &&
         bytes(c, &msg->data) && c.remaining() == 0;
}

bool decodeRos1(const uint8_t* data, size_t size, ros::CompressedImage* msg) {
  Cursor c(data, size);
  return header(c, &msg->header) && c.string(&msg->format) && bytes(c, &msg->data) &&
         c.remaining() == 0;
}

bool decodeRos1(const uint8_t* data, size_t size, ros::Imu* msg) {
  Cursor c(data, size);
  return header(c, &msg->header) && quaternion(c, &msg->orientation) &&
         f64s(c, &msg->orientation_covariance) && vector3(c, &msg->angular_velocity) &&
         f64s(c, &msg->angular_velocity_covariance) && vector3(c, &msg->linear_acceleration) &&
         f64s(c, &msg->linear_acceleration_covariance) && c.remaining() == 0;
}

bool decodeRos1(const uint8_t* data, size_t size, ros::FluidPressure* msg) {
  Cursor c(data, size);
  return header(c, &msg->header) && f64(c, &msg->fluid_pressure) && f64(c, &msg->variance) &&
         c.remaining() == 0;
}

bool decodeRos1(const uint8_t* data, size_t size, ros::TwistStamped* msg) {
  Cursor c(data, size);
  return header(c, &msg->header) && twist(c, &msg->twist) && c.remaining() == 0;
}

bool decodeRos1(const uint8_t* data, size_t size, ros::TwistWithCovarianceStamped* msg) {
  Cursor c(data, size);
  return header(c, &msg->header) && twist(c, &msg->twist.twist) &&
         f64s(c, &msg->twist.covariance) && c.remaining() == 0;
}

bool decodeRos1(const uint8_t* data, size_t size, ros::MagneticField* msg) {
  Cursor c(data, size);
  return header(c, &msg->header) && vector3(c, &msg->magnetic_field) &&
         f64s(c, &msg->magnetic_field_covariance) && c.remaining() == 0;
}

}  // namespace deepnav::rosbag
