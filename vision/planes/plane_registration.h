#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

#include "vision/planes/davenport_q_method.h"
#include "vision/planes/plane_correspondence.h"
#include "vision/planes/plane_registration_config.h"
#include "vision/planes/plane_set.h"
#include "vision/planes/plane_translation.h"

namespace deepnav {

enum class PlaneRegistrationStatus {
  kOk = 0,                // rotation observable (>= 2 non-parallel matched planes)
  kNoCandidates,          // no pair passed the unary tests
  kNoMatches,             // no consistent correspondence (or all rejected by the verification or the
                          // rotation prior)
  kRotationUnobservable,  // only one plane, or only parallel planes, matched
};

// Motion of the camera between image a and image b from their planes.
//   q_cama_camb: rotation of the camera at b in the camera frame at a (R_a^T R_b);
//   p_camb_in_cama_m: position of the camera at b in the camera frame at a (has_translation);
//   cov: order [x y z rx ry rz]; translation in frame a; rotation error about camera b's axes,
//        q_meas = q_true Exp(n) (the convention of RelativePoseMeasurement, in camera frames).
//        Unconstrained directions hold PlaneRegistrationConfig::unobservable_variance.
// What the planes constrain: one plane fixes the rotation up to a turn about its normal (2 DoF)
// and the translation along its normal (1 DoF); two non-parallel planes fix the rotation (3 DoF)
// and the translation except along their intersection line; three planes whose normals span 3D
// fix everything. `valid` means the rotation is fully observable.
struct PlaneRegistrationResult {
  bool valid = false;
  bool has_translation = false;
  PlaneRegistrationStatus status = PlaneRegistrationStatus::kNoCandidates;
  Eigen::Quaterniond q_cama_camb = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_camb_in_cama_m = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Identity();
  int matched_planes = 0;
  int rotation_dims = 0;     // constrained rotation axes (3 valid; 2 parallel planes with `subspace`)
  int translation_dims = 0;  // constrained translation directions (3 with has_translation unless `subspace`)
  std::array<PlaneMatch, PlaneCorrespondenceSearch::kMaxMatches> matches{};
  int candidate_pairs = 0;
  int rejected_by_verification = 0;
  bool rejected_by_prior = false;  // the fitted rotation exceeded max_normal_change_deg
  bool search_exhausted = false;
};

// Pathak et al. (IEEE T-RO 2010) registration of two plane sets with unknown correspondences:
// PlaneCorrespondenceSearch chooses the matches; the rotation comes from Davenport's q-method with
// weights w = 2 / (tr C_n,a + tr C_n,b) (inverse per-axis variance of n_a - R n_b from the planes'
// covariances) and covariance -(2 (K - mu_max I))^+; matches whose normals disagree after the fit
// are dropped and the fit repeated; the translation is the weighted least-squares solution of
// n_a . t = d_a - d_b (variance C_d,a + C_d,b + t^T C_n,a t, one re-weighting) when the matched
// normals span 3D. Rotation and translation are decoupled (zero cross-covariance), as in the paper.
// With config.subspace, degenerate sets give what they constrain (rotation_dims, translation_dims;
// the other directions carry unobservable_variance): see PlaneRegistrationConfig::subspace.
class PlaneRegistrar {
 public:
  bool init(const PlaneRegistrationConfig& config);
  // a: planes of image a, b: planes of image b (each in its own camera frame).
  bool registerPlanes(const PlaneSet& a, const PlaneSet& b, PlaneRegistrationResult* result);

 private:
  bool fitRotation(const PlaneSet& a, const PlaneSet& b, int count,
                   const std::array<PlaneMatch, PlaneCorrespondenceSearch::kMaxMatches>& matches,
                   QMethodResult* rotation);
  bool rotationObservable(
      const PlaneSet& a, int count,
      const std::array<PlaneMatch, PlaneCorrespondenceSearch::kMaxMatches>& matches) const;
  void fitTranslation(const PlaneSet& a, const PlaneSet& b, PlaneRegistrationResult* result);
  void fitParallelRotation(const PlaneSet& a, const PlaneSet& b, PlaneRegistrationResult* result) const;

  bool ready_ = false;
  PlaneRegistrationConfig config_;
  PlaneCorrespondenceSearch search_;
  std::array<PlaneMatch, PlaneCorrespondenceSearch::kMaxMatches> matches_{};
  static constexpr int kN = PlaneCorrespondenceSearch::kMaxMatches;
  std::array<Eigen::Vector3d, kN> v_a_{};
  std::array<Eigen::Vector3d, kN> v_b_{};
  std::array<double, kN> w_{};
  std::array<double, kN> delta_d_{};
  std::array<double, kN> var_d_{};
};

}  // namespace deepnav
