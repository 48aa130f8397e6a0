#pragma once
// Routine 3 of the hybrid tracker (thesis Alg. 2.5.1.1): while the laser tracks, camera frames
// become RGB-D key frames, anchored to the 2D key frame of their scan so they follow the pose
// graph; when the laser cannot place a scan (tilt, roll, the laser on the ground), the camera
// frame at the scan's time is aligned (thesis 2.4) to the nearest RGB-D key frame and gives
// the pose. The camera's full 3D pose (x, y, z, roll, pitch, yaw) is kept for every frame.
//
// Frames come in time order between the scans (AddFrame); compressed images are decoded only
// for key frames and alignments. A frame's pose is carried to the scan's time by the odometry
// between them.

#include <cstddef>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "bag/rgbd_pairing.hpp"
#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "reconstruct/keyframe_map.hpp"
#include "reconstruct/rgbd_aligner.hpp"
#include "reconstruct/tracker.hpp"

namespace littermap::reconstruct {

struct RgbdTrackerOptions {
  RgbdAlignerOptions aligner;
  double key_frame_distance_m = 0.15;  // camera motion between RGB-D key frames ...
  double key_frame_angle_rad = 0.25;   // ... or view direction change
  double max_frame_age_s = 0.15;       // camera frame to scan, farther: no frame for the scan
  double search_radius_m = 2.5;        // key frames whose camera is this close to the predicted
  double max_view_angle_rad = 0.7;     // one, looking within this angle of its direction,
  int max_candidates = 3;              // nearest first, this many tried
  double min_confidence = 0.3;         // RgbdAlignment::confidence to accept
  // Loops (FindLoop): RGB-D key frames at least loop_min_path_separation_m back along the path,
  // whose camera is within loop_search_radius_m + loop_search_radius_per_m of that path (the
  // drift it may have gathered; at most loop_max_search_radius_m) and looks within
  // max_view_angle_rad; nearest first, max_candidates tried, accepted at loop_min_confidence.
  bool loops = true;
  double loop_min_path_separation_m = 10;
  double loop_search_radius_m = 1.0;
  double loop_search_radius_per_m = 0.03;
  double loop_max_search_radius_m = 5;
  double loop_min_confidence = 0.5;
  void Validate() const;
};

// How a camera frame's 3D pose was found.
enum class CameraPoseSource { kLaser, kRgbd, kOdometry };

struct CameraPose {
  TimestampNs stamp_ns = 0;
  std::size_t scan_index = 0;  // the scan the frame was tracked with
  CameraPoseSource source = CameraPoseSource::kLaser;
  // The optical frame relative to the scan's base pose on the ground plane (z = 0, level): the
  // final pose is that pose, optimised, composed with this.
  Eigen::Isometry3d T_scan_camera = Eigen::Isometry3d::Identity();
};

struct RgbdTrackerStats {
  std::size_t frames = 0;
  std::size_t key_frames = 0;
  std::size_t alignments = 0;       // frames aligned for routine 3
  std::size_t aligned = 0;          // of which accepted
  std::size_t loop_alignments = 0;  // frames aligned to old key frames for a loop
};

class RgbdTracker final : public RgbdFallback {
 public:
  RgbdTracker(const RgbdTrackerOptions& options, const RgbdCameraModel& camera,
              const Eigen::Isometry3d& T_base_camera);

  // The next camera frame, with the odometry at its time if known.
  void AddFrame(bag::CompressedRgbd frame, const std::optional<PlanarPose>& T_odom_base);

  std::optional<PlanarPose> AlignAt(const TrackInput& input, const PlanarPose& predicted,
                                    const KeyFrameMap& map) override;
  void OnTracked(const TrackInput& input, const TrackStep& step, const KeyFrameMap& map) override;
  std::optional<CameraLoop> FindLoop(const TrackInput& input, const TrackStep& step,
                                     const KeyFrameMap& map) override;

  const std::vector<CameraPose>& camera_poses() const { return camera_poses_; }
  const RgbdTrackerStats& stats() const { return stats_; }

 private:
  struct Frame {
    bag::CompressedRgbd images;
    std::optional<PlanarPose> T_odom_base;
    std::optional<RgbdKeyPoints> features;  // extracted on first use
    bool recorded = false;                  // its pose is in camera_poses_
    bool aligned = false;                   // routine 3 tried it
    std::optional<Eigen::Isometry3d> T_world_camera_aligned;
  };
  struct KeyFrame {
    std::size_t map_key_frame = 0;
    Eigen::Isometry3d T_anchor_camera;  // relative to the 2D key frame's pose on the ground
    RgbdKeyPoints features;
  };

  // The current frame if it is close enough in time to the scan.
  Frame* FrameFor(TimestampNs stamp_ns);
  const RgbdKeyPoints& FeaturesOf(Frame* frame);
  Eigen::Isometry3d CameraFromBase(const PlanarPose& T_world_base,
                                   const std::optional<Tilt>& tilt) const;
  Eigen::Isometry3d WorldCamera(const KeyFrame& key_frame, const KeyFrameMap& map) const;
  // Of the first `count` key frames, those whose camera lies within radius_m(index) of
  // T_world_camera and looks within max_view_angle_rad of it: nearest first, max_candidates.
  std::vector<std::size_t> NearestKeyFrames(
      const Eigen::Isometry3d& T_world_camera, const KeyFrameMap& map, std::size_t count,
      const std::function<double(std::size_t)>& radius_m) const;

  RgbdTrackerOptions options_;
  RgbdCameraModel camera_;
  Eigen::Isometry3d T_base_camera_;
  RgbdAligner aligner_;
  std::optional<Frame> frame_;
  std::vector<KeyFrame> key_frames_;
  std::vector<CameraPose> camera_poses_;
  RgbdTrackerStats stats_;
};

// The pose of a base on the ground plane (z = 0) tilted by roll and pitch.
Eigen::Isometry3d LiftPose(const PlanarPose& T_world_base, const std::optional<Tilt>& tilt);

}  // namespace littermap::reconstruct
