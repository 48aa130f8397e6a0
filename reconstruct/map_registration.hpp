#pragma once
// Registers a run's occupancy map onto the site map: the occupied cells of both as points, a
// correlative search in a window around the initial guess (a run that starts at the dock starts
// near the site frame's origin) and ICP to refine it. The match counts only if enough of the
// run's walls and trunks land on the site's: a run elsewhere, or a park changed beyond
// recognition, is refused rather than stored in the wrong place.

#include <cstddef>
#include <functional>

#include "core/planar_pose.hpp"
#include "reconstruct/correlative_matcher.hpp"
#include "reconstruct/icp_matcher.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct MapRegistrationOptions {
  double window_m = 3;         // search half-width around the initial guess
  double window_rad = 0.26;    // 15 degrees
  double point_voxel_m = 0.1;  // both maps' points thinned to this spacing
  // Accepted when at least this share of the run's points lies within inlier_distance_m of the
  // site's after ICP.
  double min_matching_ratio = 0.5;
  // The ratio counts only run points where the site map knows the ground (free or occupied):
  // a run that maps more of the park than the site map is not refused for it. At least this
  // many such points are needed.
  std::size_t min_overlap_points = 100;
  CorrelativeOptions correlative{.cell_size_m = 0.1,
                                 .sigma_m = 0.15,
                                 .source_voxel_m = 0.4,
                                 .max_source_range_m = 1e6,
                                 .max_source_points = 400};
  IcpOptions icp;
  void Validate() const;
};

struct MapRegistrationResult {
  bool registered = false;
  PlanarPose T_site_run;
  double matching_ratio = 0;       // share of the overlapping run points on the site's, [0, 1]
  std::size_t overlap_points = 0;  // run points where the site map knows the ground
  double correlative_score = 0;    // of the coarse match, in [0, 1]
  bool icp_converged = false;      // informative: the matching ratio decides
  std::size_t run_points = 0;
  std::size_t site_points = 0;
};

// site_known: whether the site map knows the ground at a point of the site frame; unset: it
// knows it everywhere.
MapRegistrationResult RegisterMap(
    const Points2& site_points, const Points2& run_points, const PlanarPose& initial_T_site_run,
    const MapRegistrationOptions& options,
    const std::function<bool(const Eigen::Vector2d&)>& site_known = {});

}  // namespace littermap::reconstruct
