#include "vision/calib/stereo_view_calibration.h"

#include <cmath>
#include <cstdio>

#include <opencv2/calib3d.hpp>

namespace deepnav {
namespace {

constexpr int kMinPairs = 4;

std::string format(const char* fmt, double a, double b = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, fmt, a, b);
  return buffer;
}

// Calls shared(i, j) for each corner two views share (a.ids[i] == b.ids[j]), in id order: a merge of
// the two ascending id lists.
template <class Shared>
void forEachSharedCorner(const TargetView& a, const TargetView& b, Shared shared) {
  std::size_t i = 0, j = 0;
  while (i < a.ids.size() && j < b.ids.size()) {
    if (a.ids[i] < b.ids[j]) {
      ++i;
    } else if (a.ids[i] > b.ids[j]) {
      ++j;
    } else {
      shared(i, j);
      ++i;
      ++j;
    }
  }
}

// Mean distance between the corners two views share, or a negative value when they share less than
// 80 % of the smaller view (different parts of the board: not a duplicate).
double sharedCornerMotion(const TargetView& a, const TargetView& b) {
  std::size_t shared = 0;
  double sum = 0.0;
  forEachSharedCorner(a, b, [&](std::size_t i, std::size_t j) {
    sum += cv::norm(a.corners_px[i] - b.corners_px[j]);
    ++shared;
  });
  if (shared < 0.8 * std::min(a.ids.size(), b.ids.size()) || shared == 0) return -1.0;
  return sum / static_cast<double>(shared);
}

struct KeptPair {
  std::size_t index;
  TargetView left;
  TargetView right;
};

// The screening of one pair; empty reason = keep it.
std::string screen(const TargetView& left, const TargetView& right, const ViewScreening& target,
                   const std::vector<KeptPair>& kept, const std::vector<CalibrationPairInput>& inputs) {
  const int fewest = std::min(left.ids.size(), right.ids.size());
  if (fewest < target.min_corners && target.whole_board)
    return "board not wholly seen: " + std::to_string(left.ids.size()) + " corners left, " +
           std::to_string(right.ids.size()) + " right, of " + std::to_string(target.min_corners) +
           " (a checkerboard counts only whole)";
  if (fewest < target.min_corners)
    return "too few corners: " + std::to_string(left.ids.size()) + " left, " + std::to_string(right.ids.size()) +
           " right, need " + std::to_string(target.min_corners) + " in each";
  const double widest = std::max(left.edge_width_px, right.edge_width_px);
  if (widest > target.max_edge_width_px)
    return format("blur: edges %.1f px wide, limit %.1f px (max_edge_width_px)", widest, target.max_edge_width_px);
  for (const KeptPair& k : kept) {
    const double motion_left = sharedCornerMotion(left, k.left);
    const double motion_right = sharedCornerMotion(right, k.right);
    if (motion_left >= 0.0 && motion_left < target.duplicate_px && motion_right >= 0.0 &&
        motion_right < target.duplicate_px)
      return "duplicate view of " + inputs[k.index].name +
             format(": corners moved %.1f px, less than %.1f px (duplicate_px)", motion_left, target.duplicate_px);
  }
  return "";
}

// Object points (board frame, metres) and image points of the corners both views share.
void commonCorners(const TargetView& a, const TargetView& b, const std::vector<cv::Point3f>& board_corners_m,
                   std::vector<cv::Point3f>* object, std::vector<cv::Point2f>* image_a,
                   std::vector<cv::Point2f>* image_b) {
  forEachSharedCorner(a, b, [&](std::size_t i, std::size_t j) {
    object->push_back(board_corners_m[a.ids[i]]);
    image_a->push_back(a.corners_px[i]);
    image_b->push_back(b.corners_px[j]);
  });
}

double monoCalibration(const std::vector<KeptPair>& kept, bool right, const std::vector<cv::Point3f>& board_corners_m,
                       cv::Size size, int flags, CameraCalibration* camera) {
  std::vector<std::vector<cv::Point3f>> object;
  std::vector<std::vector<cv::Point2f>> corners;
  for (const KeptPair& k : kept) {
    const TargetView& v = right ? k.right : k.left;
    corners.push_back(v.corners_px);
    object.emplace_back();
    for (int id : v.ids) object.back().push_back(board_corners_m[id]);
  }
  cv::Mat K, dist;
  const double rms = cv::calibrateCamera(object, corners, size, K, dist, cv::noArray(), cv::noArray(), flags);
  camera->K = cv::Matx33d(K);
  camera->dist = dist.reshape(1, 1).clone();
  return rms;
}

}  // namespace

