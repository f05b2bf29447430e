#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace deepnav::eval {

// The paper's Table I (DexROV, IROS 2019) on a simulated recording: dense stereo backends scored
// against the simulator's true disparity, and the plane chain after each of them scored against the
// true relative camera rotation between consecutive stereo pairs.
//
// Rows: GT (the true disparity, GtDisparity), ELAS, SGBM (3-way, no WLS), ELAS+Filter, SGBM+Filter.
// Per scored pair and row:
//   disparity   -> D1 (KITTI: error > 3 px and > 5 %, a pixel without disparity counts as wrong),
//                  bad_valid (the same error rate over the pixels that have a disparity) and
//                  coverage, over the non-occluded pixels: true disparity in (0, num_disparities),
//                  match inside the right image, not hidden there by a nearer surface;
//   cloud       -> CloudFromDisparity (step 2 px, range [0.3, 6] m);
//   Filter rows -> MixedPixelFilter, then WorkspaceMap::filter (stage-1 map of the same backend);
//                  their D1/coverage count the removed pixels as without disparity;
//   planes      -> PlaneExtractor: planes and holes per pair;
//   registration-> PlaneRegistrar against the previous pair of the recording; rotation error = angle
//                  of q_est^-1 q_true, q_true = R_odom_cam(a)^T R_odom_cam(b) from /truth/frame.
// Stage-1 map (Filter rows): WorkspaceMap (defaults: 5 cm, endpoints, 3 hits) from the clouds of
// every map_every-th pair with t in [map_from_s, map_to_s), mixed pixels removed, inserted at the
// pair's true left-camera pose; those pairs are never scored.
struct Table1Options {
  int max_frames = 0;            // scored pairs (0 = all)
  double eval_from_s = 30.0;     // score pairs captured at or after this time
  double map_from_s = 0.0;       // stage-1 map pairs
  double map_to_s = 1e9;
  int map_every = 0;             // every n-th pair of the recording (from its first); 0: the board's
                                 // vision.map_every_n_frames
  int num_disparities = 0;       // at the matching size; 0: the board's vision.dense_disparities
  bool progress = false;
  // Rotation prior of the registration between consecutive pairs (PlaneRegistrationConfig::
  // max_normal_change_deg; the vehicle's default, 45 deg, is meant for a few Hz): an ROV turns well under
  // 20 deg/s, so 10 deg per 0.1 s pair is a wide margin. 0 keeps the board's.
  double max_turn_deg = 10.0;
  std::string dump_dir;          // when set: the first scored pair's images and disparity maps as PNGs
  // Board "key=value" overrides applied to the board stored in the recording (board_overrides.h).
  std::vector<std::string> overrides;
  // Rows to run, comma separated names (gt, elas, sgbm, elas-filter, sgbm-filter); empty: all. A
  // recording without truth maps (/truth/depth, /truth/disparity) has no GT row and no D1.
  std::string rows;
  std::string registrations_csv;  // when set: one line per scored registration (errors, NEES)
};

enum Table1RowId { kRowGt = 0, kRowElas, kRowSgbm, kRowElasFilter, kRowSgbmFilter, kRowCount };

struct Table1Row {
  std::string name;
  int frames = 0;                  // scored pairs
  double d1_mean = 0.0;            // fraction
  double bad_valid_mean = 0.0;     // fraction
  double coverage_mean = 0.0;      // fraction
  double planes_mean = 0.0;
  double holes_mean = 0.0;
  int registrations = 0;           // pairs with a previous pair
  int registered = 0;              // ... whose rotation was observable (result.valid)
  double rot_err_mean_deg = 0.0;   // over the registered pairs
  double rot_err_std_deg = 0.0;
  double rot_err_max_deg = 0.0;
  double rot_err_median_deg = 0.0;
  double true_rotation_mean_deg = 0.0;  // mean true rotation between the registered pairs
  double ms_per_frame = 0.0;       // CPU of the row's chain (disparity included)
  // Every registration that constrains some direction (subspace results included) against the true
  // relative camera pose: error e = [t_est - t_true; Log(R_true^T R_est)] on the constrained directions U
  // (relativePoseConstrainedBasis of the 6x6 covariance), NEES = e_U^T (U^T C U)^-1 e_U with dof k.
  int constrained = 0;             // registrations with k >= 1
  int full_pose = 0;               // ... with k = 6
  double nees_per_dof_mean = 0.0;  // mean of NEES / k
  double nees_in_band = 0.0;       // fraction with NEES inside the two-sided 95 % chi-square_k interval
  double nees_above_band = 0.0;    // fraction above it
  double trans_err_mean_m = 0.0;   // over registrations with a full translation
  int translations = 0;
  bool ran = true;                 // false: not requested, or GT without truth maps
};

struct Table1Result {
  std::string recording;
  std::array<Table1Row, kRowCount> rows;
  int map_frames = 0;
  std::size_t map_voxels_elas = 0, map_voxels_sgbm = 0;
  double first_scored_t_s = 0.0, last_scored_t_s = 0.0;
  int scale_down = 1;  // images reduced by this before matching (board vision.dense_scale_down)
  bool truth_maps = true;  // the recording holds /truth/depth and /truth/disparity (D1 and GT row)
  Table1Options options;
};

// Reads the recording (stereo pairs and /truth/* topics; the board stored in it gives the camera),
// builds the stage-1 maps, scores the pairs. False with a message naming the file on error.
bool runTable1(const std::string& recording, const Table1Options& options, Table1Result* result, std::string* error);

std::string table1Markdown(const Table1Result& result);
std::string table1Json(const Table1Result& result);

}  // namespace deepnav::eval
