#include "drivers/euroc/euroc_dataset.h"

#include <algorithm>
#include <filesystem>

namespace deepnav {
namespace {

namespace fs = std::filesystem;

bool findMavDir(const std::string& dir, std::string* mav_dir, std::string* error) {
  std::error_code ec;
  for (const fs::path& candidate : {fs::path(dir) / "mav0", fs::path(dir)}) {
    if (fs::is_directory(candidate / "cam0", ec) && fs::is_directory(candidate / "imu0", ec)) {
      *mav_dir = candidate.string();
      return true;
    }
  }
  if (error) *error = dir + ": not an EuRoC/ASL folder (no mav0/cam0 and mav0/imu0)";
  return false;
}

void pairByTimestamp(const std::vector<EurocImageEntry>& left, const std::vector<EurocImageEntry>& right,
                     EurocDataset* d) {
  std::size_t i = 0, j = 0;
  while (i < left.size() && j < right.size()) {
    if (left[i].t_ns == right[j].t_ns) {
      d->pairs.push_back(EurocStereoPair{left[i].t_ns, left[i].path, right[j].path});
      ++i;
      ++j;
    } else if (left[i].t_ns < right[j].t_ns) {
      ++i;
      ++d->cam0_unpaired;
    } else {
      ++j;
      ++d->cam1_unpaired;
    }
  }
  d->cam0_unpaired += static_cast<int>(left.size() - i);
  d->cam1_unpaired += static_cast<int>(right.size() - j);
}

template <typename T>
void keepUntil(std::int64_t end_ns, std::vector<T>* rows) {
  rows->erase(std::remove_if(rows->begin(), rows->end(), [end_ns](const T& r) { return r.t_ns > end_ns; }),
              rows->end());
}

// Keeps what lies within duration_s of the first pair, IMU or truth sample.
void clipToDuration(double duration_s, EurocDataset* d) {
  std::int64_t t0 = d->pairs.front().t_ns;
  if (!d->imu_rows.empty()) t0 = std::min(t0, d->imu_rows.front().t_ns);
  if (!d->truth.empty()) t0 = std::min(t0, d->truth.front().t_ns);
  const std::int64_t end_ns = t0 + static_cast<std::int64_t>(duration_s * 1e9);
  keepUntil(end_ns, &d->pairs);
  keepUntil(end_ns, &d->imu_rows);
  keepUntil(end_ns, &d->truth);
}

}  // namespace

bool readEurocDataset(const std::string& dir, const EurocReadOptions& options, EurocDataset* d, std::string* error) {
  *d = EurocDataset{};
  if (!findMavDir(dir, &d->mav_dir, error)) return false;
  const fs::path mav(d->mav_dir);
  std::vector<EurocImageEntry> left, right;
  if (!readEurocCamera((mav / "cam0" / "sensor.yaml").string(), &d->cam0, error) ||
      !readEurocCamera((mav / "cam1" / "sensor.yaml").string(), &d->cam1, error) ||
      !readEurocImuInfo((mav / "imu0" / "sensor.yaml").string(), &d->imu, error) ||
      !readEurocImageList((mav / "cam0").string(), &left, error,
                          options.skip_missing_images ? &d->cam0_missing : nullptr) ||
      !readEurocImageList((mav / "cam1").string(), &right, error,
                          options.skip_missing_images ? &d->cam1_missing : nullptr) ||
      !readEurocImu((mav / "imu0" / "data.csv").string(), &d->imu_rows, error)) {
    return false;
  }
  if (d->cam0.width_px != d->cam1.width_px || d->cam0.height_px != d->cam1.height_px) {
    if (error) *error = (mav / "cam1" / "sensor.yaml").string() + ": key 'resolution' differs from cam0's";
    return false;
  }
  pairByTimestamp(left, right, d);
  if (d->pairs.empty()) {
    if (error) *error = d->mav_dir + ": no cam0 image has a cam1 image with the same timestamp";
    return false;
  }
  const fs::path truth_csv = mav / "state_groundtruth_estimate0" / "data.csv";
  std::error_code ec;
  if (fs::exists(truth_csv, ec) && !readEurocTruth(truth_csv.string(), &d->truth, error)) return false;
  if (options.duration_s > 0.0) clipToDuration(options.duration_s, d);
  if (d->imu_rows.empty()) {
    if (error) *error = (mav / "imu0" / "data.csv").string() + ": no IMU sample";
    return false;
  }
  return true;
}

}  // namespace deepnav
