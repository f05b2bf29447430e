#include "vision/types/stereo_frame.h"

namespace deepnav {

bool allocateStereoFrame(StereoFrame& frame, int width_px, int height_px, int channels) {
  if (width_px <= 0 || height_px <= 0 || (channels != 1 && channels != 3)) return false;
  const int type = channels == 1 ? CV_8UC1 : CV_8UC3;
  frame.left.create(height_px, width_px, type);
  frame.right.create(height_px, width_px, type);
  frame.left.setTo(0);
  frame.right.setTo(0);
  return true;
}

}  // namespace deepnav
