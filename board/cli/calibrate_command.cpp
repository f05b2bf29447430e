#include "board/cli/calibrate_command.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <yaml-cpp/yaml.h>

#include "board/config/param_table.h"
#include "board/config/stereo_calibration_file.h"
#include "board/config/text_file.h"
#include "board/config/yaml_document.h"
#include "drivers/replay/recording_reader.h"
#include "vision/calib/stereo_charuco_calibration.h"
#include "vision/calib/stereo_checkerboard_calibration.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;
using P = ParamSpec<CharucoTarget>;

#define DEEPNAV_FIELD(expr) [](CharucoTarget& t) -> void* { return &t.expr; }

const std::array kTargetParams = {
    P{"squares_x", ParamType::kInt, "squares", 3, 100, "8", "", "chessboard squares along the board's x",
      DEEPNAV_FIELD(squares_x)},
    P{"squares_y", ParamType::kInt, "squares", 3, 100, "6", "", "chessboard squares along y", DEEPNAV_FIELD(squares_y)},
    P{"square_m", ParamType::kDouble, "m", 0.001, 1.0, "0.06", "", "side of a printed square, as measured",
      DEEPNAV_FIELD(square_m)},
    P{"marker_m", ParamType::kDouble, "m", 0.001, 1.0, "0.045", "", "side of a printed marker, as measured",
      DEEPNAV_FIELD(marker_m)},
    P{"dictionary", ParamType::kString, "-", 0, 0, "DICT_5X5_100", "", "OpenCV predefined ArUco dictionary",
      DEEPNAV_FIELD(dictionary)},
    P{"min_corners", ParamType::kInt, "corners", 6, 10000, "12", "", "corners a view needs in each camera",
      DEEPNAV_FIELD(min_corners)},
    P{"max_edge_width_px", ParamType::kDouble, "px", 1.0, 50.0, "3.5", "", "views with wider edges are blurred",
      DEEPNAV_FIELD(max_edge_width_px)},
    P{"duplicate_px", ParamType::kDouble, "px", 0.0, 100.0, "4.0", "",
      "views whose corners moved less than this from a kept view are duplicates", DEEPNAV_FIELD(duplicate_px)},
    P{"fix_k3", ParamType::kBool, "-", 0, 0, "true", "", "estimate k1 k2 p1 p2 only", DEEPNAV_FIELD(fix_k3)},
};

#undef DEEPNAV_FIELD

using C = ParamSpec<CheckerboardTarget>;

#define DEEPNAV_FIELD(expr) [](CheckerboardTarget& t) -> void* { return &t.expr; }

// inner_corners ([cols, rows]) is read apart: a pair of integers has no ParamType.
const std::array kCheckerboardParams = {
    C{"square_m", ParamType::kDouble, "m", 0.001, 1.0, "0.025", "", "side of a printed square, as measured",
      DEEPNAV_FIELD(square_m)},
    C{"max_edge_width_px", ParamType::kDouble, "px", 1.0, 50.0, "3.5", "", "views with wider edges are blurred",
      DEEPNAV_FIELD(max_edge_width_px)},
    C{"duplicate_px", ParamType::kDouble, "px", 0.0, 100.0, "4.0", "",
      "views whose corners moved less than this from a kept view are duplicates", DEEPNAV_FIELD(duplicate_px)},
    C{"fix_k3", ParamType::kBool, "-", 0, 0, "true", "", "estimate k1 k2 p1 p2 only", DEEPNAV_FIELD(fix_k3)},
};

#undef DEEPNAV_FIELD

constexpr std::array kRequiredKeys = {"squares_x", "squares_y", "square_m", "marker_m", "dictionary"};

bool isImageFile(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* known : {".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff", ".pgm", ".ppm"})
    if (ext == known) return true;
  return false;
}

cv::Mat toGrey(const cv::Mat& image) {
  cv::Mat grey;
  if (image.channels() == 3) {
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  } else if (image.channels() == 4) {
    cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  } else {
    grey = image.clone();
  }
  if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U, grey.depth() == CV_16U ? 1.0 / 257.0 : 1.0);
  return grey;
}

