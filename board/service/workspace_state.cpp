#include "board/service/workspace_state.h"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "board/replay/workspace_files.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCurrent = "workspace";
constexpr const char* kPrefix = "workspace-";

// fsync a file or a directory: a rename is durable only once the data and the directory entry are.
bool syncPath(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

std::string uniqueStamp() {
  const auto ns = std::chrono::system_clock::now().time_since_epoch();
  return std::to_string(std::chrono::duration_cast<std::chrono::microseconds>(ns).count()) + "-" +
         std::to_string(::getpid());
}

// Older saves and temporaries a kill left behind, except the one `workspace` names now.
void removeStale(const std::string& state_dir, const std::string& keep) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(state_dir, ec)) {
    const std::string name = entry.path().filename().string();
    const bool ours = name.rfind(kPrefix, 0) == 0 || name.rfind(".workspace-", 0) == 0;
    if (ours && name != keep && name != kCurrent) fs::remove_all(entry.path(), ec);
  }
}

}  // namespace

bool prepareStateDir(const std::string& state_dir, std::string* error) {
  std::error_code ec;
  fs::create_directories(state_dir, ec);
  if (ec || ::access(state_dir.c_str(), W_OK) != 0) {
    if (error) {
      *error = "service.state_dir: " + state_dir + " is not a writable directory" + (ec ? ": " + ec.message() : "");
    }
    return false;
  }
  return true;
}

bool saveWorkspaceState(const std::string& state_dir, const WorkspaceModel& model,
                        const Eigen::Isometry3d& T_odom_panel, std::string* saved_dir, std::string* error) {
  const std::string stamp = uniqueStamp();
  const std::string name = kPrefix + stamp;
  const std::string tmp_dir = state_dir + "/.workspace-" + stamp + ".tmp";
  const std::string final_dir = state_dir + "/" + name;
  if (!saveWorkspace(tmp_dir, model, T_odom_panel, error)) return false;
  if (!syncPath(tmp_dir + "/workspace.bt") || !syncPath(tmp_dir + "/workspace.yaml") || !syncPath(tmp_dir)) {
    if (error) *error = tmp_dir + ": cannot sync to disk";
    return false;
  }
  std::error_code ec;
  fs::rename(tmp_dir, final_dir, ec);
  if (ec) {
    if (error) *error = final_dir + ": " + ec.message();
    return false;
  }
  // A plain directory under the current name (copied in by hand, e.g. from `deepnav replay
  // --workspace-out`) is moved aside: rename(2) cannot put a symlink over a directory.
  const std::string current = state_dir + "/" + kCurrent;
  if (fs::is_directory(fs::symlink_status(current, ec))) fs::rename(current, state_dir + "/" + kPrefix + "previous-" + stamp, ec);
  const std::string link_tmp = state_dir + "/.workspace-" + stamp + ".link";
  fs::create_symlink(name, link_tmp, ec);
  if (!ec) fs::rename(link_tmp, current, ec);
  if (ec || !syncPath(state_dir)) {
    if (error) *error = current + ": cannot point it at " + name + (ec ? ": " + ec.message() : "");
    return false;
  }
  removeStale(state_dir, name);
  if (saved_dir) *saved_dir = final_dir;
  return true;
}

bool loadWorkspaceState(const std::string& state_dir, WorkspaceModel* model, std::string* error) {
  if (error) error->clear();
  const std::string current = state_dir + "/" + kCurrent;
  std::error_code ec;
  if (!fs::exists(current, ec)) return false;
  return loadWorkspace(current, model, error);
}

void WorkspaceSaver::onVisionPair(const WorkspaceModel& model, const VisionContext& context) {
  const bool entered_stage2 = context.stage == NavStage::kOptimised && last_stage_ != NavStage::kOptimised;
  last_stage_ = context.stage;
  if (!entered_stage2 || model.restored() || !context.panel_fixed || model.voxels() == 0) return;
  std::string dir, error;
  if (saveWorkspaceState(state_dir_, model, context.T_odom_panel, &dir, &error)) {
    std::fprintf(stderr, "deepnav run: workspace saved to %s (%d clouds, %d occupied voxels)\n", dir.c_str(),
                 model.frames(), model.voxels());
  } else {
    failures_.fetch_add(1, std::memory_order_release);
    std::fprintf(stderr, "deepnav run: service.state_dir: workspace not saved: %s\n", error.c_str());
  }
}

bool prepareWorkspaceState(const std::string& state_dir, const VehicleSetup& setup, LiveLoop* loop,
                           bool* restorable, std::string* error) {
  *restorable = false;
  if (!prepareStateDir(state_dir, error)) return false;
  WorkspaceModel probe;
  std::string why;
  if (!probe.init(visionConfig(setup).workspace, &why)) {
    if (error) *error = "service.state_dir: " + why;
    return false;
  }
  if (loadWorkspaceState(state_dir, &probe, &why)) {
    std::error_code ec;
    const std::string from = fs::canonical(state_dir + "/" + kCurrent, ec).string();
    loop->addRecordingMetadata(kWorkspaceMetadata, {{"restored", "true"},
                                                    {"from", ec ? state_dir + "/" + kCurrent : from},
                                                    {"occupied_voxels", std::to_string(probe.voxels())}});
    *restorable = true;
  } else if (!why.empty()) {
    std::fprintf(stderr, "deepnav run: service.state_dir: saved workspace not used, starting in stage 1: %s\n",
                 why.c_str());
  }
  return true;
}

bool attachWorkspaceState(const std::string& state_dir, bool restore, LiveLoop* loop,
                          std::unique_ptr<WorkspaceSaver>* saver, std::string* error) {
  if (restore) {
    std::string why;
    if (!loadWorkspaceState(state_dir, &loop->workspace(), &why)) {
      if (error) *error = "service.state_dir: the saved workspace changed during start-up: " + why;
      return false;
    }
    loop->setWorkspaceRestored();
    std::fprintf(stderr, "deepnav run: workspace restored from %s/workspace (%d occupied voxels): stage 2 once the "
                 "markers fix the panel\n", state_dir.c_str(), loop->workspace().voxels());
  }
  *saver = std::make_unique<WorkspaceSaver>(state_dir);
  WorkspaceSaver* s = saver->get();
  loop->setVisionPairHook([s](const WorkspaceModel& model, const VisionContext& context) { s->onVisionPair(model, context); });
  return true;
}

}  // namespace deepnav
