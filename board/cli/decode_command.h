#pragma once
#include <string>

namespace deepnav {

// `deepnav decode FORMAT FILE`: decodes a sensor capture and prints one JSON object per decoded message
// (SI units) on stdout; bad frames go to stderr with their byte offset and are skipped. FORMAT is one of
// pd0, pd6, wl-a50, nmea0183, n2k-candump, xsens. Returns the exit code (0, or 1 when the file cannot be
// read, 2 for an unknown format).
int runDecodeCommand(const std::string& format, const std::string& path);

// The formats, for the CLI's help and checks.
const char* const* decodeFormats();

}  // namespace deepnav
