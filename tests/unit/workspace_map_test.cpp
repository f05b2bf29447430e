#include "vision/workspace/workspace_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>
#include <random>
#include <sstream>

#include "tests/support/synthetic_scene.h"
#include "vision/cloud/cloud_from_disparity.h"
#include "vision/cloud/mixed_pixel_filter.h"

namespace deepnav {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kWallY = 3.0;
constexpr double kBoxFrontY = 1.8;

StereoGeometry geometry() { return centredStereoGeometry(300.0, kWidth, kHeight, 0.12); }

// World z up. A wall 3 m ahead and a box whose front face is 1.8 m ahead; the sides of the box
// face +-x and are never seen from the cameras below (|x| < 0.3 m). Index 0: wall, 1..6: box
// (4: front face), then the spheres.
SyntheticScene workspace() {
  SyntheticScene scene;
  scene.rectangles.push_back({Eigen::Vector3d(0, kWallY, 0), Eigen::Vector3d::UnitX(),
                              Eigen::Vector3d::UnitZ(), 3.0, 2.0, 5});
  scene.addBox(Eigen::Vector3d(0.0, kBoxFrontY + 0.2, -0.4), Eigen::Vector3d(0.6, 0.4, 0.8), 0.0,
               21);
  return scene;
}
constexpr int kWall = 0;
constexpr int kBoxFront = 6;  // addBox order: top, bottom, +x, -x, +y, -y

// Camera looking along world +y: optical x = world x, y = -world z, z = world y.
Eigen::Isometry3d cameraAt(const Eigen::Vector3d& position) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY();
  T.translation() = position;
  return T;
}

struct Frame {
  SyntheticView view;
  OrganizedCloud cloud;
  cv::Mat streak;  // CV_8UC1 mask of the mixed pixels written into the disparity
};

// Mixed pixels: on every row, the 6 wall pixels next to the box's silhouette get disparities
// interpolated between the box and the wall (a comet-like streak along the viewing rays).
void addStreaks(Frame* f) {
  f->streak = cv::Mat::zeros(kHeight, kWidth, CV_8UC1);
  for (int v = 0; v < kHeight; ++v) {
    const std::int32_t* s = f->view.surface.ptr<std::int32_t>(v);
    float* d = f->view.disparity_px.ptr<float>(v);
    for (int u = 1; u < kWidth; ++u) {
      const bool enters = s[u - 1] == kWall && s[u] == kBoxFront;
      const bool leaves = s[u - 1] == kBoxFront && s[u] == kWall;
      if (!enters && !leaves) continue;
      const int box_u = enters ? u : u - 1;
      const int dir = enters ? -1 : 1;
      const float d_box = d[box_u];
      for (int k = 1; k <= 6; ++k) {
        const int w = box_u + dir * k;
        if (w < 0 || w >= kWidth || s[w] != kWall) break;
        const float a = static_cast<float>(k) / 7.0f;
        d[w] = d_box + a * (d[w] - d_box);
        f->streak.at<std::uint8_t>(v, w) = 255;
      }
    }
  }
}

void makeFrame(const SyntheticScene& scene, const Eigen::Isometry3d& T_world_cam, bool streaks,
               Frame* f) {
  renderSyntheticView(scene, geometry(), kWidth, kHeight, T_world_cam, false, &f->view);
  if (streaks) addStreaks(f);
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(geometry(), CloudConfig{}, kWidth, kHeight));
  ASSERT_TRUE(builder.allocateCloud(&f->cloud));
  ASSERT_TRUE(builder.compute(f->view.disparity_px, &f->cloud));
}

WorkspaceConfig config(WorkspaceLookupKind lookup) {
  WorkspaceConfig c;
  c.resolution_m = 0.05;
  c.filter_distance_m = 0.10;
  c.insert_step_cells = 2;
  c.lookup = lookup;
  return c;
}

// Stage 1: six views from slightly different positions, each with a fish somewhere else and with
// streaks, which the mixed-pixel filter removes before insertion (as the pipeline does).
void buildMap(const SyntheticScene& base, WorkspaceMap* map) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(-0.5, 0.5), uy(0.8, 1.4);
  MixedPixelFilter mixed;
  ASSERT_TRUE(mixed.init(MixedPixelConfig{}, kHeight, kWidth));
  for (int k = 0; k < 6; ++k) {
    SyntheticScene scene = base;
    scene.spheres.push_back({Eigen::Vector3d(ux(rng), uy(rng), 0.5 * ux(rng)), 0.12, 9});
    const Eigen::Isometry3d T = cameraAt(Eigen::Vector3d(-0.15 + 0.06 * k, 0.0, 0.03 * (k % 2)));
    Frame f;
    makeFrame(scene, T, true, &f);
    mixed.apply(&f.cloud);
    ASSERT_TRUE(map->insert(f.cloud, T));
  }
  ASSERT_TRUE(map->freeze());
}

