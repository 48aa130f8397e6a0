#include "eval/scan_settling.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "reconstruct/keyframe_map.hpp"
#include "reconstruct/pose_graph.hpp"

namespace littermap::eval {

void ScanSettlingOptions::Validate() const {
  points.Validate();
  alignment.Validate();
  if (!(scan_voxel_size_m > 0) || !(frame_spacing_m >= 0) || !(frame_spacing_rad >= 0) ||
      !(max_time_difference_s >= 0) || !(hold_sigma_m > 0) || !(hold_sigma_rad > 0)) {
    throw UsageError(
        "scan settling: scan_voxel_size_m, hold_sigma_m and hold_sigma_rad must be > 0, "
        "frame spacings and max_time_difference_s >= 0");
  }
}

ScanSettling SettleOnScans(const std::vector<LaserScan>& scans, const PlanarPose& T_base_laser,
                           const std::vector<StampedPose>& trajectory,
                           const ScanSettlingOptions& options) {
  options.Validate();
  std::vector<StampedPose> sorted = trajectory;
  std::stable_sort(sorted.begin(), sorted.end(), [](const StampedPose& a, const StampedPose& b) {
    return a.stamp_ns < b.stamp_ns;
  });
  std::vector<std::size_t> order(scans.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scans[a].stamp_ns < scans[b].stamp_ns;
  });

  ScanSettling settling;
  settling.scans = scans.size();
  std::vector<reconstruct::KeyFrame> frames;
  std::vector<PlanarPose> poses;
  double path_length_m = 0;
  std::optional<PlanarPose> last_placed;
  for (std::size_t index : order) {
    const LaserScan& scan = scans[index];
    const std::optional<PlanarPose> T_world_base =
        PlanarPoseNearest(sorted, scan.stamp_ns, options.max_time_difference_s);
    if (!T_world_base) continue;
    reconstruct::Points2 points = reconstruct::VoxelDownsample(
        reconstruct::ScanToPoints(scan, T_base_laser, options.points).points_base,
        options.scan_voxel_size_m);
    if (points.size() < options.min_scan_points) continue;
    ++settling.scans_placed;
    if (last_placed) {
      const PlanarPose step = Between(*last_placed, *T_world_base);
      path_length_m += std::hypot(step.x_m, step.y_m);
    }
    last_placed = T_world_base;
    if (!poses.empty()) {
      const PlanarPose moved = Between(poses.back(), *T_world_base);
      if (std::hypot(moved.x_m, moved.y_m) < options.frame_spacing_m &&
          std::abs(moved.theta_rad) < options.frame_spacing_rad) {
        continue;
      }
    }
    reconstruct::KeyFrame frame;
    frame.scan_index = index;
    frame.stamp_ns = scan.stamp_ns;
    frame.T_world_base = *T_world_base;
    frame.points_base = std::move(points);
    frame.path_length_m = path_length_m;
    frames.push_back(std::move(frame));
    poses.push_back(*T_world_base);
  }
  if (frames.size() < 2) {
    throw BadInputError("scan settling: " + std::to_string(frames.size()) + " of " +
                        std::to_string(scans.size()) +
                        " scans have a trajectory pose and enough echoes; at least 2 are needed");
  }

  std::vector<reconstruct::PoseGraphEdge> holds;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    holds.push_back({k - 1, k, Between(poses[k - 1], poses[k]),
                     reconstruct::DiagonalInformation(options.hold_sigma_m, options.hold_sigma_rad),
                     false});
  }
  for (const reconstruct::KeyFrame& frame : frames) {
    settling.given.emplace_back(frame.stamp_ns, frame.T_world_base);
  }
  settling.alignment = reconstruct::AlignScans(frames, holds, &poses, options.alignment);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    settling.settled.emplace_back(frames[k].stamp_ns, poses[k]);
  }
  return settling;
}

}  // namespace littermap::eval
