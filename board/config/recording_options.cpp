#include "board/config/recording_options.h"

namespace deepnav {

RecordingOptions recordingOptions(const BoardConfig& c) {
  RecordingOptions ro = c.recording.options;
  // The encode buffer is sized for the cameras' images.
  ro.image_width_px = c.camera.width_px;
  ro.image_height_px = c.camera.height_px;
  ro.image_channels = c.camera.channels;
  return ro;
}

}  // namespace deepnav
