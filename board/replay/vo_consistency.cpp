#include "board/replay/vo_consistency.h"

#include "board/replay/output_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include <Eigen/Cholesky>

#include "base/so3.h"

namespace deepnav {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

const Eigen::Isometry3d* truthAt(const std::vector<FrameTruthPose>& truth, TimeUs t_us) {
  const auto it = std::lower_bound(truth.begin(), truth.end(), t_us,
                                   [](const FrameTruthPose& p, TimeUs t) { return p.t_us < t; });
  return it != truth.end() && it->t_us == t_us ? &it->T_odom_cam : nullptr;
}

// e^T P^-1 e over the first `dof` components (translation first), NaN when P is not positive definite.
double neesOf(const Eigen::Matrix<double, 6, 1>& e, const Eigen::Matrix<double, 6, 6>& P, int dof) {
  const int first = 6 - dof;
  const Eigen::MatrixXd block = P.block(first, first, dof, dof);
  const Eigen::LLT<Eigen::MatrixXd> llt(block);
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::VectorXd x = e.segment(first, dof);
  return x.dot(llt.solve(x));
}

void summarise(const std::vector<VoConsistencyRow>& rows, VoSource source, VoModalityConsistency* m) {
  std::vector<double> all, fused, rejected;
  double t2 = 0.0, r2 = 0.0;
  std::array<double, 6> z2{};
  std::array<std::size_t, 6> zn{};
  for (const VoConsistencyRow& r : rows) {
    if (r.source != source) continue;
    all.push_back(r.nees);
    if (r.outcome == VoOutcome::kFused || r.outcome == VoOutcome::kQueued) fused.push_back(r.nees);
    if (r.outcome == VoOutcome::kRejected) rejected.push_back(r.nees);
    t2 += r.error.head<3>().squaredNorm();
    r2 += r.error.tail<3>().squaredNorm();
    for (int i = 6 - r.dof; i < 6; ++i) {
      if (r.sigma[i] <= 0.0) continue;
      z2[i] += (r.error[i] / r.sigma[i]) * (r.error[i] / r.sigma[i]);
      ++zn[i];
    }
  }
  int used_dof = 6;  // a modality's results all have the same dof (planes: 3 when rotation-only)
  for (const VoConsistencyRow& r : rows) {
    if (r.source == source) {
      used_dof = r.dof;
      break;
    }
  }
  m->nees = summarizeNees(all, used_dof);
  m->nees_fused = summarizeNees(fused, used_dof);
  m->nees_rejected = summarizeNees(rejected, used_dof);
  const double n = static_cast<double>(std::max<std::size_t>(all.size(), 1));
  m->translation_rms_m = std::sqrt(t2 / n);
  m->rotation_rms_deg = std::sqrt(r2 / n) * kRadToDeg;
  for (int i = 0; i < 6; ++i) m->z_rms[i] = zn[i] ? std::sqrt(z2[i] / zn[i]) : 0.0;
}

std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

std::string neesJson(const NeesSummary& n) {
  std::ostringstream o;
  o << "{\"dof\": " << n.dof << ", \"count\": " << n.count << ", \"mean\": " << num(n.mean)
    << ", \"median\": " << num(n.median) << ", \"band\": [" << num(n.band.lo) << ", " << num(n.band.hi)
    << "], \"in_band_fraction\": " << num(n.in_band_fraction) << ", \"above_fraction\": "
    << num(n.above_fraction) << ", \"below_fraction\": " << num(n.below_fraction) << "}";
  return o.str();
}

std::string modalityJson(const VoModalityConsistency& m) {
  std::ostringstream o;
  o << "{\"offered\": " << m.offered << ", \"without_truth\": " << m.without_truth
    << ", \"nees\": " << neesJson(m.nees) << ", \"nees_fused\": " << neesJson(m.nees_fused)
    << ", \"nees_rejected\": " << neesJson(m.nees_rejected) << ", \"translation_rms_m\": "
    << num(m.translation_rms_m) << ", \"rotation_rms_deg\": " << num(m.rotation_rms_deg) << ", \"z_rms\": [";
  for (int i = 0; i < 6; ++i) o << (i ? ", " : "") << num(m.z_rms[i]);
  o << "]}";
  return o.str();
}

const char* outcomeName(VoOutcome o) {
  switch (o) {
    case VoOutcome::kNone: return "none";
    case VoOutcome::kNoClone: return "no_clone";
    case VoOutcome::kUnusable: return "unusable";
    case VoOutcome::kFused: return "fused";
    case VoOutcome::kQueued: return "queued";
    case VoOutcome::kRejected: return "rejected";
    case VoOutcome::kNotFused: return "not_fused";
  }
  return "?";
}

}  // namespace

