#include "reconstruct/keyframe_map.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace littermap::reconstruct {

void KeyFrameMapOptions::Validate() const {
  if (!(translation_threshold_m > 0) || !(rotation_threshold_rad > 0)) {
    throw UsageError("key frames: thresholds must be > 0");
  }
  if (local_window < 1) throw UsageError("key frames: local_window must be >= 1");
}

KeyFrameMap::KeyFrameMap(const KeyFrameMapOptions& options, const IcpOptions& icp_options)
    : options_(options), icp_options_(icp_options) {
  options_.Validate();
}

bool KeyFrameMap::NeedsKeyFrame(const PlanarPose& T_world_base) const {
  if (key_frames_.empty()) return true;
  const PlanarPose moved = Between(key_frames_.back().T_world_base, T_world_base);
  return std::hypot(moved.x_m, moved.y_m) > options_.translation_threshold_m ||
         std::abs(moved.theta_rad) > options_.rotation_threshold_rad;
}

std::size_t KeyFrameMap::Add(KeyFrame key_frame) {
  // Normals once per key frame, in its own frame: rebuilding a target then costs a KD-tree only.
  if (icp_options_.point_to_line && key_frame.normals_base.empty()) {
    key_frame.normals_base = EstimateNormals(key_frame.points_base, icp_options_);
  }
  key_frames_.push_back(std::move(key_frame));
  local_target_.reset();
  return key_frames_.size() - 1;
}

void KeyFrameMap::SetPoses(const std::vector<PlanarPose>& poses) {
  for (std::size_t i = 0; i < poses.size() && i < key_frames_.size(); ++i) {
    key_frames_[i].T_world_base = poses[i];
  }
  local_target_.reset();
}

std::vector<PlanarPose> KeyFrameMap::Poses() const {
  std::vector<PlanarPose> poses;
  poses.reserve(key_frames_.size());
  for (const KeyFrame& k : key_frames_) poses.push_back(k.T_world_base);
  return poses;
}

MapPoints KeyFrameMap::WorldPoints(std::size_t first, std::size_t last) const {
  std::vector<std::size_t> indices;
  for (std::size_t i = first; i <= last && i < key_frames_.size(); ++i) indices.push_back(i);
  return WorldPoints(indices);
}

MapPoints KeyFrameMap::WorldPoints(const std::vector<std::size_t>& indices) const {
  MapPoints all;
  const bool with_normals = icp_options_.point_to_line;
  for (std::size_t i : indices) {
    const KeyFrame& k = key_frames_.at(i);
    const double c = std::cos(k.T_world_base.theta_rad), s = std::sin(k.T_world_base.theta_rad);
    for (std::size_t j = 0; j < k.points_base.size(); ++j) {
      all.points.push_back(Transform(k.T_world_base, k.points_base[j]));
      if (with_normals) {
        const Eigen::Vector2d& n = k.normals_base[j];
        all.normals.push_back({c * n.x() - s * n.y(), s * n.x() + c * n.y()});
      }
    }
  }
  MapPoints kept;
  for (std::size_t i : VoxelIndices(all.points, options_.target_voxel_size_m)) {
    kept.points.push_back(all.points[i]);
    if (with_normals) kept.normals.push_back(all.normals[i]);
  }
  return kept;
}

const IcpTarget& KeyFrameMap::LocalTarget() {
  if (!local_target_) {
    const std::size_t n = key_frames_.size();
    const std::size_t first = n > options_.local_window ? n - options_.local_window : 0;
    MapPoints points = n == 0 ? MapPoints{} : WorldPoints(first, n - 1);
    local_target_ =
        std::make_unique<IcpTarget>(std::move(points.points), std::move(points.normals));
  }
  return *local_target_;
}

}  // namespace littermap::reconstruct
