#include "sim/recorder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "bag/image_codec.hpp"
#include "bag/message_header.hpp"
#include "bag/output_guard.hpp"
#include "bag/sensor_messages.hpp"
#include "bag/topics.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/time.hpp"
#include "sim/ground_truth.hpp"
#include "sim/instance_masks.hpp"
#include "sim/rgbd_camera.hpp"
#include "sim/sensor_messages.hpp"
#include "sim/simulation.hpp"

namespace littermap::sim {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

RgbdCameraOptions CameraOptions(const WorldSpec& spec, bool masks) {
  RgbdCameraOptions options;
  options.seed = spec.RunSeed();
  options.output_instance_ids = masks;
  options.instance_mask_every_n_frames = std::max(1, spec.truth.mask_every_n_frames);
  return options;
}

// Writes every message of a simulated run in time order: camera frames fall between the
// odometry ticks (their clock is offset and jittered), laser scans and IMU samples on them.
class RunRecorder {
 public:
  RunRecorder(const Simulation& simulation, bag::BagWriter& writer,
              const std::filesystem::path& truth_dir, const SimRecordOptions& options,
              const ProgressCallback& progress)
      : simulation_(simulation),
        spec_(simulation.world().spec),
        writer_(writer),
        progress_(progress),
        start_ns_(FromSeconds(spec_.start_time_s)),
        camera_(simulation.world(),
                CameraOptions(spec_, !truth_dir.empty() && spec_.truth.mask_every_n_frames > 0)),
        masks_(camera_.options().output_instance_ids
                   ? std::make_unique<InstanceMaskWriter>(truth_dir)
                   : nullptr) {
    codec_.jpeg_quality = spec_.robot.camera.jpeg_quality;
    codec_.png_compression = options.png_compression;
  }

  void Run(SimRecordResult& result) {
    AddTopics();
    writer_.WriteMessage(topics::kTfStatic, start_ns_,
                         bag::sensor_messages::StaticTransforms(
                             start_ns_, simulation_.T_base_laser(), simulation_.T_base_optical()));
    const auto& states = simulation_.states();
    for (std::size_t i = 0; i < states.size(); ++i) {
      const double t = static_cast<double>(i) / spec_.robot.odometry.rate_hz;
      WriteFramesBefore(t);
      // Odometry before the scan of the same tick: a consumer that sees a scan has the
      // odometry of its time already.
      const TimestampNs stamp = start_ns_ + FromSeconds(t);
      writer_.WriteMessage(
          topics::kOdometry, stamp,
          bag::sensor_messages::Odometry(
              stamp, Between(simulation_.odometry().front(), simulation_.odometry()[i]),
              states[i].linear_mps, states[i].angular_radps));
      WriteImuUpTo(t);
      WriteScansUpTo(t);
    }
    WriteFramesBefore(std::numeric_limits<double>::infinity());
    if (masks_) masks_->Close();
    result.scans = scan_;
    result.odometry = states.size();
    result.imu = imu_;
    result.frames = frame_;
    result.masks = masks_ ? masks_->written() : 0;
    result.render_s = render_s_;
  }

 private:
  void AddTopics() {
    writer_.AddTopic<msg::TFMessage>(topics::kTfStatic, bag::TopicQos::kLatched);
    writer_.AddTopic<msg::Odometry>(topics::kOdometry, bag::TopicQos::kReliable);
    writer_.AddTopic<msg::Imu>(topics::kImu, bag::TopicQos::kSensorData);
    writer_.AddTopic<msg::LaserScan>(topics::kScan, bag::TopicQos::kSensorData);
    writer_.AddTopic<msg::CameraInfo>(topics::kCameraInfo, bag::TopicQos::kSensorData);
    writer_.AddTopic<msg::CompressedImage>(topics::kColor, bag::TopicQos::kSensorData);
    writer_.AddTopic<msg::CameraInfo>(topics::kDepthCameraInfo, bag::TopicQos::kSensorData);
    writer_.AddTopic<msg::CompressedImage>(topics::kDepth, bag::TopicQos::kSensorData);
  }

  void WriteImuUpTo(double t) {
    const double tilt_sigma_rad = spec_.robot.imu.tilt_noise_deg * std::numbers::pi / 180;
    for (; imu_ < simulation_.imu_count() &&
           static_cast<double>(imu_) / spec_.robot.imu.rate_hz <= t + 1e-9;
         ++imu_) {
      const ImuSample sample = simulation_.Imu(imu_);
      const TimestampNs stamp = start_ns_ + FromSeconds(sample.t_s);
      writer_.WriteMessage(topics::kImu, stamp, ImuMessage(stamp, sample, tilt_sigma_rad));
    }
  }

  void WriteScansUpTo(double t) {
    for (; scan_ < simulation_.scan_count() && simulation_.ScanTime(scan_) <= t + 1e-9; ++scan_) {
      const LaserScan laser = simulation_.Scan(scan_);
      const TimestampNs stamp = start_ns_ + laser.stamp_ns;
      writer_.WriteMessage(topics::kScan, stamp, bag::sensor_messages::Scan(stamp, laser));
    }
  }

