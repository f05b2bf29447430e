#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "drivers/camera/raw_image.h"
#include "nav/types/time.h"

namespace deepnav {

// One V4L2 video capture device with memory-mapped streaming (VIDIOC_REQBUFS / QBUF / DQBUF): the
// driver fills buffers mapped into this process once at open(); nothing is allocated afterwards.
class V4l2Capture {
 public:
  static constexpr int kMaxBuffers = 32;

  struct Frame {
    int index = -1;          // buffer to give back with requeue()
    RawImage image;
    TimeUs t_us = 0;         // the buffer's timestamp on the monotonic clock
    TimeUs dequeued_us = 0;  // monotonic time of the dequeue
    std::uint32_t sequence = 0;
    bool error = false;      // V4L2_BUF_FLAG_ERROR: the driver says the data may be corrupt
  };

  V4l2Capture() = default;
  ~V4l2Capture() { close(); }
  V4l2Capture(const V4l2Capture&) = delete;
  V4l2Capture& operator=(const V4l2Capture&) = delete;

  // Opens `path` (non-blocking), sets the format (exact width, height and pixel format, or an error
  // saying what the device offers instead), the frame interval, and maps `buffers` buffers.
  bool open(const std::string& path, int width_px, int height_px, PixelFormat format, double rate_hz,
            double exposure_us, int buffers, std::string* error);
  bool start(std::string* error);  // queues every buffer, STREAMON
  void close();                    // STREAMOFF, unmap, close
  bool isOpen() const { return fd_ >= 0; }
  int fd() const { return fd_; }

  // 1: *frame holds a filled buffer (give it back with requeue()); 0: none ready; -1: the device
  // failed (e.g. unplugged: errno ENODEV), *error says why.
  int dequeue(Frame* frame, std::string* error);
  bool requeue(int index);

 private:
  struct Mapped {
    void* data = nullptr;
    std::size_t length = 0;
  };
  int fd_ = -1;
  std::string path_;
  std::array<Mapped, kMaxBuffers> mapped_{};
  int buffer_count_ = 0;
  int width_px_ = 0;
  int height_px_ = 0;
  std::size_t stride_bytes_ = 0;
  PixelFormat format_ = PixelFormat::kMono8;
  bool streaming_ = false;
};

}  // namespace deepnav
