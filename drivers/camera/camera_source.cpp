#include "drivers/camera/camera_source.h"

#include <sstream>

#include "base/fail.h"
#include "drivers/camera/aravis_stereo_camera.h"
#include "drivers/camera/raw_image.h"
#include "drivers/camera/v4l2_stereo_camera.h"

namespace deepnav {

bool checkStart(const CameraSourceConfig& c, const FramePool* pool, const SpscRing<int>* frames, bool cameras_open,
                std::string* error) {
  if (pool == nullptr || frames == nullptr || pool->size() == 0) return fail(error, "camera: no frame pool");
  const StereoFrame& f = pool->frame(0);
  if (f.left.cols != c.width_px || f.left.rows != c.height_px || f.left.channels() != c.channels) {
    return fail(error, "camera: the frame pool's frames do not have the camera's size and channels");
  }
  if (!cameras_open) return fail(error, "camera: start() before a successful open()");
  return true;
}

bool validateCameraSourceConfig(const CameraSourceConfig& c, std::string* error, PixelFormat* format_out) {
  if (c.driver != "aravis" && c.driver != "v4l2") {
    return fail(error, "camera.driver is '" + c.driver + "'; a camera source needs aravis or v4l2");
  }
  if (c.left.empty() || c.right.empty()) {
    return fail(error, "camera.left and camera.right must name the two cameras (driver " + c.driver + ")");
  }
  if (c.left == c.right) return fail(error, "camera.left and camera.right are both '" + c.left + "'");
  PixelFormat format;
  if (!parsePixelFormat(c.pixel_format, &format)) {
    return fail(error, "camera.pixel_format '" + c.pixel_format + "' is not a known format");
  }
  if (c.width_px <= 0 || c.height_px <= 0 || (c.channels != 1 && c.channels != 3) || !(c.rate_hz > 0)) {
    return fail(error, "camera.width_px, height_px, channels, rate_hz: invalid image size or rate");
  }
  if (c.trigger != "free" && c.trigger != "software" && c.trigger != "hardware") {
    return fail(error, "camera.trigger '" + c.trigger + "': allowed free, software, hardware");
  }
  if (c.trigger == "hardware" && c.trigger_line.empty()) {
    return fail(error, "camera.trigger is hardware but camera.trigger_line is empty");
  }
  if (c.timestamp != "host" && c.timestamp != "device") {
    return fail(error, "camera.timestamp '" + c.timestamp + "': allowed host, device");
  }
  if (c.driver == "v4l2") {
    if (c.trigger != "free") return fail(error, "camera.trigger: V4L2 cameras free-run; set it to free");
    if (c.timestamp != "host") return fail(error, "camera.timestamp: V4L2 frames carry the kernel's time; set host");
    if (c.offset_x_px != 0 || c.offset_y_px != 0) {
      return fail(error, "camera.offset_x_px / offset_y_px: the V4L2 driver does not crop; set 0");
    }
  }
  const double period_ms = 1000.0 / c.rate_hz;
  if (!(c.pair_tolerance_ms > 0) || c.pair_tolerance_ms >= 0.5 * period_ms) {
    std::ostringstream o;
    o << "camera.pair_tolerance_ms is " << c.pair_tolerance_ms << " ms; it must be above 0 and below half the frame "
      << "period (" << 0.5 * period_ms << " ms at camera.rate_hz " << c.rate_hz << ")";
    return fail(error, o.str());
  }
  if (static_cast<double>(c.stale_after_us) <= period_ms * 1000.0) {
    return fail(error, "camera.stale_after_s must be longer than the frame period");
  }
  if (c.stream_buffers < 4) return fail(error, "camera.stream_buffers must be at least 4");
  if (format_out != nullptr) *format_out = format;
  return true;
}

std::unique_ptr<CameraSource> makeCameraSource(const CameraSourceConfig& config, std::string* error) {
  if (config.driver == "aravis") return std::make_unique<AravisStereoCamera>(config);
  if (config.driver == "v4l2") return std::make_unique<V4l2StereoCamera>(config);
  if (error) *error = "camera.driver is '" + config.driver + "': no live camera source";
  return nullptr;
}

}  // namespace deepnav
