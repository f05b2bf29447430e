#include "drivers/camera/v4l2_capture.h"

#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "drivers/clock/monotonic_clock.h"

namespace deepnav {
namespace {

std::uint32_t fourcc(PixelFormat f) {
  switch (f) {
    case PixelFormat::kMono8: return V4L2_PIX_FMT_GREY;
    case PixelFormat::kBayerRG8: return V4L2_PIX_FMT_SRGGB8;
    case PixelFormat::kBayerGR8: return V4L2_PIX_FMT_SGRBG8;
    case PixelFormat::kBayerGB8: return V4L2_PIX_FMT_SGBRG8;
    case PixelFormat::kBayerBG8: return V4L2_PIX_FMT_SBGGR8;
    case PixelFormat::kRgb8: return V4L2_PIX_FMT_RGB24;
    case PixelFormat::kBgr8: return V4L2_PIX_FMT_BGR24;
    case PixelFormat::kYuyv: return V4L2_PIX_FMT_YUYV;
  }
  return V4L2_PIX_FMT_GREY;
}

std::string fourccText(std::uint32_t f) {
  std::string s(4, ' ');
  for (int i = 0; i < 4; ++i) s[static_cast<std::size_t>(i)] = static_cast<char>((f >> (8 * i)) & 0xff);
  return s;
}

// ioctl, retried when a signal interrupts it.
int xioctl(int fd, unsigned long request, void* arg) {
  int r;
  do {
    r = ioctl(fd, request, arg);
  } while (r == -1 && errno == EINTR);
  return r;
}

bool fail(const std::string& what, std::string* error) {
  if (error) *error = what + ": " + std::strerror(errno);
  return false;
}

bool setControl(int fd, std::uint32_t id, std::int32_t value) {
  v4l2_control c{};
  c.id = id;
  c.value = value;
  return xioctl(fd, VIDIOC_S_CTRL, &c) == 0;
}

}  // namespace

bool V4l2Capture::open(const std::string& path, int width_px, int height_px, PixelFormat format, double rate_hz,
                       double exposure_us, int buffers, std::string* error) {
  close();
  path_ = path;
  fd_ = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) return fail(path + ": cannot open", error);

  v4l2_capability cap{};
  if (xioctl(fd_, VIDIOC_QUERYCAP, &cap) != 0) return close(), fail(path + ": not a V4L2 device", error);
  const std::uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
  if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
    if (error) *error = path + ": not a video capture device with streaming I/O";
    close();
    return false;
  }

  v4l2_format fmt{};
  fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  fmt.fmt.pix.width = static_cast<std::uint32_t>(width_px);
  fmt.fmt.pix.height = static_cast<std::uint32_t>(height_px);
  fmt.fmt.pix.pixelformat = fourcc(format);
  fmt.fmt.pix.field = V4L2_FIELD_NONE;
  if (xioctl(fd_, VIDIOC_S_FMT, &fmt) != 0) return close(), fail(path + ": VIDIOC_S_FMT", error);
  if (fmt.fmt.pix.width != static_cast<std::uint32_t>(width_px) ||
      fmt.fmt.pix.height != static_cast<std::uint32_t>(height_px) || fmt.fmt.pix.pixelformat != fourcc(format)) {
    if (error) {
      *error = path + ": asked for " + std::to_string(width_px) + "x" + std::to_string(height_px) + " " +
               pixelFormatName(format) + ", the device offers " + std::to_string(fmt.fmt.pix.width) + "x" +
               std::to_string(fmt.fmt.pix.height) + " " + fourccText(fmt.fmt.pix.pixelformat) +
               " (camera.width_px, height_px, pixel_format)";
    }
    close();
    return false;
  }
  width_px_ = width_px;
  height_px_ = height_px;
  format_ = format;
  stride_bytes_ = fmt.fmt.pix.bytesperline;

  v4l2_streamparm parm{};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(fd_, VIDIOC_G_PARM, &parm) == 0 && (parm.parm.capture.capability & V4L2_CAP_TIMEPERFRAME)) {
    // The device picks the nearest interval it supports; pairing copes with whatever it chose.
    parm.parm.capture.timeperframe.numerator = 1000;
    parm.parm.capture.timeperframe.denominator = static_cast<std::uint32_t>(std::lround(rate_hz * 1000.0));
    xioctl(fd_, VIDIOC_S_PARM, &parm);
  }
  if (exposure_us > 0) {
    // V4L2_CID_EXPOSURE_ABSOLUTE counts 100 us units.
    if (!setControl(fd_, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL) ||
        !setControl(fd_, V4L2_CID_EXPOSURE_ABSOLUTE, static_cast<std::int32_t>(std::lround(exposure_us / 100.0)))) {
      return close(), fail(path + ": manual exposure (camera.exposure_us)", error);
    }
  } else {
    setControl(fd_, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_AUTO);  // devices without it keep their own
  }

  v4l2_requestbuffers req{};
  req.count = static_cast<std::uint32_t>(buffers);
  req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  req.memory = V4L2_MEMORY_MMAP;
  if (xioctl(fd_, VIDIOC_REQBUFS, &req) != 0) return close(), fail(path + ": VIDIOC_REQBUFS", error);
  if (req.count < 2 || req.count > static_cast<std::uint32_t>(kMaxBuffers)) {
    if (error) *error = path + ": the device granted " + std::to_string(req.count) + " buffers";
    close();
    return false;
  }
  buffer_count_ = static_cast<int>(req.count);
  for (int i = 0; i < buffer_count_; ++i) {
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = static_cast<std::uint32_t>(i);
    if (xioctl(fd_, VIDIOC_QUERYBUF, &b) != 0) return close(), fail(path + ": VIDIOC_QUERYBUF", error);
    void* p = mmap(nullptr, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, b.m.offset);
    if (p == MAP_FAILED) return close(), fail(path + ": mmap", error);
    mapped_[static_cast<std::size_t>(i)] = {p, b.length};
  }
  return true;
}

