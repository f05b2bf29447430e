#include "board/config/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "base/fail.h"

namespace deepnav {
namespace {

std::string sizeText(std::size_t bytes) {
  if (bytes % (1024u * 1024u) == 0) return std::to_string(bytes / (1024u * 1024u)) + " MiB";
  if (bytes % 1024u == 0) return std::to_string(bytes / 1024u) + " KiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

bool readTextFile(const std::string& path, const std::string& what, std::string* text, std::string* error,
                  std::size_t max_bytes) {
  // open(2) of a directory for reading succeeds and read(2) then fails with EISDIR: an std::ifstream
  // returned it as an empty file, i.e. an empty (all defaults) board.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return fail(error, path + ": cannot open " + what);
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
    ::close(fd);
    return fail(error, path + ": is a directory, not " + what);
  }
  std::string out;
  // A regular file's size is known; a pipe or device is read in chunks until its end or the limit.
  out.reserve(S_ISREG(st.st_mode) ? std::min<std::size_t>(static_cast<std::size_t>(st.st_size), max_bytes) + 1 : 4096);
  char buffer[65536];
  while (true) {
    const std::size_t want = std::min(sizeof buffer, max_bytes + 1 - out.size());
    const ssize_t n = ::read(fd, buffer, want);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int e = errno;
      ::close(fd);
      return fail(error, path + ": cannot read " + what + ": " + std::strerror(e));
    }
    if (n == 0) break;
    out.append(buffer, static_cast<std::size_t>(n));
    if (out.size() > max_bytes) {
      ::close(fd);
      return fail(error, path + ": " + what + " is larger than " + sizeText(max_bytes) +
                             ", the limit for a text input (a wrong file, a device or an endless stream?)");
    }
  }
  ::close(fd);
  *text = std::move(out);
  return true;
}

}  // namespace deepnav
