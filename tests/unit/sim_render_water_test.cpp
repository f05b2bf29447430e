// The deep-sea image formation terms of the renderer (water keys): lamp backscatter that follows the lamps'
// position and beam, marine snow seen with the parallax of its depth, sediment plumes local in space and
// time, forward-scatter blur growing with range, and the keys' validation.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "tools/sim/render/forward_scatter.h"
#include "tools/sim/render/sediment_plume.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/render/water_column.h"
#include "tools/sim/scenario_loader.h"
#include "tests/support/x86_64_reference.h"

namespace deepnav::sim {
namespace {

struct Pair {
  StereoFrame frame;
  RenderTruth truth;
};

Pair renderOnce(const Scenario& s, const CameraTick& tick, StereoRenderer* renderer = nullptr) {
  StereoRenderer local;
  StereoRenderer& r = renderer ? *renderer : local;
  std::string error;
  EXPECT_TRUE(r.init(s, 1, 1, &error)) << error;
  Pair p;
  allocateStereoFrame(p.frame, s.camera.width_px, s.camera.height_px, 1);
  r.allocateTruth(&p.truth);
  EXPECT_TRUE(r.render(tick, &p.frame, &p.truth));
  return p;
}

// 30 m from the front face, nose 45 deg up: nothing but water in view.
CameraTick openWaterTick(const Scenario& s) { return tickFacingFace(s, 1, 30.0, -0.15, 1.3, 0.0, -45.0, 40'000'000); }

double meanIn(const cv::Mat& image, const cv::Rect& r) { return cv::mean(image(r))[0]; }

// The lamp backscatter of one pinhole view (688 x 516, f 580 px) looking along +x of P from the origin,
// lamps 0.25 m outside each camera of a 0.3 m rig and `above_m` above them, aimed along the axis.
struct ColumnView {
  WaterOptics optics = waterOptics(WaterPreset::kMurky);
  WaterEffects effects;
  WaterColumn column;
  Eigen::Matrix3f R_panel_cam;
  std::array<Eigen::Vector3f, 2> lamps;
  explicit ColumnView(double above_m, double half_angle_deg) {
    WaterConfig config;
    config.lamp_backscatter = true;
    config.lamp_beam_half_angle_deg = half_angle_deg;
    effects = waterEffects(config, optics);
    R_panel_cam.col(0) = -Eigen::Vector3f::UnitY();
    R_panel_cam.col(1) = -Eigen::Vector3f::UnitZ();
    R_panel_cam.col(2) = Eigen::Vector3f::UnitX();
    const float up = static_cast<float>(above_m);
    lamps = {R_panel_cam * Eigen::Vector3f(-0.25f, -up, 0.0f), R_panel_cam * Eigen::Vector3f(0.55f, -up, 0.0f)};
    column.init(688, 516, optics, effects, nullptr);
    column.prepare(Eigen::Vector3f::Zero(), ray(0.0, 0.0), R_panel_cam.col(0) / 580.0f, R_panel_cam.col(1) / 580.0f,
                   lamps, R_panel_cam.col(2));
  }
  Eigen::Vector3f ray(double u, double v) const {
    return R_panel_cam * Eigen::Vector3f(static_cast<float>((u - 344.0) / 580.0), static_cast<float>((v - 258.0) / 580.0), 1.0f);
  }
  float veil(int u, int v) const { return column.at(u, v, WaterColumn::kLastPosition)[1]; }  // green
  // The README's integral evaluated directly (1 mm steps, std::exp) for the green channel.
  double bruteForce(int u, int v) const {
    const Eigen::Vector3d d = ray(u, v).cast<double>().normalized();
    const double beta = optics.attenuation_per_m[1], b = effects.scattering_per_m[1], g = effects.phase.g;
    const double cos_edge = std::cos(effects.beam.cut_off ? std::acos(effects.beam.cos_edge) : M_PI / 2);
    double sum = 0.0;
    for (double s = 0.0005; s < WaterColumn::kRange_m; s += 0.001) {
      for (const Eigen::Vector3f& lamp : lamps) {
        const Eigen::Vector3d l = s * d - lamp.cast<double>();
        const double r = l.norm(), cos_phi = R_panel_cam.col(2).cast<double>().dot(l) / r;
        const double x = std::clamp((cos_phi - cos_edge) * effects.beam.inv_span, 0.0, 1.0);
        const double beam = std::max(cos_phi, 0.0) * (effects.beam.cut_off ? x * x * (3.0 - 2.0 * x) : 1.0);
        const double cos_theta = -l.dot(d) / r;
        const double phase = (1.0 - g * g) / (4.0 * M_PI * std::pow(1.0 + g * g - 2.0 * g * cos_theta, 1.5));
        sum += 0.001 * b * phase * M_PI * optics.lamp_intensity * beam / (r * r) * std::exp(-beta * (r + s));
      }
    }
    return sum;
  }
};

TEST(SimRenderWater, LampBackscatterIsBrightInsideTheBeamsAndFollowsTheLamps) {
  // 20 deg cones: the left lamp's axis meets the far field at the image's left third, 0.2 m up (u 183,
  // v 129 at 0.9 m, tending to the centre far out); the rays of the bottom edge's middle stay more than
  // 24 deg below both lamps' axes.
  const ColumnView above(0.2, 20.0);
  const float inside = above.veil(183, 129), outside = above.veil(344, 500);
  EXPECT_GT(inside, 20.0f * outside) << "inside " << inside << ", outside " << outside;
  // The quadratic sample spacing and the trapezoids against the integral itself on grid rays (multiples
  // of 32 px), inside a cone and near its edges; between grid rays the bilinear interpolation, checked
  // inside a cone (at the edges it is off by up to a third of a faint veil: 1.7e-4 integrated, 2.3e-4
  // interpolated at pixel (100, 300)).
  for (const auto& [u, v] : {std::pair{192, 128}, std::pair{352, 256}, std::pair{96, 288}, std::pair{608, 64}}) {
    const double expected = above.bruteForce(u, v);
    EXPECT_NEAR(above.veil(u, v), expected, 0.03 * expected + 1e-7) << "pixel " << u << ", " << v;
  }
  EXPECT_NEAR(above.veil(183, 129), above.bruteForce(183, 129), 0.1 * above.bruteForce(183, 129));
  // Lamps 0.4 m below the cameras instead: the beams' near field now crosses the lower rays.
  const ColumnView below(-0.4, 20.0);
  const float low_ray_above = above.veil(183, 480), low_ray_below = below.veil(183, 480);
  const float high_ray_above = above.veil(183, 129), high_ray_below = below.veil(183, 129);
  EXPECT_GT(low_ray_below, 5.0f * low_ray_above);
  EXPECT_LT(high_ray_below, 0.5f * high_ray_above);
  // The cosine beam (no cut-off) lights the bottom edge's rays too.
  const ColumnView cosine(0.2, 90.0);
  EXPECT_GT(cosine.veil(344, 500), 5.0f * outside);
}

TEST(SimRenderWater, BeamCutOffDarkensTheSurfaceOutsideTheCone) {
  // The dwell view of the valves face from 0.9 m: with a 20 deg cone the left lamp lights a disc of
  // 0.33 m around its axis (u 183, v 129 in the left image), the bottom middle (more than 25 deg off both
  // axes) gets no lamp light.
  Scenario s;
  s.water.preset = WaterPreset::kClear;
  const CameraTick tick = tickFacingFace(s, 0, 0.9, -0.15, 1.3, 0.0, 0.0, 40'000'000);
  const Pair cosine = renderOnce(s, tick);
  s.water.lamp_beam_half_angle_deg = 20.0;
  const Pair cone = renderOnce(s, tick);
  const cv::Rect off_beam(314, 440, 60, 60), in_beam(153, 99, 60, 60);
  const double ratio_cosine = meanIn(cosine.frame.left, off_beam) / meanIn(cosine.frame.left, in_beam);
  const double ratio_cone = meanIn(cone.frame.left, off_beam) / meanIn(cone.frame.left, in_beam);
  EXPECT_GT(ratio_cosine, 0.2);
  EXPECT_LT(ratio_cone, 0.1 * ratio_cosine) << "bottom middle / beam: cosine beam " << ratio_cosine << ", cone " << ratio_cone;
}

TEST(SimRenderWater, SnowParticlesAppearAtTheDisparityOfTheirDepth) {
  Scenario s;
  s.water.preset = WaterPreset::kClear;
  s.water.snow_density_per_m3 = 60.0;
  s.water.snow_diameter_mm = {2.0, 4.0};
  s.water.current_mps = {0.1, 0.0, 0.0};
  StereoRenderer renderer;
  const CameraTick tick = openWaterTick(s);
  const Pair p = renderOnce(s, tick, &renderer);
  const auto& lit = renderer.snow().lit();
  ASSERT_GT(lit.size(), 20u);
  const ViewPose left = renderer.leftView(tick);
  const double f = s.camera.fx_px, b = s.camera.baseline_m;
  struct Seen {
    double u, v, z;
  };
  std::vector<Seen> seen;
  for (const auto& particle : lit) {
    const Eigen::Vector3f q = left.R_panel_cam.transpose() * (particle.p_in_panel_m - left.p_cam_in_panel_m);
    if (q.z() < 0.5f) continue;
    seen.push_back({s.camera.cx_px + f * q.x() / q.z(), s.camera.cy_px + s.camera.fy_px * q.y() / q.z(), q.z()});
  }
  int tested = 0, matched = 0;
  for (const Seen& a : seen) {
    const double d = f * b / a.z;
    if (a.z > 2.5 || a.v < 3 || a.v > s.camera.height_px - 4 || a.u - d < 25 || a.u > s.camera.width_px - 25) continue;
    // Alone in both images (no other particle within 8 px), and standing out in the left one.
    const bool alone = std::none_of(seen.begin(), seen.end(), [&](const Seen& o) {
      if (&o == &a) return false;
      const double dv = std::abs(o.v - a.v), d_o = f * b / o.z;
      return dv < 8.0 && (std::abs(o.u - a.u) < 8.0 || std::abs((o.u - d_o) - (a.u - d)) < 8.0 ||
                          std::abs((o.u - d_o) - a.u) < 8.0 || std::abs(o.u - (a.u - d)) < 8.0);
    });
    const int row = static_cast<int>(std::lround(a.v));
    if (!alone || p.frame.left.at<std::uint8_t>(row, static_cast<int>(std::lround(a.u))) < 100) continue;
    // The brightest column of the right image's row near the predicted position (3 rows summed).
    int best_u = -1;
    double best = -1.0;
    for (int u = static_cast<int>(a.u - d) - 20; u <= static_cast<int>(a.u - d) + 20; ++u) {
      double sum = 0.0;
      for (int dv = -1; dv <= 1; ++dv) sum += p.frame.right.at<std::uint8_t>(row + dv, u);
      if (sum > best) best = sum, best_u = u;
    }
    ++tested;
    if (std::abs(static_cast<double>(best_u) - (a.u - d)) <= 1.5) ++matched;
  }
  EXPECT_GE(tested, 8);
  EXPECT_GE(matched, tested * 9 / 10) << matched << " of " << tested << " particles at their true disparity";
}

TEST(SimRenderWater, SnowIsLitOnlyInsideTheBeams) {
  Scenario s;
  s.water.snow_density_per_m3 = 200.0;
  s.water.lamp_beam_half_angle_deg = 25.0;
  StereoRenderer renderer;
  const CameraTick tick = openWaterTick(s);
  renderOnce(s, tick, &renderer);
  const LampSet lamps = renderer.lamps(renderer.leftView(tick));
  ASSERT_FALSE(renderer.snow().lit().empty());
  for (const auto& particle : renderer.snow().lit()) {
    double best_cos = -1.0;
    for (const auto& lamp : lamps.p_lamp_in_panel_m)
      best_cos = std::max(best_cos, static_cast<double>(lamps.axis_in_panel.dot((particle.p_in_panel_m - lamp).normalized())));
    EXPECT_GT(best_cos, std::cos(25.0 * M_PI / 180.0) - 1e-5);
  }
}

TEST(SimRenderWater, PlumeAttenuatesOnlyNearItsCentreAndAfterItsStart) {
  SedimentPlumeConfig c;
  c.t_start_s = 100.0;
  c.centre_in_odom_m = {2.0, 3.0};
  c.radius_m = 0.5;
  c.height_m = 0.4;
  c.growth_mps = 0.01;
  c.attenuation_per_m = 3.0;
  c.rise_s = 10.0;
  c.decay_s = 200.0;
  Eigen::Isometry3d T_odom_panel = Eigen::Isometry3d::Identity();
  T_odom_panel.translation() = Eigen::Vector3d(0.0, 0.0, -5.0);
  SedimentPlumes plumes;
  plumes.init({c}, T_odom_panel, {0.05, 0.0, 0.0});
  const Eigen::Vector3f centre(2.0f, 3.0f, 0.0f);
  plumes.setTime(99.0);
  EXPECT_EQ(plumes.attenuationAt(centre), 0.0f);
  plumes.setTime(120.0);  // 20 s on: full ramp, k = 1 + 0.01 x 20 / 0.5 = 1.4, drifted 1 m east
  const double k = 1.4, peak = 3.0 * std::exp(-20.0 / 200.0) / (k * k * k);
  const Eigen::Vector3f drifted = centre + Eigen::Vector3f(1.0f, 0.0f, 0.0f);
  EXPECT_NEAR(plumes.attenuationAt(drifted), peak, 1e-4 * peak);
  const double sigma_h = 0.5 * k, sigma_v = 0.4 * k;
  EXPECT_NEAR(plumes.attenuationAt(drifted + Eigen::Vector3f(0.0f, static_cast<float>(sigma_h), 0.0f)),
              peak * std::exp(-0.5), 1e-4 * peak);
  EXPECT_NEAR(plumes.attenuationAt(drifted + Eigen::Vector3f(0.0f, 0.0f, static_cast<float>(sigma_v))),
              peak * std::exp(-0.5), 1e-4 * peak);
  EXPECT_LT(plumes.attenuationAt(drifted + Eigen::Vector3f(4.0f * static_cast<float>(sigma_h), 0.0f, 0.0f)), 1e-3 * peak);
  plumes.setTime(2100.0);  // ten decay times on
  EXPECT_LT(plumes.attenuationAt(centre + Eigen::Vector3f(100.0f, 0.0f, 0.0f)), 1e-4 * peak);

  // In the image: the valves face from 0.9 m in moderate water, a plume raised on the seabed in front of it.
  Scenario s;
  const CameraTick tick = tickFacingFace(s, 0, 0.9, -0.15, 1.3, 0.0, 10.0, 40'000'000);
  const Pair clean = renderOnce(s, tick);
  const auto differenceTo = [&](const std::array<double, 2>& where, double t_start_s) {
    Scenario with = s;
    SedimentPlumeConfig plume;
    plume.t_start_s = t_start_s;
    plume.centre_in_odom_m = where;
    plume.radius_m = 0.6;
    plume.height_m = 1.0;
    with.water.plumes = {plume};
    const Pair p = renderOnce(with, tick);
    cv::Mat diff;
    cv::absdiff(p.frame.left, clean.frame.left, diff);
    return cv::mean(diff)[0];
  };
  // The valves face looks +y in P; with the panel at the odom origin, unyawed, 1.6 m north of the centre
  // is in front of it, on the seabed below the view.
  const double near_active = differenceTo({-0.15, 1.6}, 30.0);
  const double near_later = differenceTo({-0.15, 1.6}, 60.0);
  const double far_active = differenceTo({40.0, 40.0}, 30.0);
  // The auto exposure makes up for the overall darkening; what is left is the plume's gradient (3 DN is
  // 6 times the rounding differences of the other two).
  EXPECT_GT(near_active, 3.0);
  EXPECT_LT(near_later, 0.5);
  EXPECT_LT(far_active, 0.5) << "near " << near_active << " DN, before its start " << near_later << " DN";
}

// The rms width (pixels) of a row profile about its centroid.
double rmsWidth(const std::vector<float>& profile) {
  const double sum = std::accumulate(profile.begin(), profile.end(), 0.0);
  double mean = 0.0, var = 0.0;
  for (std::size_t i = 0; i < profile.size(); ++i) mean += i * profile[i] / sum;
  for (std::size_t i = 0; i < profile.size(); ++i) var += (i - mean) * (i - mean) * profile[i] / sum;
  return std::sqrt(var);
}

TEST(SimRenderWater, ForwardScatterBlurGrowsWithRange) {
  constexpr int kW = 160, kH = 96;
  WaterOptics optics = waterOptics(WaterPreset::kModerate);
  WaterConfig config;
  config.forward_scatter_mrad_per_m = 5.0;
  const WaterEffects effects = waterEffects(config, optics);
  ForwardScatter blur;
  const float fx = 580.0f;
  blur.init(kW, kH, 1, fx, effects);
  // A bright vertical line (column 80) on black, all at one range.
  std::vector<float> direct(kW * kH, 0.0f);
  for (int v = 0; v < kH; ++v) direct[v * kW + 80] = 1.0f;
  double previous_width = 0.0;
  for (double range_m : {0.3, 1.0, 2.0, 4.0}) {
    std::vector<float> distance(kW * kH, static_cast<float>(range_m)), radiance = direct;
    blur.apply(direct.data(), distance.data(), radiance.data());
    // The scattered part: the output minus the unscattered line, over the scattered fraction.
    const double b_f = effects.forward_scatter_per_m[1], scattered = 1.0 - std::exp(-b_f * range_m);
    std::vector<float> profile(kW);
    double total = 0.0;
    for (int u = 0; u < kW; ++u) {
      const float unscattered = static_cast<float>((1.0 - scattered) * direct[48 * kW + u]);
      profile[u] = static_cast<float>((radiance[48 * kW + u] - unscattered) / scattered);
      total += radiance[48 * kW + u];
    }
    EXPECT_NEAR(total, 1.0, 0.02) << "energy kept at " << range_m << " m";
    const double width = rmsWidth(profile), expected = fx * 5e-3 * range_m;
    EXPECT_GT(width, previous_width + 0.3) << range_m << " m";
    EXPECT_GT(width, 0.6 * expected) << range_m << " m";
    EXPECT_LT(width, 1.6 * expected + 0.5) << range_m << " m";
    previous_width = width;
  }
  // Open water (range 0) is left alone.
  std::vector<float> none(kW * kH, 0.0f), radiance = direct;
  blur.apply(direct.data(), none.data(), radiance.data());
  EXPECT_EQ(radiance, direct);
}

// FNV-1a over the bytes of the left image, the right image and the left depth map.
std::uint64_t hashPair(const Pair& p) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  const auto add = [&h](const cv::Mat& m) {
    const auto* bytes = m.ptr<std::uint8_t>();
    for (std::size_t i = 0; i < m.total() * m.elemSize(); ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
  };
  add(p.frame.left), add(p.frame.right), add(p.truth.depth_m);
  return h;
}

TEST(SimRenderWater, DefaultsRenderAsBeforeTheWaterTerms) {
  DEEPNAV_SKIP_UNLESS_X86_64_REFERENCE();
  // Hashes of renders made by the renderer of c8fce7c (before the deep-sea terms existed): the valves face
  // from 0.9 m at t = 36 s, in clear water with 6 fish (grey), in murky water with 6 fish (BGR), and in
  // murky water through a flat acrylic port (BGR). Every water key at its default must leave them as
  // they were, bit for bit.
  struct Case {
    WaterPreset preset;
    int channels;
    bool port;
    std::uint64_t hash;
  };
  for (const Case& c : {Case{WaterPreset::kClear, 1, false, 0x56fc0526289b1ecbull},
                        Case{WaterPreset::kMurky, 3, false, 0x30224b529522050full},
                        Case{WaterPreset::kMurky, 3, true, 0x9732974611903c04ull}}) {
    Scenario s;
    s.water.preset = c.preset;
    s.water.fish_count = c.port ? 0 : 6;
    if (c.port) {
      s.camera.flat_port = true;
      s.camera.port.pinhole_to_glass_m = 0.008;
      s.camera.port.glass_thickness_m = 0.012;
      s.camera.port.n_glass = 1.49;
    }
    StereoRenderer r;
    std::string error;
    ASSERT_TRUE(r.init(s, 1, c.channels, &error)) << error;
    Pair p;
    allocateStereoFrame(p.frame, s.camera.width_px, s.camera.height_px, c.channels);
    r.allocateTruth(&p.truth);
    ASSERT_TRUE(r.render(tickFacingFace(s, 0, 0.9, -0.15, 1.3, 0.0, 0.0, 36'000'000), &p.frame, &p.truth));
    EXPECT_EQ(hashPair(p), c.hash) << waterPresetName(c.preset) << (c.port ? " through the port" : "");
  }
}

TEST(SimRenderWater, WaterKeysAreReadAndCheckedWithTheirNames) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario(R"(
water:
  preset: murky
  lamp_backscatter: true
  lamp_beam_half_angle_deg: 35
  current_mps: [0.1, -0.05, 0.0]
  snow_density_per_m3: 300
  forward_scatter_mrad_per_m: 4
  plumes:
    - {t_start_s: 60, centre_in_odom_m: [1.0, 2.0], radius_m: 0.8}
)",
                            "test", &s, &error))
      << error;
  EXPECT_TRUE(s.water.lamp_backscatter);
  EXPECT_EQ(s.water.lamp_beam_half_angle_deg, 35.0);
  EXPECT_EQ(s.water.current_mps[1], -0.05);
  ASSERT_EQ(s.water.plumes.size(), 1u);
  EXPECT_EQ(s.water.plumes[0].radius_m, 0.8);
  EXPECT_EQ(s.water.plumes[0].decay_s, SedimentPlumeConfig{}.decay_s);
  EXPECT_FALSE(parseScenario("water: {plumes: [{radius_m: 0.0}]}", "t", &s, &error));
  EXPECT_NE(error.find("water.plumes[0].radius_m"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("water: {snow_diameter_mm: [3.0, 1.0]}", "t", &s, &error));
  EXPECT_NE(error.find("water.snow_diameter_mm"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("water: {lamp_beam_half_angle_deg: 120}", "t", &s, &error));
  EXPECT_NE(error.find("water.lamp_beam_half_angle_deg"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("water: {plumes: 3}", "t", &s, &error));
  EXPECT_NE(error.find("water.plumes"), std::string::npos) << error;
  // Every term off by default.
  const Scenario defaults;
  EXPECT_FALSE(waterEffects(defaults.water, waterOptics(defaults.water.preset)).any());
}

}  // namespace
}  // namespace deepnav::sim
