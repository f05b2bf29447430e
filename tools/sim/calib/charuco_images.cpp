#include "tools/sim/calib/charuco_images.h"

#include <cmath>

#include <opencv2/aruco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace deepnav::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBackground = 70.0;  // grey level around the board
constexpr double kBlack = 25.0;
constexpr double kWhite = 215.0;

// Undistorted normalised coordinates of every pixel centre of a camera.
cv::Mat pixelRays(const CameraCalibration& cam, cv::Size size) {
  std::vector<cv::Point2d> pixels;
  pixels.reserve(size.area());
  for (int v = 0; v < size.height; ++v)
    for (int u = 0; u < size.width; ++u) pixels.emplace_back(u, v);
  std::vector<cv::Point2d> normalised;
  cv::undistortPoints(pixels, normalised, cam.K, cam.dist, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 50, 1e-12));
  return cv::Mat(normalised, true).reshape(2, size.height);
}

cv::Matx33d rotationRpy(double roll_deg, double pitch_deg, double yaw_deg) {
  cv::Mat R;
  cv::Rodrigues(cv::Vec3d(roll_deg, 0, 0) * (kPi / 180), R);
  cv::Mat P, Y;
  cv::Rodrigues(cv::Vec3d(0, pitch_deg, 0) * (kPi / 180), P);
  cv::Rodrigues(cv::Vec3d(0, 0, yaw_deg) * (kPi / 180), Y);
  return cv::Matx33d(cv::Mat(Y * P * R));
}

}  // namespace

bool CharucoImageRenderer::init(const CharucoTarget& target, const StereoCalibration& rig, std::string* error) {
  const auto board = makeCharucoBoard(target);
  if (!board) {
    validateCharucoTarget(target, error);
    return false;
  }
  rig_ = rig;
  texels_per_m_ = 2000.0;
  margin_texels_ = target.square_m * texels_per_m_;  // one square of white quiet zone
  const int width = static_cast<int>(std::lround(target.squares_x * target.square_m * texels_per_m_ + 2 * margin_texels_));
  const int height = static_cast<int>(std::lround(target.squares_y * target.square_m * texels_per_m_ + 2 * margin_texels_));
  cv::Mat texture(height, width, CV_8UC1, cv::Scalar(kWhite));
  auto toTexel = [&](double x_m, double y_m) {
    return cv::Point2f(static_cast<float>(x_m * texels_per_m_ + margin_texels_ - 0.5),
                       static_cast<float>(y_m * texels_per_m_ + margin_texels_ - 0.5));
  };
  // Chessboard: a square is black unless a marker sits in it.
  std::vector<cv::Point2f> marker_centres;
  for (const auto& corners : board->objPoints) {
    cv::Point2f c(0, 0);
    for (const auto& p : corners) c += cv::Point2f(p.x, p.y) * 0.25f;
    marker_centres.push_back(c);
  }
  for (int sy = 0; sy < target.squares_y; ++sy) {
    for (int sx = 0; sx < target.squares_x; ++sx) {
      const cv::Point2f centre((sx + 0.5f) * static_cast<float>(target.square_m),
                               (sy + 0.5f) * static_cast<float>(target.square_m));
      bool has_marker = false;
      for (const auto& m : marker_centres) has_marker |= cv::norm(m - centre) < 0.25 * target.square_m;
      if (has_marker) continue;
      const cv::Point2f a = toTexel(sx * target.square_m, sy * target.square_m);
      const cv::Point2f b = toTexel((sx + 1) * target.square_m, (sy + 1) * target.square_m);
      cv::rectangle(texture, cv::Rect(cv::Point(std::lround(a.x + 0.5f), std::lround(a.y + 0.5f)),
                                      cv::Point(std::lround(b.x + 0.5f), std::lround(b.y + 0.5f))),
                    cv::Scalar(kBlack), cv::FILLED);
    }
  }
  // Markers: the bit pattern warped onto the marker's object corners (corner 0 = the pattern's top-left).
  const int bits_px = 240;
  for (std::size_t m = 0; m < board->objPoints.size(); ++m) {
    cv::Mat pattern;
    cv::aruco::drawMarker(board->dictionary, board->ids[m], bits_px, pattern, 1);
    pattern.convertTo(pattern, CV_8U, (kWhite - kBlack) / 255.0, kBlack);
    const auto& obj = board->objPoints[m];
    const std::vector<cv::Point2f> from = {{-0.5f, -0.5f}, {bits_px - 0.5f, -0.5f}, {bits_px - 0.5f, bits_px - 0.5f},
                                           {-0.5f, bits_px - 0.5f}};
    std::vector<cv::Point2f> to;
    for (const auto& p : obj) to.push_back(toTexel(p.x, p.y));
    const cv::Mat H = cv::getPerspectiveTransform(from, to);
    cv::warpPerspective(pattern, texture, H, texture.size(), cv::INTER_AREA, cv::BORDER_TRANSPARENT);
  }
  texture.convertTo(texture_, CV_32F);
  // The texture is finer than the image (2-4 texels per pixel): pre-filter so bilinear sampling does
  // not alias.
  cv::GaussianBlur(texture_, texture_, cv::Size(0, 0), 1.2);
  left_rays_ = pixelRays(rig.left, rig.image_size);
  right_rays_ = pixelRays(rig.right, rig.image_size);
  return true;
}

