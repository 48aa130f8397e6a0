#pragma once
// Correlative scan matching (Olson, ICRA 2009; the two-level branch and bound of Hess et al.,
// ICRA 2016, "Real-time loop closure in 2D LIDAR SLAM"): an exhaustive search over a window of
// translations and rotations for the pose under which the scan's points fall on the target's
// likelihood field. Unlike ICP it does not need an initial guess inside the basin of attraction,
// so it finds a revisited place after the tracker has drifted metres and degrees; ICP then
// refines the pose it returns.
// Coarse translations 2^k cells apart are scored with a grid that holds, per cell, the maximum of
// the likelihood over the 2^k x 2^k cells ahead of it: an upper bound of every fine translation
// they cover, so the coarse candidates are expanded best first and the search stops when the
// bound falls below the best fine score (exact, not approximate).

#include <cstddef>

#include "core/planar_pose.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct CorrelativeOptions {
  double cell_size_m = 0.1;
  double sigma_m = 0.1;            // of the likelihood field around each target point
  int coarse_cells = 8;            // a coarse translation step, in cells
  double source_voxel_m = 0.3;     // the scan's points are thinned to this spacing
  double max_source_range_m = 12;  // far points make the rotation step small for little gain
  std::size_t max_source_points = 100;
  void Validate() const;
};

struct CorrelativeResult {
  bool found = false;
  PlanarPose T_target_source;
  double score = 0;  // mean likelihood of the scan's points at the pose, in [0, 1]
  std::size_t coarse_candidates = 0;
  std::size_t fine_evaluations = 0;
};

// Searches T_target_source within +-window_m (x and y) and +-window_rad of `initial`. Source
// points are in the source frame (base_link), target points in the target frame.
CorrelativeResult MatchCorrelative(const Points2& source_base, const Points2& target,
                                   const PlanarPose& initial, double window_m, double window_rad,
                                   const CorrelativeOptions& options);

}  // namespace littermap::reconstruct
