#include "board/config/calibration_import_opencv.h"

#include <cstdio>
#include <memory>

#include <opencv2/core/persistence.hpp>

#include "board/config/text_file.h"
#include "board/config/yaml_document.h"

namespace deepnav {
namespace {

struct OpenCvFile {
  std::string path;
  std::unique_ptr<cv::FileStorage> storage;
};

bool openFile(const std::string& path, OpenCvFile* f, std::string* error) {
  std::string text;
  if (!readTextFile(path, "the OpenCV calibration file", &text, error)) return false;
  // OpenCV keeps the first of two equal keys without a word; its "%YAML:1.0" directive is not YAML 1.2.
  const std::size_t directive = text.rfind("%YAML:", 0) == 0 ? text.find('\n') : 0;
  if (!checkYamlKeysUnique(text.substr(directive == std::string::npos ? text.size() : directive), path, error))
    return false;
  f->path = path;
  f->storage = std::make_unique<cv::FileStorage>();
  try {
    if (text.empty() ||
        !f->storage->open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML)) {
      *error = path + ": empty or not an OpenCV YAML file";
      return false;
    }
  } catch (const cv::Exception& e) {
    *error = path + ": not an OpenCV YAML file (" + e.err + ")";
    return false;
  }
  return true;
}

// The one file holding `key`; nullptr with an error when none or two do (required) or none (optional).
const OpenCvFile* findKey(const std::vector<OpenCvFile>& files, const std::string& key, bool required,
                          std::string* error) {
  const OpenCvFile* found = nullptr;
  for (const OpenCvFile& f : files) {
    if ((*f.storage)[key].empty()) continue;
    if (found) {
      *error = f.path + ": key '" + key + "' is also in " + found->path + "; give it once";
      return nullptr;
    }
    found = &f;
  }
  if (!found && required) {
    std::string names;
    for (const OpenCvFile& f : files) names += (names.empty() ? "" : ", ") + f.path;
    *error = names + ": key '" + key + "' is missing (stereo_calib writes M1 D1 M2 D2 and R T)";
  }
  return found;
}

bool readMatrix(const std::vector<OpenCvFile>& files, const std::string& key, int rows, int cols, cv::Mat* out,
                std::string* error) {
  const OpenCvFile* f = findKey(files, key, true, error);
  if (!f) return false;
  cv::Mat m;
  try {
    (*f->storage)[key] >> m;
  } catch (const cv::Exception&) {
    m.release();
  }
  const bool shape_ok = cols > 0 ? (m.rows == rows && m.cols == cols) : (m.rows == 1 || m.cols == 1);
  if (m.empty() || !shape_ok || m.channels() != 1) {
    *error = f->path + ": key '" + key + "' must be an opencv-matrix of " +
             (cols > 0 ? std::to_string(rows) + " x " + std::to_string(cols) : std::string("1 x N")) + " numbers" +
             (m.empty() ? "" : ", not " + std::to_string(m.rows) + " x " + std::to_string(m.cols));
    return false;
  }
  m.convertTo(*out, CV_64F);
  if (!cv::checkRange(*out)) {
    *error = f->path + ": key '" + key + "' holds non-finite values";
    return false;
  }
  return true;
}

bool readImageSize(const std::vector<OpenCvFile>& files, cv::Size option, cv::Size* size, std::string* error) {
  const OpenCvFile* w = findKey(files, "image_width", false, error);
  if (!w && !error->empty()) return false;
  const OpenCvFile* h = findKey(files, "image_height", false, error);
  if (!h && !error->empty()) return false;
  if (!w || !h) {
    if (option.width <= 0) {
      *error = files.front().path +
               ": no image size (keys 'image_width', 'image_height'; stereo_calib writes none): "
               "give --image-size WIDTHxHEIGHT";
      return false;
    }
    *size = option;
    return true;
  }
  const cv::FileNode wn = (*w->storage)["image_width"], hn = (*h->storage)["image_height"];
  if (!wn.isInt() || !hn.isInt()) {
    *error =
        (wn.isInt() ? h : w)->path + ": key '" + (wn.isInt() ? "image_height" : "image_width") + "' must be an integer";
    return false;
  }
  *size = cv::Size(static_cast<int>(wn), static_cast<int>(hn));
  if (option.width > 0 && option != *size) {
    *error = w->path + ": key 'image_width', 'image_height' (" + std::to_string(size->width) + " x " +
             std::to_string(size->height) + ") disagrees with --image-size " + std::to_string(option.width) + "x" +
             std::to_string(option.height);
    return false;
  }
  return true;
}

}  // namespace

bool importOpenCvStereo(const std::vector<std::string>& paths, cv::Size image_size, ImportedCalibration* out,
                        std::string* error) {
  std::vector<OpenCvFile> files(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i)
    if (!openFile(paths[i], &files[i], error)) return false;
  if (files.empty()) {
    *error = "no OpenCV calibration file given";
    return false;
  }
  ImportedCalibration result;
  StereoCalibration& c = result.calibration;
  cv::Mat M1, D1, M2, D2, R, T;
  error->clear();
  if (!readImageSize(files, image_size, &c.image_size, error) || !readMatrix(files, "M1", 3, 3, &M1, error) ||
      !readMatrix(files, "D1", 1, 0, &D1, error) || !readMatrix(files, "M2", 3, 3, &M2, error) ||
      !readMatrix(files, "D2", 1, 0, &D2, error) || !readMatrix(files, "R", 3, 3, &R, error) ||
      !readMatrix(files, "T", 3, 1, &T, error))
    return false;
  c.left.K = cv::Matx33d(M1);
  c.right.K = cv::Matx33d(M2);
  c.left.dist = D1.reshape(1, 1).clone();
  c.right.dist = D2.reshape(1, 1).clone();
  c.R = cv::Matx33d(R);
  c.T = cv::Vec3d(T);
  const auto where = [&](const char* key) { return findKey(files, key, true, error)->path; };
  if (!checkSameResolution(c.image_size, c.image_size, files.front().path, "image_width", error) ||
      !checkCameraMatrix(c.left.K, where("M1"), "M1", error) ||
      !checkDistortion(c.left.dist, where("D1"), "D1", error) ||
      !checkCameraMatrix(c.right.K, where("M2"), "M2", error) ||
      !checkDistortion(c.right.dist, where("D2"), "D2", error) || !checkRotation(c.R, where("R"), "R", error) ||
      !checkBaseline(c.T, where("T"), "T", error))
    return false;
  if (cv::norm(c.T) > 5.0) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "T is %.3f long: deepnav takes it in metres; if the calibration's square size was in millimetres, "
                  "the baseline is %.4f m and the file must be scaled",
                  cv::norm(c.T), cv::norm(c.T) / 1000.0);
    result.notes.push_back(text);
  }
  *out = result;
  return true;
}

}  // namespace deepnav
