#include "board/replay/workspace_files.h"

#include <cerrno>
#include <filesystem>
#include <fstream>

#include <yaml-cpp/yaml.h>

#include "board/config/yaml_document.h"
#include "board/replay/output_file.h"

namespace deepnav {

bool saveWorkspace(const std::string& dir, const WorkspaceModel& model, const Eigen::Isometry3d& T_odom_panel,
                   std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  errno = 0;
  std::ofstream bt(dir + "/workspace.bt", std::ios::binary);
  Eigen::Isometry3d T_panel_map;
  if (!bt || !model.save(bt, T_odom_panel, &T_panel_map) || !bt.flush()) {
    if (error) *error = writeFailure(dir + "/workspace.bt", errno);
    return false;
  }
  const Eigen::Quaterniond q(T_panel_map.linear());
  const Eigen::Vector3d& p = T_panel_map.translation();
  YAML::Emitter y;
  y << YAML::BeginMap << YAML::Key << "p_map_in_panel_m" << YAML::Value << YAML::Flow << YAML::BeginSeq << p.x()
    << p.y() << p.z() << YAML::EndSeq << YAML::Key << "q_panel_map_xyzw" << YAML::Value << YAML::Flow
    << YAML::BeginSeq << q.x() << q.y() << q.z() << q.w() << YAML::EndSeq << YAML::Key << "resolution_m"
    << YAML::Value << model.map().config().resolution_m << YAML::Key << "occupied_voxels" << YAML::Value
    << model.voxels() << YAML::EndMap;
  std::ofstream meta;
  if (!openOutput(&meta, dir + "/workspace.yaml", error)) return false;
  meta << y.c_str() << "\n";
  return closeOutput(&meta, dir + "/workspace.yaml", error);
}

namespace {

bool readPose(const std::string& path, Eigen::Isometry3d* T_panel_map, std::string* error) {
  std::string text;
  YAML::Node root;
  if (!loadYamlFile(path, "the workspace", &text, &root, error)) return false;
  try {
    const YAML::Node p = root["p_map_in_panel_m"];
    const YAML::Node q = root["q_panel_map_xyzw"];
    if (!p || !p.IsSequence() || p.size() != 3) throw std::runtime_error("p_map_in_panel_m: expected [x, y, z]");
    if (!q || !q.IsSequence() || q.size() != 4) throw std::runtime_error("q_panel_map_xyzw: expected [x, y, z, w]");
    Eigen::Quaterniond quat(q[3].as<double>(), q[0].as<double>(), q[1].as<double>(), q[2].as<double>());
    if (!(quat.norm() > 0.5 && quat.norm() < 1.5)) throw std::runtime_error("q_panel_map_xyzw: not a unit quaternion");
    *T_panel_map = Eigen::Isometry3d::Identity();
    T_panel_map->linear() = quat.normalized().toRotationMatrix();
    T_panel_map->translation() = Eigen::Vector3d(p[0].as<double>(), p[1].as<double>(), p[2].as<double>());
    if (!T_panel_map->matrix().allFinite()) throw std::runtime_error("p_map_in_panel_m: not finite");
  } catch (const std::exception& e) {
    if (error) *error = path + ": " + e.what();
    return false;
  }
  return true;
}

}  // namespace

bool loadWorkspace(const std::string& dir, WorkspaceModel* model, std::string* error) {
  Eigen::Isometry3d T_panel_map;
  if (!readPose(dir + "/workspace.yaml", &T_panel_map, error)) return false;
  std::ifstream bt(dir + "/workspace.bt", std::ios::binary);
  if (!bt) {
    if (error) *error = dir + "/workspace.bt: cannot read";
    return false;
  }
  std::string e;
  if (!model->restore(bt, T_panel_map, &e)) {
    if (error) *error = dir + "/workspace.bt: " + e;
    return false;
  }
  return true;
}

}  // namespace deepnav
