#pragma once
// Visual odometry for runs without a laser (a TUM RGB-D sequence): every camera frame is aligned
// (thesis 2.4) to the current RGB-D key frame; a frame that moved far enough from it, or whose
// alignment grows weak, becomes the next key frame. A frame that does not align to the key frame
// is tried against the last frame tracked (which then becomes the key frame); one that aligns to
// neither gets no pose and the next frames are tried the same way; after max_lost_frames in a row
// tracking
// is lost: the next frame starts a new segment at the last known pose (its motion since then is
// unknown), and the count of segments is reported.
//
// Poses are of the camera's optical frame, in the first frame's optical frame.

#include <cstddef>
#include <optional>

#include <Eigen/Geometry>

#include "reconstruct/rgbd_aligner.hpp"

namespace littermap::reconstruct {

struct VisualOdometryOptions {
  RgbdAlignerOptions aligner;
  double key_frame_distance_m = 0.1;  // a new key frame after this much camera motion ...
  double key_frame_angle_rad = 0.15;  // ... or rotation
  double min_confidence = 0.3;        // RgbdAlignment::confidence to accept a frame's pose
  // An accepted frame with fewer ICP inliers than this becomes a key frame: the view is leaving
  // the key frame's.
  int min_key_frame_inliers = 60;
  std::size_t max_lost_frames = 15;  // frames in a row without a pose before a new segment
  void Validate() const;
};

struct VisualOdometryStep {
  bool tracked = false;  // the frame has a pose
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  RgbdAlignment alignment;  // against the key frame (default for key frames of a new segment)
  bool new_key_frame = false;
  bool previous_became_key_frame = false;  // the last frame tracked, to align this one
  bool new_segment = false;                // this frame starts a segment (the first frame does too)
};

struct VisualOdometryStats {
  std::size_t frames = 0;
  std::size_t tracked = 0;
  std::size_t key_frames = 0;
  std::size_t segments = 0;
};

class VisualOdometry {
 public:
  VisualOdometry(const VisualOdometryOptions& options, const RgbdCameraModel& camera);

  // Throws UsageError for an image of the wrong type (see RgbdAligner::Extract).
  VisualOdometryStep Track(const RgbdImage& image);
  const VisualOdometryStats& stats() const { return stats_; }

 private:
  VisualOdometryOptions options_;
  RgbdCameraModel camera_;
  RgbdAligner aligner_;
  bool Accepted(const RgbdAlignment& alignment) const;

  std::optional<RgbdKeyPoints> key_frame_;
  Eigen::Isometry3d T_world_key_frame_ = Eigen::Isometry3d::Identity();
  std::optional<RgbdKeyPoints> last_tracked_;                       // when it is not the key frame
  Eigen::Isometry3d T_world_last_ = Eigen::Isometry3d::Identity();  // last pose known
  std::size_t lost_in_a_row_ = 0;
  VisualOdometryStats stats_;
};

}  // namespace littermap::reconstruct