void CharucoImageRenderer::renderView(const cv::Matx33d& R_cam_board, const cv::Vec3d& t_cam_board,
                                      const cv::Mat& rays, std::uint64_t seed, double blur_sigma_px,
                                      cv::Mat* out) const {
  // Board plane z = 0: normalised ray n ~ [r1 r2 t] (x, y, 1)^T, so (x, y, 1) ~ H^-1 n.
  const cv::Matx33d H(R_cam_board(0, 0), R_cam_board(0, 1), t_cam_board[0], R_cam_board(1, 0), R_cam_board(1, 1),
                      t_cam_board[1], R_cam_board(2, 0), R_cam_board(2, 1), t_cam_board[2]);
  const cv::Matx33d H_inv = H.inv();
  const cv::Size size = rig_.image_size;
  cv::Mat map(size, CV_32FC2);
  for (int v = 0; v < size.height; ++v) {
    const auto* ray = rays.ptr<cv::Vec2d>(v);
    auto* row = map.ptr<cv::Vec2f>(v);
    for (int u = 0; u < size.width; ++u) {
      const cv::Vec3d b = H_inv * cv::Vec3d(ray[u][0], ray[u][1], 1.0);
      // b[2] <= 0: the ray misses the board's front side.
      if (b[2] <= 0.0) {
        row[u] = cv::Vec2f(-1e4f, -1e4f);
        continue;
      }
      row[u] = cv::Vec2f(static_cast<float>(b[0] / b[2] * texels_per_m_ + margin_texels_ - 0.5),
                         static_cast<float>(b[1] / b[2] * texels_per_m_ + margin_texels_ - 0.5));
    }
  }
  cv::Mat image;
  cv::remap(texture_, image, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(kBackground));
  cv::GaussianBlur(image, image, cv::Size(0, 0), std::hypot(0.6, blur_sigma_px));
  cv::Mat noise(size, CV_32F);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 2.0);
  image += noise;
  image.convertTo(*out, CV_8U);
}

void CharucoImageRenderer::renderPair(const BoardPose& pose, std::uint64_t seed, double blur_sigma_px, cv::Mat* left,
                                      cv::Mat* right) const {
  renderView(pose.R_left_board, pose.p_board_in_left_m, left_rays_, seed * 2 + 1, blur_sigma_px, left);
  const cv::Matx33d R_right_board = rig_.R * pose.R_left_board;
  const cv::Vec3d t_right = rig_.R * pose.p_board_in_left_m + rig_.T;
  renderView(R_right_board, t_right, right_rays_, seed * 2 + 2, blur_sigma_px, right);
}

