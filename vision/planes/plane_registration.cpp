#include "vision/planes/plane_registration.h"

#include <algorithm>
#include <cmath>

namespace deepnav {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

}  // namespace

bool PlaneRegistrar::init(const PlaneRegistrationConfig& config) {
  ready_ = false;
  if (!search_.init(config) || config.max_residual_angle_deg <= 0.0 ||
      config.max_offset_residual_m <= 0.0 || config.min_translation_eigenvalue <= 0.0 ||
      config.unobservable_variance <= 0.0 || config.covariance_scale <= 0.0) {
    return false;
  }
  config_ = config;
  ready_ = true;
  return true;
}

bool PlaneRegistrar::fitRotation(
    const PlaneSet& a, const PlaneSet& b, int count,
    const std::array<PlaneMatch, PlaneCorrespondenceSearch::kMaxMatches>& matches,
    QMethodResult* rotation) {
  for (int i = 0; i < count; ++i) {
    const Plane& pa = a[matches[i].a];
    const Plane& pb = b[matches[i].b];
    v_a_[i] = pa.n_in_cam;
    v_b_[i] = pb.n_in_cam;
    // Per-axis variance of n_a - R n_b: the residual lies in the (2D) tangent of the normals.
    const double var = 0.5 * (pa.normalCovariance().trace() + pb.normalCovariance().trace());
    w_[i] = 1.0 / std::max(var, 1e-18);
  }
  return davenportQMethod(v_a_.data(), v_b_.data(), w_.data(), count, config_.unobservable_variance,
                          rotation);
}

bool PlaneRegistrar::rotationObservable(
    const PlaneSet& a, int count,
    const std::array<PlaneMatch, PlaneCorrespondenceSearch::kMaxMatches>& matches) const {
  const double cos_parallel = std::cos(config_.parallel_angle_deg * kDegToRad);
  for (int i = 0; i < count; ++i) {
    for (int k = i + 1; k < count; ++k) {
      if (std::abs(a[matches[i].a].n_in_cam.dot(a[matches[k].a].n_in_cam)) < cos_parallel) {
        return true;
      }
    }
  }
  return false;
}

void PlaneRegistrar::fitTranslation(const PlaneSet& a, const PlaneSet& b,
                                    PlaneRegistrationResult* result) {
  const int count = result->matched_planes;
  TranslationResult translation;
  TranslationSubspaceResult subspace;
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  for (int pass = 0; pass < 2; ++pass) {  // pass 1 re-weights with the normal term t^T C_n t
    for (int i = 0; i < count; ++i) {
      const Plane& pa = a[result->matches[i].a];
      const Plane& pb = b[result->matches[i].b];
      v_a_[i] = pa.n_in_cam;
      delta_d_[i] = pa.d_m - pb.d_m;
      var_d_[i] = std::max(pa.offsetVariance() + pb.offsetVariance() +
                               t.dot((pa.normalCovariance() + pb.normalCovariance()) * t),
                           1e-18);
    }
    if (config_.subspace) {
      if (!solvePlaneTranslationSubspace(v_a_.data(), delta_d_.data(), var_d_.data(), count,
                                         config_.min_translation_eigenvalue, &subspace) ||
          subspace.dims == 0) {
        return;
      }
      t = subspace.t_m;
    } else {
      if (!solvePlaneTranslation(v_a_.data(), delta_d_.data(), var_d_.data(), count,
                                 config_.min_translation_eigenvalue, &translation) ||
          !translation.observable) {
        return;
      }
      t = translation.t_m;
    }
  }
  for (int i = 0; i < count; ++i) {
    if (std::abs(v_a_[i].dot(t) - delta_d_[i]) > config_.max_offset_residual_m) {
      ++result->rejected_by_verification;
      return;  // inconsistent offsets: keep the rotation only
    }
  }
  result->has_translation = true;
  result->p_camb_in_cama_m = t;
  if (config_.subspace) {
    result->translation_dims = subspace.dims;
    // Only the constrained directions are scaled: the others hold the unobservable variance.
    result->cov.topLeftCorner<3, 3>() = subspace.cov_constrained_m2 * config_.covariance_scale +
                                        subspace.unconstrained * config_.unobservable_variance;
  } else {
    result->translation_dims = 3;
    result->cov.topLeftCorner<3, 3>() = translation.cov_m2 * config_.covariance_scale;
  }
}

