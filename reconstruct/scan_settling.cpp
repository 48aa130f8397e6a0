#include "reconstruct/scan_settling.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "core/error.hpp"
#include "reconstruct/keyframe_map.hpp"
#include "reconstruct/pose_graph.hpp"

namespace littermap::reconstruct {

void ScanSettlingOptions::Validate() const {
  points.Validate();
  alignment.Validate();
  if (!(scan_voxel_size_m > 0) || !(frame_spacing_m >= 0) || !(frame_spacing_rad >= 0) ||
      !(hold_sigma_m > 0) || !(hold_sigma_rad > 0)) {
    throw UsageError(
        "scan settling: scan_voxel_size_m, hold_sigma_m and hold_sigma_rad must be > 0, frame "
        "spacings >= 0");
  }
}

ScanSettling SettleOnScans(const std::vector<LaserScan>& scans,
                           const std::vector<std::optional<PlanarPose>>& T_world_base,
                           const PlanarPose& T_base_laser, const ScanSettlingOptions& options) {
  options.Validate();
  if (T_world_base.size() != scans.size()) {
    throw InternalError("scan settling: " + std::to_string(T_world_base.size()) + " poses for " +
                        std::to_string(scans.size()) + " scans");
  }
  std::vector<std::size_t> order(scans.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scans[a].stamp_ns < scans[b].stamp_ns;
  });

  ScanSettling settling;
  settling.scans = scans.size();
  std::vector<KeyFrame> frames;
  std::vector<PlanarPose> poses;
  for (std::size_t index : order) {
    if (!T_world_base[index]) continue;
    ++settling.scans_posed;
    const PlanarPose& pose = *T_world_base[index];
    ScanPoints points = ScanToPoints(scans[index], T_base_laser, options.points);
    if (points.valid_beams < options.min_scan_points) continue;
    ++settling.scans_placed;
    if (!poses.empty()) {
      const PlanarPose moved = Between(poses.back(), pose);
      if (std::hypot(moved.x_m, moved.y_m) < options.frame_spacing_m &&
          std::abs(moved.theta_rad) < options.frame_spacing_rad) {
        continue;
      }
    }
    KeyFrame frame;
    frame.scan_index = index;
    frame.stamp_ns = scans[index].stamp_ns;
    frame.T_world_base = pose;
    frame.points_base = VoxelDownsample(points.points_base, options.scan_voxel_size_m);
    frames.push_back(std::move(frame));
    poses.push_back(pose);
  }
  if (frames.size() < 3) {
    throw BadInputError("scan settling: " + std::to_string(settling.scans_placed) + " of " +
                        std::to_string(scans.size()) +
                        " scans have a pose and enough echoes, and " +
                        std::to_string(frames.size()) +
                        " of them lie a frame spacing apart; at least 3 are needed");
  }

  std::vector<PoseGraphEdge> holds;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    holds.push_back({k - 1, k, Between(poses[k - 1], poses[k]),
                     DiagonalInformation(options.hold_sigma_m, options.hold_sigma_rad), false});
  }
  for (const KeyFrame& frame : frames)
    settling.given.emplace_back(frame.stamp_ns, frame.T_world_base);
  settling.alignment = AlignScans(frames, holds, &poses, options.alignment);
  if (settling.alignment.pairs_matched == 0) {
    throw BadInputError("scan settling: no two of the " + std::to_string(frames.size()) +
                        " scans aligned see the same walls");
  }
  for (std::size_t k = 0; k < frames.size(); ++k) {
    settling.settled.emplace_back(frames[k].stamp_ns, poses[k]);
  }
  return settling;
}

}  // namespace littermap::reconstruct
