#include "reconstruct/reconstruction.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <optional>
#include <utility>

#include "bag/bag_reader.hpp"
#include "bag/camera_image.hpp"
#include "bag/camera_setup.hpp"
#include "bag/image_codec.hpp"
#include "bag/message_header.hpp"
#include "bag/message_stream.hpp"
#include "bag/rgbd_pairing.hpp"
#include "bag/transform_tree.hpp"
#include "core/error.hpp"
#include "core/pose3.hpp"
#include "reconstruct/frame_queue.hpp"
#include "reconstruct/odometry_history.hpp"

namespace littermap::reconstruct {
namespace {

Tilt TiltOf(const msg::Quaternion& q) {  // roll and pitch of a ZYX (yaw-pitch-roll) rotation
  return {std::atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y)),
          std::asin(std::clamp(2 * (q.w * q.y - q.z * q.x), -1.0, 1.0))};
}

LaserScan ToScan(const msg::LaserScan& message) {
  LaserScan scan;
  scan.stamp_ns = bag::StampOf(message.header);
  scan.angle_min_rad = message.angle_min;
  scan.angle_increment_rad = message.angle_increment;
  scan.range_min_m = message.range_min;
  scan.range_max_m = message.range_max;
  scan.scan_time_s = message.scan_time;
  scan.ranges_m = message.ranges;
  return scan;
}

// The latest reading if it is at most max_age_s from stamp_ns.
template <typename T>
std::optional<T> Recent(const std::optional<std::pair<TimestampNs, T>>& latest,
                        TimestampNs stamp_ns, double max_age_s) {
  if (latest && std::abs(ToSeconds(stamp_ns - latest->first)) <= max_age_s) return latest->second;
  return std::nullopt;
}

// Warnings, run time and rate of a pass over a bag that handled `done` scans or frames.
ReconstructionResult Finished(const bag::MessageStream& stream,
                              std::chrono::steady_clock::time_point start, std::uint64_t done) {
  ReconstructionResult result;
  for (const std::string& warning : stream.warnings()) result.warnings.push_back(warning);
  result.run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.scans_per_s = result.run_time_s > 0 ? static_cast<double>(done) / result.run_time_s : 0.0;
  return result;
}

}  // namespace

void ReconstructionOptions::Validate() const {
  if (topics.scan.empty()) throw UsageError("reconstruct: the scan topic must not be empty");
  if (!(max_odometry_age_s > 0)) throw UsageError("reconstruct: max_odometry_age_s must be > 0");
  gyro.Validate();
  slam.Validate();
  rgbd_tracker.Validate();
  visual_odometry.Validate();
}

PlanarPose ReadLaserExtrinsic(const std::filesystem::path& bag,
                              const ReconstructionOptions& options,
                              std::vector<std::string>* warnings, double* height_m) {
  if (height_m != nullptr) *height_m = 0;
  bag::BagReader reader(bag);
  reader.SetStampSource(options.stamps);
  const bag::TransformTree tree = bag::ReadTransformTree(reader, options.topics);
  // The laser's frame is "laser", or else the one its scans name.
  std::string frame = frames::kLaser;
  auto transform = tree.LookupTransform(frames::kBase, frame);
  if (!transform && reader.info().FindTopic(options.topics.scan) != nullptr) {
    reader.SetTopicFilter({options.topics.scan});
    bag::MessageStream stream(reader);
    const auto first = stream.Next();
    const auto* scan = first ? std::get_if<msg::LaserScan>(&first->message) : nullptr;
    if (scan != nullptr && !scan->header.frame_id.empty()) {
      frame += " (or " + scan->header.frame_id + ")";
      transform = tree.LookupTransform(frames::kBase, scan->header.frame_id);
    }
  }
  if (transform) {
    if (height_m != nullptr) *height_m = transform->translation.z;
    return {transform->translation.x, transform->translation.y,
            YawOf(bag::ToEigen(transform->rotation))};
  }
  warnings->push_back(bag.string() + ": no " + std::string(frames::kBase) + " -> " + frame +
                      " transform on " + options.topics.tf_static + " or /tf" +
                      "; assuming the laser sits at base_link");
  return {};
}

