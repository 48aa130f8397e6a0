#pragma once
// How sharp a map each of several trajectory files draws from a bag's scans
// (eval/map_sharpness.hpp), as `littermap eval map` compares them.

#include <filesystem>
#include <string>
#include <vector>

#include "bag/topics.hpp"
#include "core/progress.hpp"
#include "eval/map_sharpness.hpp"
#include "reconstruct/bag_scans.hpp"

namespace littermap::reconstruct {

struct TrajectoryMapsOptions {
  std::string scan_topic = bag::RunTopics{}.scan;
  eval::MapSharpnessOptions map;
};

// One result per trajectory, in order. `progress` is told each step as it starts (a task without
// counts: reading the scans, drawing them with each trajectory); `warn` hears of the bag's
// missing extrinsic and of each trajectory that leaves scans undrawn, as they are found. Throws
// UsageError for invalid options, BadInputError naming the bag and topic or the trajectory file
// at fault.
std::vector<eval::MapSharpness> MeasureTrajectoryMaps(const std::filesystem::path& bag,
                                                      const std::vector<std::string>& trajectories,
                                                      const TrajectoryMapsOptions& options,
                                                      const ProgressCallback& progress = {},
                                                      const WarningCallback& warn = {});

}  // namespace littermap::reconstruct
