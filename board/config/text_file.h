#pragma once
#include <cstddef>
#include <string>

namespace deepnav {

// Largest text input read at start-up (board, panel, calibration, calibration target, simulator scenario).
// The largest real one, a board with every key commented, is about 20 KiB; 4 MiB leaves two orders of
// magnitude for generated files and still refuses /dev/zero, a mistyped image or an endless pipe after
// reading 4 MiB instead of gigabytes.
constexpr std::size_t kMaxTextFileBytes = 4u * 1024u * 1024u;

// Reads a whole (small) text file: board, panel or scenario files at start-up. A FIFO or character device
// (`--board <(...)`, /dev/stdin) is read like a file, up to the same limit. False, with one message naming
// the file and <what>, when it cannot be opened, is a directory, cannot be read, or holds more than
// max_bytes.
bool readTextFile(const std::string& path, const std::string& what, std::string* text, std::string* error,
                  std::size_t max_bytes = kMaxTextFileBytes);

}  // namespace deepnav
