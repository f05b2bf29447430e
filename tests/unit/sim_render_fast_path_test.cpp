// The renderer's speed-ups change nothing visible: its tile culling (bounding spheres and the tiles'
// side planes), per-pixel tables, packets of four pixels and 4-lane shading against a brute-force evaluation of the documented image-formation model (every primitive
// tested per ray, std::exp), and its second thread against the single-threaded render, bit for bit.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"

namespace deepnav::sim {
namespace {

// Radiance per the README's equations at one pixel, without any of the renderer's shortcuts.
Eigen::Vector3f bruteForceRadiance(const Scene& scene, const WaterOptics& optics, const CameraConfig& cam,
                                   const ViewPose& pose, const LampSet& lamps, int u, int v, float* depth_m) {
  const float xn = static_cast<float>((u - cam.cx_px) / cam.fx_px), yn = static_cast<float>((v - cam.cy_px) / cam.fy_px);
  const Eigen::Vector3f d = pose.R_panel_cam * Eigen::Vector3f(xn, yn, 1.0f);
  const float length = d.norm();
  const Eigen::Vector3f b_inf(optics.backscatter[0], optics.backscatter[1], optics.backscatter[2]);
  const float cos4 = std::pow(1.0f / length, 4.0f);
  SceneHit hit;
  if (!scene.intersect(pose.p_cam_in_panel_m, d, 1e-3f, ViewRenderer::kMaxRange_m / length, &hit)) {
    *depth_m = 0.0f;
    return b_inf * cos4;
  }
  *depth_m = hit.t;
  const auto T = [&](float x) {
    return Eigen::Vector3f(std::exp(-optics.attenuation_per_m[0] * x), std::exp(-optics.attenuation_per_m[1] * x),
                           std::exp(-optics.attenuation_per_m[2] * x));
  };
  const float distance = hit.t * length;
  const Eigen::Vector3f p = pose.p_cam_in_panel_m + hit.t * d;
  const Eigen::Vector3f n = scene.normalAt(hit);
  const float fronto = hit.t / static_cast<float>(cam.fx_px);
  const float cos_view = std::max(std::abs(n.dot(d)) / length, 0.1f);
  const Eigen::Vector3f albedo = scene.albedoAt(hit, pose.p_cam_in_panel_m, d, fronto * fronto / cos_view).head<3>();
  Eigen::Vector3f E = Eigen::Vector3f::Zero();
  for (const Eigen::Vector3f& lamp : lamps.p_lamp_in_panel_m) {
    const Eigen::Vector3f l = lamp - p;
    const float dl = l.norm();
    const float cos_surface = n.dot(l) / dl, cos_beam = -lamps.axis_in_panel.dot(l) / dl;
    if (cos_surface > 0.0f && cos_beam > 0.0f)
      E += optics.lamp_intensity * cos_surface * cos_beam / (dl * dl) * T(dl + distance);
  }
  return (albedo.cwiseProduct(E) + b_inf.cwiseProduct(Eigen::Vector3f::Ones() - T(distance))) * cos4;
}

void expectFastPathMatchesBruteForce(const Scenario& s, const CameraTick& tick) {
  StereoRenderer renderer;
  std::string error;
  ASSERT_TRUE(renderer.init(s, 3, 3, &error)) << error;
  // render() moves the fish to the tick's time; the views below then see the same scene.
  StereoFrame frame;
  allocateStereoFrame(frame, s.camera.width_px, s.camera.height_px, 3);
  ASSERT_TRUE(renderer.render(tick, &frame, nullptr));
  const Scene& scene = renderer.scene();
  ViewRenderer view;
  ASSERT_TRUE(view.init(s.camera, 3, renderer.optics(), &scene, &error)) << error;
  const int w = s.camera.width_px, h = s.camera.height_px;
  std::vector<float> radiance(static_cast<std::size_t>(w) * h * 3), depth(static_cast<std::size_t>(w) * h);
  const ViewPose pose = renderer.leftView(tick);
  const LampSet lamps = renderer.lamps(pose);
  view.render(pose, lamps, radiance.data(), depth.data());
  // Every 3rd pixel: 40k rays. The seabed's Newton iteration stops within 0.2 mm of the relief from a
  // different first guess here, so depths agree to that and radiance to a fraction of a percent (more
  // where that shifts a texture edge).
  std::vector<float> relative;
  int hits_differ = 0, depth_off = 0;
  for (int v = 1; v < h; v += 3) {
    for (int u = 1; u < w; u += 3) {
      float z = 0.0f;
      const Eigen::Vector3f ref = bruteForceRadiance(scene, renderer.optics(), s.camera, pose, lamps, u, v, &z);
      const std::size_t i = static_cast<std::size_t>(v) * w + u;
      if ((z > 0.0f) != (depth[i] > 0.0f)) ++hits_differ;
      if (std::abs(z - depth[i]) > 1e-3f * std::max(z, 1.0f)) ++depth_off;
      for (int c = 0; c < 3; ++c) relative.push_back(std::abs(radiance[3 * i + c] - ref[c]) / std::max(ref[c], 1e-4f));
    }
  }
  std::sort(relative.begin(), relative.end());
  const std::size_t n = relative.size();
  EXPECT_LE(hits_differ, 0.001 * n / 3);
  EXPECT_LE(depth_off, 0.001 * n / 3);
  EXPECT_LT(relative[n / 2], 1e-4f);
  EXPECT_LT(relative[n * 99 / 100], 1e-2f);
  EXPECT_LT(relative[n * 999 / 1000], 5e-2f);
}

TEST(SimRenderFastPath, SeabedViewMatchesBruteForceShadingOfTheModel) {
  const Scenario s;
  expectFastPathMatchesBruteForce(s, tickFacingFace(s, 1, 3.0, -0.15, 1.3, 0.0, 35.0));
}

TEST(SimRenderFastPath, PanelViewWithFishMatchesBruteForceShadingOfTheModel) {
  Scenario s;
  s.water.fish_count = 8;
  expectFastPathMatchesBruteForce(s, tickFacingFace(s, 1, 1.6, 0.9, 1.2, 35.0, 5.0, 57'000'000));
}

TEST(SimRenderFastPath, ImageSizeNotAMultipleOfTileOrPacketMatchesBruteForce) {
  // 301 x 203 px: each row's last tile is 13 px wide, so its last packet of four holds one pixel, and the
  // last tile row is 11 rows high; a view of the valves face's corner with seabed and water.
  Scenario s;
  s.camera.width_px = 301, s.camera.height_px = 203;
  s.camera.fx_px = s.camera.fy_px = 300.0, s.camera.cx_px = 150.0, s.camera.cy_px = 101.0;
  expectFastPathMatchesBruteForce(s, tickFacingFace(s, 0, 1.8, 0.6, 1.2, 25.0, 15.0));
}

TEST(SimRenderFastPath, SecondThreadGivesTheSameImagesAndTruth) {
  Scenario s;
  s.water.fish_count = 4;
  StereoRenderer one, two;
  std::string error;
  ASSERT_TRUE(one.init(s, 5, 1, &error)) << error;
  ASSERT_TRUE(two.init(s, 5, 1, &error)) << error;
  ASSERT_TRUE(two.useSecondThread());
  for (const CameraTick& tick : {tickFacingFace(s, 0, 1.5, 0.0, 1.2, 10.0, 5.0, 1'000'000),
                                 tickFacingFace(s, 1, 3.0, -0.15, 1.3, 0.0, 35.0, 2'000'000)}) {
    StereoFrame a, b;
    allocateStereoFrame(a, s.camera.width_px, s.camera.height_px, 1);
    allocateStereoFrame(b, s.camera.width_px, s.camera.height_px, 1);
    RenderTruth ta, tb;
    one.allocateTruth(&ta);
    two.allocateTruth(&tb);
    ASSERT_TRUE(one.render(tick, &a, &ta));
    ASSERT_TRUE(two.render(tick, &b, &tb));
    EXPECT_EQ(cv::norm(a.left, b.left, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(a.right, b.right, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(ta.depth_m, tb.depth_m, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(ta.right_depth_m, tb.right_depth_m, cv::NORM_INF), 0.0);
    EXPECT_EQ(ta.visible_marker_ids, tb.visible_marker_ids);
  }
}

}  // namespace
}  // namespace deepnav::sim
