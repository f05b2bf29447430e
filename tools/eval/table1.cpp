#include "tools/eval/table1.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

#include <Eigen/Eigenvalues>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "base/so3.h"
#include "board/config/board_overrides.h"
#include "board/config/vehicle_setup.h"
#include "drivers/replay/truth_frame_reader.h"
#include "nav/ekf/innovation_gate.h"
#include "nav/ekf/relative_pose_updater.h"
#include "vision/cloud/stereo_cloud.h"
#include "vision/planes/plane_extractor.h"
#include "vision/planes/plane_registration.h"
#include "vision/stereo/gt_disparity.h"
#include "vision/stereo/stereo_accuracy.h"
#include "vision/workspace/workspace_map.h"

namespace deepnav::eval {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
enum Backend { kGt = 0, kElas, kSgbm, kBackendCount };

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

Eigen::Isometry3d leftCameraPose(const FrameTruth& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = t.q_odom_left_cam.normalized().toRotationMatrix();
  T.translation() = t.p_left_cam_in_odom_m;
  return T;
}

// The two-sided 95 % interval of chi-square with k dof (bisection on the tail, k in [1, 6]).
std::array<double, 2> chiSquareBand(int k) {
  std::array<double, 2> q{};
  const double tails[2] = {0.975, 0.025};
  for (int j = 0; j < 2; ++j) {
    double lo = 0.0, hi = 100.0;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      (chiSquareTail(k, mid) > tails[j] ? lo : hi) = mid;
    }
    q[j] = 0.5 * (lo + hi);
  }
  return q;
}

// Error of a registration against the true relative camera pose on the directions it constrains.
struct PoseScore {
  int dof = 0;
  double nees = 0.0;
  double rot_err_rad = 0.0;
  double trans_err_m = -1.0;  // full translation only
};

PoseScore scoreRegistration(const PlaneRegistrationResult& reg, const Eigen::Isometry3d& T_true) {
  PoseScore score;
  Eigen::Matrix<double, 6, 1> e;
  const Eigen::Matrix3d R_true = T_true.linear();
  const Eigen::Matrix3d R_est = reg.q_cama_camb.normalized().toRotationMatrix();
  e.head<3>() = reg.p_camb_in_cama_m - T_true.translation();
  e.tail<3>() = logSo3(R_true.transpose() * R_est);
  MeasMatrix cov = reg.cov;
  MeasMatrix U;
  MeasVector variance;
  score.dof = relativePoseConstrainedBasis(cov, &U, &variance);
  const MeasVector e_u = U.transpose() * e;
  for (int i = 0; i < score.dof; ++i) score.nees += e_u(i) * e_u(i) / variance(i);
  score.rot_err_rad = e.tail<3>().norm();
  if (reg.has_translation && reg.translation_dims == 3) score.trans_err_m = e.head<3>().norm();
  return score;
}

// sqrt of the summed variances of a 3x3 block's constrained directions (0 when none).
double constrainedSigma(const Eigen::Matrix3d& block) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(block, Eigen::EigenvaluesOnly);
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
    if (eig.eigenvalues()(i) < kRelativePoseUnconstrainedVariance) sum += eig.eigenvalues()(i);
  return std::sqrt(sum);
}

// Mean fitted cells of the matched planes of image b.
double fittedCells(const PlaneRegistrationResult& reg, const PlaneSet& b) {
  double sum = 0.0;
  for (int i = 0; i < reg.matched_planes; ++i) sum += b[reg.matches[i].b].fit_point_count;
  return reg.matched_planes > 0 ? sum / reg.matched_planes : 0.0;
}

// One row's running sums and its two plane sets (previous and current pair).
struct RowState {
  bool run = true;
  int backend = kGt;
  bool filtered = false;
  OrganizedCloud cloud;
  PlaneSet planes[2];
  int current = 0;
  bool has_previous = false;
  cv::Mat disparity_px;  // filtered rows: the backend's map without the removed pixels
  double d1 = 0, bad_valid = 0, coverage = 0, planes_sum = 0, holes_sum = 0, ms = 0;
  int frames = 0, registrations = 0;
  std::vector<double> errors_deg, true_rotations_deg;
  int constrained = 0, full_pose = 0, in_band = 0, above_band = 0, translations = 0;
  double nees_per_dof_sum = 0.0, trans_err_sum = 0.0;
};

