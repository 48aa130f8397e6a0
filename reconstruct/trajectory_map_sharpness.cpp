#include "reconstruct/trajectory_map_sharpness.hpp"

#include <cstdio>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"

namespace littermap::reconstruct {

std::vector<eval::MapSharpness> MeasureTrajectoryMaps(const std::filesystem::path& bag,
                                                      const std::vector<std::string>& trajectories,
                                                      const TrajectoryMapsOptions& options,
                                                      const ProgressCallback& progress,
                                                      const WarningCallback& warn) {
  options.map.Validate();
  const BagScans scans = ReadBagScans(bag, options.scan_topic, progress, warn);
  std::vector<eval::MapSharpness> maps;
  for (const std::string& path : trajectories) {
    const std::string task = "drawing the scans with " + path;
    ReportProgress(progress, {task});
    const std::vector<StampedPose> trajectory = bag::ReadTumTrajectory(path);
    eval::MapSharpness map;
    try {
      map = eval::MeasureMapSharpness(scans.scans, scans.T_base_laser, trajectory, options.map);
    } catch (const BadInputError& error) {
      throw BadInputError(path + ": " + error.what());
    }
    if (map.scans_drawn < map.scans && warn) {
      char within[64];
      std::snprintf(within, sizeof within, "%g s", options.map.max_time_difference_s);
      warn(path + ": " + std::to_string(map.scans - map.scans_drawn) + " of " +
           std::to_string(map.scans) + " scans have no pose within " + within +
           " and are not drawn; counts of trajectories that draw different scans do not compare");
    }
    maps.push_back(map);
  }
  return maps;
}

}  // namespace littermap::reconstruct
