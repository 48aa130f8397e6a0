#include "reconstruct/map_registration.hpp"

#include <utility>

#include "core/error.hpp"

namespace littermap::reconstruct {

void MapRegistrationOptions::Validate() const {
  if (!(window_m >= 0) || !(window_rad >= 0) || !(point_voxel_m > 0)) {
    throw UsageError("map registration: windows must be >= 0 and point_voxel_m > 0");
  }
  if (!(min_matching_ratio > 0 && min_matching_ratio <= 1)) {
    throw UsageError("map registration: min_matching_ratio must be in (0, 1]");
  }
  correlative.Validate();
  icp.Validate();
}

MapRegistrationResult RegisterMap(const Points2& site_points, const Points2& run_points,
                                  const PlanarPose& initial_T_site_run,
                                  const MapRegistrationOptions& options,
                                  const std::function<bool(const Eigen::Vector2d&)>& site_known) {
  options.Validate();
  MapRegistrationResult result;
  result.T_site_run = initial_T_site_run;
  Points2 site = VoxelDownsample(site_points, options.point_voxel_m);
  const Points2 run = VoxelDownsample(run_points, options.point_voxel_m);
  result.site_points = site.size();
  result.run_points = run.size();
  if (site.empty() || run.size() < options.icp.min_correspondences) return result;
  const CorrelativeResult coarse = MatchCorrelative(run, site, initial_T_site_run, options.window_m,
                                                    options.window_rad, options.correlative);
  if (!coarse.found) return result;
  result.correlative_score = coarse.score;
  const IcpTarget target(std::move(site), options.icp);
  // Two whole maps hold walls that agree to a cell, not to the millimetre ICP's convergence test
  // asks for: its last stage may end still creeping along a wall. Whether the run lies where the
  // site's walls are is what the matching ratio below decides.
  const IcpResult fine = MatchIcp(run, target, coarse.T_target_source, options.icp);
  result.icp_converged = fine.converged;
  result.T_site_run = fine.T_target_source;
  const double inlier_sq = options.icp.inlier_distance_m * options.icp.inlier_distance_m;
  std::size_t inliers = 0;
  for (const Eigen::Vector2d& p : run) {
    const Eigen::Vector2d in_site = Transform(result.T_site_run, p);
    if (site_known && !site_known(in_site)) continue;
    ++result.overlap_points;
    std::size_t nearest = 0;
    double distance_sq = 0;
    if (target.NearestWithin(in_site, inlier_sq, &nearest, &distance_sq)) ++inliers;
  }
  if (result.overlap_points > 0) {
    result.matching_ratio =
        static_cast<double>(inliers) / static_cast<double>(result.overlap_points);
  }
  result.registered = result.overlap_points >= options.min_overlap_points &&
                      result.matching_ratio >= options.min_matching_ratio;
  return result;
}

}  // namespace littermap::reconstruct