struct Evaluator {
  Table1Options options;
  VisionPipelineConfig vision;  // the vehicle's chain, from the stored board
  int width = 0, height = 0;    // at the matching size
  StereoCloud clouds[kBackendCount];  // GT uses computeFromDisparity only
  GtDisparity gt;
  cv::Mat truth_small_px;
  cv::Mat disparity_px[kBackendCount];
  double backend_ms[kBackendCount] = {};
  PlaneExtractor extractor;
  PlaneRegistrar registrar;
  WorkspaceMap maps[2];  // built from ELAS and from SGBM clouds
  OrganizedCloud backend_cloud[kBackendCount];
  std::array<RowState, kRowCount> rows;
  cv::Mat scored_mask;
  bool have_previous_truth = false;
  Eigen::Quaterniond q_odom_previous_cam = Eigen::Quaterniond::Identity();
  bool has_maps = true;
  Eigen::Isometry3d T_cam_rect = Eigen::Isometry3d::Identity();  // rectified (cloud) frame in the camera's
  Eigen::Isometry3d T_odom_previous_rect = Eigen::Isometry3d::Identity();
  std::array<std::array<double, 2>, 7> band{};
  std::ofstream csv;
  const char* row_names[kRowCount] = {"GT", "ELAS", "SGBM", "ELAS+Filter", "SGBM+Filter"};

  bool init(const VehicleSetup& setup, std::string* error) {
    vision = visionConfig(setup);
    T_cam_rect = robotFromCamera(setup.config).inverse() * robotFromCamera(setup);
    for (int k = 1; k <= 6; ++k) band[k] = chiSquareBand(k);
    const StereoCloudConfig& dense = vision.dense;
    StereoGeometry geometry;
    geometry.fx_px = vision.rig.fx_px;
    geometry.fy_px = vision.rig.fy_px;
    geometry.cx_px = vision.rig.cx_px;
    geometry.cy_px = vision.rig.cy_px;
    geometry.baseline_m = vision.rig.baseline_m;
    const DenseStereoMethod methods[kBackendCount] = {DenseStereoMethod::kElas, DenseStereoMethod::kElas,
                                                      DenseStereoMethod::kSgbm};
    for (int b = 0; b < kBackendCount; ++b) {
      StereoCloudConfig c = dense;
      c.method = methods[b];
      if (options.num_disparities > 0) c.num_disparities = options.num_disparities;
      if (!clouds[b].init(c, geometry, vision.width_px, vision.height_px, error) ||
          !clouds[b].allocateCloud(&backend_cloud[b]))
        return false;
    }
    num_disparities = options.num_disparities > 0 ? options.num_disparities : dense.num_disparities;
    scale = dense.scale_down;
    width = clouds[0].cols() * dense.cloud_step_px;
    height = clouds[0].rows() * dense.cloud_step_px;
    bool ok = gt.init(vision.width_px / scale, vision.height_px / scale, num_disparities) &&
              extractor.init(vision.planes.extraction, clouds[0].geometry(), clouds[0].rows(), clouds[0].cols(),
                             dense.cloud_step_px) &&
              registrar.init(registrationConfig()) && maps[0].init(vision.workspace.map) &&
              maps[1].init(vision.workspace.map);
    const int backend_of_row[kRowCount] = {kGt, kElas, kSgbm, kElas, kSgbm};
    for (int r = 0; r < kRowCount && ok; ++r) {
      rows[r].backend = backend_of_row[r];
      rows[r].filtered = r >= kRowElasFilter;
      ok = clouds[0].allocateCloud(&rows[r].cloud) && extractor.allocatePlaneSet(&rows[r].planes[0]) &&
           extractor.allocatePlaneSet(&rows[r].planes[1]);
    }
    if (!ok && error) *error = "table1: cannot initialise the plane chain from the stored board";
    return ok;
  }
  int num_disparities = 96;
  int scale = 2;

