#include "board/config/recording_options.h"

namespace deepnav {

RecordingOptions recordingOptions(const BoardConfig& c) {
  RecordingOptions ro;
  ro.compression = c.recording.compression;
  ro.chunk_max_duration_s = c.recording.chunk_max_duration_s;
  ro.chunk_size_kib = c.recording.chunk_size_kib;
  ro.image_width_px = c.camera.width_px;
  ro.image_height_px = c.camera.height_px;
  ro.image_channels = c.camera.channels;
  ro.record_images = c.recording.record_images;
  return ro;
}

}  // namespace deepnav