ReconstructionResult ReconstructBag(const std::filesystem::path& bag,
                                    const ReconstructionOptions& options, SlamPipeline* pipeline,
                                    const ProgressCallback& progress, RgbdTracker* rgbd) {
  options.Validate();
  const auto start = std::chrono::steady_clock::now();
  bag::BagReader reader(bag);
  reader.SetStampSource(options.stamps);
  const std::uint64_t total = reader.RequireTopic(options.topics.scan, "laser scan").message_count;
  std::vector<std::string> wanted = {options.topics.scan, options.topics.odometry,
                                     options.topics.imu};
  if (rgbd != nullptr) {
    wanted.push_back(options.topics.colour);
    wanted.push_back(options.topics.depth);
  }
  reader.SetTopicFilter(wanted);
  bag::MessageStream stream(reader);
  bag::RgbdPairing pairing;
  GyroOdometry gyro(options.gyro);
  OdometryHistory odometry(options.max_odometry_age_s);
  std::optional<std::pair<TimestampNs, Tilt>> tilt;
  // A scan waits for the odometry reading after it (or until odometry is overdue), so its pose
  // is interpolated, not the last one before it.
  std::deque<std::pair<LaserScan, std::optional<Tilt>>> waiting;
  FrameQueue frames_waiting;  // and so does a camera frame
  const auto add_waiting_frames = [&](std::optional<TimestampNs> until_ns) {
    for (OdometryFrame& ready : frames_waiting.TakeReady(odometry, until_ns)) {
      rgbd->AddFrame(std::move(ready.frame), ready.T_odom_base);
    }
  };
  std::uint64_t done = 0;
  const std::string task = "reconstructing " + bag.filename().string();
  const auto track_waiting = [&](std::optional<TimestampNs> newest_scan_ns) {
    while (!waiting.empty()) {
      const TimestampNs stamp_ns = waiting.front().first.stamp_ns;
      const bool overdue =
          !newest_scan_ns || ToSeconds(*newest_scan_ns - stamp_ns) > options.max_odometry_age_s;
      if (!odometry.Covers(stamp_ns) && !overdue) return;
      add_waiting_frames(stamp_ns);
      pipeline->AddScan(waiting.front().first, odometry.At(stamp_ns), waiting.front().second);
      waiting.pop_front();
      odometry.DropBefore(waiting.empty() ? stamp_ns : waiting.front().first.stamp_ns);
      if (++done % 50 == 0) ReportProgress(progress, {task, done, total});
    }
  };
  while (auto message = stream.Next()) {
    if (const auto* odom = std::get_if<msg::Odometry>(&message->message)) {
      const auto& pose = odom->pose.pose;
      const TimestampNs stamp_ns = bag::StampOf(odom->header);
      const PlanarPose T_odom_base{pose.position.x, pose.position.y,
                                   YawOf(bag::ToEigen(pose.orientation))};
      odometry.Add(stamp_ns, gyro.AddOdometry(stamp_ns, T_odom_base));
      add_waiting_frames(std::nullopt);
      if (!waiting.empty()) track_waiting(waiting.back().first.stamp_ns);
      continue;
    }
    if (const auto* imu = std::get_if<msg::Imu>(&message->message)) {
      tilt.emplace(bag::StampOf(imu->header), TiltOf(imu->orientation));
      gyro.AddPitch(tilt->second.pitch_rad);
      // A covariance of -1 says the IMU does not measure angular velocity (sensor_msgs/Imu).
      if (options.gyro_heading && imu->angular_velocity_covariance[0] != -1) {
        gyro.AddYawRate(bag::StampOf(imu->header), imu->angular_velocity.z);
      }
      continue;
    }
    if (auto image = bag::TakeCameraImage(message->message)) {
      std::string origin = bag::MessageOrigin(reader, *message);
      std::optional<bag::CompressedRgbd> frame =
          message->topic->name == options.topics.colour
              ? pairing.AddColour(std::move(*image), std::move(origin))
              : pairing.AddDepth(std::move(*image), std::move(origin));
      if (frame) {  // images are read only for an RGB-D tracker
        frames_waiting.Push(std::move(*frame));
        add_waiting_frames(std::nullopt);
      }
      continue;
    }
    const auto* laser = std::get_if<msg::LaserScan>(&message->message);
    if (laser == nullptr) continue;
    LaserScan scan = ToScan(*laser);
    const TimestampNs stamp_ns = scan.stamp_ns;
    waiting.emplace_back(std::move(scan), Recent(tilt, stamp_ns, options.max_odometry_age_s));
    track_waiting(stamp_ns);
  }
  track_waiting(std::nullopt);
  ReportProgress(progress, {task, done, total});
  pipeline->Finish();
  return Finished(stream, start, done);
}

