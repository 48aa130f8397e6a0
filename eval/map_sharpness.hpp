#pragma once
// How sharp a map a trajectory draws from the scans of its run: every scan's echoes are placed
// with the trajectory's pose for it, and the grid cells they fall in are counted. A pose error
// smears a wall over more cells, so of two trajectories of the same run the one that occupies
// fewer cells lays the scans more consistently over each other. This needs no reference, so it
// also judges runs without ground truth, and it can judge a reference itself (the CARMEN
// "corrected" poses came from another SLAM system). Counts are comparable only between
// trajectories of the same scans with the same options.

#include <cstddef>
#include <vector>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "eval/trajectory_metrics.hpp"

namespace littermap::eval {

struct MapSharpnessOptions {
  double cell_size_m = 0.05;
  // Far echoes are few, and a heading error moves them most: they would weigh the count by the
  // sensor's range, not by the trajectory.
  double max_range_m = 20.0;
  double max_time_difference_s = 0.02;  // a scan without a pose this close is not drawn
  void Validate() const;                // throws UsageError
};

struct MapSharpness {
  std::size_t scans = 0;
  std::size_t scans_drawn = 0;  // scans with a pose within max_time_difference_s
  std::size_t echoes_drawn = 0;
  std::size_t occupied_cells = 0;
};

// The trajectory gives T_world_base at the scans' stamps (the pose nearest in time); T_base_laser
// places the laser on the base. Scans need not be sorted. Throws BadInputError when the
// trajectory is empty or places no scan.
MapSharpness MeasureMapSharpness(const std::vector<LaserScan>& scans,
                                 const PlanarPose& T_base_laser,
                                 const std::vector<StampedPose>& trajectory,
                                 const MapSharpnessOptions& options = {});

// The maps of several trajectories as a JSON object (2-space indent): cell_size_m, max_range_m
// and per trajectory (named by `names`, one per result) its counts.
std::string ToJson(const std::vector<std::string>& names, const std::vector<MapSharpness>& maps,
                   const MapSharpnessOptions& options);
// The same as a table, one line per trajectory: occupied cells, their share of the first
// trajectory's, echoes and scans drawn.
std::string ToText(const std::vector<std::string>& names, const std::vector<MapSharpness>& maps,
                   const MapSharpnessOptions& options);

}  // namespace littermap::eval