VoConsistencyRow scoreVoResult(const VoMeasurement& vo, const Eigen::Isometry3d& T_a_b_true) {
  VoConsistencyRow r;
  r.source = vo.source;
  r.t_reference_us = vo.t_reference_us;
  r.dof = vo.has_translation ? 6 : 3;
  const Eigen::Matrix3d R_meas = vo.q_cama_camb.normalized().toRotationMatrix();
  r.error.head<3>() = vo.has_translation ? Eigen::Vector3d(vo.p_camb_in_cama_m - T_a_b_true.translation())
                                         : Eigen::Vector3d::Zero();
  r.error.tail<3>() = logSo3(T_a_b_true.linear().transpose() * R_meas);
  r.sigma = vo.cov.diagonal().cwiseMax(0.0).cwiseSqrt();
  r.nees = neesOf(r.error, vo.cov, r.dof);
  return r;
}

VoConsistency computeVoConsistency(const std::vector<VoOffer>& offers, const std::vector<FrameTruthPose>& truth) {
  VoConsistency c;
  for (const VoOffer& o : offers) {
    VoModalityConsistency& m = o.vo.source == VoSource::kPlanes ? c.planes : c.orb;
    ++m.offered;
    const Eigen::Isometry3d* a = truthAt(truth, o.vo.t_reference_us);
    const Eigen::Isometry3d* b = truthAt(truth, o.t_us);
    if (!a || !b) {
      ++m.without_truth;
      continue;
    }
    VoConsistencyRow r = scoreVoResult(o.vo, a->inverse() * *b);
    r.t_us = o.t_us;
    r.outcome = o.outcome;
    c.rows.push_back(r);
  }
  summarise(c.rows, VoSource::kOrb, &c.orb);
  summarise(c.rows, VoSource::kPlanes, &c.planes);
  return c;
}

bool writeVoConsistencyCsv(const std::string& path, const VoConsistency& c, std::string* error) {
  std::ofstream out;
  if (!openOutput(&out, path, error)) return false;
  out << "t_s,t_reference_s,source,outcome,dof,nees,ex_m,ey_m,ez_m,erx_rad,ery_rad,erz_rad,"
         "sx_m,sy_m,sz_m,srx_rad,sry_rad,srz_rad\n";
  char line[512];
  for (const VoConsistencyRow& r : c.rows) {
    std::snprintf(line, sizeof line,
                  "%.6f,%.6f,%s,%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                  usToS(r.t_us), usToS(r.t_reference_us), toString(r.source), outcomeName(r.outcome), r.dof,
                  r.nees, r.error[0], r.error[1], r.error[2], r.error[3], r.error[4], r.error[5], r.sigma[0],
                  r.sigma[1], r.sigma[2], r.sigma[3], r.sigma[4], r.sigma[5]);
    out << line;
  }
  return closeOutput(&out, path, error);
}

std::string voConsistencyJson(const VoConsistency& c) {
  return "{\"orb\": " + modalityJson(c.orb) + ", \"planes\": " + modalityJson(c.planes) + "}";
}

}  // namespace deepnav
