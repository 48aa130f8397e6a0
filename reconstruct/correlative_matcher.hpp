#pragma once
// Correlative scan matching (Olson, ICRA 2009) with the multi-level branch and bound of Hess et
// al., ICRA 2016, "Real-time loop closure in 2D LIDAR SLAM": a search over a window of
// translations and rotations for the pose under which the scan's points fall on the target's
// likelihood field. Unlike ICP it does not need an initial guess inside the basin of attraction,
// so it finds a revisited place after the tracker has drifted metres and degrees; ICP then
// refines the pose it returns.
// The search is exact, not approximate. A candidate at height h stands for the 2^h x 2^h fine
// translations ahead of it, and is scored on a precomputed grid that holds, per cell, the maximum
// of the likelihood over the 2^h x 2^h cells ahead of it: an upper bound of every translation it
// stands for. Candidates are split into four of height h - 1, best first and depth first, and
// a branch whose bound is no better than the best fine score found is not expanded.

#include <cstddef>

#include "core/planar_pose.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct CorrelativeOptions {
  double cell_size_m = 0.1;
  double sigma_m = 0.1;  // of the likelihood field around each target point
  // The highest candidates stand for 2^depth x 2^depth cells (Cartographer's default, 7, is 12.8 m
  // at 10 cm cells); a smaller window starts lower. 0 scores every pose of the window.
  int max_branch_and_bound_depth = 7;
  double source_voxel_m = 0.3;     // the scan's points are thinned to this spacing
  double max_source_range_m = 12;  // far points make the rotation step small for little gain
  std::size_t max_source_points = 100;
  // A pose must score above this mean likelihood to be found: branches that cannot reach it are
  // not searched (0: the best pose whatever its score).
  double min_score = 0;
  void Validate() const;
};

struct CorrelativeResult {
  bool found = false;
  PlanarPose T_target_source;
  double score = 0;  // mean likelihood of the scan's points at the pose, in [0, 1]; 0 if not found
  std::size_t window_poses = 0;       // translations x rotations of the window
  std::size_t bound_evaluations = 0;  // candidates scored above the fine level
  std::size_t fine_evaluations = 0;   // poses scored
};

// Searches T_target_source within +-window_m (x and y) and +-window_rad of `initial`. Source
// points are in the source frame (base_link), target points in the target frame.
CorrelativeResult MatchCorrelative(const Points2& source_base, const Points2& target,
                                   const PlanarPose& initial, double window_m, double window_rad,
                                   const CorrelativeOptions& options);

}  // namespace littermap::reconstruct