  void WriteFramesBefore(double t) {
    const std::size_t frames = simulation_.camera_frame_count();
    for (; frame_ < frames && simulation_.CameraFrameTime(frame_) < t; ++frame_) {
      WriteFrame(frame_);
      ReportProgress(progress_, {"simulating", frame_ + 1, frames});
    }
  }

  // Colour and depth share the stamp (the Kinect's registered depth) and the optical frame.
  void WriteFrame(std::size_t k) {
    const double t = simulation_.CameraFrameTime(k);
    const TimestampNs stamp = start_ns_ + FromSeconds(t);
    const msg::Header header = bag::MakeHeader(stamp, frames::kCamera);
    const auto render_start = Clock::now();
    const RgbdRender render = camera_.Render(simulation_.TrueOpticalPose(t), k);
    render_s_ += SecondsSince(render_start);
    const msg::CameraInfo info = CameraInfoMessage(camera_.options().intrinsics, header);
    writer_.WriteMessage(topics::kCameraInfo, stamp, info);
    writer_.WriteMessage(topics::kColor, stamp,
                         bag::EncodeColorJpeg(render.colour_bgr, header, codec_));
    writer_.WriteMessage(topics::kDepthCameraInfo, stamp, info);
    writer_.WriteMessage(topics::kDepth, stamp,
                         bag::EncodeDepthPng(render.depth_mm, header, codec_));
    if (masks_ && WantsInstanceMask(static_cast<std::int64_t>(k), camera_.options())) {
      masks_->Write(k, stamp, render.instance_ids, render.depth_mm);
    }
  }

  const Simulation& simulation_;
  const WorldSpec& spec_;
  bag::BagWriter& writer_;
  const ProgressCallback& progress_;
  const TimestampNs start_ns_;
  RgbdCamera camera_;
  std::unique_ptr<InstanceMaskWriter> masks_;
  bag::ImageCodecOptions codec_;
  std::size_t scan_ = 0, imu_ = 0, frame_ = 0;
  double render_s_ = 0;
};

}  // namespace

WorldSpec RunSpec(const WorldSpec& world_spec, const SimRecordOptions& options) {
  WorldSpec spec = world_spec;
  if (options.seed) spec.seed = *options.seed;
  if (options.run_seed) spec.run_seed = *options.run_seed;
  if (options.start_time_s) {
    if (!(*options.start_time_s >= 0 && *options.start_time_s < kMaxStartTimeS)) {
      const double t = *options.start_time_s;
      throw UsageError("--start-time " +
                       (std::abs(t) < 1e12 ? FormatUtc(t, "%Y-%m-%dT%H:%M:%S") : "") +
                       ": a run starts from 1970-01-01 to 2033-05-18 UTC");
    }
    spec.start_time_s = *options.start_time_s;
  }
  spec.litter_day = options.litter_day;
  spec.driven_route = options.route;
  spec.DrivenRoute();  // an unknown name fails before any file is created
  return spec;
}

SimRecordResult RecordSimulation(const WorldSpec& world_spec, const std::filesystem::path& bag_path,
                                 const std::filesystem::path& truth_dir,
                                 const SimRecordOptions& options,
                                 const ProgressCallback& progress) {
  const WorldSpec spec = RunSpec(world_spec, options);
  const Simulation simulation(spec, {options.max_duration_s});
  bag::OutputGuard guard;
  guard.Add(bag_path);
  guard.Add(truth_dir);
  if (!truth_dir.empty()) {
    PrepareOutputFolder(truth_dir, {"--truth",
                                    {"trajectory.tum", "litter.csv", "natural.csv", "world.json",
                                     "masks", "map.pgm", "map.yaml"},
                                    options.force_truth});
  }
  bag::BagWriter writer(bag_path, options.bag);
  SimRecordResult result;
  const auto clock_start = Clock::now();
  RunRecorder(simulation, writer, truth_dir, options, progress).Run(result);
  writer.Close();
  result.simulate_s = SecondsSince(clock_start);
  if (!truth_dir.empty()) WriteGroundTruth(truth_dir, simulation, spec.start_time_s);
  guard.Commit();

  result.duration_s = simulation.duration_s();
  result.distance_m = simulation.drive().distance_m;
  result.route_completed = simulation.drive().reached_goal;
  const World& world = simulation.world();
  result.litter = world.Count(ObjectKind::kLitter);
  result.natural = world.Count(ObjectKind::kNatural);
  result.objects = world.objects.size();
  result.seed = spec.seed;
  result.run_seed = spec.RunSeed();
  result.route = spec.driven_route.empty() ? "route" : spec.driven_route;
  result.laser = spec.robot.laser.preset;
  return result;
}

}  // namespace littermap::sim