StereoCalibration simulatedCalibrationRig() {
  StereoCalibration c;
  c.image_size = cv::Size(688, 516);
  c.left.K = cv::Matx33d(702.0, 0.0, 340.3, 0.0, 703.5, 261.2, 0.0, 0.0, 1.0);
  c.left.dist = (cv::Mat_<double>(1, 5) << -0.12, 0.09, 0.0006, -0.0004, 0.0);
  c.right.K = cv::Matx33d(698.5, 0.0, 347.1, 0.0, 699.0, 254.6, 0.0, 0.0, 1.0);
  c.right.dist = (cv::Mat_<double>(1, 5) << -0.11, 0.08, -0.0003, 0.0005, 0.0);
  cv::Mat R;
  cv::Rodrigues(cv::Vec3d(0.003, -0.015, 0.002), R);  // ~0.9 deg toe-in
  c.R = cv::Matx33d(R);
  c.T = cv::Vec3d(-0.300, 0.0015, 0.002);
  return c;
}

std::vector<BoardPose> calibrationPoses() {
  // Board 0.48 x 0.36 m; its origin is a corner, so centre it: p = centre - R (0.24, 0.18, 0).
  struct Spec {
    double x, y, z, roll, pitch, yaw;
  };
  const Spec specs[] = {
      {0.15, 0.0, 1.0, 0, 0, 0},       {0.15, 0.0, 1.3, 25, 0, 0},     {0.15, 0.0, 1.3, -25, 0, 0},
      {0.15, 0.0, 1.2, 0, 30, 0},      {0.15, 0.0, 1.2, 0, -30, 0},    {-0.05, -0.15, 1.1, 15, 20, 10},
      {0.35, -0.15, 1.1, 15, -20, -10}, {-0.05, 0.15, 1.1, -15, 20, -5}, {0.35, 0.15, 1.1, -20, -20, 8},
      {0.15, 0.0, 0.85, 10, 10, 45},   {0.15, 0.05, 1.6, -10, 15, -30}, {0.0, 0.1, 1.4, 35, 5, 0},
      {0.3, -0.1, 1.4, -5, 35, 15},    {0.15, -0.2, 1.25, 20, -25, 90},
  };
  std::vector<BoardPose> poses;
  for (const Spec& s : specs) {
    BoardPose p;
    p.R_left_board = rotationRpy(s.roll, s.pitch, s.yaw);
    p.p_board_in_left_m = cv::Vec3d(s.x, s.y, s.z) - p.R_left_board * cv::Vec3d(0.24, 0.18, 0.0);
    poses.push_back(p);
  }
  return poses;
}

std::vector<CalibrationPairInput> makeCalibrationPairs(const CharucoImageRenderer& renderer, std::uint64_t seed) {
  std::vector<CalibrationPairInput> pairs;
  const std::vector<BoardPose> poses = calibrationPoses();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    CalibrationPairInput in;
    in.name = "pose_" + std::to_string(i);
    renderer.renderPair(poses[i], seed + i, 0.0, &in.left, &in.right);
    pairs.push_back(in);
  }
  CalibrationPairInput blurred;
  blurred.name = "blurred";
  BoardPose close = poses[9];  // close up: the markers stay readable through the defocus
  close.p_board_in_left_m += cv::Vec3d(0.02, 0.01, -0.1);
  renderer.renderPair(close, seed + 100, 1.5, &blurred.left, &blurred.right);
  pairs.push_back(blurred);
  CalibrationPairInput duplicate;
  duplicate.name = "duplicate";
  BoardPose again = poses[0];
  again.p_board_in_left_m += cv::Vec3d(0.001, 0.0, 0.0);  // 1 mm: the same view, fresh noise
  renderer.renderPair(again, seed + 101, 0.0, &duplicate.left, &duplicate.right);
  pairs.push_back(duplicate);
  CalibrationPairInput few;
  few.name = "few_corners";
  BoardPose off = poses[0];
  off.p_board_in_left_m += cv::Vec3d(0.62, 0.0, 0.0);  // slid right: the left camera sees one column
  renderer.renderPair(off, seed + 102, 0.0, &few.left, &few.right);
  pairs.push_back(few);
  return pairs;
}

}  // namespace deepnav::sim