  PlaneRegistrationConfig registrationConfig() const {
    PlaneRegistrationConfig c = vision.planes.registration;
    if (options.max_turn_deg > 0.0) c.max_normal_change_deg = options.max_turn_deg;
    return c;
  }

  // The stored board must describe the rendered camera: disparity = fx B / depth.
  bool checkGeometry(const FrameTruth& t, std::string* error) const {
    if (t.depth_m.cols != vision.width_px || t.depth_m.rows != vision.height_px ||
        t.disparity_px.size() != t.depth_m.size()) {
      if (error) *error = "table1: truth maps are not of the board's camera size";
      return false;
    }
    const double fb = vision.rig.fx_px * vision.rig.baseline_m;
    for (int v = 0; v < t.depth_m.rows; v += 16) {
      for (int u = 0; u < t.depth_m.cols; u += 16) {
        const float z = t.depth_m.at<float>(v, u);
        if (z <= 0.0f) continue;
        const double expected = fb / z;
        if (std::abs(t.disparity_px.at<float>(v, u) - expected) > 0.01 + 1e-4 * expected) {
          if (error) *error = "table1: the board's camera (fx * baseline) does not match the rendered disparity";
          return false;
        }
      }
    }
    return true;
  }

  // The scored pixels (Middlebury/KITTI "non-occluded"): a true disparity in (0, max), a match inside
  // the right image (u - d >= 0), and not hidden in the right view: a pixel further right landing left
  // of it in the right image (x_r = u - d smaller) is nearer and covers it.
  static void noOcclusionMask(const cv::Mat& truth_px, float max_px, cv::Mat* mask) {
    mask->create(truth_px.size(), CV_8UC1);
    for (int v = 0; v < truth_px.rows; ++v) {
      const float* d = truth_px.ptr<float>(v);
      std::uint8_t* m = mask->ptr<std::uint8_t>(v);
      float min_right_x = INFINITY;
      for (int u = truth_px.cols - 1; u >= 0; --u) {
        const bool surface = d[u] > 0.0f;
        const float x_r = surface ? static_cast<float>(u) - d[u] : INFINITY;
        m[u] = surface && d[u] < max_px && x_r >= 0.0f && x_r <= min_right_x + 0.5f ? 255 : 0;
        min_right_x = std::min(min_right_x, x_r);
      }
    }
  }

  bool isMapPair(int index, TimeUs t_us) const {
    const double t_s = usToS(t_us);
    return index % options.map_every == 0 && t_s >= options.map_from_s && t_s < options.map_to_s;
  }

  // The true disparity at the matching size: the full-size pixel (s u, s v), divided by s.
  void reduceTruth(const FrameTruth& truth) {
    cv::resize(truth.disparity_px, truth_small_px, cv::Size(vision.width_px / scale, vision.height_px / scale), 0, 0,
               cv::INTER_NEAREST);
    truth_small_px *= 1.0 / scale;
  }

  bool computeBackend(int b, const StereoFrame& pair) {
    const auto t0 = Clock::now();
    bool ok = false;
    if (b == kGt) {
      ok = gt.setTruth(truth_small_px) && gt.compute(truth_small_px, truth_small_px, &disparity_px[kGt]) &&
           clouds[kGt].computeFromDisparity(disparity_px[kGt], &backend_cloud[kGt]);
    } else {
      ok = clouds[b].compute(pair.left, pair.right, &backend_cloud[b]);
      disparity_px[b] = clouds[b].disparity();
    }
    backend_ms[b] = msSince(t0);
    return ok;
  }

  // Stage 1: the pair's ELAS and SGBM clouds (mixed pixels removed, as the vehicle's StereoCloud does)
  // into their maps.
  bool insertIntoMaps(const StereoFrame& pair, const FrameTruth& truth) {
    for (int m = 0; m < 2; ++m) {
      if (!rows[m == 0 ? kRowElasFilter : kRowSgbmFilter].run) continue;
      const int b = m == 0 ? kElas : kSgbm;
      if (!computeBackend(b, pair)) return false;
      maps[m].insert(backend_cloud[b], leftCameraPose(truth));  // false only for a cloud without points
    }
    return true;
  }