// The stage-1 map, built once for the tests below, with all three lookups.
const WorkspaceMap& sharedMap() {
  static WorkspaceMap* map = [] {
    auto* m = new WorkspaceMap;
    EXPECT_TRUE(m->init(config(WorkspaceLookupKind::kGrid)));
    buildMap(workspace(), m);
    EXPECT_TRUE(m->buildLookup(WorkspaceLookupKind::kOctree));
    EXPECT_TRUE(m->buildLookup(WorkspaceLookupKind::kKdTree));
    return m;
  }();
  return *map;
}

class WorkspaceFilter : public ::testing::TestWithParam<WorkspaceLookupKind> {};

TEST_P(WorkspaceFilter, RemovesStreaksAndFishKeepsWallAndBox) {
  // GIVEN a workspace map of the wall and the box built in stage 1
  const SyntheticScene base = workspace();
  const WorkspaceMap& map = sharedMap();
  // GIVEN a stage-2 frame from a new position with a fish 1.2 m ahead and streaks at the box's
  // borders (no mixed-pixel filter: the map alone must remove them)
  SyntheticScene scene = base;
  scene.spheres.push_back({Eigen::Vector3d(-0.35, 1.2, 0.2), 0.12, 9});
  const int fish = static_cast<int>(scene.rectangles.size());
  const Eigen::Isometry3d T = cameraAt(Eigen::Vector3d(0.05, 0.1, 0.02));
  Frame f;
  makeFrame(scene, T, true, &f);
  ASSERT_GT(cv::countNonZero(f.view.surface == fish), 300);
  ASSERT_GT(cv::countNonZero(f.streak), 500);

  const cv::Mat unfiltered = f.cloud.p_point_in_cam_m.clone();

  // WHEN filtered by the map
  const int removed = map.filter(T, &f.cloud, GetParam());

  // THEN every fish point and every streak point away from the surfaces is gone, and the wall
  // and box points remain
  ASSERT_GT(removed, 0);
  int fish_kept = 0, streak_far = 0, streak_far_kept = 0, surface = 0, surface_kept = 0;
  const double margin = map.config().filter_distance_m + 0.05 * std::sqrt(3.0);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const std::int32_t s = f.view.surface.at<std::int32_t>(v, u);
      const bool kept = OrganizedCloud::isValid(f.cloud.row(v)[u]);
      if (f.streak.at<std::uint8_t>(v, u) != 0) {
        // world y of the point: its depth; the wall and the box front are y planes
        const double y = T.translation().y() + unfiltered.at<cv::Vec3f>(v, u)[2];
        const double lower_bound = std::min(kWallY - y, y - kBoxFrontY);
        if (lower_bound > margin) {
          ++streak_far;
          streak_far_kept += kept ? 1 : 0;
        }
      } else if (s == fish) {
        fish_kept += kept ? 1 : 0;
      } else if (s == kWall || s == kBoxFront) {
        ++surface;
        surface_kept += kept ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(fish_kept, 0);
  EXPECT_GT(streak_far, 200);
  EXPECT_EQ(streak_far_kept, 0);
  EXPECT_GT(surface_kept, 0.99 * surface);
}

INSTANTIATE_TEST_SUITE_P(Lookups, WorkspaceFilter,
                         ::testing::Values(WorkspaceLookupKind::kOctree,
                                           WorkspaceLookupKind::kKdTree,
                                           WorkspaceLookupKind::kGrid));

TEST(WorkspaceMap, OctreeAndKdTreeAgreeAndGridIsAConservativeSuperset) {
  // GIVEN a frozen map with all three lookups
  const WorkspaceMap& map = sharedMap();
  // WHEN queried at random points around the workspace
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> ux(-1.5f, 1.5f), uy(1.4f, 3.4f), uz(-1.0f, 1.0f);
  int near = 0;
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3f p(ux(rng), uy(rng), uz(rng));
    const bool octree = map.isNear(p, WorkspaceLookupKind::kOctree);
    const bool kdtree = map.isNear(p, WorkspaceLookupKind::kKdTree);
    const bool grid = map.isNear(p, WorkspaceLookupKind::kGrid);
    // THEN the two exact lookups agree, and the grid accepts whatever they accept
    EXPECT_EQ(octree, kdtree) << p.transpose();
    if (octree) {
      EXPECT_TRUE(grid) << p.transpose();
    }
    near += octree ? 1 : 0;
  }
  EXPECT_GT(near, 250);
  EXPECT_LT(near, 4750);
}

