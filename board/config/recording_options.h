#pragma once
#include "board/config/board_config.h"
#include "drivers/recording/recording_writer.h"

namespace deepnav {

// The recorder's options as the board sets them: recording.* as held, the image size from camera.*.
RecordingOptions recordingOptions(const BoardConfig& config);

}  // namespace deepnav