  // The backend's disparity without the pixels whose point the map filter removed.
  void maskRemoved(const cv::Mat& disparity, const OrganizedCloud& unfiltered, const OrganizedCloud& kept,
                   cv::Mat* out) const {
    disparity.copyTo(*out);
    const int step = vision.dense.cloud_step_px;
    for (int v = 0; v < out->rows; ++v) {
      const int r = std::min(v / step, kept.rows() - 1);
      float* d = out->ptr<float>(v);
      for (int u = 0; u < out->cols; ++u) {
        const int c = std::min(u / step, kept.cols() - 1);
        if (OrganizedCloud::isValid(unfiltered.row(r)[c]) && !OrganizedCloud::isValid(kept.row(r)[c]))
          d[u] = kInvalidDisparity;
      }
    }
  }

  // Runs every row on one pair; scores it when `score`.
  bool backendUsed(int b) const {
    for (const RowState& row : rows)
      if (row.run && row.backend == b) return true;
    return false;
  }

  void scorePose(int r, const PlaneRegistrationResult& reg, const Eigen::Isometry3d& T_true, TimeUs t_us,
                 const PlaneSet& b) {
    RowState& row = rows[r];
    if (reg.rotation_dims == 0 && reg.translation_dims == 0) return;
    const PoseScore p = scoreRegistration(reg, T_true);
    if (p.dof == 0) return;
    ++row.constrained;
    row.full_pose += p.dof == 6 ? 1 : 0;
    row.nees_per_dof_sum += p.nees / p.dof;
    row.in_band += p.nees >= band[p.dof][0] && p.nees <= band[p.dof][1] ? 1 : 0;
    row.above_band += p.nees > band[p.dof][1] ? 1 : 0;
    if (p.trans_err_m >= 0.0) {
      ++row.translations;
      row.trans_err_sum += p.trans_err_m;
    }
    if (!csv.is_open()) return;
    const Eigen::AngleAxisd turn(T_true.linear());
    csv << row_names[r] << ',' << usToS(t_us) << ',' << reg.matched_planes << ',' << reg.rotation_dims << ','
        << reg.translation_dims << ',' << p.dof << ',' << p.nees << ',' << p.rot_err_rad * kRadToDeg << ','
        << p.trans_err_m << ',' << constrainedSigma(reg.cov.bottomRightCorner<3, 3>()) * kRadToDeg << ','
        << constrainedSigma(reg.cov.topLeftCorner<3, 3>()) << ','
        << turn.angle() * kRadToDeg << ',' << T_true.translation().norm() << ',' << fittedCells(reg, b) << '\n';
  }