std::vector<LaserScan> ReadScans(const std::filesystem::path& bag, const std::string& scan_topic) {
  bag::BagReader reader(bag);
  reader.RequireTopic(scan_topic, "laser scan");
  reader.SetTopicFilter({scan_topic});
  bag::MessageStream stream(reader);
  std::vector<LaserScan> scans;
  while (auto message = stream.Next()) {
    if (const auto* laser = std::get_if<msg::LaserScan>(&message->message)) {
      scans.push_back(ToScan(*laser));
    }
  }
  return scans;
}

bool HasLaser(const std::filesystem::path& bag, const ReconstructionOptions& options) {
  return bag::BagReader(bag).info().FindTopic(options.topics.scan) != nullptr;
}

ReconstructionResult ReconstructBagVisually(const std::filesystem::path& bag,
                                            const ReconstructionOptions& options,
                                            std::vector<VisualFrame>* frames,
                                            VisualOdometryStats* stats,
                                            const ProgressCallback& progress) {
  options.Validate();
  const auto start = std::chrono::steady_clock::now();
  bag::BagReader reader(bag);
  reader.SetStampSource(options.stamps);
  const bag::TopicInfo* colour_info = reader.info().FindTopic(options.topics.colour);
  if (colour_info == nullptr) {
    throw BadInputError(bag.string() + ": no laser scan topic " + options.topics.scan +
                        " (choose one with --scan-topic) and no colour image topic " +
                        options.topics.colour + " for visual odometry");
  }
  const std::uint64_t total = colour_info->message_count;
  reader.RequireTopic(options.topics.depth, "depth image");
  const bag::CameraSetup setup =
      bag::ReadCameraSetup(bag, options.topics, bag::Extrinsic::kOptional);
  VisualOdometry odometry(options.visual_odometry, CameraModelFromInfo(setup.info));
  reader.SetTopicFilter({options.topics.colour, options.topics.depth});
  bag::MessageStream stream(reader);
  bag::RgbdPairing pairing;
  std::uint64_t done = 0;
  const std::string task = "visual odometry on " + bag.filename().string();
  while (auto message = stream.Next()) {
    auto image = bag::TakeCameraImage(message->message);
    if (!image) continue;
    const bool colour = message->topic->name == options.topics.colour;
    if (colour && ++done % 20 == 0) ReportProgress(progress, {task, done, total});
    std::string origin = bag::MessageOrigin(reader, *message);
    std::optional<bag::CompressedRgbd> frame =
        colour ? pairing.AddColour(std::move(*image), std::move(origin))
               : pairing.AddDepth(std::move(*image), std::move(origin));
    if (!frame) continue;
    const RgbdImage decoded{bag::DecodeColor(*frame), bag::DecodeDepthMm(*frame), 0.001};
    frames->push_back({frame->stamp_ns, odometry.Track(decoded)});
  }
  ReportProgress(progress, {task, done, total});
  *stats = odometry.stats();
  return Finished(stream, start, done);
}

std::unique_ptr<RgbdTracker> MakeRgbdTracker(const std::filesystem::path& bag,
                                             const ReconstructionOptions& options,
                                             std::vector<std::string>* warnings) {
  if (!options.rgbd) return nullptr;
  const bag::BagReader reader(bag);
  for (const std::string& topic :
       {options.topics.colour, options.topics.depth, options.topics.camera_info}) {
    if (reader.info().FindTopic(topic) == nullptr) {
      warnings->push_back(bag.string() + ": no topic " + topic +
                          "; tracking with the laser alone (no RGB-D routine)");
      return nullptr;
    }
  }
  const bag::CameraSetup setup = bag::ReadCameraSetup(bag, options.topics);
  return std::make_unique<RgbdTracker>(options.rgbd_tracker, CameraModelFromInfo(setup.info),
                                       setup.T_base_camera);
}

}  // namespace littermap::reconstruct