// Image files name their camera: "...left..." pairs with the same name with "right".
bool addImagePair(const fs::path& left_path, std::vector<CalibrationPairInput>* pairs, std::string* error) {
  std::string name = left_path.filename().string();
  const std::size_t at = name.rfind("left");
  const fs::path right_path = left_path.parent_path() / name.replace(at, 4, "right");
  if (!fs::exists(right_path)) {
    *error = left_path.string() + ": no matching right image " + right_path.string();
    return false;
  }
  CalibrationPairInput in;
  in.name = left_path.filename().string();
  in.left = cv::imread(left_path.string(), cv::IMREAD_GRAYSCALE);
  in.right = cv::imread(right_path.string(), cv::IMREAD_GRAYSCALE);
  if (in.left.empty() || in.right.empty()) {
    *error = (in.left.empty() ? left_path : right_path).string() + ": cannot read the image";
    return false;
  }
  pairs->push_back(std::move(in));
  return true;
}

bool addRecording(const std::string& path, int every, std::vector<CalibrationPairInput>* pairs, std::string* error) {
  RecordingReader reader;
  if (!reader.open(path, error)) return false;
  std::uint64_t frame_index = 0;
  const bool ok = reader.forEach(
      true,
      [&](const ReplayEvent& e) {
        if (e.kind != ReplayEvent::Kind::kFrame || e.frame == nullptr) return true;
        if (frame_index++ % static_cast<std::uint64_t>(every) != 0) return true;
        CalibrationPairInput in;
        in.name = fs::path(path).filename().string() + "#" + std::to_string(e.frame->sequence);
        in.left = toGrey(e.frame->left);
        in.right = toGrey(e.frame->right);
        pairs->push_back(std::move(in));
        return true;
      },
      error);
  if (ok && frame_index == 0) {
    *error = path + ": the recording holds no stereo images";
    return false;
  }
  return ok;
}

bool collectPairs(const CalibrateCommandOptions& o, std::vector<CalibrationPairInput>* pairs, std::string* error) {
  for (const std::string& input : o.inputs) {
    const fs::path p(input);
    if (!fs::exists(p)) {
      *error = input + ": no such file or folder";
      return false;
    }
    if (p.extension() == ".mcap") {
      if (!addRecording(input, o.every, pairs, error)) return false;
      continue;
    }
    std::vector<fs::path> files;
    if (fs::is_directory(p)) {
      for (const auto& entry : fs::directory_iterator(p))
        if (entry.is_regular_file() && isImageFile(entry.path())) files.push_back(entry.path());
      std::sort(files.begin(), files.end());
    } else {
      files.push_back(p);
    }
    for (const fs::path& f : files) {
      const std::string name = f.filename().string();
      if (name.find("left") != std::string::npos) {
        if (!addImagePair(f, pairs, error)) return false;
      } else if (name.find("right") == std::string::npos) {
        *error = f.string() + ": cannot tell the camera; name the images *left* and *right* (e.g. left_000.png, "
                              "right_000.png)";
        return false;
      }
    }
  }
  if (pairs->empty()) {
    *error = "no stereo pairs found in the inputs";
    return false;
  }
  return true;
}

void printPairReports(const StereoCalibrationResult& r) {
  std::printf("%-28s %-8s %7s %7s %7s %11s %13s  %s\n", "pair", "status", "left", "right", "common", "edge (px)",
              "rms L/R (px)", "reason");
  for (const auto& p : r.pairs) {
    char rms[32] = "-";
    if (p.used) std::snprintf(rms, sizeof rms, "%.3f/%.3f", p.rms_left_px, p.rms_right_px);
    std::printf("%-28s %-8s %7d %7d %7d %5.2f/%5.2f %13s  %s\n", p.name.c_str(), p.used ? "used" : "rejected",
                p.corners_left, p.corners_right, p.corners_common, p.edge_width_left_px, p.edge_width_right_px, rms,
                p.reason.c_str());
  }
}

