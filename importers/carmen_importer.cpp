#include "importers/carmen_importer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bag/message_header.hpp"
#include "bag/output_guard.hpp"
#include "bag/topics.hpp"
#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"

namespace littermap::importers {
namespace {

msg::Quaternion YawQuaternion(double theta_rad) {
  msg::Quaternion q;
  q.z = std::sin(theta_rad / 2);
  q.w = std::cos(theta_rad / 2);
  return q;
}

msg::Odometry MakeOdometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base) {
  msg::Odometry odometry;
  odometry.header = bag::MakeHeader(stamp_ns, frames::kOdom);
  odometry.child_frame_id = frames::kBase;
  odometry.pose.pose.position.x = T_odom_base.x_m;
  odometry.pose.pose.position.y = T_odom_base.y_m;
  odometry.pose.pose.orientation = YawQuaternion(T_odom_base.theta_rad);
  return odometry;  // covariances stay 0: the log gives none
}

msg::TFMessage MakeStaticTf(TimestampNs stamp_ns, const PlanarPose& T_base_laser) {
  msg::TransformStamped transform;
  transform.header = bag::MakeHeader(stamp_ns, frames::kBase);
  transform.child_frame_id = frames::kLaser;
  transform.transform.translation.x = T_base_laser.x_m;
  transform.transform.translation.y = T_base_laser.y_m;
  transform.transform.rotation = YawQuaternion(T_base_laser.theta_rad);
  return msg::TFMessage{{transform}};
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string StampWarning(const std::filesystem::path& log_path, const MonotonicStampResult& repair,
                         const MonotonicStampOptions& options) {
  const std::string name = log_path.filename().string();
  const std::string total = std::to_string(repair.stamps_ns.size());
  const std::string out_of_range = repair.out_of_range == 0
                                       ? std::string()
                                       : " (" + std::to_string(repair.out_of_range) +
                                             " outside 0 .. " + Number(options.max_stamp_s) + " s)";
  if (repair.synthesised) {
    return name + ": the scans carry no usable time stamps" + out_of_range + "; " +
           std::to_string(repair.changed) + " of " + total + " stamps synthesised at " +
           Number(options.nominal_interval_s) + " s per scan";
  }
  return name + ": " + std::to_string(repair.changed) + " of " + total +
         " scan time stamps were not increasing" + out_of_range + "; moved them " +
         Number(options.min_step_s * 1000) + " ms after their predecessor";
}

void CollectWarnings(const std::filesystem::path& log_path, const CarmenImportOptions& options,
                     CarmenImportResult& result, const MonotonicStampResult& repair) {
  if (repair.changed > 0) result.warnings.push_back(StampWarning(log_path, repair, options.stamps));
  if (!result.mounting.note.empty()) {
    result.warnings.push_back(log_path.filename().string() + ": " + result.mounting.note);
  }
  if (result.beam_count_min != result.beam_count_max) {
    result.warnings.push_back(log_path.filename().string() + ": scans have between " +
                              std::to_string(result.beam_count_min) + " and " +
                              std::to_string(result.beam_count_max) + " beams");
  }
}

struct BagContent {
  const CarmenLog* log = nullptr;
  const CarmenTimedPoses* poses = nullptr;
  const std::vector<PlanarPose>* odometry = nullptr;
  CarmenRangeLimits ranges;
  PlanarPose T_base_laser;
};

void WriteCarmenBag(const std::filesystem::path& log_path, const std::filesystem::path& bag_path,
                    const BagContent& content, const CarmenImportOptions& options,
                    const ProgressCallback& progress) {
  bag::BagWriter writer(bag_path, options.bag);
  writer.AddTopic<msg::TFMessage>(topics::kTfStatic, bag::TopicQos::kLatched);
  writer.AddTopic<msg::Odometry>(topics::kOdometry, bag::TopicQos::kReliable);
  writer.AddTopic<msg::LaserScan>(topics::kScan, bag::TopicQos::kSensorData);
  const std::vector<TimestampNs>& stamps = content.poses->stamps_ns;
  writer.WriteMessage(topics::kTfStatic, stamps.front(),
                      MakeStaticTf(stamps.front(), content.T_base_laser));
  const std::string task =
      "writing " + bag_path.filename().string() + " from " + log_path.filename().string();
  const std::size_t count = content.log->scans.size();
  for (std::size_t i = 0; i < count; ++i) {
    // Odometry first: a consumer that sees a scan has the odometry of its time already.
    writer.WriteMessage(topics::kOdometry, stamps[i],
                        MakeOdometry(stamps[i], (*content.odometry)[i]));
    writer.WriteMessage(topics::kScan, stamps[i],
                        ToLaserScan(content.log->scans[i],
                                    bag::MakeHeader(stamps[i], frames::kLaser), content.ranges));
    if (i % 64 == 0) ReportProgress(progress, {task, i, count});
  }
  writer.Close();
  ReportProgress(progress, {task, count, count});
}

void WriteReference(const std::filesystem::path& path, const CarmenTimedPoses& poses) {
  std::vector<StampedPose> tum;
  tum.reserve(poses.robot_poses.size());
  for (std::size_t i = 0; i < poses.robot_poses.size(); ++i) {
    tum.push_back(StampedPoseFromPlanar(poses.stamps_ns[i], poses.robot_poses[i]));
  }
  bag::WriteTumTrajectory(path, tum);
}

CarmenImportResult Summarise(const std::filesystem::path& log_path, const CarmenLog& log) {
  if (log.scans.empty()) {
    throw BadInputError(log_path.string() + ": no FLASER or ROBOTLASER1 records (no laser scans)");
  }
  CarmenImportResult result;
  result.line_count = log.line_count;
  result.scan_count = log.scans.size();
  result.odom_records_ignored = log.odometry.size();
  result.param_count = log.params.size();
  result.skipped_types = log.skipped_types;
  const auto [fewest, most] = std::minmax_element(
      log.scans.begin(), log.scans.end(),
      [](const auto& a, const auto& b) { return a.ranges_m.size() < b.ranges_m.size(); });
  result.beam_count_min = fewest->ranges_m.size();
  result.beam_count_max = most->ranges_m.size();
  return result;
}

}  // namespace

CarmenTimedPoses CarmenReferencePoses(const CarmenLog& log, const MonotonicStampOptions& options) {
  std::vector<double> raw_s;
  raw_s.reserve(log.scans.size());
  CarmenTimedPoses poses;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    raw_s.push_back(log.scans[i].timestamp_s);
    poses.robot_poses.push_back(log.scans[i].robot_pose);
  }
  poses.stamp_repair = MakeMonotonicStamps(raw_s, options);
  poses.stamps_ns = poses.stamp_repair.stamps_ns;
  return poses;
}