  bool process(const StereoFrame& pair, const FrameTruth& truth, bool score) {
    if (has_maps) reduceTruth(truth);
    for (int b = 0; b < kBackendCount; ++b)
      if (backendUsed(b) && !computeBackend(b, pair)) return false;
    if (has_maps) noOcclusionMask(truth_small_px, static_cast<float>(num_disparities), &scored_mask);
    const Eigen::Quaterniond q_cam = truth.q_odom_left_cam.normalized();
    const Eigen::Quaterniond q_true = q_odom_previous_cam.conjugate() * q_cam;
    const Eigen::Isometry3d T_odom_rect = leftCameraPose(truth) * T_cam_rect;
    const Eigen::Isometry3d T_true = T_odom_previous_rect.inverse() * T_odom_rect;
    for (int r = 0; r < kRowCount; ++r) {
      RowState& row = rows[r];
      if (!row.run) continue;
      const auto t0 = Clock::now();
      const cv::Mat* disparity = &disparity_px[row.backend];
      backend_cloud[row.backend].p_point_in_cam_m.copyTo(row.cloud.p_point_in_cam_m);
      if (row.filtered) {
        maps[row.backend == kElas ? 0 : 1].filter(leftCameraPose(truth), &row.cloud);
        maskRemoved(*disparity, backend_cloud[row.backend], row.cloud, &row.disparity_px);
        disparity = &row.disparity_px;
      }
      PlaneSet& planes = row.planes[row.current];
      extractor.extract(row.cloud, &planes);
      PlaneRegistrationResult reg;
      const bool ran = row.has_previous && registrar.registerPlanes(row.planes[1 - row.current], planes, &reg);
      const bool registered = ran && reg.valid;
      const double chain_ms = msSince(t0);
      if (score) {
        ++row.frames;
        if (has_maps) {
          const StereoAccuracy acc = evaluateDisparity(*disparity, truth_small_px, scored_mask);
          row.d1 += acc.d1;
          row.coverage += acc.coverage;
          row.bad_valid +=
              acc.coverage > 0.0 ? std::clamp((acc.d1 - (1.0 - acc.coverage)) / acc.coverage, 0.0, 1.0) : 0.0;
        }
        row.planes_sum += planes.size();
        for (int i = 0; i < planes.size(); ++i) row.holes_sum += planes.holeCount(i);
        row.ms += backend_ms[row.backend] + chain_ms;
        if (row.has_previous && have_previous_truth) {
          ++row.registrations;
          if (ran) scorePose(r, reg, T_true, truth.t_us, planes);
          if (registered) {
            const Eigen::Quaterniond q_est = reg.q_cama_camb.normalized();
            row.errors_deg.push_back(q_est.angularDistance(q_true) * kRadToDeg);
            row.true_rotations_deg.push_back(Eigen::Quaterniond::Identity().angularDistance(q_true) * kRadToDeg);
          }
        }
      }
      row.has_previous = true;
      row.current = 1 - row.current;
    }
    q_odom_previous_cam = q_cam;
    T_odom_previous_rect = T_odom_rect;
    have_previous_truth = true;
    return true;
  }

  // Disparities as 8-bit (255 = num_disparities, 0 = none) next to the pair, for a look.
  void dump(const std::string& dir, const StereoFrame& pair) const {
    cv::imwrite(dir + "/left.png", pair.left);
    cv::imwrite(dir + "/right.png", pair.right);
    const char* names[kBackendCount] = {"gt", "elas", "sgbm"};
    for (int b = 0; b < kBackendCount; ++b) {
      cv::Mat d8;
      disparity_px[b].convertTo(d8, CV_8U, 255.0 / num_disparities);
      cv::imwrite(dir + "/disparity_" + names[b] + ".png", d8);
    }
    cv::imwrite(dir + "/scored_mask.png", scored_mask);
    cv::Mat d8;
    truth_small_px.convertTo(d8, CV_8U, 255.0 / num_disparities);
    cv::imwrite(dir + "/disparity_truth.png", d8);
  }

  void summarise(Table1Result* result) const {
    const char* names[kRowCount] = {"GT", "ELAS", "SGBM", "ELAS+Filter", "SGBM+Filter"};
    for (int r = 0; r < kRowCount; ++r) {
      const RowState& s = rows[r];
      Table1Row& out = result->rows[r];
      out = Table1Row{};
      out.name = names[r];
      out.ran = s.run;
      out.frames = s.frames;
      out.constrained = s.constrained;
      out.full_pose = s.full_pose;
      out.translations = s.translations;
      if (s.constrained > 0) {
        out.nees_per_dof_mean = s.nees_per_dof_sum / s.constrained;
        out.nees_in_band = static_cast<double>(s.in_band) / s.constrained;
        out.nees_above_band = static_cast<double>(s.above_band) / s.constrained;
      }
      if (s.translations > 0) out.trans_err_mean_m = s.trans_err_sum / s.translations;
      const double n = std::max(1, s.frames);
      out.d1_mean = s.d1 / n;
      out.bad_valid_mean = s.bad_valid / n;
      out.coverage_mean = s.coverage / n;
      out.planes_mean = s.planes_sum / n;
      out.holes_mean = s.holes_sum / n;
      out.ms_per_frame = s.ms / n;
      out.registrations = s.registrations;
      out.registered = static_cast<int>(s.errors_deg.size());
      if (s.errors_deg.empty()) continue;
      const double k = static_cast<double>(s.errors_deg.size());
      double sum = 0, sum2 = 0, sum_true = 0;
      for (std::size_t i = 0; i < s.errors_deg.size(); ++i) {
        sum += s.errors_deg[i];
        sum2 += s.errors_deg[i] * s.errors_deg[i];
        sum_true += s.true_rotations_deg[i];
      }
      out.rot_err_mean_deg = sum / k;
      out.rot_err_std_deg = std::sqrt(std::max(0.0, sum2 / k - out.rot_err_mean_deg * out.rot_err_mean_deg));
      out.rot_err_max_deg = *std::max_element(s.errors_deg.begin(), s.errors_deg.end());
      std::vector<double> sorted = s.errors_deg;
      std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
      out.rot_err_median_deg = sorted[sorted.size() / 2];
      out.true_rotation_mean_deg = sum_true / k;
    }
  }
};

}  // namespace