void printRow(const char* key, const double* v, int n) {
  std::printf("  %s: [", key);
  for (int i = 0; i < n; ++i) std::printf("%s%.8g", i ? ", " : "", v[i]);
  std::printf("]\n");
}

// sensor_msgs/CameraInfo fields of both cameras, rectified with the plain pinhole model.
void printCameraInfo(const StereoCalibration& c) {
  cv::Mat R1, R2, P1, P2, Q;
  cv::stereoRectify(c.left.K, c.left.dist, c.right.K, c.right.dist, c.image_size, c.R, c.T, R1, R2, P1, P2, Q,
                    cv::CALIB_ZERO_DISPARITY, 0.0, c.image_size);
  for (int side = 0; side < 2; ++side) {
    const CameraCalibration& cam = side == 0 ? c.left : c.right;
    const cv::Mat& R = side == 0 ? R1 : R2;
    const cv::Mat& P = side == 0 ? P1 : P2;
    std::printf("%s camera_info:\n  width: %d\n  height: %d\n  distortion_model: %s\n", side == 0 ? "left" : "right",
                c.image_size.width, c.image_size.height, cam.dist.total() <= 5 ? "plumb_bob" : "rational_polynomial");
    std::vector<double> d(cam.dist.begin<double>(), cam.dist.end<double>());
    if (cam.dist.total() < 5) d.resize(5, 0.0);
    printRow("D", d.data(), static_cast<int>(d.size()));
    printRow("K", cam.K.val, 9);
    printRow("R", R.ptr<double>(), 9);
    printRow("P", P.ptr<double>(), 12);
  }
}

}  // namespace

namespace {

bool readTargetRoot(const std::string& path, YAML::Node* root, std::string* error) {
  std::string text;
  if (!readTextFile(path, "the calibration target", &text, error)) return false;
  if (!parseYamlDocument(text, path, root, error)) return false;
  if (!root->IsMap()) {
    *error = path + ": expected a map of keys (type, and squares_x, squares_y, square_m, marker_m, dictionary for "
                    "ChArUco or inner_corners, square_m for a checkerboard)";
    return false;
  }
  return true;
}

bool applyCharucoTarget(const YAML::Node& root, const std::string& path, CharucoTarget* target, std::string* error) {
  for (const char* key : kRequiredKeys) {
    if (!root[key]) {
      *error = path + ": key '" + key + "' is missing; the target's geometry must be given (measure the print)";
      return false;
    }
  }
  CharucoTarget t;
  if (!applyParams(bindParams(kTargetParams, t), root, path, error)) return false;
  std::string why;
  if (!validateCharucoTarget(t, &why)) {
    *error = path + ": " + why;
    return false;
  }
  *target = t;
  return true;
}

bool readInnerCorners(const YAML::Node& node, const std::string& path, CheckerboardTarget* t, std::string* error) {
  const std::string bad = path + ": key 'inner_corners' must be [cols, rows]: the inner corners (where four squares "
                                 "meet) along a row and along a column, integers from 3 to 100";
  if (!node.IsSequence() || node.size() != 2) {
    *error = bad;
    return false;
  }
  int counts[2] = {0, 0};
  for (std::size_t i = 0; i < 2; ++i) {
    try {
      counts[i] = node[i].as<int>();
    } catch (const YAML::Exception&) {
      *error = bad;
      return false;
    }
    if (counts[i] < 3 || counts[i] > 100) {
      *error = bad;
      return false;
    }
  }
  t->inner_cols = counts[0];
  t->inner_rows = counts[1];
  return true;
}

bool applyCheckerboardTarget(YAML::Node root, const std::string& path, CheckerboardTarget* target,
                             std::string* error) {
  for (const char* key : {"inner_corners", "square_m"}) {
    if (!root[key]) {
      *error = path + ": key '" + key + "' is missing; a checkerboard target needs inner_corners: [cols, rows] and "
                                        "square_m (measure the print)";
      return false;
    }
  }
  CheckerboardTarget t;
  if (!readInnerCorners(root["inner_corners"], path, &t, error)) return false;
  root.remove("inner_corners");
  if (!applyParams(bindParams(kCheckerboardParams, t), root, path, error)) return false;
  std::string why;
  if (!validateCheckerboardTarget(t, &why)) {
    *error = path + ": " + why;
    return false;
  }
  *target = t;
  return true;
}

std::string describeTarget(const CalibrationTargetFile& f) {
  char text[200];
  if (f.type == "checkerboard") {
    const CheckerboardTarget& t = f.checkerboard;
    std::snprintf(text, sizeof text, "checkerboard %d x %d inner corners, square %.4f m", t.inner_cols, t.inner_rows,
                  t.square_m);
  } else {
    const CharucoTarget& t = f.charuco;
    std::snprintf(text, sizeof text, "ChArUco %d x %d, square %.4f m, marker %.4f m, %s", t.squares_x, t.squares_y,
                  t.square_m, t.marker_m, t.dictionary.c_str());
  }
  return text;
}

}  // namespace