// Parallel planes only: the smallest rotation taking the (weighted mean) normal of b onto that of a;
// per-axis variance 1 / sum w across the normal (the q-method's information sum w (I - n n^T) about
// b's axes), unobservable about it.
void PlaneRegistrar::fitParallelRotation(const PlaneSet& a, const PlaneSet& b,
                                         PlaneRegistrationResult* result) const {
  Eigen::Vector3d n_a = Eigen::Vector3d::Zero(), n_b = Eigen::Vector3d::Zero();
  double w_sum = 0.0;
  for (int i = 0; i < result->matched_planes; ++i) {
    const Plane& pa = a[result->matches[i].a];
    const Plane& pb = b[result->matches[i].b];
    const double var = 0.5 * (pa.normalCovariance().trace() + pb.normalCovariance().trace());
    const double w = 1.0 / std::max(var, 1e-18);
    n_a += w * pa.n_in_cam;
    n_b += w * pb.n_in_cam;
    w_sum += w;
  }
  n_a.normalize();
  n_b.normalize();
  result->q_cama_camb = Eigen::Quaterniond::FromTwoVectors(n_b, n_a);
  const Eigen::Matrix3d along = n_b * n_b.transpose();
  result->cov.bottomRightCorner<3, 3>() = (Eigen::Matrix3d::Identity() - along) *
                                              (config_.covariance_scale / w_sum) +
                                          config_.unobservable_variance * along;
  result->rotation_dims = 2;
}

bool PlaneRegistrar::registerPlanes(const PlaneSet& a, const PlaneSet& b,
                                    PlaneRegistrationResult* result) {
  if (!ready_ || result == nullptr) return false;
  *result = PlaneRegistrationResult{};
  result->cov = Eigen::Matrix<double, 6, 6>::Identity() * config_.unobservable_variance;
  int count = search_.find(a, b, &matches_);
  result->candidate_pairs = search_.candidateCount();
  result->search_exhausted = search_.searchExhausted();
  if (result->candidate_pairs == 0) {
    result->status = PlaneRegistrationStatus::kNoCandidates;
    return true;
  }
  // Fit, drop the matches the rotation does not explain, refit.
  QMethodResult rotation;
  const double max_residual = config_.max_residual_angle_deg * kDegToRad;
  for (int pass = 0; pass < 2 && count > 0; ++pass) {
    if (!fitRotation(a, b, count, matches_, &rotation)) return false;
    const Eigen::Matrix3d R = rotation.q_a_b.toRotationMatrix();
    int kept = 0;
    for (int i = 0; i < count; ++i) {
      const double c = a[matches_[i].a].n_in_cam.dot(R * b[matches_[i].b].n_in_cam);
      if (std::acos(std::clamp(c, -1.0, 1.0)) <= max_residual) matches_[kept++] = matches_[i];
    }
    result->rejected_by_verification += count - kept;
    if (kept == count) break;
    count = kept;
  }
  // The rotation prior bounds an observable fit too: matched normals that agree only after a turn beyond
  // it are a wrong correspondence (typically two near-parallel pairs swapped), not motion.
  const double turn_rad = Eigen::AngleAxisd(rotation.q_a_b).angle();
  if (count > 0 && rotation.observable_dims == 3 && rotationObservable(a, count, matches_) &&
      std::min(turn_rad, 2.0 * M_PI - turn_rad) > config_.max_normal_change_deg * kDegToRad) {
    result->rejected_by_prior = true;
    count = 0;
  }
  if (count == 0) {
    result->status = PlaneRegistrationStatus::kNoMatches;
    return true;
  }
  result->matched_planes = count;
  std::copy(matches_.begin(), matches_.begin() + count, result->matches.begin());
  result->q_cama_camb = rotation.q_a_b;
  result->cov.bottomRightCorner<3, 3>() = rotation.cov_rotvec_rad2 * config_.covariance_scale;
  result->valid = rotation.observable_dims == 3 && rotationObservable(a, count, matches_);
  result->status =
      result->valid ? PlaneRegistrationStatus::kOk : PlaneRegistrationStatus::kRotationUnobservable;
  if (result->valid) {
    result->rotation_dims = 3;
    fitTranslation(a, b, result);
  } else if (config_.subspace) {
    fitParallelRotation(a, b, result);
    fitTranslation(a, b, result);
  }
  return true;
}

}  // namespace deepnav
