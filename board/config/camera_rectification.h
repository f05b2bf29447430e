#pragma once
#include <string>

#include "board/config/board_config.h"
#include "vision/calib/stereo_rectification.h"

namespace deepnav {

// The rectification options the board asks for (camera.port.*): kNone unless camera.port.model is flat.
RectificationOptions rectificationOptions(const BoardConfig& config);

// Start-up: when the board names camera.calibration_file (relative to board_dir), reads it, checks its
// image size against camera.width_px/height_px and builds the rectification maps (PinAx for a flat
// port). *needed is false (and nothing is built) when the board names no calibration file: the frames
// then arrive rectified.
// The same from the calibration file's text (a recording's metadata); errors name `name`.
bool buildCameraRectificationFromText(const BoardConfig& config, const std::string& calibration_text,
                                      const std::string& name, StereoRectification* out, std::string* error);

bool buildCameraRectification(const BoardConfig& config, const std::string& board_dir, StereoRectification* out,
                              bool* needed, std::string* error);

}  // namespace deepnav
