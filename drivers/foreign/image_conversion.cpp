#include "drivers/foreign/image_conversion.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace deepnav::foreign {
namespace {

struct Layout {
  int bytes_per_pixel = 0;
  int cv_type = 0;
  int to_bgr = -1;  // cv::cvtColor code to BGR (3 channels), -1: already grey or BGR
};

bool layoutOf(const std::string& encoding, Layout* l) {
  if (encoding == "mono8" || encoding == "8UC1") *l = {1, CV_8UC1, -1};
  else if (encoding == "bgr8" || encoding == "8UC3") *l = {3, CV_8UC3, -1};
  else if (encoding == "rgb8") *l = {3, CV_8UC3, cv::COLOR_RGB2BGR};
  else if (encoding == "bgra8") *l = {4, CV_8UC4, cv::COLOR_BGRA2BGR};
  else if (encoding == "rgba8") *l = {4, CV_8UC4, cv::COLOR_RGBA2BGR};
  else if (encoding == "mono16" || encoding == "16UC1") *l = {2, CV_16UC1, -1};
  else return false;
  return true;
}

// 8-bit grey or BGR in `channels` from a grey, BGR (or 4-channel, converted first) image.
void toChannels(const cv::Mat& in, int to_bgr, int channels, cv::Mat* out) {
  // A fresh Mat for the conversion: assigning `in` would share its buffer and cvtColor would write the
  // converted pixels into the message's bytes.
  cv::Mat converted;
  if (to_bgr >= 0) cv::cvtColor(in, converted, to_bgr);
  const cv::Mat& bgr_or_grey = to_bgr >= 0 ? converted : in;
  if (bgr_or_grey.channels() == channels) {
    bgr_or_grey.copyTo(*out);
  } else if (channels == 1) {
    cv::cvtColor(bgr_or_grey, *out, cv::COLOR_BGR2GRAY);
  } else {
    cv::cvtColor(bgr_or_grey, *out, cv::COLOR_GRAY2BGR);
  }
}

// mono16 to 8 bits: value >> (bits - 8), saturated (a pixel above the stated depth reads white).
cv::Mat mono16To8(const cv::Mat& in, bool big_endian, int bits) {
  cv::Mat host = in;
  if (big_endian) {
    host = in.clone();
    for (int r = 0; r < host.rows; ++r) {
      auto* p = host.ptr<std::uint16_t>(r);
      for (int c = 0; c < host.cols; ++c) p[c] = static_cast<std::uint16_t>((p[c] >> 8) | (p[c] << 8));
    }
  }
  cv::Mat out;
  host.convertTo(out, CV_8U, 1.0 / static_cast<double>(1 << (bits - 8)));
  return out;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

bool imageFromRos(const ros::Image& m, int channels, int mono16_bits, cv::Mat* out, std::string* error) {
  Layout l;
  if (!layoutOf(m.encoding, &l)) {
    *error = "image encoding '" + m.encoding +
             "' is not read (mono8, 8UC1, bgr8, 8UC3, rgb8, bgra8, rgba8, mono16, 16UC1 are; debayer or convert "
             "the images first)";
    return false;
  }
  const std::size_t row_bytes = static_cast<std::size_t>(m.width) * static_cast<std::size_t>(l.bytes_per_pixel);
  if (m.width == 0 || m.height == 0 || m.step < row_bytes ||
      m.data.size() < static_cast<std::size_t>(m.step) * (m.height - 1) + row_bytes) {
    *error = "image of " + std::to_string(m.width) + "x" + std::to_string(m.height) + " " + m.encoding + ", step " +
             std::to_string(m.step) + ", holds " + std::to_string(m.data.size()) + " bytes: too few";
    return false;
  }
  // The message's bytes, viewed in place (OpenCV does not write through a const view here).
  const cv::Mat view(static_cast<int>(m.height), static_cast<int>(m.width), l.cv_type,
                     const_cast<std::uint8_t*>(m.data.data()), m.step);
  if (l.cv_type == CV_16UC1) {
    toChannels(mono16To8(view, m.is_bigendian != 0, mono16_bits), -1, channels, out);
  } else {
    toChannels(view, l.to_bgr, channels, out);
  }
  return true;
}

bool imageFromRos(const ros::CompressedImage& m, int channels, int mono16_bits, cv::Mat* out, std::string* error) {
  const std::string format = lower(m.format);
  if (format.find("compresseddepth") != std::string::npos ||
      (format.find("jpeg") == std::string::npos && format.find("jpg") == std::string::npos &&
       format.find("png") == std::string::npos)) {
    *error = "compressed image format '" + m.format + "' is not read (jpeg and png are)";
    return false;
  }
  if (m.data.empty()) {
    *error = "compressed image (" + m.format + ") holds no bytes";
    return false;
  }
  const cv::Mat bytes(1, static_cast<int>(m.data.size()), CV_8UC1, const_cast<std::uint8_t*>(m.data.data()));
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  if (decoded.empty() || (decoded.depth() != CV_8U && decoded.depth() != CV_16U) ||
      (decoded.channels() != 1 && decoded.channels() != 3 && decoded.channels() != 4)) {
    *error = "compressed image (" + m.format + ", " + std::to_string(m.data.size()) + " bytes) does not decode" +
             (decoded.empty() ? std::string() : " to 8- or 16-bit grey, BGR or BGRA");
    return false;
  }
  // A 16-bit PNG (grey, or colour) is brought to 8 bits as a mono16 Image is.
  cv::Mat eight_bit = decoded;
  if (decoded.depth() == CV_16U) {
    decoded.convertTo(eight_bit, CV_8U, 1.0 / static_cast<double>(1 << (mono16_bits - 8)));
  }
  toChannels(eight_bit, eight_bit.channels() == 4 ? cv::COLOR_BGRA2BGR : -1, channels, out);
  return true;
}

}  // namespace deepnav::foreign
