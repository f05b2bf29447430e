#pragma once
#include <memory>
#include <string>

#include "drivers/buffers/frame_pool.h"
#include "drivers/buffers/spsc_ring.h"
#include "drivers/camera/camera_config.h"
#include "drivers/camera/camera_status.h"
#include "drivers/camera/raw_image.h"

namespace deepnav {

// A stereo camera as the rest of deepnav sees it, whatever the hardware (GigE Vision through Aravis,
// V4L2): open() at start-up finds and configures both cameras (one clear error naming the camera and
// the setting otherwise); start() runs the driver thread, which fills slots of the frame pool with
// synchronised pairs and pushes their indices into `frames`; status() is safe from any thread.
class CameraSource {
 public:
  virtual ~CameraSource() = default;

  virtual bool open(std::string* error) = 0;
  // The pool's frames must have the configured size and channel count (checked; false otherwise).
  virtual bool start(FramePool* pool, SpscRing<int>* frames, std::string* error) = 0;
  virtual void stop() = 0;
  virtual CameraStatus status() const = 0;
};

// The driver named by config.driver ("aravis" or "v4l2"); nullptr with *error set for "none" or an
// unknown name.
std::unique_ptr<CameraSource> makeCameraSource(const CameraSourceConfig& config, std::string* error);

// The check of every driver's start(): a pool whose frames have the configured size and channel count,
// a ring, and both cameras opened (cameras_open: the driver's own open() succeeded).
bool checkStart(const CameraSourceConfig& config, const FramePool* pool, const SpscRing<int>* frames,
                bool cameras_open, std::string* error);

// Checks what every driver needs from the config (formats, tolerance against the frame period...).
// When the config is valid and format is given, *format receives the parsed camera.pixel_format.
bool validateCameraSourceConfig(const CameraSourceConfig& config, std::string* error, PixelFormat* format = nullptr);

}  // namespace deepnav
