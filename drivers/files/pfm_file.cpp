#include "drivers/files/pfm_file.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace deepnav {

bool writePfm(const std::string& path, const cv::Mat& disparity_px, std::string* error) {
  if (disparity_px.type() != CV_32FC1 || disparity_px.empty()) {
    if (error) *error = path + ": a PFM disparity map must be a non-empty CV_32FC1 image";
    return false;
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) {
    if (error) *error = path + ": cannot write";
    return false;
  }
  out << "Pf\n" << disparity_px.cols << " " << disparity_px.rows << "\n-1.0\n";
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> row(static_cast<std::size_t>(disparity_px.cols));
  for (int y = disparity_px.rows - 1; y >= 0; --y) {
    const float* src = disparity_px.ptr<float>(y);
    for (int x = 0; x < disparity_px.cols; ++x) row[static_cast<std::size_t>(x)] = src[x] < 0.0f ? inf : src[x];
    out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(float)));
  }
  if (!out) {
    if (error) *error = path + ": write failed";
    return false;
  }
  return true;
}

bool readPfm(const std::string& path, cv::Mat* image, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int width = 0, height = 0;
  double scale = 0.0;
  if (!(in >> magic >> width >> height >> scale) || magic != "Pf" || width <= 0 || height <= 0 ||
      width > 65536 || height > 65536 || scale == 0.0) {
    if (error) *error = path + ": not a greyscale PFM file";
    return false;
  }
  in.get();  // the single whitespace after the scale
  image->create(height, width, CV_32FC1);
  const bool swap = scale > 0.0;  // positive scale: big-endian data
  for (int y = height - 1; y >= 0; --y) {
    float* dst = image->ptr<float>(y);
    in.read(reinterpret_cast<char*>(dst), static_cast<std::streamsize>(width * sizeof(float)));
    if (!in) {
      if (error) *error = path + ": truncated PFM data";
      return false;
    }
    if (!swap) continue;
    for (int x = 0; x < width; ++x) {
      std::uint32_t v;
      std::memcpy(&v, &dst[x], 4);
      v = __builtin_bswap32(v);
      std::memcpy(&dst[x], &v, 4);
    }
  }
  return true;
}

}  // namespace deepnav
