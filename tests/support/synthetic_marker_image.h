#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <string>

#include "vision/markers/pinhole_intrinsics.h"

namespace deepnav {

// A printed ArUco marker on a flat plate, for synthetic images (tests, benchmarks, simulator).
struct SyntheticMarker {
  int id = 0;
  double marker_size_m = 0.15;  // black border side
  double quiet_zone_m = 0.03;   // white margin around the black border, each side
  Eigen::Quaterniond q_cam_marker =
      Eigen::Quaterniond::Identity();  // marker frame M in the camera C
  Eigen::Vector3d p_marker_in_cam_m = Eigen::Vector3d(0.0, 0.0, 1.0);
  std::uint8_t black = 20;   // grey level of the black cells
  std::uint8_t white = 230;  // grey level of the white cells and quiet zone
};

// Paints the marker into a CV_8UC1 image seen by a pinhole camera, over what is already there.
// Each pixel is the exact area average of supersample x supersample point samples: a sample's ray
// is intersected with the marker plane and takes the cell colour there (no interpolation, so edges
// land where the geometry puts them, to about 1/supersample px). A marker seen from behind is not
// drawn. False for an unknown dictionary or id, a bad image type or supersample outside [1, 16].
bool drawSyntheticMarker(const std::string& dictionary, const SyntheticMarker& marker,
                         const PinholeIntrinsics& camera, int supersample, cv::Mat* image);

// Adds zero-mean Gaussian noise of sigma grey levels (drawn from rng) to a CV_8UC1 image, saturating at
// 0 and 255: the sensor noise of the marker tests and benchmarks.
void addGaussianNoise(double sigma, cv::RNG* rng, cv::Mat* image);

// The exact image of corner k (ArUco order) of the marker: where a perfect detector finds it.
Eigen::Vector2d projectMarkerCorner(const SyntheticMarker& marker, const PinholeIntrinsics& camera,
                                    int k);

}  // namespace deepnav
