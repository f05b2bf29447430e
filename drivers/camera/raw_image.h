#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

namespace deepnav {

// Pixel layouts the camera drivers accept (board key camera.pixel_format).
enum class PixelFormat { kMono8, kBayerRG8, kBayerGR8, kBayerGB8, kBayerBG8, kRgb8, kBgr8, kYuyv };

// Parses a camera.pixel_format value ("mono8", "bayer_rg8", ...); false when unknown.
bool parsePixelFormat(const std::string& name, PixelFormat* format);
const char* pixelFormatName(PixelFormat format);
int bytesPerPixelTimes2(PixelFormat format);  // 2, 6 or 4 (YUYV: 2 bytes per pixel)

// One camera image as the hardware delivered it (memory owned by the driver's buffer).
struct RawImage {
  const std::uint8_t* data = nullptr;
  std::size_t size_bytes = 0;
  int width_px = 0;
  int height_px = 0;
  std::size_t stride_bytes = 0;  // bytes from one row to the next (>= width * bytes per pixel)
  PixelFormat format = PixelFormat::kMono8;
};

// Converts a raw image into a preallocated CV_8UC1 (grey) or CV_8UC3 (BGR) image of the same size
// (debayering, colour conversion or a plain copy). Returns false, touching nothing, when the sizes do
// not match or the buffer is too short. No allocation when `out` already has the right size and type.
bool convertRawImage(const RawImage& in, cv::Mat& out);

}  // namespace deepnav
