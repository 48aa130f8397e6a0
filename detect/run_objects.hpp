#pragma once
// The segmented objects of a run placed in the world: every n-th RGB-D frame of the bag is
// segmented (thesis 3.1) and each object's centroid carried into the world frame with the
// trajectory interpolated at the frame's stamp. Shared by `detect` (which classifies and fuses
// them) and `samples` (which labels them from the simulator's truth for training).

#include <filesystem>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "bag/tum_trajectory.hpp"
#include "core/progress.hpp"
#include "detect/frame_segmenter.hpp"
#include "detect/object_sample.hpp"
#include "detect/rgbd_frames.hpp"

namespace littermap::detect {

struct RunObjectsOptions {
  SegmentationOptions segmentation;
  RgbdFrameOptions frames;
  std::size_t every = 1;        // process every n-th frame
  double max_pose_gap_s = 0.5;  // farther from a trajectory pose: the frame is skipped
  void Validate() const;
};

struct PlacedObject {
  const RgbdFrame* frame = nullptr;
  const SegmentedObject* object = nullptr;
  Eigen::Vector3d position_world_m = Eigen::Vector3d::Zero();
  ObjectSample sample;  // crop, mask and geometry; no label
};

// A segmented frame and where its camera was: what `on_frame` sees.
struct ProcessedFrame {
  const RgbdFrame& frame;
  const FrameSegmentation& segmentation;
  Eigen::Isometry3d T_world_camera;  // the optical frame in the trajectory's world
  const CameraIntrinsics& intrinsics;
};
using FrameCallback = std::function<void(const ProcessedFrame&)>;

struct RunObjectsResult {
  std::size_t frames = 0;  // segmented
  std::size_t frames_without_pose = 0;
  std::size_t frames_without_ground = 0;
  std::size_t objects = 0;
  SegmentationTimings time;  // summed over the frames
};

// Visits the objects of every processed frame; `on_frame` (optional) sees each frame with a pose
// after its objects. Throws BadInputError for a bag or trajectory at fault.
RunObjectsResult ForEachRunObject(const std::filesystem::path& bag,
                                  const std::vector<StampedPose>& trajectory,
                                  const RunObjectsOptions& options,
                                  const ProgressCallback& progress,
                                  const std::function<void(const PlacedObject&)>& visit,
                                  const FrameCallback& on_frame = {});

// T_world_base at stamp_ns, linearly interpolated (yaw by the shorter arc) between the two
// trajectory poses around it; nullopt outside the trajectory or across a gap > max_gap_s.
std::optional<Eigen::Isometry3d> InterpolatePose(const std::vector<StampedPose>& trajectory,
                                                 TimestampNs stamp_ns, double max_gap_s);

}  // namespace littermap::detect