// The reference for the map's insertion: every frame's voxels (each once) through OctoMap's eager
// updateNode, which fixes the parents and prunes after each voxel.
void insertEagerly(const OrganizedCloud& cloud, const Eigen::Isometry3d& T_odom_cam, const WorkspaceConfig& c,
                   octomap::OcTree* tree) {
  const Eigen::Matrix3f R = T_odom_cam.linear().cast<float>();
  const Eigen::Vector3f t = T_odom_cam.translation().cast<float>();
  const float range2 = static_cast<float>(c.max_range_m * c.max_range_m);
  octomap::KeySet keys;
  for (int r = 0; r < cloud.rows(); r += c.insert_step_cells) {
    const cv::Vec3f* p = cloud.row(r);
    for (int col = 0; col < cloud.cols(); col += c.insert_step_cells) {
      if (!OrganizedCloud::isValid(p[col])) continue;
      const Eigen::Vector3f p_cam(p[col][0], p[col][1], p[col][2]);
      if (p_cam.squaredNorm() > range2) continue;
      const Eigen::Vector3f q = R * p_cam + t;
      octomap::OcTreeKey key;
      if (tree->coordToKeyChecked(octomap::point3d(q.x(), q.y(), q.z()), key)) keys.insert(key);
    }
  }
  std::vector<octomap::OcTreeKey> sorted(keys.begin(), keys.end());
  const auto packed = [](const octomap::OcTreeKey& k) {
    return std::uint64_t{k[0]} | (std::uint64_t{k[1]} << 16) | (std::uint64_t{k[2]} << 32);
  };
  std::sort(sorted.begin(), sorted.end(), [&](const auto& a, const auto& b) { return packed(a) < packed(b); });
  for (const octomap::OcTreeKey& k : sorted) tree->updateNode(k, true);
}

// Every node of both trees, in the same order, at the same depth and key, with the same log-odds
// and the same children: the same tree, pruned the same way.
int expectSameTree(const octomap::OcTree& a, const octomap::OcTree& b) {
  int pruned = 0;
  auto ia = a.begin_tree(), ib = b.begin_tree();
  for (; ia != a.end_tree() && ib != b.end_tree(); ++ia, ++ib) {
    EXPECT_EQ(ia.getDepth(), ib.getDepth());
    EXPECT_EQ(ia.getKey(), ib.getKey());
    EXPECT_EQ(ia->getLogOdds(), ib->getLogOdds());
    EXPECT_EQ(a.nodeHasChildren(&*ia), b.nodeHasChildren(&*ib));
    pruned += ia.isLeaf() && ia.getDepth() < a.getTreeDepth();
  }
  EXPECT_TRUE(ia == a.end_tree() && ib == b.end_tree()) << "node counts differ";
  EXPECT_EQ(a.size(), b.size());
  return pruned;
}

// A solid block of points 1.5 m ahead of the camera, one per voxel centre (5 cm voxels), 8x8x8
// voxels: surfaces never fill a 2x2x2 block of voxels, a solid does, and its nodes prune.
void fillWithSolidBlock(OrganizedCloud* cloud) {
  int cell = 0;
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      for (int k = 0; k < 8; ++k, ++cell) {
        cloud->row(cell / cloud->cols())[cell % cloud->cols()] =
            cv::Vec3f(0.025f + 0.05f * i, 0.025f + 0.05f * j, 1.525f + 0.05f * k);
      }
    }
  }
  for (; cell < cloud->rows() * cloud->cols(); ++cell) {
    OrganizedCloud::invalidate(cloud->row(cell / cloud->cols())[cell % cloud->cols()]);
  }
}

