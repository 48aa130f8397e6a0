#pragma once
// How far a trajectory lies from a trajectory its own scans agree with. The scans are placed with
// the trajectory's poses and aligned against each other by the final scan alignment (AlignScans:
// every scan point to line against the scans that see the same walls, those before it along the
// path and those of earlier visits), held to the trajectory's own steps only weakly, where the
// walls leave a direction open (along a corridor). How far the trajectory moves is how much its
// scans dispute it. A trajectory that littermap reconstructed moves little; a reference from
// another system may move further than the accuracy it is used to judge.
// Like map sharpness, this ranks agreement with the scans, not accuracy: the scans of a tilting
// base cut the terrain at changing heights, and agreeing with them is then no virtue; and where
// the scans leave the large-scale shape open, the settled poses slide along that freedom.

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "reconstruct/scan_alignment.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct ScanSettlingOptions {
  ScanPointsOptions points;          // as reconstruct places echoes
  double scan_voxel_size_m = 0.05;   // and downsamples them (SlamOptions)
  std::size_t min_scan_points = 20;  // fewer valid echoes: the scan is left out
  // Scans are thinned like key frames: one per this much motion along the trajectory.
  double frame_spacing_m = 0.5;
  double frame_spacing_rad = 0.3;
  double hold_sigma_m = 1.0;  // the weak hold of each step of the trajectory
  double hold_sigma_rad = 0.5;
  ScanAlignmentOptions alignment;
  void Validate() const;  // throws UsageError
};

struct ScanSettling {
  std::size_t scans = 0;
  std::size_t scans_posed = 0;   // with a pose
  std::size_t scans_placed = 0;  // and enough valid echoes
  // The scans aligned (thinned by frame spacing), in stamp order, T_world_base as given and as
  // settled.
  std::vector<std::pair<TimestampNs, PlanarPose>> given;
  std::vector<std::pair<TimestampNs, PlanarPose>> settled;
  ScanAlignmentResult alignment;
};

// T_world_base: the trajectory's pose of each scan (same order as scans), if it has one;
// T_base_laser places the laser on the base. Throws BadInputError when fewer than three scans
// are left to align, or when no two of them see the same walls.
ScanSettling SettleOnScans(const std::vector<LaserScan>& scans,
                           const std::vector<std::optional<PlanarPose>>& T_world_base,
                           const PlanarPose& T_base_laser, const ScanSettlingOptions& options = {});

}  // namespace littermap::reconstruct