bool loadCharucoTarget(const std::string& path, CharucoTarget* target, std::string* error) {
  YAML::Node root;
  return readTargetRoot(path, &root, error) && applyCharucoTarget(root, path, target, error);
}

bool loadCalibrationTarget(const std::string& path, CalibrationTargetFile* target, std::string* error) {
  YAML::Node root;
  if (!readTargetRoot(path, &root, error)) return false;
  CalibrationTargetFile out;
  if (root["type"]) {
    const YAML::Node type = root["type"];
    out.type = type.IsScalar() ? type.Scalar() : "";
    if (out.type != "charuco" && out.type != "checkerboard") {
      *error = path + ": key 'type' must be charuco or checkerboard";
      return false;
    }
    root.remove("type");
  }
  const bool ok = out.type == "checkerboard" ? applyCheckerboardTarget(root, path, &out.checkerboard, error)
                                             : applyCharucoTarget(root, path, &out.charuco, error);
  if (!ok) return false;
  *target = out;
  return true;
}

int runCalibrateCommand(const CalibrateCommandOptions& o) {
  CalibrationTargetFile target;
  std::string error;
  if (!loadCalibrationTarget(o.target_path, &target, &error)) {
    std::fprintf(stderr, "deepnav calibrate: %s\n", error.c_str());
    return 2;
  }
  std::vector<CalibrationPairInput> pairs;
  if (!collectPairs(o, &pairs, &error)) {
    std::fprintf(stderr, "deepnav calibrate: %s\n", error.c_str());
    return 2;
  }
  StereoCalibrationResult result;
  const bool ok = target.type == "checkerboard"
                      ? calibrateStereoCheckerboard(pairs, target.checkerboard, &result, &error)
                      : calibrateStereoCharuco(pairs, target.charuco, &result, &error);
  printPairReports(result);
  if (!ok) {
    std::fprintf(stderr, "deepnav calibrate: %s\n", error.c_str());
    return 1;
  }
  const StereoCalibration& c = result.calibration;
  std::printf("\n%d of %zu pairs used; reprojection error %.3f px (stereo), %.3f / %.3f px (left / right alone)\n",
              result.pairs_used, result.pairs.size(), result.rms_px, result.rms_left_mono_px, result.rms_right_mono_px);
  std::printf("baseline %.4f m\n\n", cv::norm(c.T));
  printCameraInfo(c);
  StereoCalibrationInfo info;
  info.rms_px = result.rms_px;
  info.pairs_used = result.pairs_used;
  info.target = describeTarget(target);
  if (!writeStereoCalibrationFile(o.out_path, c, info, &error)) {
    std::fprintf(stderr, "deepnav calibrate: %s\n", error.c_str());
    return 2;
  }
  std::printf("\ncalibration written to %s (point camera.calibration_file of the board at it)\n", o.out_path.c_str());
  return 0;
}

}  // namespace deepnav
