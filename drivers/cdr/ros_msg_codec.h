#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/cdr/ros_msgs.h"

// CDR encoding and decoding of the ROS 2 messages in ros_msgs.h, byte-compatible with rmw.
//
// encodeFields()/decodeFields() handle one struct's fields inside a message that is being
// written or read, so project messages can reuse them (e.g. a std_msgs/Header first, then their
// own fields with CdrWriter's primitives: see encodeCustom()). encode()/decode() handle a whole
// message: encapsulation header included.
namespace deepnav::ros {

void encodeFields(cdr::CdrWriter& w, const Time& m);
void encodeFields(cdr::CdrWriter& w, const Header& m);
void encodeFields(cdr::CdrWriter& w, const Vector3& m);
void encodeFields(cdr::CdrWriter& w, const Point& m);
void encodeFields(cdr::CdrWriter& w, const Quaternion& m);
void encodeFields(cdr::CdrWriter& w, const Pose& m);
void encodeFields(cdr::CdrWriter& w, const PoseWithCovariance& m);
void encodeFields(cdr::CdrWriter& w, const Twist& m);
void encodeFields(cdr::CdrWriter& w, const TwistWithCovariance& m);
void encodeFields(cdr::CdrWriter& w, const TwistWithCovarianceStamped& m);
void encodeFields(cdr::CdrWriter& w, const Imu& m);
void encodeFields(cdr::CdrWriter& w, const Image& m);
void encodeFields(cdr::CdrWriter& w, const ImageView& m);
void encodeFields(cdr::CdrWriter& w, const FluidPressure& m);
void encodeFields(cdr::CdrWriter& w, const Odometry& m);
void encodeFields(cdr::CdrWriter& w, const TwistStamped& m);
void encodeFields(cdr::CdrWriter& w, const CompressedImage& m);
void encodeFields(cdr::CdrWriter& w, const MagneticField& m);

bool decodeFields(cdr::CdrReader& r, Time* m);
bool decodeFields(cdr::CdrReader& r, Header* m);
bool decodeFields(cdr::CdrReader& r, Vector3* m);
bool decodeFields(cdr::CdrReader& r, Point* m);
bool decodeFields(cdr::CdrReader& r, Quaternion* m);
bool decodeFields(cdr::CdrReader& r, Pose* m);
bool decodeFields(cdr::CdrReader& r, PoseWithCovariance* m);
bool decodeFields(cdr::CdrReader& r, Twist* m);
bool decodeFields(cdr::CdrReader& r, TwistWithCovariance* m);
bool decodeFields(cdr::CdrReader& r, TwistWithCovarianceStamped* m);
bool decodeFields(cdr::CdrReader& r, Imu* m);
bool decodeFields(cdr::CdrReader& r, Image* m);
bool decodeFields(cdr::CdrReader& r, FluidPressure* m);
bool decodeFields(cdr::CdrReader& r, Odometry* m);
bool decodeFields(cdr::CdrReader& r, TwistStamped* m);
bool decodeFields(cdr::CdrReader& r, CompressedImage* m);
bool decodeFields(cdr::CdrReader& r, MagneticField* m);

// Bytes the whole encoded message takes, encapsulation header included.
template <typename Msg>
size_t encodedSize(const Msg& m) {
  cdr::CdrWriter w = cdr::CdrWriter::sizer();
  encodeFields(w, m);
  return w.size();
}

// Encodes into out[0, capacity) without allocating. Returns the size, or 0 if it did not fit.
template <typename Msg>
size_t encode(const Msg& m, uint8_t* out, size_t capacity) {
  cdr::CdrWriter w(out, capacity);
  encodeFields(w, m);
  return w.ok() ? w.size() : 0;
}

// Encodes into *out, resized to the message; allocates only when out's capacity is too small.
template <typename Msg>
bool encode(const Msg& m, std::vector<uint8_t>* out) {
  out->resize(encodedSize(m));
  return encode(m, out->data(), out->size()) == out->size();
}

template <typename Msg>
bool decode(const uint8_t* data, size_t size, Msg* m) {
  cdr::CdrReader r(data, size);
  return decodeFields(r, m) && r.ok();
}

// A project message: write_fields(CdrWriter&) writes its fields in declaration order with the
// primitives above; alignment is handled by CdrWriter. Returns the size, or 0 if it did not fit
// (pass out = nullptr to only measure: the size needed is returned).
template <typename WriteFields>
size_t encodeCustom(uint8_t* out, size_t capacity, WriteFields&& write_fields) {
  cdr::CdrWriter w(out, capacity);
  write_fields(w);
  return w.ok() ? w.size() : 0;
}

}  // namespace deepnav::ros
