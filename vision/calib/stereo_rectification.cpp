#include "vision/calib/stereo_rectification.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace deepnav {
namespace {

bool finite(const cv::Mat& m) { return cv::checkRange(m, true, nullptr, -1e12, 1e12); }

bool checkCalibration(const StereoCalibration& c, std::string* error) {
  auto fail = [&](const std::string& what) {
    if (error) *error = "stereo calibration: " + what;
    return false;
  };
  if (c.image_size.width < 16 || c.image_size.height < 16) return fail("image size below 16 x 16 px");
  for (const CameraCalibration* cam : {&c.left, &c.right}) {
    const char* side = cam == &c.left ? "left" : "right";
    if (!finite(cv::Mat(cam->K)) || !(cam->K(0, 0) > 0.0) || !(cam->K(1, 1) > 0.0))
      return fail(std::string(side) + " camera matrix: focal lengths must be finite and positive");
    const int n = static_cast<int>(cam->dist.total());
    if (cam->dist.type() != CV_64F || !(n == 4 || n == 5 || n == 8 || n == 12 || n == 14) || !finite(cam->dist))
      return fail(std::string(side) + " distortion: 4, 5, 8, 12 or 14 finite doubles expected");
  }
  if (!finite(cv::Mat(c.R)) || !finite(cv::Mat(c.T)) || cv::norm(c.T) <= 0.0)
    return fail("R and T must be finite and the baseline non-zero");
  return true;
}

// Raw pixel of every rectified pixel of one camera through the PinAx virtual pinhole.
void pinaxMap(const CameraCalibration& cam, const PinaxConfig& pinax, double z_virtual, const cv::Matx33d& R_rect,
              const cv::Matx34d& P_rect, cv::Size size, cv::Mat* raw_px) {
  raw_px->create(size, CV_32FC2);
  const double f = P_rect(0, 0);
  const double cx = P_rect(0, 2);
  const double cy = P_rect(1, 2);
  const cv::Matx33d R_cam_rect = R_rect.t();
  std::vector<cv::Point3d> normalised(size.width);
  std::vector<unsigned char> seen(size.width);
  std::vector<cv::Point2d> pixels;
  for (int v = 0; v < size.height; ++v) {
    for (int u = 0; u < size.width; ++u) {
      const cv::Vec3d d = R_cam_rect * cv::Vec3d((u - cx) / f, (v - cy) / f, 1.0);
      Eigen::Vector2d xy(0.0, 0.0);
      seen[u] = pinaxVirtualToRealNormalised(pinax, z_virtual, Eigen::Vector3d(d[0], d[1], d[2]), &xy);
      normalised[u] = cv::Point3d(xy.x(), xy.y(), 1.0);
    }
    cv::projectPoints(normalised, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cam.K, cam.dist, pixels);
    auto* row = raw_px->ptr<cv::Vec2f>(v);
    for (int u = 0; u < size.width; ++u) {
      // Unseen rays map far outside the image, where remap writes the border value.
      row[u] = seen[u] ? cv::Vec2f(static_cast<float>(pixels[u].x), static_cast<float>(pixels[u].y))
                       : cv::Vec2f(-1000.0f, -1000.0f);
    }
  }
}

}  // namespace

bool computeStereoRectification(const StereoCalibration& calib, const RectificationOptions& options,
                                StereoRectification* out, std::string* error) {
  if (!checkCalibration(calib, error)) return false;
  const cv::Size size = calib.image_size;
  cv::Mat R1, R2, P1, P2, Q;
  out->image_size = size;
  if (options.correction == PortCorrection::kNone) {
    cv::stereoRectify(calib.left.K, calib.left.dist, calib.right.K, calib.right.dist, size, calib.R, calib.T, R1, R2,
                      P1, P2, Q, cv::CALIB_ZERO_DISPARITY, options.alpha, size);
    cv::initUndistortRectifyMap(calib.left.K, calib.left.dist, R1, P1, size, CV_32FC2, out->left_raw_px, cv::noArray());
    cv::initUndistortRectifyMap(calib.right.K, calib.right.dist, R2, P2, size, CV_32FC2, out->right_raw_px,
                                cv::noArray());
    out->virtual_centre_z_m = 0.0;
  } else {
    std::string port_error;
    if (!validatePinaxConfig(options.pinax, &port_error)) {
      if (error) *error = "flat port: " + port_error;
      return false;
    }
    const double widest = std::max(maxAirAngleRad(calib.left.K, calib.left.dist, size),
                                   maxAirAngleRad(calib.right.K, calib.right.dist, size));
    const double z_v = pinaxVirtualCentreZ(options.pinax.port, widest);
    if (!(options.pinax.reference_distance_m > options.pinax.port.pinhole_to_glass_m +
                                                   options.pinax.port.glass_thickness_m)) {
      if (error) *error = "flat port: reference_distance_m must lie beyond the glass";
      return false;
    }
    const double scale = pinaxFocalScale(options.pinax, z_v, widest);
    // Virtual pinholes: undistorted, focal scaled, each moved by z_v along its own axis, so the
    // virtual extrinsics are T_v = T + (R - I) e_z z_v (p_rv = R p_lv + T_v).
    cv::Matx33d Kv1 = calib.left.K, Kv2 = calib.right.K;
    for (cv::Matx33d* K : {&Kv1, &Kv2}) {
      (*K)(0, 0) *= scale;
      (*K)(1, 1) *= scale;
      (*K)(0, 1) *= scale;
    }
    const cv::Vec3d T_v = calib.T + (calib.R - cv::Matx33d::eye()) * cv::Vec3d(0.0, 0.0, z_v);
    cv::stereoRectify(Kv1, cv::noArray(), Kv2, cv::noArray(), size, calib.R, T_v, R1, R2, P1, P2, Q,
                      cv::CALIB_ZERO_DISPARITY, options.alpha, size);
    pinaxMap(calib.left, options.pinax, z_v, cv::Matx33d(R1), cv::Matx34d(P1), size, &out->left_raw_px);
    pinaxMap(calib.right, options.pinax, z_v, cv::Matx33d(R2), cv::Matx34d(P2), size, &out->right_raw_px);
    out->virtual_centre_z_m = z_v;
  }
  cv::convertMaps(out->left_raw_px, cv::noArray(), out->left_map_xy, out->left_map_frac, CV_16SC2);
  cv::convertMaps(out->right_raw_px, cv::noArray(), out->right_map_xy, out->right_map_frac, CV_16SC2);
  out->rectified.fx_px = P1.at<double>(0, 0);
  out->rectified.fy_px = P1.at<double>(1, 1);
  out->rectified.cx_px = P1.at<double>(0, 2);
  out->rectified.cy_px = P1.at<double>(1, 2);
  out->baseline_m = -P2.at<double>(0, 3) / P2.at<double>(0, 0);
  out->R_rect_left = cv::Matx33d(R1);
  out->R_rect_right = cv::Matx33d(R2);
  return true;
}

