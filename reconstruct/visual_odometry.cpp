#include "reconstruct/visual_odometry.hpp"

#include <utility>

#include "core/error.hpp"

namespace littermap::reconstruct {

void VisualOdometryOptions::Validate() const {
  aligner.Validate();
  if (!(key_frame_distance_m > 0) || !(key_frame_angle_rad > 0) ||
      !(min_confidence >= 0 && min_confidence <= 1) || min_key_frame_inliers < 0 ||
      max_lost_frames < 1) {
    throw UsageError(
        "visual odometry: key-frame distance and angle must be > 0, min_confidence in [0, 1], "
        "min_key_frame_inliers >= 0, max_lost_frames >= 1");
  }
}

VisualOdometry::VisualOdometry(const VisualOdometryOptions& options, const RgbdCameraModel& camera)
    : options_((options.Validate(), options)), camera_(camera), aligner_(options.aligner) {}

bool VisualOdometry::Accepted(const RgbdAlignment& alignment) const {
  return alignment.ok && alignment.confidence >= options_.min_confidence;
}

VisualOdometryStep VisualOdometry::Track(const RgbdImage& image) {
  ++stats_.frames;
  RgbdKeyPoints features = aligner_.Extract(image, camera_);
  VisualOdometryStep step;
  if (!key_frame_ || lost_in_a_row_ >= options_.max_lost_frames) {
    // The first frame, or tracking lost: a new segment from the last pose known.
    step.tracked = true;
    step.new_segment = true;
    step.T_world_camera = T_world_last_;
    ++stats_.segments;
  } else {
    step.alignment = aligner_.Align(*key_frame_, features);
    if (!Accepted(step.alignment) && last_tracked_) {
      // The view left the key frame's: the last frame tracked becomes the key frame.
      const RgbdAlignment from_last = aligner_.Align(*last_tracked_, features);
      if (Accepted(from_last)) {
        key_frame_ = std::move(last_tracked_);
        T_world_key_frame_ = T_world_last_;
        ++stats_.key_frames;
        step.alignment = from_last;
        step.previous_became_key_frame = true;
      }
      last_tracked_.reset();
    }
    if (!Accepted(step.alignment)) {
      ++lost_in_a_row_;
      return step;
    }
    step.tracked = true;
    step.T_world_camera = T_world_key_frame_ * step.alignment.T_keyframe_frame;
  }
  ++stats_.tracked;
  lost_in_a_row_ = 0;
  T_world_last_ = step.T_world_camera;
  const Eigen::Isometry3d& T_key_frame = step.alignment.T_keyframe_frame;
  step.new_key_frame =
      step.new_segment || T_key_frame.translation().norm() >= options_.key_frame_distance_m ||
      Eigen::AngleAxisd(T_key_frame.linear()).angle() >= options_.key_frame_angle_rad ||
      step.alignment.icp_inliers < options_.min_key_frame_inliers;
  if (step.new_key_frame) {
    key_frame_ = std::move(features);
    T_world_key_frame_ = step.T_world_camera;
    last_tracked_.reset();
    ++stats_.key_frames;
  } else {
    last_tracked_ = std::move(features);
  }
  return step;
}

}  // namespace littermap::reconstruct