bool V4l2Capture::start(std::string* error) {
  for (int i = 0; i < buffer_count_; ++i) {
    if (!requeue(i)) return fail(path_ + ": VIDIOC_QBUF", error);
  }
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(fd_, VIDIOC_STREAMON, &type) != 0) return fail(path_ + ": VIDIOC_STREAMON", error);
  streaming_ = true;
  return true;
}

void V4l2Capture::close() {
  if (fd_ >= 0 && streaming_) {
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    xioctl(fd_, VIDIOC_STREAMOFF, &type);
  }
  streaming_ = false;
  for (int i = 0; i < buffer_count_; ++i) {
    Mapped& m = mapped_[static_cast<std::size_t>(i)];
    if (m.data != nullptr) munmap(m.data, m.length);
    m = {};
  }
  buffer_count_ = 0;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

int V4l2Capture::dequeue(Frame* frame, std::string* error) {
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  if (xioctl(fd_, VIDIOC_DQBUF, &b) != 0) {
    if (errno == EAGAIN) return 0;
    fail(path_ + ": VIDIOC_DQBUF", error);
    return -1;
  }
  if (b.index >= static_cast<std::uint32_t>(buffer_count_)) {
    if (error) *error = path_ + ": buffer index out of range";
    return -1;
  }
  const Mapped& m = mapped_[b.index];
  frame->index = static_cast<int>(b.index);
  frame->image.data = static_cast<const std::uint8_t*>(m.data);
  frame->image.size_bytes = std::min<std::size_t>(b.bytesused, m.length);
  frame->image.width_px = width_px_;
  frame->image.height_px = height_px_;
  frame->image.stride_bytes = stride_bytes_;
  frame->image.format = format_;
  frame->sequence = b.sequence;
  frame->error = (b.flags & V4L2_BUF_FLAG_ERROR) != 0;
  frame->dequeued_us = monotonicUs();
  if ((b.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC) {
    frame->t_us = static_cast<TimeUs>(b.timestamp.tv_sec) * kUsPerS + static_cast<TimeUs>(b.timestamp.tv_usec);
  } else {
    frame->t_us = frame->dequeued_us;  // a driver without monotonic stamps: the dequeue time is the best left
  }
  return 1;
}

bool V4l2Capture::requeue(int index) {
  if (index < 0 || index >= buffer_count_) return false;
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  b.index = static_cast<std::uint32_t>(index);
  return xioctl(fd_, VIDIOC_QBUF, &b) == 0;
}

}  // namespace deepnav
