#include "drivers/camera/raw_image.h"

#include <array>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace deepnav {
namespace {

constexpr std::array<std::pair<PixelFormat, const char*>, 8> kNames = {{
    {PixelFormat::kMono8, "mono8"},
    {PixelFormat::kBayerRG8, "bayer_rg8"},
    {PixelFormat::kBayerGR8, "bayer_gr8"},
    {PixelFormat::kBayerGB8, "bayer_gb8"},
    {PixelFormat::kBayerBG8, "bayer_bg8"},
    {PixelFormat::kRgb8, "rgb8"},
    {PixelFormat::kBgr8, "bgr8"},
    {PixelFormat::kYuyv, "yuyv"},
}};

// OpenCV names a Bayer pattern by the second row's second and third pixels, GenICam and V4L2 by the
// first row's first two: GenICam BayerRG8 (R G / G B) is OpenCV's BayerBG.
int bayerCode(PixelFormat f, bool colour) {
  switch (f) {
    case PixelFormat::kBayerRG8: return colour ? cv::COLOR_BayerBG2BGR : cv::COLOR_BayerBG2GRAY;
    case PixelFormat::kBayerGR8: return colour ? cv::COLOR_BayerGB2BGR : cv::COLOR_BayerGB2GRAY;
    case PixelFormat::kBayerGB8: return colour ? cv::COLOR_BayerGR2BGR : cv::COLOR_BayerGR2GRAY;
    default: return colour ? cv::COLOR_BayerRG2BGR : cv::COLOR_BayerRG2GRAY;
  }
}

}  // namespace

bool parsePixelFormat(const std::string& name, PixelFormat* format) {
  for (const auto& [f, n] : kNames) {
    if (name == n) {
      *format = f;
      return true;
    }
  }
  return false;
}

const char* pixelFormatName(PixelFormat format) {
  for (const auto& [f, n] : kNames) {
    if (f == format) return n;
  }
  return "?";
}

int bytesPerPixelTimes2(PixelFormat format) {
  switch (format) {
    case PixelFormat::kRgb8:
    case PixelFormat::kBgr8: return 6;
    case PixelFormat::kYuyv: return 4;
    default: return 2;
  }
}

bool convertRawImage(const RawImage& in, cv::Mat& out) {
  if (in.data == nullptr || in.width_px != out.cols || in.height_px != out.rows) return false;
  if (out.type() != CV_8UC1 && out.type() != CV_8UC3) return false;
  const std::size_t row_bytes =
      static_cast<std::size_t>(in.width_px) * static_cast<std::size_t>(bytesPerPixelTimes2(in.format)) / 2;
  if (in.stride_bytes < row_bytes) return false;
  const std::size_t needed = in.stride_bytes * static_cast<std::size_t>(in.height_px - 1) + row_bytes;
  if (in.height_px <= 0 || in.size_bytes < needed) return false;

  const bool colour = out.channels() == 3;
  // A header over the driver's memory: no copy until the conversion writes into `out`.
  void* data = const_cast<std::uint8_t*>(in.data);
  switch (in.format) {
    case PixelFormat::kMono8: {
      const cv::Mat src(in.height_px, in.width_px, CV_8UC1, data, in.stride_bytes);
      if (colour) {
        cv::cvtColor(src, out, cv::COLOR_GRAY2BGR);
      } else {
        src.copyTo(out);
      }
      return true;
    }
    case PixelFormat::kBayerRG8:
    case PixelFormat::kBayerGR8:
    case PixelFormat::kBayerGB8:
    case PixelFormat::kBayerBG8: {
      const cv::Mat src(in.height_px, in.width_px, CV_8UC1, data, in.stride_bytes);
      cv::cvtColor(src, out, bayerCode(in.format, colour));
      return true;
    }
    case PixelFormat::kRgb8:
    case PixelFormat::kBgr8: {
      const cv::Mat src(in.height_px, in.width_px, CV_8UC3, data, in.stride_bytes);
      const bool rgb = in.format == PixelFormat::kRgb8;
      if (colour) {
        if (rgb) {
          cv::cvtColor(src, out, cv::COLOR_RGB2BGR);
        } else {
          src.copyTo(out);
        }
      } else {
        cv::cvtColor(src, out, rgb ? cv::COLOR_RGB2GRAY : cv::COLOR_BGR2GRAY);
      }
      return true;
    }
    case PixelFormat::kYuyv: {
      const cv::Mat src(in.height_px, in.width_px, CV_8UC2, data, in.stride_bytes);
      cv::cvtColor(src, out, colour ? cv::COLOR_YUV2BGR_YUYV : cv::COLOR_YUV2GRAY_YUYV);
      return true;
    }
  }
  return false;
}

}  // namespace deepnav
