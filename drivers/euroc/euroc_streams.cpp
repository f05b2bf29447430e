#include "drivers/euroc/euroc_streams.h"

#include <cmath>
#include <filesystem>

#include "drivers/euroc/euroc_csv.h"
#include "drivers/euroc/euroc_text.h"

namespace deepnav {
namespace {

// Ground-truth quaternions are written with ~15 digits; a norm off by more than this is a damaged row.
constexpr double kUnitQuaternionTolerance = 1e-3;

}  // namespace

bool readEurocImageList(const std::string& camera_dir, std::vector<EurocImageEntry>* images, std::string* error,
                        int* skipped_missing) {
  namespace fs = std::filesystem;
  const std::string csv = (fs::path(camera_dir) / "data.csv").string();
  std::vector<EurocCsvRow> rows;
  if (!readEurocCsv(csv, 2, &rows, error)) return false;
  images->clear();
  images->reserve(rows.size());
  for (const EurocCsvRow& r : rows) {
    const fs::path file = fs::path(camera_dir) / "data" / r.fields[0];
    std::error_code ec;
    if (r.fields[0].empty() || !fs::is_regular_file(file, ec)) {
      if (skipped_missing != nullptr && !r.fields[0].empty()) {
        ++*skipped_missing;
        continue;
      }
      return failAtLine(csv, r.line, "image file " + file.string() + " is missing", error);
    }
    images->push_back(EurocImageEntry{r.t_ns, file.string(), r.line});
  }
  return true;
}

bool readEurocImu(const std::string& csv_path, std::vector<EurocImuRow>* out, std::string* error) {
  std::vector<EurocCsvRow> rows;
  if (!readEurocCsv(csv_path, 7, &rows, error)) return false;
  out->clear();
  out->reserve(rows.size());
  std::vector<double> v;
  for (const EurocCsvRow& r : rows) {
    if (!eurocCsvNumbers(csv_path, r, &v, error)) return false;
    out->push_back(EurocImuRow{r.t_ns, Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(v[3], v[4], v[5])});
  }
  return true;
}

bool readEurocTruth(const std::string& csv_path, std::vector<EurocTruthRow>* out, std::string* error) {
  std::vector<EurocCsvRow> rows;
  if (!readEurocCsv(csv_path, 17, &rows, error)) return false;
  out->clear();
  out->reserve(rows.size());
  std::vector<double> v;
  for (const EurocCsvRow& r : rows) {
    if (!eurocCsvNumbers(csv_path, r, &v, error)) return false;
    EurocTruthRow t;
    t.t_ns = r.t_ns;
    t.p_body_in_world_m = Eigen::Vector3d(v[0], v[1], v[2]);
    t.q_world_body = Eigen::Quaterniond(v[3], v[4], v[5], v[6]);  // q_RS_w, x, y, z
    if (std::abs(t.q_world_body.norm() - 1.0) > kUnitQuaternionTolerance) {
      return failAtLine(csv_path, r.line, "quaternion q_RS (columns 5-8) is not unit length", error);
    }
    t.q_world_body.normalize();
    t.v_body_in_world_mps = Eigen::Vector3d(v[7], v[8], v[9]);
    t.b_gyro_radps = Eigen::Vector3d(v[10], v[11], v[12]);
    t.b_accel_mps2 = Eigen::Vector3d(v[13], v[14], v[15]);
    out->push_back(t);
  }
  return true;
}

}  // namespace deepnav
