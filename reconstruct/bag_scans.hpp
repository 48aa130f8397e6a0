#pragma once
// A bag's laser scans with the base_link -> laser extrinsic, as the scan-based trajectory checks
// (map sharpness, settling) draw them.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/progress.hpp"

namespace littermap::reconstruct {

struct BagScans {
  PlanarPose T_base_laser;  // identity when the bag has none (with a warning)
  std::vector<LaserScan> scans;
};

// The laser extrinsic from /tf_static, then every scan on the topic in bag order; `progress` is
// told "reading the scans of BAG" (a task without counts) in between. Throws BadInputError naming
// the bag and topic when the topic is missing or a message does not decode.
BagScans ReadBagScans(const std::filesystem::path& bag, const std::string& scan_topic,
                      const ProgressCallback& progress = {}, const WarningCallback& warn = {});

}  // namespace littermap::reconstruct