bool runTable1(const std::string& path, const Table1Options& options, Table1Result* result, std::string* error) {
  *result = Table1Result{};
  result->recording = path;
  result->options = options;
  if (options.num_disparities != 0 && (options.num_disparities < 16 || options.num_disparities > 256)) {
    if (error) *error = "table1: num_disparities must be 0 (the board's) or in [16, 256]";
    return false;
  }
  TruthFrameReader reader;
  if (!reader.open(path, error)) return false;
  if (!reader.hasImages() || reader.count(Topic::kFrameTruth) == 0) {
    if (error) *error = path + ": needs rendered stereo pairs and their true poses (/truth/frame)";
    return false;
  }
  result->truth_maps = reader.hasMaps();
  VehicleSetup setup;
  bool found = false;
  if (!setupFromMetadata(reader.metadata("deepnav.board"), reader.metadata("deepnav.panel"), path + " (stored board)",
                         &setup, error, &found))
    return false;
  if (!found) {
    if (error) *error = path + ": no board stored in the recording (deepnav.board metadata)";
    return false;
  }
  if (!options.overrides.empty() && !applyBoardOverrides(options.overrides, &setup, error)) return false;
  auto ev = std::make_unique<Evaluator>();
  ev->options = options;
  ev->has_maps = result->truth_maps;
  const char* keys[kRowCount] = {"gt", "elas", "sgbm", "elas-filter", "sgbm-filter"};
  for (int r = 0; r < kRowCount; ++r) {
    const std::string list = "," + options.rows + ",";
    ev->rows[r].run = (options.rows.empty() || list.find(std::string(",") + keys[r] + ",") != std::string::npos) &&
                      (r != kRowGt || ev->has_maps);
  }
  if (!options.registrations_csv.empty()) {
    ev->csv.open(options.registrations_csv);
    if (!ev->csv) {
      if (error) *error = "table1: cannot write " + options.registrations_csv;
      return false;
    }
    ev->csv << "row,t_s,matched,rotation_dims,translation_dims,dof,nees,rot_err_deg,trans_err_m,rot_sigma_deg,"
               "trans_sigma_m,true_turn_deg,true_move_m,fitted_cells\n";
  }
  if (ev->options.map_every <= 0) {
    ev->options.map_every = std::max(1, setup.config.vision.workspace.insert_every_n_frames);
  }
  if (!ev->init(setup, error)) return false;
  result->options.map_every = ev->options.map_every;
  result->options.num_disparities = ev->num_disparities;
  result->scale_down = ev->scale;

  // Pass 1: the stage-1 maps (when a Filter row runs).
  int index = 0;
  bool ok = true;
  std::string failure;
  const bool filter_rows = ev->rows[kRowElasFilter].run || ev->rows[kRowSgbmFilter].run;
  const bool read1 = !filter_rows || reader.forEach(
      [&](const StereoFrame* pair, const FrameTruth& truth) {
        if (index == 0 && ev->has_maps && !ev->checkGeometry(truth, &failure)) return ok = false;
        if (ev->isMapPair(index, truth.t_us)) {
          if (!ev->insertIntoMaps(*pair, truth)) {
            failure = path + ": stereo failed on the pair at t = " + std::to_string(usToS(truth.t_us)) + " s";
            return ok = false;
          }
          ++result->map_frames;
        }
        ++index;
        return true;
      },
      error);
  if (!read1) return false;
  if (!ok || (filter_rows && (result->map_frames == 0 || !ev->maps[0].freeze() || !ev->maps[1].freeze()))) {
    if (error) *error = !failure.empty() ? failure : path + ": no stage-1 map (no pair in the map window, or too large)";
    return false;
  }
  result->map_voxels_elas = ev->maps[0].occupiedVoxelCount();
  result->map_voxels_sgbm = ev->maps[1].occupiedVoxelCount();
  if (options.progress)
    std::fprintf(stderr, "table1: stage-1 maps from %d pairs (%zu / %zu voxels)\n", result->map_frames,
                 result->map_voxels_elas, result->map_voxels_sgbm);

  // Pass 2: score. The pair just before the first scored one is processed too (registration needs it).
  index = 0;
  int scored = 0;
  const TimeUs eval_from_us = static_cast<TimeUs>(options.eval_from_s * 1e6);
  const TimeUs camera_period_us = static_cast<TimeUs>(1e6 / std::max(0.1, setup.config.camera.rate_hz));
  const bool read2 = reader.forEach(
      [&](const StereoFrame* pair, const FrameTruth& truth) {
        const int i = index++;
        if (truth.t_us + camera_period_us < eval_from_us) return true;
        const bool score = truth.t_us >= eval_from_us && !ev->isMapPair(i, truth.t_us);
        if (!ev->process(*pair, truth, score)) {
          failure = path + ": chain failed on the pair at t = " + std::to_string(usToS(truth.t_us)) + " s";
          return ok = false;
        }
        if (score) {
          if (scored == 0 && !options.dump_dir.empty()) ev->dump(options.dump_dir, *pair);
          if (scored == 0) result->first_scored_t_s = usToS(truth.t_us);
          result->last_scored_t_s = usToS(truth.t_us);
          ++scored;
          if (options.progress && scored % 50 == 0) std::fprintf(stderr, "table1: %d pairs scored\n", scored);
        }
        return options.max_frames <= 0 || scored < options.max_frames;
      },
      error);
  if (!read2) return false;
  if (!ok || scored == 0) {
    if (error) *error = !failure.empty() ? failure : path + ": no stereo pair to score after eval_from_s";
    return false;
  }
  ev->summarise(result);
  return true;
}

