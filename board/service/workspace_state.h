#pragma once
#include <atomic>
#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "board/config/vehicle_setup.h"
#include "board/loop/live_loop.h"
#include "nav/types/nav_solution.h"
#include "vision/pipeline/vision_context.h"
#include "vision/pipeline/workspace_model.h"

namespace deepnav {

// The service's workspace across restarts (`service.state_dir`). Layout of the state directory:
//   DIR/workspace            symlink to the current saved workspace (read with loadWorkspace)
//   DIR/workspace-<stamp>/   workspace.bt + workspace.yaml (board/replay/workspace_files.h)
// A save writes a new workspace-<stamp> directory under a temporary name, fsyncs its files, renames it,
// then swaps the `workspace` symlink with rename(2): a kill -9 at any instant leaves either the previous
// workspace or the new one, never a half-written map under the name the next start reads.
bool saveWorkspaceState(const std::string& state_dir, const WorkspaceModel& model,
                        const Eigen::Isometry3d& T_odom_panel, std::string* saved_dir, std::string* error);
// false with *error empty: nothing saved yet; false with *error set: a saved workspace that cannot be read.
bool loadWorkspaceState(const std::string& state_dir, WorkspaceModel* model, std::string* error);
// Creates the state directory and checks it is writable (start-up validation of `service.state_dir`).
bool prepareStateDir(const std::string& state_dir, std::string* error);

// Saves the workspace of this run once the stage machine enters stage 2 with the panel fixed (the map is
// complete then: stage 2 inserts nothing). Runs on the vision worker (LiveLoop's pair hook): one save per
// entry into stage 2, a little file I/O that never touches the nav loop. A restored map is not saved again.
class WorkspaceSaver {
 public:
  explicit WorkspaceSaver(std::string state_dir) : state_dir_(std::move(state_dir)) {}
  void onVisionPair(const WorkspaceModel& model, const VisionContext& context);

  int failures() const { return failures_.load(std::memory_order_acquire); }

 private:
  std::string state_dir_;
  NavStage last_stage_ = NavStage::kInit;
  std::atomic<int> failures_{0};
};

// Recording metadata of a run that started from a saved workspace ({restored: true, from, occupied_voxels}):
// the bench replay reproduces such a run with its stage machine told so.
inline constexpr const char* kWorkspaceMetadata = "deepnav.workspace";

// Start-up of `service.state_dir` for `deepnav run`, before the loop's init(): prepares the directory
// (false: not writable, the start fails naming the key) and checks the saved workspace; a readable one is
// announced in the recording's metadata and *restorable set. One that cannot be read is reported on
// stderr and the run starts in stage 1: navigation must not depend on it.
bool prepareWorkspaceState(const std::string& state_dir, const VehicleSetup& setup, LiveLoop* loop,
                           bool* restorable, std::string* error);
// After the loop's init(): restores the workspace into the loop (when restorable) and installs the saver
// as the loop's vision pair hook.
bool attachWorkspaceState(const std::string& state_dir, bool restore, LiveLoop* loop,
                          std::unique_ptr<WorkspaceSaver>* saver, std::string* error);

}  // namespace deepnav
