#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav {

// One image of mav0/camN/data.csv, with its file checked to exist.
struct EurocImageEntry {
  std::int64_t t_ns = 0;
  std::string path;  // camN/data/<filename>
  int line = 0;      // its line in data.csv
};

// One row of mav0/imu0/data.csv, in the IMU sensor frame S (w_RS_S, a_RS_S).
struct EurocImuRow {
  std::int64_t t_ns = 0;
  Eigen::Vector3d w_sensor_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d f_sensor_mps2 = Eigen::Vector3d::Zero();  // specific force (accelerometer output)
};

// One row of mav0/state_groundtruth_estimate0/data.csv: the body frame B in the Vicon world frame W
// (z up), and the batch solution's IMU biases (in S).
struct EurocTruthRow {
  std::int64_t t_ns = 0;
  Eigen::Vector3d p_body_in_world_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_world_body = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_body_in_world_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d b_gyro_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d b_accel_mps2 = Eigen::Vector3d::Zero();
};

// Readers of the three kinds of data.csv. Errors name the file and line (missing file, bad or unsorted
// timestamps, wrong column count, a value that is not a number, a listed image file that is missing,
// a quaternion that is not unit length).
// skipped_missing: when not null, a listed image whose file is missing is left out and counted there
// instead of failing (a folder cut short, as the shared micro extract of V1_01 is).
bool readEurocImageList(const std::string& camera_dir, std::vector<EurocImageEntry>* images, std::string* error,
                        int* skipped_missing = nullptr);
bool readEurocImu(const std::string& csv_path, std::vector<EurocImuRow>* rows, std::string* error);
bool readEurocTruth(const std::string& csv_path, std::vector<EurocTruthRow>* rows, std::string* error);

}  // namespace deepnav
