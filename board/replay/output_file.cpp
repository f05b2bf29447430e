#include "board/replay/output_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace deepnav {

std::string writeFailure(const std::string& path, int errno_value) {
  return path + ": cannot write: " + (errno_value != 0 ? std::strerror(errno_value) : "write error");
}

bool prepareOutputDir(const std::string& dir, std::string* error) {
  if (dir.empty()) {
    if (error) *error = "--out: the output directory is empty; give a directory (e.g. --out out/replay)";
    return false;
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!ec && std::filesystem::is_directory(dir, ec)) return true;
  if (error) *error = dir + ": cannot create the output directory" + (ec ? ": " + ec.message() : ": not a directory");
  return false;
}

bool openOutput(std::ofstream* out, const std::string& path, std::string* error) {
  errno = 0;
  out->open(path);
  if (*out) return true;
  if (error) *error = writeFailure(path, errno);
  return false;
}

// A stream keeps no errno: the one its failed write or close left is read right after (nothing between
// that sets errno on success), which is the disk's reason (ENOSPC, EIO, EDQUOT).
bool closeOutput(std::ofstream* out, const std::string& path, std::string* error) {
  const bool written = static_cast<bool>(out->flush());
  const int write_errno = errno;
  errno = 0;
  out->close();
  if (written && !out->fail()) return true;
  if (error) *error = writeFailure(path, written ? errno : write_errno);
  return false;
}

}  // namespace deepnav
