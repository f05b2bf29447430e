#include "tests/support/synthetic_plane_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <utility>

namespace deepnav {

cv::Mat makeSyntheticTexture(int width_px, int height_px, std::uint64_t seed, double contrast) {
  cv::RNG rng(seed);
  cv::Mat sum(height_px, width_px, CV_32F, cv::Scalar(0.0));
  cv::Mat noise;
  constexpr std::array<double, 4> kSigmaPx = {1.0, 2.5, 6.0, 15.0};
  constexpr std::array<double, 4> kWeight = {0.6, 1.0, 1.5, 2.0};
  for (std::size_t k = 0; k < kSigmaPx.size(); ++k) {
    // Coarse scales are drawn at a quarter of the resolution and enlarged: same look, 10x cheaper.
    const int shrink = kSigmaPx[k] >= 4.0 ? 4 : 1;
    cv::Mat small((height_px + shrink - 1) / shrink, (width_px + shrink - 1) / shrink, CV_32F);
    rng.fill(small, cv::RNG::NORMAL, 0.0, 1.0);
    cv::GaussianBlur(small, small, cv::Size(0, 0), kSigmaPx[k] / shrink);
    if (shrink == 1) {
      noise = small;
    } else {
      cv::resize(small, noise, cv::Size(width_px, height_px), 0.0, 0.0, cv::INTER_LINEAR);
    }
    cv::Scalar mean, stddev;
    cv::meanStdDev(noise, mean, stddev);
    sum += noise * (kWeight[k] / stddev[0]);
  }
  cv::Scalar mean, stddev;
  cv::meanStdDev(sum, mean, stddev);
  sum = (sum - mean[0]) * (1.0 / stddev[0]);
  const int shapes = width_px * height_px / 6000;
  for (int i = 0; i < shapes; ++i) {
    const cv::Point centre(rng.uniform(0, width_px), rng.uniform(0, height_px));
    const int size = rng.uniform(4, 28);
    const double level = rng.uniform(-2.0, 2.0);
    if (rng.uniform(0, 2) == 0) {
      cv::circle(sum, centre, size, cv::Scalar(level), cv::FILLED, cv::LINE_AA);
    } else {
      cv::rectangle(sum, cv::Rect(centre.x, centre.y, size, rng.uniform(4, 28)), cv::Scalar(level),
                    cv::FILLED);
    }
  }
  cv::Mat texture;
  sum.convertTo(texture, CV_8U, 45.0 * contrast, 128.0);
  return texture;
}

void SyntheticPlaneScene::render(const StereoRig& rig, const Eigen::Quaterniond& q_world_cam,
                                 const Eigen::Vector3d& p_cam_in_world_m, std::uint8_t background,
                                 cv::Mat* left, cv::Mat* right) const {
  const Eigen::Matrix3d R_cam_world = q_world_cam.toRotationMatrix().transpose();
  const Eigen::Vector3d p_world_in_cam_m = -R_cam_world * p_cam_in_world_m;
  renderView(rig, R_cam_world, p_world_in_cam_m, background, left);
  // The right camera sits at +baseline along x of the left one.
  renderView(rig, R_cam_world, p_world_in_cam_m - Eigen::Vector3d(rig.baseline_m, 0.0, 0.0),
             background, right);
}

void SyntheticPlaneScene::renderView(const StereoRig& rig, const Eigen::Matrix3d& R_cam_world,
                                     const Eigen::Vector3d& p_world_in_cam_m,
                                     std::uint8_t background, cv::Mat* image) const {
  image->create(rig.height_px, rig.width_px, CV_8UC1);
  image->setTo(cv::Scalar(background));
  // Painter's algorithm: the plane whose centre is farthest is drawn first.
  std::vector<std::pair<double, int>> order;
  for (int i = 0; i < planeCount(); ++i) {
    const TexturedPlane& p = planes_[i];
    const Eigen::Vector3d centre =
        p.p_origin_in_world_m +
        0.5 * p.texel_m * (p.texture.cols * p.axis_s_in_world + p.texture.rows * p.axis_t_in_world);
    order.emplace_back(-(R_cam_world * centre + p_world_in_cam_m).norm(), i);
  }
  std::sort(order.begin(), order.end());
  Eigen::Matrix3d K;
  K << rig.fx_px, 0.0, rig.cx_px, 0.0, rig.fy_px, rig.cy_px, 0.0, 0.0, 1.0;
  for (const auto& [distance, i] : order) {
    const TexturedPlane& p = planes_[i];
    Eigen::Matrix3d A;
    A.col(0) = R_cam_world * p.axis_s_in_world * p.texel_m;
    A.col(1) = R_cam_world * p.axis_t_in_world * p.texel_m;
    A.col(2) = R_cam_world * p.p_origin_in_world_m + p_world_in_cam_m;
    const Eigen::Matrix3d H = K * A;
    // Warp only the bounding box of the plane's image (planes are in front of the camera).
    double u0 = image->cols, v0 = image->rows, u1 = 0.0, v1 = 0.0;
    for (const auto& [s, t] : {std::pair{0, 0},
                               {p.texture.cols, 0},
                               {0, p.texture.rows},
                               {p.texture.cols, p.texture.rows}}) {
      const Eigen::Vector3d x = H * Eigen::Vector3d(s, t, 1.0);
      u0 = std::min(u0, x.x() / x.z());
      u1 = std::max(u1, x.x() / x.z());
      v0 = std::min(v0, x.y() / x.z());
      v1 = std::max(v1, x.y() / x.z());
    }
    const cv::Rect box =
        cv::Rect(
            cv::Point(static_cast<int>(std::floor(u0)) - 2, static_cast<int>(std::floor(v0)) - 2),
            cv::Point(static_cast<int>(std::ceil(u1)) + 3, static_cast<int>(std::ceil(v1)) + 3)) &
        cv::Rect(0, 0, image->cols, image->rows);
    if (box.empty()) continue;
    Eigen::Matrix3d shift = Eigen::Matrix3d::Identity();
    shift(0, 2) = -box.x;
    shift(1, 2) = -box.y;
    const Eigen::Matrix3d H_box = shift * H;
    cv::Matx33d h;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) h(r, c) = H_box(r, c);
    }
    cv::Mat target = (*image)(box);
    cv::warpPerspective(p.texture, target, h, box.size(), cv::INTER_LINEAR, cv::BORDER_TRANSPARENT);
  }
}

