#pragma once
// The final scan alignment: after the pose graph, all key-frame poses are refined together
// against the scans themselves. The pose graph sees each scan match only as one relative pose
// with a 3x3 information, and only between consecutive key frames and the few loops it accepted;
// here every key frame is matched point to line against the key frames that see the same walls:
// its predecessors along the path and the nearest key frame of each earlier visit to the place,
// whether or not the loop closer tried that pair. The odometry between consecutive key frames
// keeps the directions the walls leave open (along a corridor). Associations are made anew in a
// few rounds with a shrinking distance threshold, as in ICP, and weighted by a Cauchy loss, so a
// wall that moved, or two places that only look alike, pull with a bounded force.
//
// For fixed associations the squared point-to-line errors between two scans are an exact
// quadratic form in (cos, sin, x, y, 1) of their relative pose, so each pair of key frames
// enters the least-squares problem as one 5-residual block, whatever its number of points.

#include <cstddef>
#include <vector>

#include "core/planar_pose.hpp"
#include "reconstruct/keyframe_map.hpp"
#include "reconstruct/pose_graph.hpp"
#include "reconstruct/scan_normals.hpp"

namespace littermap::reconstruct {

struct ScanAlignmentOptions {
  // One association round per entry: points farther apart than this are not paired.
  std::vector<double> max_correspondence_distances_m = {0.3, 0.2, 0.1, 0.1};
  double pair_radius_m = 10;                  // key frames this close can see the same walls
  std::size_t sequential_pairs = 3;           // each key frame with up to this many predecessors
  std::size_t max_revisit_pairs = 6;          // and the nearest key frame of up to this many visits
  double source_voxel_size_m = 0.15;          // the points of a key frame that are paired
  ScanNormalsOptions normals;                 // of every key frame's points
  std::size_t min_pair_correspondences = 20;  // fewer: the pair is left out of the round
  double point_sigma_m = 0.03;                // of a point-to-line distance
  double cauchy_scale_m = 0.05;
  int max_iterations_per_round = 10;
  void Validate() const;
};

struct ScanAlignmentResult {
  // Every round's solution was usable; if not, the poses are those of the last usable round.
  bool usable = false;
  std::size_t pairs = 0;            // key-frame pairs considered
  std::size_t pairs_matched = 0;    // with enough correspondences in the last round
  std::size_t correspondences = 0;  // in the last round
  int rounds = 0;
  double initial_cost = 0;  // of the first round
  double final_cost = 0;    // of the last round
};

// Refines `poses` (one per key frame, T_world_base) in place; `odometry`: relative-pose edges
// between key frames (normally consecutive ones), with their information. Pose 0 stays fixed.
ScanAlignmentResult AlignScans(const std::vector<KeyFrame>& key_frames,
                               const std::vector<PoseGraphEdge>& odometry,
                               std::vector<PlanarPose>* poses, const ScanAlignmentOptions& options);

// The same for frames of which some are held (fixed[i]: one flag per frame): every free frame is
// aligned against held frames only, the held frame before and after it along the path and the
// nearest held frame of up to max_revisit_pairs other visits within pair_radius_m (before or
// after it), never against another free frame. So only the held frames need a search tree, and
// every scan of a run can be refined against its aligned key frames at little cost. The free
// frames' points are paired, sources like the later frame of an AlignScans pair.
ScanAlignmentResult AlignScansToHeld(const std::vector<KeyFrame>& frames,
                                     const std::vector<PoseGraphEdge>& odometry,
                                     const std::vector<bool>& fixed, std::vector<PlanarPose>* poses,
                                     const ScanAlignmentOptions& options);

}  // namespace littermap::reconstruct