bool calibrateStereoViews(const std::vector<CalibrationPairInput>& pairs, const ViewDetector& detect,
                          const std::vector<cv::Point3f>& board_corners_m, const ViewScreening& target,
                          const PairCheck& pair_check, StereoCalibrationResult* result, std::string* error) {
  *result = StereoCalibrationResult{};
  std::vector<KeptPair> kept;
  cv::Size size(0, 0);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const CalibrationPairInput& in = pairs[i];
    CalibrationPairReport report;
    report.name = in.name;
    if (in.left.empty() || in.right.empty() || in.left.size() != in.right.size() || in.left.type() != CV_8UC1 ||
        in.right.type() != CV_8UC1) {
      report.reason = "not a pair of grey images of one size";
    } else if (size.width != 0 && in.left.size() != size) {
      report.reason = "image size " + std::to_string(in.left.cols) + " x " + std::to_string(in.left.rows) +
                      " differs from the first pair's";
    } else {
      if (size.width == 0) size = in.left.size();
      TargetView left = detect(in.left);
      TargetView right = detect(in.right);
      const std::string pair_reason =
          pair_check && !left.ids.empty() && !right.ids.empty() ? pair_check(left, &right) : std::string();
      report.corners_left = static_cast<int>(left.ids.size());
      report.corners_right = static_cast<int>(right.ids.size());
      report.edge_width_left_px = left.edge_width_px;
      report.edge_width_right_px = right.edge_width_px;
      std::vector<cv::Point3f> object;
      std::vector<cv::Point2f> a, b;
      commonCorners(left, right, board_corners_m, &object, &a, &b);
      report.corners_common = static_cast<int>(object.size());
      report.reason = screen(left, right, target, kept, pairs);
      if (report.reason.empty() && report.corners_common < target.min_corners)
        report.reason = "too few corners seen by both cameras: " + std::to_string(report.corners_common) + ", need " +
                        std::to_string(target.min_corners);
      if (report.reason.empty()) report.reason = pair_reason;
      if (report.reason.empty()) kept.push_back({i, std::move(left), std::move(right)});
    }
    report.used = report.reason.empty();
    result->pairs.push_back(report);
  }
  result->pairs_used = static_cast<int>(kept.size());
  if (result->pairs_used < kMinPairs) {
    if (error)
      *error = std::to_string(result->pairs_used) + " usable pairs out of " + std::to_string(pairs.size()) +
               "; calibration needs at least " + std::to_string(kMinPairs);
    return false;
  }
  const int distortion_flags = target.fix_k3 ? cv::CALIB_FIX_K3 : 0;
  StereoCalibration& calib = result->calibration;
  calib.image_size = size;
  try {
    result->rms_left_mono_px = monoCalibration(kept, false, board_corners_m, size, distortion_flags, &calib.left);
    result->rms_right_mono_px = monoCalibration(kept, true, board_corners_m, size, distortion_flags, &calib.right);
    std::vector<std::vector<cv::Point3f>> object(kept.size());
    std::vector<std::vector<cv::Point2f>> image_left(kept.size()), image_right(kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k)
      commonCorners(kept[k].left, kept[k].right, board_corners_m, &object[k], &image_left[k], &image_right[k]);
    cv::Mat K1(calib.left.K), K2(calib.right.K), D1 = calib.left.dist.clone(), D2 = calib.right.dist.clone();
    cv::Mat R, T, E, F, per_view;
    result->rms_px = cv::stereoCalibrate(object, image_left, image_right, K1, D1, K2, D2, size, R, T, E, F, per_view,
                                         cv::CALIB_USE_INTRINSIC_GUESS | distortion_flags,
                                         cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-12));
    calib.left.K = cv::Matx33d(K1);
    calib.right.K = cv::Matx33d(K2);
    calib.left.dist = D1.reshape(1, 1).clone();
    calib.right.dist = D2.reshape(1, 1).clone();
    calib.R = cv::Matx33d(R);
    calib.T = cv::Vec3d(T);
    for (std::size_t k = 0; k < kept.size(); ++k) {
      CalibrationPairReport& report = result->pairs[kept[k].index];
      report.rms_left_px = per_view.at<double>(static_cast<int>(k), 0);
      report.rms_right_px = per_view.at<double>(static_cast<int>(k), 1);
    }
  } catch (const cv::Exception& e) {
    if (error) *error = std::string("calibration failed in OpenCV: ") + e.what();
    return false;
  }
  if (!std::isfinite(result->rms_px)) {
    if (error) *error = "calibration diverged (non-finite reprojection error)";
    return false;
  }
  return true;
}

}  // namespace deepnav
