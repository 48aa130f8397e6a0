#include "detect/run_objects.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/pose3.hpp"

namespace littermap::detect {
namespace {

ObjectSample SampleOf(const RgbdFrame& frame, const SegmentedObject& object) {
  ObjectSample sample;
  sample.colour_bgr = frame.colour_bgr(object.box).clone();
  sample.mask = object.mask.clone();
  sample.size_m = object.size_m;
  sample.width_m = object.width_m;
  sample.height_m = object.height_m;
  sample.range_m = object.range_m;
  return sample;
}

}  // namespace

void RunObjectsOptions::Validate() const {
  segmentation.Validate();
  if (every == 0) throw UsageError("detect: --every must be >= 1");
  if (!(max_pose_gap_s > 0)) throw UsageError("detect: max_pose_gap_s must be > 0");
}

std::optional<Eigen::Isometry3d> InterpolatePose(const std::vector<StampedPose>& trajectory,
                                                 TimestampNs stamp_ns, double max_gap_s) {
  const auto after = std::lower_bound(
      trajectory.begin(), trajectory.end(), stamp_ns,
      [](const StampedPose& pose, TimestampNs stamp) { return pose.stamp_ns < stamp; });
  if (after == trajectory.end() || (after == trajectory.begin() && after->stamp_ns != stamp_ns)) {
    return std::nullopt;
  }
  const StampedPose& b = *after;
  const StampedPose& a = after == trajectory.begin() ? b : *(after - 1);
  const double gap_s = 1e-9 * static_cast<double>(b.stamp_ns - a.stamp_ns);
  if (gap_s > max_gap_s) return std::nullopt;
  const double t = gap_s > 0 ? 1e-9 * static_cast<double>(stamp_ns - a.stamp_ns) / gap_s : 0.0;
  const double yaw_a = YawOf(a.orientation);
  double delta = YawOf(b.orientation) - yaw_a;
  delta = std::remainder(delta, 2 * std::numbers::pi);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_a + t * delta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = (1 - t) * a.position_m + t * b.position_m;
  return T;
}

RunObjectsResult ForEachRunObject(const std::filesystem::path& bag,
                                  const std::vector<StampedPose>& trajectory,
                                  const RunObjectsOptions& options,
                                  const ProgressCallback& progress,
                                  const std::function<void(const PlacedObject&)>& visit,
                                  const FrameCallback& on_frame) {
  options.Validate();
  if (trajectory.empty()) throw BadInputError("detect: the trajectory has no pose");
  const RgbdFrameReader reader(bag, options.frames);
  RunObjectsResult result;
  const std::string task = "detecting in " + bag.filename().string();
  const std::uint64_t total = (reader.colour_count() + options.every - 1) / options.every;
  std::uint64_t done = 0;
  FrameSegmenter segmenter(options.segmentation);
  reader.ForEach(options.every, [&](const RgbdFrame& frame) {
    ReportProgress(progress, {task, ++done, total});
    const auto T_world_base = InterpolatePose(trajectory, frame.stamp_ns, options.max_pose_gap_s);
    if (!T_world_base) {
      ++result.frames_without_pose;
      return;
    }
    const Eigen::Isometry3f T_level_camera = LevelledCamera(reader.T_base_camera(), frame.tilt);
    const FrameSegmentation segmentation =
        segmenter.Segment(frame.colour_bgr, frame.depth_mm, reader.intrinsics(), T_level_camera);
    ++result.frames;
    result.frames_without_ground += !segmentation.ground_found;
    result.time += segmentation.timings;
    for (const SegmentedObject& object : segmentation.objects) {
      PlacedObject placed;
      placed.frame = &frame;
      placed.object = &object;
      // The level frame shares base_link's origin and heading; the world pose is planar.
      placed.position_world_m = *T_world_base * object.centroid_level_m.cast<double>();
      placed.sample = SampleOf(frame, object);
      ++result.objects;
      visit(placed);
    }
    if (on_frame) {
      on_frame({frame, segmentation, *T_world_base * T_level_camera.cast<double>(),
                reader.intrinsics()});
    }
  });
  return result;
}

}  // namespace littermap::detect
