#include "tools/sim/render/face_paint.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "tools/sim/normal_rng.h"
#include "tools/sim/render/procedural_noise.h"

namespace deepnav::sim {

namespace {

constexpr float kMarkerBlack = 0.04f;
constexpr float kMarkerWhite = 0.85f;

cv::Vec3b toTexel(const Eigen::Vector3f& albedo) {
  cv::Vec3b t;
  for (int c = 0; c < 3; ++c) t[c] = cv::saturate_cast<std::uint8_t>(albedo[c] * 255.0f + 0.5f);
  return t;
}

// Noise fields of a painted surface, one value per texel.
struct PaintNoise {
  cv::Mat mottling, blotches, grain, streaks;
};

PaintNoise weatheringNoise(int width, int height, double texel_m, std::uint32_t seed) {
  const auto cells = [&](double metres) { return static_cast<float>(metres / texel_m); };
  PaintNoise n;
  n.mottling = fractalNoiseImage(width, height, cells(0.25), 4, 0.55f, seed);
  n.blotches = fractalNoiseImage(width, height, cells(0.05), 3, 0.5f, seed + 4);
  n.grain = fractalNoiseImage(width, height, cells(0.006), 2, 0.5f, seed + 1);
  // Rust streaks run down in places: noise stretched vertically, masked by a broad patch noise.
  n.streaks = valueNoiseImage(width, height, cells(0.012), cells(0.35), seed + 2)
                  .mul(valueNoiseImage(width, height, cells(0.3), cells(0.6), seed + 3));
  return n;
}

// Yellow paint with weathering at texel (u, v), z metres above the seabed.
Eigen::Vector3f weatheredPaint(const Eigen::Vector3f& base, const PaintNoise& n, int u, int v, float z) {
  const float mottling = n.mottling.at<float>(v, u), blotches = n.blotches.at<float>(v, u);
  const float grain = n.grain.at<float>(v, u), streak = n.streaks.at<float>(v, u);
  Eigen::Vector3f c = base * (1.0f + 0.25f * mottling + 0.12f * blotches + 0.10f * grain);
  // Chipped paint shows the dark primer in small irregular patches.
  if (blotches > 0.5f) c = Eigen::Vector3f(0.09f, 0.10f, 0.11f) * (1.0f + 0.3f * grain);
  if (streak > 0.3f) {
    const float w = std::min(1.0f, (streak - 0.3f) / 0.4f) * 0.45f;
    c = (1.0f - w) * c + w * Eigen::Vector3f(0.07f, 0.18f, 0.33f);
  }
  // Sediment settles near the seabed.
  if (z < 0.35f) {
    const float w = (1.0f - std::max(z, 0.0f) / 0.35f) * (0.55f + 0.25f * mottling);
    c = (1.0f - w) * c + w * Eigen::Vector3f(0.22f, 0.26f, 0.28f);
  }
  return c;
}

// Grey paint with about 1.5 % contrast: the "textureless" face.
void paintPlain(double texel_m, std::uint32_t seed, cv::Mat* img) {
  const cv::Mat broad = fractalNoiseImage(img->cols, img->rows, static_cast<float>(0.6 / texel_m), 3, 0.5f, seed);
  const cv::Mat grain = valueNoiseImage(img->cols, img->rows, 2.0f, 2.0f, seed + 1);
  const Eigen::Vector3f grey(0.40f, 0.41f, 0.40f);
  for (int v = 0; v < img->rows; ++v) {
    cv::Vec3b* row = img->ptr<cv::Vec3b>(v);
    for (int u = 0; u < img->cols; ++u)
      row[u] = toTexel(grey * (1.0f + 0.012f * broad.at<float>(v, u) + 0.004f * grain.at<float>(v, u)));
  }
}

void paintWeathered(const Eigen::Vector3f& base, double height_m, double texel_m, std::uint32_t seed, cv::Mat* img) {
  const PaintNoise noise = weatheringNoise(img->cols, img->rows, texel_m, seed);
  for (int v = 0; v < img->rows; ++v) {
    const float z = static_cast<float>(height_m - (v + 0.5) * texel_m);
    cv::Vec3b* row = img->ptr<cv::Vec3b>(v);
    for (int u = 0; u < img->cols; ++u) row[u] = toTexel(weatheredPaint(base, noise, u, v, z));
  }
}

// Fouling spots, painted frames around the valve cluster and stencilled labels: strong local texture.
void paintDetails(int face_index, const FaceFrame& face, const FacePaintSpec& spec, std::uint32_t seed,
                  cv::Mat* img) {
  const double px = 1.0 / spec.texel_m;
  const auto toPx = [&](double s, double z) {
    return cv::Point(static_cast<int>((s + face.half_width_m) * px), static_cast<int>((face.height_m - z) * px));
  };
  NormalRng rng(NormalRng::subSeed(seed, 11));
  for (int i = 0; i < 160; ++i) {
    const double s = (2.0 * rng.uniform() - 1.0) * face.half_width_m;
    const double z = rng.uniform() * face.height_m;
    const int radius = static_cast<int>((0.002 + 0.008 * rng.uniform() * rng.uniform()) * px);
    const bool pale = rng.uniform() < 0.4;
    const cv::Scalar colour = pale ? cv::Scalar(105, 115, 115) : cv::Scalar(28, 45, 62);
    cv::circle(*img, toPx(s, z), radius, colour, cv::FILLED, cv::LINE_AA);
  }
  const int line = static_cast<int>(0.008 * px);
  const double a = face.half_width_m, h = face.height_m;
  const cv::Scalar black(12, 12, 12);
  if (face_index == 0) {
    cv::rectangle(*img, toPx(-0.3 * a, 0.967 * h), toPx(0.3 * a, 0.633 * h), black, line, cv::LINE_AA);
    cv::rectangle(*img, toPx(-0.9 * a, 0.32 * h), toPx(0.9 * a, 0.12 * h), black, line, cv::LINE_AA);
  } else {
    cv::rectangle(*img, toPx(-0.25 * a, 0.985 * h), toPx(0.25 * a, 0.645 * h), black, line, cv::LINE_AA);
    cv::rectangle(*img, toPx(-0.9 * a, 0.4 * h), toPx(0.9 * a, 0.2 * h), black, line, cv::LINE_AA);
  }
  // Label plates: white with black stencil text, under the valves / by the handles.
  const char* labels[2][3] = {{"V-101", "V-102", "V-103"}, {"GRAB", "H-1", "H-2"}};
  const double plates[2][3][2] = {{{-0.16, 0.8}, {0.1, 0.8}, {0.16, 0.713}}, {{0.0, 0.733}, {-0.15, 0.96}, {0.15, 0.96}}};
  for (int k = 0; k < 3; ++k) {
    const double s = plates[face_index][k][0] * a, z = plates[face_index][k][1] * h;
    cv::rectangle(*img, toPx(s - 0.06, z + 0.018), toPx(s + 0.06, z - 0.018), cv::Scalar(200, 205, 205), cv::FILLED);
    cv::putText(*img, labels[face_index][k], toPx(s - 0.052, z - 0.011), cv::FONT_HERSHEY_SIMPLEX, 0.012 * px / 11.0,
                cv::Scalar(15, 15, 15), std::max(1, static_cast<int>(0.003 * px)), cv::LINE_AA);
  }
}

// Supersampled marker with its quiet zone, at its exact place on the face.
void paintMarker(const FaceFrame& face, const PanelMarker& m, double size_m, const cv::Mat& bits,
                 const FacePaintSpec& spec, cv::Mat* img) {
  const Eigen::Vector3d c = m.p_marker_in_panel_m - face.origin_in_panel_m;
  const double s_c = c.dot(face.right_in_panel), z_c = c.z();
  const double half = 0.5 * size_m, outer = half + spec.quiet_zone_m;
  const int cells = bits.rows;
  const double cell_m = size_m / cells;
  const int u0 = std::max(0, static_cast<int>(std::floor((s_c - outer + face.half_width_m) / spec.texel_m)));
  const int u1 = std::min(img->cols - 1, static_cast<int>(std::ceil((s_c + outer + face.half_width_m) / spec.texel_m)));
  const int v0 = std::max(0, static_cast<int>(std::floor((face.height_m - z_c - outer) / spec.texel_m)));
  const int v1 = std::min(img->rows - 1, static_cast<int>(std::ceil((face.height_m - z_c + outer) / spec.texel_m)));
  constexpr int kSub = 4;
  for (int v = v0; v <= v1; ++v) {
    for (int u = u0; u <= u1; ++u) {
      float sum = 0.0f;
      int inside = 0;
      for (int j = 0; j < kSub; ++j) {
        for (int i = 0; i < kSub; ++i) {
          const double s = (u + (i + 0.5) / kSub) * spec.texel_m - face.half_width_m - s_c;
          const double z = face.height_m - (v + (j + 0.5) / kSub) * spec.texel_m - z_c;
          if (std::abs(s) > outer || std::abs(z) > outer) continue;
          ++inside;
          if (std::abs(s) >= half || std::abs(z) >= half) {
            sum += kMarkerWhite;
            continue;
          }
          const int col = std::clamp(static_cast<int>((s + half) / cell_m), 0, cells - 1);
          const int row = std::clamp(static_cast<int>((half - z) / cell_m), 0, cells - 1);
          sum += bits.at<std::uint8_t>(row, col) ? kMarkerWhite : kMarkerBlack;
        }
      }
      if (inside == 0) continue;
      // Partly covered texels at the quiet zone's edge blend with the paint below.
      const float cover = static_cast<float>(inside) / (kSub * kSub);
      cv::Vec3b& t = img->at<cv::Vec3b>(v, u);
      const std::uint8_t value = cv::saturate_cast<std::uint8_t>(sum / inside * 255.0f + 0.5f);
      for (int ch = 0; ch < 3; ++ch) t[ch] = cv::saturate_cast<std::uint8_t>((1.0f - cover) * t[ch] + cover * value);
    }
  }
}

}  // namespace

bool paintFace(const FaceFrame& face, int face_index, const PanelDescription& panel, const FacePaintSpec& spec,
               std::uint32_t seed, TextureMap* texture, std::string* error) {
  const int width = static_cast<int>(std::ceil(2.0 * face.half_width_m / spec.texel_m));
  const int height = static_cast<int>(std::ceil((face.height_m - spec.z_bottom_m) / spec.texel_m));
  if (!texture->create(width, height, false)) {
    if (error) *error = "renderer: face texture of " + face.name + " is too small";
    return false;
  }
  cv::Mat& img = texture->base();
  const std::uint32_t face_seed = hashU32(seed, static_cast<std::uint32_t>(face_index), 0xFACEU);
  const Eigen::Vector3f yellow = face_index == 0 ? Eigen::Vector3f(0.06f, 0.45f, 0.74f)
                                                 : Eigen::Vector3f(0.05f, 0.38f, 0.74f);
  if (face_index == 2) {
    paintPlain(spec.texel_m, face_seed, &img);
  } else {
    paintWeathered(yellow, face.height_m, spec.texel_m, face_seed, &img);
    paintDetails(face_index, face, spec, face_seed, &img);
  }
  if (!panel.markers.empty()) {
    const cv::Ptr<cv::aruco::Dictionary> dict = arucoDictionaryByName(panel.dictionary);
    if (!dict) {
      if (error) *error = "renderer: unknown ArUco dictionary '" + panel.dictionary + "'";
      return false;
    }
    for (const PanelMarker& m : panel.markers) {
      if (m.face != face_index) continue;
      cv::Mat bits;  // one pixel per cell, border included
      cv::aruco::drawMarker(dict, m.id, dict->markerSize + 2, bits, 1);
      paintMarker(face, m, panel.marker_size_m, bits, spec, &img);
    }
  }
  texture->buildMips();
  return true;
}

void paintCorner(double arc_length_m, double height_m, const FacePaintSpec& spec, std::uint32_t seed,
                 TextureMap* texture) {
  const int width = std::max(2, static_cast<int>(std::ceil(arc_length_m / spec.texel_m)));
  const int height = static_cast<int>(std::ceil((height_m - spec.z_bottom_m) / spec.texel_m));
  texture->create(width, height, false);
  paintWeathered(Eigen::Vector3f(0.05f, 0.40f, 0.74f), height_m, spec.texel_m, seed, &texture->base());
  texture->buildMips();
}

}  // namespace deepnav::sim
