#pragma once
// How far a trajectory lies from the nearest trajectory its own scans agree with. The scans are
// placed with the trajectory's poses and aligned against each other with reconstruct's final scan
// alignment (AlignScans: every scan point to line against the scans that see the same walls,
// those before it along the path and those of earlier visits), held to the trajectory's own
// shape only weakly, where the walls leave a direction open (along a corridor). The settled
// trajectory is the local optimum of scan agreement nearest the given one; how far the given
// one moved is what its scans disagree with it. A trajectory that littermap reconstructed moves
// little; a reference from another system may move further than the accuracy it is used to judge.
// Like map sharpness, this ranks agreement with the scans, not accuracy: the scans of a tilting
// base cut the terrain at changing heights, and agreeing with them is then no virtue.

#include <cstddef>
#include <utility>
#include <vector>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "eval/trajectory_metrics.hpp"
#include "reconstruct/scan_alignment.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::eval {

struct ScanSettlingOptions {
  reconstruct::ScanPointsOptions points;  // reconstruct's defaults
  double scan_voxel_size_m = 0.05;        // as the tracker downsamples
  std::size_t min_scan_points = 20;       // fewer valid echoes: the scan is left out
  double frame_spacing_m = 0.5;           // scans are thinned like key frames: one per this
  double frame_spacing_rad = 0.3;         // much motion along the trajectory
  double max_time_difference_s = 0.02;    // a scan without a pose this close is left out
  double hold_sigma_m = 1.0;              // the weak hold of each step of the trajectory
  double hold_sigma_rad = 0.5;
  reconstruct::ScanAlignmentOptions alignment;
  void Validate() const;  // throws UsageError
};

struct ScanSettling {
  std::size_t scans = 0;
  std::size_t scans_placed = 0;  // with a pose within max_time_difference_s and enough echoes
  // The scans aligned (thinned by frame spacing), as given and as settled: T_world_base.
  std::vector<std::pair<TimestampNs, PlanarPose>> given;
  std::vector<std::pair<TimestampNs, PlanarPose>> settled;
  reconstruct::ScanAlignmentResult alignment;
};

// The trajectory gives T_world_base at the scans' stamps (the pose nearest in time); T_base_laser
// places the laser on the base. Throws BadInputError when fewer than two scans can be placed.
ScanSettling SettleOnScans(const std::vector<LaserScan>& scans, const PlanarPose& T_base_laser,
                           const std::vector<StampedPose>& trajectory,
                           const ScanSettlingOptions& options = {});

}  // namespace littermap::eval