CarmenImportResult ImportCarmenLog(const std::filesystem::path& log_path,
                                   const std::filesystem::path& bag_path,
                                   const CarmenImportOptions& options,
                                   const ProgressCallback& progress) {
  const CarmenLog log = ReadCarmenLog(log_path, progress);
  CarmenImportResult result = Summarise(log_path, log);
  const CarmenTimedPoses poses = CarmenReferencePoses(log, options.stamps);
  result.stamps_changed = poses.stamp_repair.changed;
  result.stamps_synthesised = poses.stamp_repair.synthesised;
  result.duration_s = ToSeconds(poses.stamps_ns.back() - poses.stamps_ns.front());
  result.ranges = CarmenRanges(log.scans, options.ranges);
  try {
    result.mounting = EstimateLaserMounting(log, options.mounting);
  } catch (const BadInputError& error) {
    throw BadInputError(log_path.string() + ": " + error.what());
  }
  result.noisy_odometry = options.odometry_noise_seed.has_value();
  const std::vector<PlanarPose> odometry =
      result.noisy_odometry
          ? CorruptOdometry(poses.robot_poses, *options.odometry_noise_seed, options.odometry_noise)
          : poses.robot_poses;
  CollectWarnings(log_path, options, result, poses.stamp_repair);

  bag::OutputGuard guard;  // the reference first: a bad path fails before the bag is written
  guard.Add(options.reference_path);
  guard.Add(bag_path);
  if (!options.reference_path.empty()) {
    WriteReference(options.reference_path, poses);
    result.reference_poses = poses.robot_poses.size();
  }
  WriteCarmenBag(log_path, bag_path,
                 {&log, &poses, &odometry, result.ranges, result.mounting.T_base_laser}, options,
                 progress);
  guard.Commit();
  result.odometry_count = odometry.size();
  return result;
}

}  // namespace littermap::importers
