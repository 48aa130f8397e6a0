#pragma once
// A bag's laser scans with the base_link -> laser extrinsic, for `eval map` and `eval settle`.

#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "reconstruct/reconstruction.hpp"

namespace littermap::cli {

struct BagScans {
  PlanarPose T_base_laser;
  std::vector<LaserScan> scans;
};

// A bag's laser extrinsic (warnings reported) and all its scans.
inline BagScans ReadBagScans(const std::string& bag, const std::string& scan_topic,
                             CliContext& context) {
  reconstruct::ReconstructionOptions bag_options;
  bag_options.topics.scan = scan_topic;
  std::vector<std::string> warnings;
  BagScans read;
  read.T_base_laser = reconstruct::ReadLaserExtrinsic(bag, bag_options, &warnings);
  for (const std::string& warning : warnings) context.Warn(warning);
  context.Status("reading the scans of " + bag);
  read.scans = reconstruct::ReadScans(bag, scan_topic);
  return read;
}

}  // namespace littermap::cli
