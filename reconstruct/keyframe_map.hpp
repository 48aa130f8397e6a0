#pragma once
// The top map of thesis 2.3 (GKMap): only key frames, i.e. scans whose pose moved more than a
// translation or rotation threshold from the last key frame. Each key frame keeps its points in
// its own frame and its pose in the world, so after a pose-graph optimisation the map follows
// the new poses without re-matching. Scans are matched against the points of the most recent
// key frames (a local window of the top map): older parts of the map are brought in by loop
// closure, which corrects their drift first, so they never print a second copy of a wall.
// The bottom map (GMap, every scan) is the occupancy grid rendered from all scans.

#include <cstddef>
#include <memory>
#include <vector>

#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "reconstruct/icp_matcher.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct KeyFrame {
  std::size_t scan_index = 0;
  TimestampNs stamp_ns = 0;
  PlanarPose T_world_base;
  Points2 points_base;
  double path_length_m = 0;  // distance travelled (estimate) up to this key frame
  Points2 normals_base;      // filled by KeyFrameMap::Add, once per key frame
};

// Points with their line normals (empty normals: point-to-point).
struct MapPoints {
  Points2 points;
  Points2 normals;
};

struct KeyFrameMapOptions {
  double translation_threshold_m = 0.5;
  double rotation_threshold_rad = 0.3;
  std::size_t local_window = 12;  // key frames in the tracking target
  double target_voxel_size_m = 0.05;
  void Validate() const;
};

class KeyFrameMap {
 public:
  KeyFrameMap(const KeyFrameMapOptions& options, const IcpOptions& icp_options);

  // True if the pose moved enough from the last key frame to make a new one (thesis 2.3).
  bool NeedsKeyFrame(const PlanarPose& T_world_base) const;
  std::size_t Add(KeyFrame key_frame);
  // New poses for all key frames (after optimisation).
  void SetPoses(const std::vector<PlanarPose>& poses);

  const std::vector<KeyFrame>& key_frames() const { return key_frames_; }
  bool empty() const { return key_frames_.empty(); }
  std::vector<PlanarPose> Poses() const;

  // KD-tree target over the last local_window key frames in the world frame, rebuilt lazily.
  const IcpTarget& LocalTarget();
  // World points and normals of key frames [first, last], voxel-downsampled.
  MapPoints WorldPoints(std::size_t first, std::size_t last) const;
  // World points and normals of the listed key frames, voxel-downsampled.
  MapPoints WorldPoints(const std::vector<std::size_t>& indices) const;

 private:
  KeyFrameMapOptions options_;
  IcpOptions icp_options_;
  std::vector<KeyFrame> key_frames_;
  std::unique_ptr<IcpTarget> local_target_;
};

}  // namespace littermap::reconstruct