SyntheticPlaneScene makeOrbVoTestScene(std::uint64_t seed, double contrast) {
  SyntheticPlaneScene scene;
  TexturedPlane wall;
  wall.texel_m = 0.0045;
  wall.texture = makeSyntheticTexture(1100, 900, seed + 1, contrast);
  wall.p_origin_in_world_m = {-2.5, -2.0, 3.0};
  scene.addPlane(wall);

  TexturedPlane floor;
  floor.texel_m = 0.003;
  floor.texture = makeSyntheticTexture(1000, 640, seed + 2, contrast);
  floor.axis_s_in_world = Eigen::Vector3d::UnitX();
  // Rows run away from the camera
  floor.axis_t_in_world = Eigen::Vector3d(0.0, -0.15, 1.0).normalized();
  floor.p_origin_in_world_m = {-1.5, 0.5, 1.0};
  scene.addPlane(floor);

  TexturedPlane panel;
  panel.texel_m = 0.0015;
  panel.texture = makeSyntheticTexture(600, 467, seed + 3, contrast);
  const Eigen::Vector3d centre(-0.4, -0.2, 1.5);
  panel.axis_s_in_world = Eigen::AngleAxisd(std::numbers::pi / 6.0, Eigen::Vector3d::UnitY()) *
                          Eigen::Vector3d::UnitX();
  panel.axis_t_in_world = Eigen::Vector3d::UnitY();
  panel.p_origin_in_world_m = centre - 0.45 * panel.axis_s_in_world - 0.35 * panel.axis_t_in_world;
  scene.addPlane(panel);

  TexturedPlane box;
  box.texel_m = 0.0012;
  box.texture = makeSyntheticTexture(417, 417, seed + 4, contrast);
  box.p_origin_in_world_m = {0.3, -0.1, 1.1};
  scene.addPlane(box);
  return scene;
}

cv::Mat renderOrbVoTestImage(std::uint64_t scene_seed, double contrast, std::uint64_t noise_seed) {
  const SyntheticPlaneScene scene = makeOrbVoTestScene(scene_seed, contrast);
  cv::Mat left, right;
  scene.render(StereoRig{}, Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), 90, &left, &right);
  cv::Mat noise(left.size(), CV_16SC1), sum;
  cv::RNG(noise_seed).fill(noise, cv::RNG::NORMAL, 0.0, 1.5);
  left.convertTo(sum, CV_16SC1);
  sum += noise;
  sum.convertTo(left, CV_8UC1);
  return left;
}

}  // namespace deepnav
