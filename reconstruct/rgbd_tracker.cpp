#include "reconstruct/rgbd_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "bag/image_codec.hpp"
#include "core/error.hpp"
#include "core/pose3.hpp"

namespace littermap::reconstruct {
namespace {

// Angle between the viewing directions (optical z axes) of two camera poses.
double ViewAngle(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const double c = a.linear().col(2).dot(b.linear().col(2));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

// A pose carried by the odometry from one time to another (kept when either odometry is unknown).
PlanarPose Carry(const PlanarPose& pose, const std::optional<PlanarPose>& T_odom_from,
                 const std::optional<PlanarPose>& T_odom_to) {
  if (!T_odom_from || !T_odom_to) return pose;
  return Compose(pose, Between(*T_odom_from, *T_odom_to));
}

}  // namespace

Eigen::Isometry3d LiftPose(const PlanarPose& T_world_base, const std::optional<Tilt>& tilt) {
  RollPitchYaw rpy{0, 0, T_world_base.theta_rad};
  if (tilt) {
    rpy.roll_rad = tilt->roll_rad;
    rpy.pitch_rad = tilt->pitch_rad;
  }
  return MakeIsometry({T_world_base.x_m, T_world_base.y_m, 0}, rpy);
}

void RgbdTrackerOptions::Validate() const {
  aligner.Validate();
  if (!(key_frame_distance_m > 0) || !(key_frame_angle_rad > 0) || !(max_frame_age_s > 0) ||
      !(search_radius_m > 0) || !(max_view_angle_rad > 0) || max_candidates < 1 ||
      !(min_confidence >= 0 && min_confidence <= 1)) {
    throw UsageError(
        "RGB-D tracker: key-frame spacing, frame age, search radius and view angle must be > 0, "
        "max_candidates >= 1, min_confidence in [0, 1]");
  }
  if (!(loop_min_path_separation_m > 0) || !(loop_search_radius_m > 0) ||
      !(loop_search_radius_per_m >= 0) || !(loop_max_search_radius_m >= loop_search_radius_m) ||
      !(loop_min_confidence >= 0 && loop_min_confidence <= 1)) {
    throw UsageError(
        "RGB-D tracker: loop path separation and search radius must be > 0, the radius's share "
        "of the path >= 0, its maximum >= the radius, loop_min_confidence in [0, 1]");
  }
}

RgbdTracker::RgbdTracker(const RgbdTrackerOptions& options, const RgbdCameraModel& camera,
                         const Eigen::Isometry3d& T_base_camera)
    : options_((options.Validate(), options)),
      camera_(camera),
      T_base_camera_(T_base_camera),
      aligner_(options.aligner) {}

void RgbdTracker::AddFrame(bag::CompressedRgbd frame,
                           const std::optional<PlanarPose>& T_odom_base) {
  ++stats_.frames;
  Frame next;
  next.images = std::move(frame);
  next.T_odom_base = T_odom_base;
  frame_ = std::move(next);
}

RgbdTracker::Frame* RgbdTracker::FrameFor(TimestampNs stamp_ns) {
  if (!frame_ ||
      std::abs(ToSeconds(stamp_ns - frame_->images.stamp_ns)) > options_.max_frame_age_s) {
    return nullptr;
  }
  return &*frame_;
}

const RgbdKeyPoints& RgbdTracker::FeaturesOf(Frame* frame) {
  if (!frame->features) {
    RgbdImage image;
    image.colour_bgr = bag::DecodeColor(frame->images);
    image.depth = bag::DecodeDepthMm(frame->images);
    frame->features = aligner_.Extract(image, camera_);
  }
  return *frame->features;
}

Eigen::Isometry3d RgbdTracker::CameraFromBase(const PlanarPose& T_world_base,
                                              const std::optional<Tilt>& tilt) const {
  return LiftPose(T_world_base, tilt) * T_base_camera_;
}

std::vector<std::size_t> RgbdTracker::NearestKeyFrames(
    const Eigen::Isometry3d& T_world_camera, const KeyFrameMap& map, std::size_t count,
    const std::function<double(std::size_t)>& radius_m) const {
  std::vector<std::pair<double, std::size_t>> candidates;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Isometry3d T_world_kf = WorldCamera(key_frames_[i], map);
    const double distance_m = (T_world_kf.translation() - T_world_camera.translation()).norm();
    if (distance_m <= radius_m(i) &&
        ViewAngle(T_world_kf, T_world_camera) <= options_.max_view_angle_rad) {
      candidates.emplace_back(distance_m, i);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<std::size_t> nearest;
  for (const auto& [distance_m, index] : candidates) {
    if (nearest.size() == static_cast<std::size_t>(options_.max_candidates)) break;
    nearest.push_back(index);
  }
  return nearest;
}

Eigen::Isometry3d RgbdTracker::WorldCamera(const KeyFrame& key_frame,
                                           const KeyFrameMap& map) const {
  return LiftPose(map.key_frames()[key_frame.map_key_frame].T_world_base, std::nullopt) *
         key_frame.T_anchor_camera;
}

std::optional<PlanarPose> RgbdTracker::AlignAt(const TrackInput& input, const PlanarPose& predicted,
                                               const KeyFrameMap& map) {
  Frame* frame = FrameFor(input.stamp_ns);
  if (frame == nullptr || key_frames_.empty()) return std::nullopt;
  if (!frame->aligned) {
    frame->aligned = true;
    ++stats_.alignments;
    const Eigen::Isometry3d T_world_camera_predicted =
        CameraFromBase(Carry(predicted, input.T_odom_base, frame->T_odom_base), input.tilt);
    for (std::size_t index :
         NearestKeyFrames(T_world_camera_predicted, map, key_frames_.size(),
                          [&](std::size_t) { return options_.search_radius_m; })) {
      const KeyFrame& key_frame = key_frames_[index];
      const RgbdAlignment alignment = aligner_.Align(key_frame.features, FeaturesOf(frame));
      if (alignment.ok && alignment.confidence >= options_.min_confidence) {
        frame->T_world_camera_aligned = WorldCamera(key_frame, map) * alignment.T_keyframe_frame;
        ++stats_.aligned;
        break;
      }
    }
  }
  if (!frame->T_world_camera_aligned) return std::nullopt;
  const Eigen::Isometry3d T_world_base = *frame->T_world_camera_aligned * T_base_camera_.inverse();
  return Carry(ToPlanar(T_world_base), frame->T_odom_base, input.T_odom_base);
}

std::optional<CameraLoop> RgbdTracker::FindLoop(const TrackInput& input, const TrackStep& step,
                                                const KeyFrameMap& map) {
  Frame* frame = FrameFor(input.stamp_ns);
  if (!options_.loops || frame == nullptr || key_frames_.empty()) return std::nullopt;
  const auto& frames = map.key_frames();
  const double path_m = frames[step.key_frame].path_length_m;
  const Eigen::Isometry3d T_world_camera =
      CameraFromBase(Carry(step.T_world_base, input.T_odom_base, frame->T_odom_base), input.tilt);
  const auto separation_m = [&](std::size_t i) {
    return path_m - frames[key_frames_[i].map_key_frame].path_length_m;
  };
  // Key frames are taken in path order: the old enough ones come first.
  std::size_t old_enough = 0;
  while (old_enough < key_frames_.size() &&
         separation_m(old_enough) >= options_.loop_min_path_separation_m) {
    ++old_enough;
  }
  const auto radius_m = [&](std::size_t i) {
    return std::min(
        options_.loop_max_search_radius_m,
        options_.loop_search_radius_m + options_.loop_search_radius_per_m * separation_m(i));
  };
  for (std::size_t index : NearestKeyFrames(T_world_camera, map, old_enough, radius_m)) {
    const KeyFrame& key_frame = key_frames_[index];
    ++stats_.loop_alignments;
    const RgbdAlignment alignment = aligner_.Align(key_frame.features, FeaturesOf(frame));
    if (!alignment.ok || alignment.confidence < options_.loop_min_confidence) continue;
    const Eigen::Isometry3d T_world_base =
        WorldCamera(key_frame, map) * alignment.T_keyframe_frame * T_base_camera_.inverse();
    return CameraLoop{key_frame.map_key_frame,
                      Carry(ToPlanar(T_world_base), frame->T_odom_base, input.T_odom_base),
                      alignment.confidence};
  }
  return std::nullopt;
}

void RgbdTracker::OnTracked(const TrackInput& input, const TrackStep& step,
                            const KeyFrameMap& map) {
  Frame* frame = FrameFor(input.stamp_ns);
  if (frame == nullptr) return;
  const bool by_laser = step.routine == Routine::kGlobal || step.routine == Routine::kBuffer;
  const bool by_rgbd = step.routine == Routine::kRgbd && frame->T_world_camera_aligned;
  const Eigen::Isometry3d T_world_camera =
      by_rgbd ? *frame->T_world_camera_aligned
              : CameraFromBase(Carry(step.T_world_base, input.T_odom_base, frame->T_odom_base),
                               input.tilt);
  if (!frame->recorded) {
    frame->recorded = true;
    CameraPose pose;
    pose.stamp_ns = frame->images.stamp_ns;
    pose.scan_index = step.scan_index;
    pose.source = by_rgbd    ? CameraPoseSource::kRgbd
                  : by_laser ? CameraPoseSource::kLaser
                             : CameraPoseSource::kOdometry;
    pose.T_scan_camera = LiftPose(step.T_world_base, std::nullopt).inverse() * T_world_camera;
    camera_poses_.push_back(pose);
  }
  // Key frames come from frames the laser placed, and from aligned ones while it cannot (so a
  // long failure keeps a key frame near).
  if (!by_laser && !by_rgbd) return;
  if (!key_frames_.empty()) {
    const Eigen::Isometry3d T_world_last = WorldCamera(key_frames_.back(), map);
    if ((T_world_camera.translation() - T_world_last.translation()).norm() <
            options_.key_frame_distance_m &&
        ViewAngle(T_world_camera, T_world_last) < options_.key_frame_angle_rad) {
      return;
    }
  }
  KeyFrame key_frame;
  key_frame.map_key_frame = step.key_frame;
  key_frame.T_anchor_camera =
      LiftPose(map.key_frames()[step.key_frame].T_world_base, std::nullopt).inverse() *
      T_world_camera;
  key_frame.features = FeaturesOf(frame);
  key_frames_.push_back(std::move(key_frame));
  ++stats_.key_frames;
}

}  // namespace littermap::reconstruct