namespace {

int scoredPairs(const Table1Result& r) {
  int n = 0;
  for (const Table1Row& row : r.rows) n = std::max(n, row.frames);
  return n;
}

}  // namespace

std::string table1Markdown(const Table1Result& r) {
  std::ostringstream s;
  char line[512];
  s << "| method | D1 (%) | bad, valid px (%) | coverage (%) | planes | holes | rotation error (deg) | median (deg) "
       "| registered | ms/pair |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Table1Row& row : r.rows) {
    if (!row.ran) continue;
    std::snprintf(line, sizeof(line), "| %s | %.2f | %.2f | %.1f | %.2f | %.2f | %.2f ± %.2f | %.2f | %d / %d | %.0f |\n",
                  row.name.c_str(), 100.0 * row.d1_mean, 100.0 * row.bad_valid_mean, 100.0 * row.coverage_mean,
                  row.planes_mean, row.holes_mean, row.rot_err_mean_deg, row.rot_err_std_deg, row.rot_err_median_deg,
                  row.registered, row.registrations, row.ms_per_frame);
    s << line;
  }
  std::snprintf(line, sizeof(line),
                "\n%d pairs scored (t = %.1f .. %.1f s), stage-1 map from %d pairs (every %d-th pair in [%.0f, %.0f) s: "
                "%zu voxels ELAS, %zu SGBM), matching at 1/%d size with %d disparities.\n",
                scoredPairs(r), r.first_scored_t_s, r.last_scored_t_s, r.map_frames, r.options.map_every,
                r.options.map_from_s, std::min(r.options.map_to_s, 1e6), r.map_voxels_elas, r.map_voxels_sgbm,
                r.scale_down, r.options.num_disparities);
  s << line;
  s << "\nRelative poses against the true camera motion (constrained directions only):\n\n"
       "| method | constrained / registrations | 6-DoF | NEES/dof | NEES in 95 % band | above | translation error (m) |\n"
       "|---|---|---|---|---|---|---|\n";
  for (const Table1Row& row : r.rows) {
    if (!row.ran) continue;
    std::snprintf(line, sizeof(line), "| %s | %d / %d | %d | %.2f | %.0f %% | %.0f %% | %.3f (%d) |\n", row.name.c_str(),
                  row.constrained, row.registrations, row.full_pose, row.nees_per_dof_mean, 100.0 * row.nees_in_band,
                  100.0 * row.nees_above_band, row.trans_err_mean_m, row.translations);
    s << line;
  }
  if (!r.truth_maps) s << "\nNo truth maps in the recording: D1, bad and coverage are not scored.\n";
  return s.str();
}