TEST(WorkspaceMap, InsertionGivesTheTreeOfEagerOctoMapUpdates) {
  // GIVEN the workspace seen from six positions, and a solid block seen in every other frame
  const SyntheticScene scene = workspace();
  WorkspaceConfig c = config(WorkspaceLookupKind::kGrid);
  c.insert_step_cells = 1;
  WorkspaceMap map;
  ASSERT_TRUE(map.init(c));
  octomap::OcTree reference(c.resolution_m);
  reference.setProbHit(map.octree().getProbHit());
  reference.setProbMiss(map.octree().getProbMiss());
  reference.setOccupancyThres(map.octree().getOccupancyThres());
  reference.setClampingThresMax(map.octree().getClampingThresMax());
  reference.setClampingThresMin(map.octree().getClampingThresMin());
  // WHEN both take the same frames (each frame is compared, so pruning and re-expansion between frames count)
  int pruned = 0;
  for (int k = 0; k < 6; ++k) {
    const Eigen::Isometry3d T = cameraAt(Eigen::Vector3d(-0.15 + 0.06 * k, 0.0, 0.03 * (k % 3)));
    Frame f;
    makeFrame(scene, T, false, &f);
    if (k % 2 == 1) fillWithSolidBlock(&f.cloud);
    ASSERT_TRUE(map.insert(f.cloud, T));
    insertEagerly(f.cloud, T, c, &reference);
    // THEN the trees are the same node for node
    pruned = expectSameTree(map.octree(), reference);
  }
  EXPECT_GT(pruned, 0) << "no pruned node: the test would not see a pruning difference";
}

TEST(WorkspaceMap, WriteReadRoundTripKeepsTheOccupiedVoxels) {
  // GIVEN a map, written to a stream
  const WorkspaceMap& map = sharedMap();
  std::stringstream stream;
  ASSERT_TRUE(map.write(stream));
  // WHEN read into a map initialised with another resolution
  WorkspaceMap copy;
  WorkspaceConfig other = config(WorkspaceLookupKind::kGrid);
  other.resolution_m = 0.2;
  ASSERT_TRUE(copy.init(other));
  ASSERT_TRUE(copy.read(stream));
  // THEN it has the map's resolution, voxels and answers
  EXPECT_DOUBLE_EQ(copy.octree().getResolution(), 0.05);
  EXPECT_EQ(copy.occupiedVoxelCount(), map.occupiedVoxelCount());
  EXPECT_FALSE(copy.frozen());
  ASSERT_TRUE(copy.freeze());
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(-1.5f, 3.5f);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3f p(u(rng), u(rng), u(rng));
    EXPECT_EQ(copy.isNear(p), map.isNear(p));
  }
  // a damaged stream is refused
  std::stringstream bad("# Octomap OcTree binary file\nnonsense");
  EXPECT_FALSE(copy.read(bad));
}

TEST(WorkspaceMap, RayCastingClearsAnObjectThatLeftEndpointsModeKeepsIt) {
  // GIVEN a fish that stays for three frames, then leaves for three frames
  for (const WorkspaceInsertMode mode :
       {WorkspaceInsertMode::kEndpoints, WorkspaceInsertMode::kRayCast}) {
    WorkspaceConfig c = config(WorkspaceLookupKind::kOctree);
    c.insert_mode = mode;
    c.insert_step_cells = 3;
    WorkspaceMap map;
    ASSERT_TRUE(map.init(c));
    const Eigen::Vector3d fish_centre(0.4, 1.2, 0.0);
    for (int k = 0; k < 6; ++k) {
      SyntheticScene scene = workspace();
      if (k < 3) scene.spheres.push_back({fish_centre, 0.12, 9});
      const Eigen::Isometry3d T = cameraAt(Eigen::Vector3d(0.02 * k, 0.0, 0.0));
      Frame f;
      makeFrame(scene, T, false, &f);
      ASSERT_TRUE(map.insert(f.cloud, T));
    }
    ASSERT_TRUE(map.freeze());
    EXPECT_FALSE(map.insert(OrganizedCloud{}, Eigen::Isometry3d::Identity()));  // frozen
    // WHEN asked about the fish's front surface
    const Eigen::Vector3f front = (fish_centre - Eigen::Vector3d(0, 0.12, 0)).cast<float>();
    // THEN only ray casting has cleared it
    EXPECT_EQ(map.isNear(front), mode == WorkspaceInsertMode::kEndpoints);
    // and the wall is there in both modes
    EXPECT_TRUE(map.isNear(Eigen::Vector3f(1.0f, static_cast<float>(kWallY), 0.0f)));
  }
}

TEST(WorkspaceMap, FilterBeforeFreezeIsRefused) {
  WorkspaceMap map;
  ASSERT_TRUE(map.init(config(WorkspaceLookupKind::kGrid)));
  OrganizedCloud cloud;
  ASSERT_TRUE(cloud.allocate(4, 4, 1));
  EXPECT_EQ(map.filter(Eigen::Isometry3d::Identity(), &cloud), -1);
  WorkspaceConfig bad = config(WorkspaceLookupKind::kGrid);
  bad.resolution_m = 0.0;
  EXPECT_FALSE(map.init(bad));
}

}  // namespace
}  // namespace deepnav