bool StereoRectifier::init(const StereoRectification& maps, std::string* error) {
  if (maps.left_map_xy.empty() || maps.right_map_xy.empty() || maps.left_map_xy.size() != maps.image_size) {
    if (error) *error = "stereo rectifier: maps missing or of the wrong size";
    return false;
  }
  maps_ = maps;
  return true;
}

namespace {

// Bilinear remap with the fixed-point maps of cv::convertMaps (CV_16SC2 integer source pixel, CV_16UC1
// fraction index fy * 32 + fx in 1/32 px), border pixels 0 as cv::BORDER_CONSTANT. It is cv::remap's
// INTER_LINEAR on these maps (within one grey level: 10-bit instead of 15-bit weights), written out
// because cv::remap allocates two scratch images per stripe on every call (OpenCV 4.6 RemapInvoker),
// and the vision worker allocates nothing per pair.
template <int kChannels>
void remapLinear(const cv::Mat& src, const cv::Mat& map_xy, const cv::Mat& map_frac, cv::Mat& dst) {
  const int w = src.cols, h = src.rows;
  for (int v = 0; v < dst.rows; ++v) {
    const cv::Vec2s* xy = map_xy.ptr<cv::Vec2s>(v);
    const std::uint16_t* frac = map_frac.ptr<std::uint16_t>(v);
    std::uint8_t* out = dst.ptr<std::uint8_t>(v);
    for (int u = 0; u < dst.cols; ++u, out += kChannels) {
      const int x = xy[u][0], y = xy[u][1];
      const int fx = frac[u] & 31, fy = (frac[u] >> 5) & 31;
      const int w00 = (32 - fx) * (32 - fy), w01 = fx * (32 - fy), w10 = (32 - fx) * fy, w11 = fx * fy;
      if (x >= 0 && y >= 0 && x + 1 < w && y + 1 < h) {
        const std::uint8_t* p0 = src.ptr<std::uint8_t>(y) + x * kChannels;
        const std::uint8_t* p1 = src.ptr<std::uint8_t>(y + 1) + x * kChannels;
        for (int c = 0; c < kChannels; ++c)
          out[c] = static_cast<std::uint8_t>(
              (p0[c] * w00 + p0[kChannels + c] * w01 + p1[c] * w10 + p1[kChannels + c] * w11 + 512) >> 10);
        continue;
      }
      // At the border each of the four samples is the source pixel or 0 outside the image.
      const auto sample = [&](int sx, int sy, int c) -> int {
        return sx >= 0 && sy >= 0 && sx < w && sy < h ? src.ptr<std::uint8_t>(sy)[sx * kChannels + c] : 0;
      };
      for (int c = 0; c < kChannels; ++c)
        out[c] = static_cast<std::uint8_t>((sample(x, y, c) * w00 + sample(x + 1, y, c) * w01 +
                                            sample(x, y + 1, c) * w10 + sample(x + 1, y + 1, c) * w11 + 512) >>
                                           10);
    }
  }
}

void remapImage(const cv::Mat& src, const cv::Mat& map_xy, const cv::Mat& map_frac, cv::Mat& dst) {
  if (src.channels() == 1) {
    remapLinear<1>(src, map_xy, map_frac, dst);
  } else {
    remapLinear<3>(src, map_xy, map_frac, dst);
  }
}

}  // namespace

bool StereoRectifier::rectify(const cv::Mat& raw_left, const cv::Mat& raw_right, cv::Mat& rect_left,
                              cv::Mat& rect_right) const {
  const cv::Size size = maps_.image_size;
  const bool type_ok = raw_left.type() == CV_8UC1 || raw_left.type() == CV_8UC3;
  if (!type_ok || raw_right.type() != raw_left.type() || raw_left.size() != size || raw_right.size() != size ||
      rect_left.size() != size || rect_right.size() != size || rect_left.type() != raw_left.type() ||
      rect_right.type() != raw_right.type())
    return false;
  remapImage(raw_left, maps_.left_map_xy, maps_.left_map_frac, rect_left);
  remapImage(raw_right, maps_.right_map_xy, maps_.right_map_frac, rect_right);
  return true;
}

}  // namespace deepnav
