#pragma once
#include <string>

#include <opencv2/core.hpp>

namespace deepnav {

// Portable Float Map (PFM, greyscale "Pf"): header "Pf\n<width> <height>\n-1.0\n" (negative scale =
// little-endian), then float32 rows from the BOTTOM row up, as the format defines. Invalid disparities
// are written as +infinity, the convention of the Middlebury 2014 evaluation tools.
bool writePfm(const std::string& path, const cv::Mat& disparity_px, std::string* error);
// Reads a greyscale PFM (either endianness) into CV_32FC1, top row first.
bool readPfm(const std::string& path, cv::Mat* image, std::string* error);

}  // namespace deepnav