std::string table1Json(const Table1Result& r) {
  std::ostringstream s;
  char buf[1024];
  s << "{\n  \"recording\": \"" << r.recording << "\",\n";
  std::snprintf(buf, sizeof(buf),
                "  \"scored_pairs\": %d,\n  \"first_scored_t_s\": %.3f,\n  \"last_scored_t_s\": %.3f,\n"
                "  \"map_pairs\": %d,\n  \"map_every\": %d,\n  \"map_from_s\": %.3f,\n  \"map_to_s\": %.3f,\n"
                "  \"map_voxels_elas\": %zu,\n  \"map_voxels_sgbm\": %zu,\n  \"num_disparities\": %d,\n  \"rows\": [\n",
                scoredPairs(r), r.first_scored_t_s, r.last_scored_t_s, r.map_frames, r.options.map_every,
                r.options.map_from_s, std::min(r.options.map_to_s, 1e6), r.map_voxels_elas, r.map_voxels_sgbm,
                r.options.num_disparities);
  s << buf;
  for (int i = 0; i < kRowCount; ++i) {
    const Table1Row& row = r.rows[i];
    std::snprintf(buf, sizeof(buf),
                  "    {\"name\": \"%s\", \"frames\": %d, \"d1\": %.6f, \"bad_valid\": %.6f, \"coverage\": %.6f, "
                  "\"planes\": %.4f, \"holes\": %.4f, \"registrations\": %d, \"registered\": %d, "
                  "\"rot_err_mean_deg\": %.4f, \"rot_err_std_deg\": %.4f, \"rot_err_median_deg\": %.4f, "
                  "\"rot_err_max_deg\": %.4f, \"true_rotation_mean_deg\": %.4f, \"ms_per_pair\": %.2f, "
                  "\"ran\": %s, \"constrained\": %d, \"full_pose\": %d, \"nees_per_dof_mean\": %.4f, "
                  "\"nees_in_band\": %.4f, \"nees_above_band\": %.4f, \"trans_err_mean_m\": %.4f, "
                  "\"translations\": %d}%s\n",
                  row.name.c_str(), row.frames, row.d1_mean, row.bad_valid_mean, row.coverage_mean, row.planes_mean,
                  row.holes_mean, row.registrations, row.registered, row.rot_err_mean_deg, row.rot_err_std_deg,
                  row.rot_err_median_deg, row.rot_err_max_deg, row.true_rotation_mean_deg, row.ms_per_frame,
                  row.ran ? "true" : "false", row.constrained, row.full_pose, row.nees_per_dof_mean, row.nees_in_band,
                  row.nees_above_band, row.trans_err_mean_m, row.translations, i + 1 < kRowCount ? "," : "");
    s << buf;
  }
  s << "  ]\n}\n";
  return s.str();
}

}  // namespace deepnav::eval
