#include "run/run_writer.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"
#include "run/quality_file.hpp"
#include "run/run_files.hpp"

namespace littermap::run {

using namespace reconstruct;  // the pipeline's types, written out here

namespace {

void CreateRunDirectory(const std::filesystem::path& run_dir) {
  std::error_code error;
  std::filesystem::create_directories(run_dir, error);
  if (error) throw FileFailure(run_dir, "cannot create the folder", error.value());
}

void WriteRoutines(const std::filesystem::path& path, const std::vector<ScanRecord>& scans) {
  std::string text = "time,routine,matching_ratio,landmark_sightings\n";
  char ratio[32];
  for (const ScanRecord& scan : scans) {
    std::snprintf(ratio, sizeof ratio, "%.4f", scan.matching_ratio);
    text += bag::FormatTumStamp(scan.stamp_ns) + ',' + std::string(RoutineName(scan.routine)) +
            ',' + ratio + ',' + std::to_string(scan.landmark_sightings) + '\n';
  }
  WriteFileAtomically(path, text);
}

// One row per loop judged: the later key frame's time first, like routines.csv.
void WriteLoops(const std::filesystem::path& path, const std::vector<LoopRecord>& loops) {
  std::string text =
      "time,kind,from_time,outcome,confirmed,matching_ratio,correction_m,correction_deg,"
      "weakest_sigma_m\n";
  char figures[128];
  for (const LoopRecord& loop : loops) {
    text += bag::FormatTumStamp(loop.to_stamp_ns) + ',' + std::string(LoopKindName(loop.kind)) +
            ',' + bag::FormatTumStamp(loop.from_stamp_ns) + ',' +
            std::string(LoopOutcomeName(loop.outcome)) + ',' + (loop.confirmed ? "1" : "0") + ',';
    if (loop.matching_ratio) {
      std::snprintf(figures, sizeof figures, "%.4f", *loop.matching_ratio);
      text += figures;
    }
    std::snprintf(figures, sizeof figures, ",%.4f,%.3f,",
                  std::hypot(loop.correction.x_m, loop.correction.y_m),
                  loop.correction.theta_rad * 180 / std::numbers::pi);
    text += figures;
    if (loop.weakest_sigma_m) {
      std::snprintf(figures, sizeof figures, "%.4f", *loop.weakest_sigma_m);
      text += figures;
    }
    text += '\n';
  }
  WriteFileAtomically(path, text);
}

std::string_view SourceName(CameraPoseSource source) {
  switch (source) {
    case CameraPoseSource::kLaser:
      return "laser";
    case CameraPoseSource::kRgbd:
      return "rgbd";
    case CameraPoseSource::kOdometry:
      return "odometry";
  }
  return "odometry";
}

void WriteCameraPoses(const std::filesystem::path& run_dir, const SlamPipeline& pipeline,
                      const RgbdTracker& rgbd) {
  std::vector<StampedPose> poses;
  std::string sources = "time,source\n";
  for (const CameraPose& pose : rgbd.camera_poses()) {
    const Eigen::Isometry3d T_world_camera =
        LiftPose(pipeline.scans()[pose.scan_index].T_world_base, std::nullopt) * pose.T_scan_camera;
    poses.push_back(StampedPoseFromIsometry(pose.stamp_ns, T_world_camera));
    sources +=
        bag::FormatTumStamp(pose.stamp_ns) + ',' + std::string(SourceName(pose.source)) + '\n';
  }
  WriteFileAtomically(RunFiles(run_dir).camera_sources(), sources);
  bag::WriteTumTrajectory(RunFiles(run_dir).camera(), poses);
}

ReconstructionQuality SlamRunQuality(const SlamQuality& quality, const ReconstructionResult& result,
                                     const RgbdTracker* rgbd) {
  ReconstructionQuality q;
  q.scans = quality.scans_in;
  q.scans_tracked = quality.scans_tracked;
  q.scans_without_echoes = quality.scans_without_echoes;
  q.ground_echoes_dropped = quality.ground_echoes;
  q.scans_moving_echo_filtered = quality.scans_moving_echo_filtered;
  q.moving_echoes_dropped = quality.moving_echoes;
  q.scans_given_up_to_moving_echoes = quality.scans_moving_echoes;
  q.stamps_backwards = quality.stamps_backwards;
  q.stamps_duplicate = quality.stamps_duplicate;
  q.odometry_missing = quality.odometry_missing;
  q.odometry_rejected = quality.odometry_rejected;
  q.odometry_arbitrated_by_laser = quality.odometry_arbitrated;
  for (std::size_t r = 0; r < quality.routine_counts.size(); ++r) {
    q.routines.emplace_back(RoutineName(static_cast<Routine>(r)), quality.routine_counts[r]);
  }
  q.key_frames = quality.key_frames;
  q.loop_closures_found = quality.loop_candidates;
  q.loop_closures_accepted = quality.loops_accepted;
  q.loop_closures_rejected_match = quality.loops_rejected_match;
  q.loop_closures_rejected_disagreement = quality.loops_rejected_disagreement;
  q.loop_closures_rejected_degenerate = quality.loops_rejected_degenerate;
  q.loop_closures_rejected_after_optimisation = quality.loops_rejected_after_optimisation;
  q.loop_closures_rejected_inconsistent = quality.loops_rejected_inconsistent;
  q.loop_closures_confirmed = quality.loops_confirmed;
  q.loop_closures_rejected = quality.loops_rejected();
  q.landmarks = {quality.landmarks,
                 quality.landmark_sightings,
                 quality.landmark_associations,
                 quality.landmark_loops_found,
                 quality.landmark_loops_accepted,
                 quality.landmark_loops_rejected};
  q.optimisations = quality.optimisations;
  q.final_cost = quality.final_cost;
  const auto alignment = [](const ScanAlignmentResult& a) -> std::optional<ScanAlignmentQuality> {
    if (a.rounds == 0) return std::nullopt;
    return ScanAlignmentQuality{a.pairs,  a.pairs_matched, a.correspondences,
                                a.rounds, a.initial_cost,  a.final_cost};
  };
  q.scan_alignment = alignment(quality.alignment);
  q.scan_refinement = alignment(quality.refinement);
  if (rgbd != nullptr) {
    const RgbdTrackerStats& stats = rgbd->stats();
    q.rgbd = RgbdQuality{stats.frames,
                         stats.key_frames,
                         stats.alignments,
                         stats.aligned,
                         stats.loop_alignments,
                         quality.camera_loops_found,
                         quality.camera_loops_accepted,
                         quality.camera_loops_rejected};
  }
  q.run_time_s = result.run_time_s;
  q.scans_per_s = result.scans_per_s;
  q.warnings = result.warnings;
  return q;
}

}  // namespace

void WriteRun(const std::filesystem::path& run_dir, const SlamPipeline& pipeline,
              const ReconstructionResult& result, const RgbdTracker* rgbd) {
  CreateRunDirectory(run_dir);
  const RunFiles files(run_dir);
  std::vector<StampedPose> trajectory;
  for (const ScanRecord& scan : pipeline.scans()) {
    trajectory.push_back(StampedPoseFromPlanar(scan.stamp_ns, scan.T_world_base));
    trajectory.back().position_m.z() = scan.z_m;
  }
  bag::WriteTumTrajectory(files.trajectory(), trajectory);
  // The odometry at the scans' times, to compare SLAM with odometry alone.
  std::vector<StampedPose> odometry;
  for (const ScanRecord& scan : pipeline.scans()) {
    if (scan.T_odom_base)
      odometry.push_back(StampedPoseFromPlanar(scan.stamp_ns, *scan.T_odom_base));
  }
  if (!odometry.empty()) bag::WriteTumTrajectory(files.odometry(), odometry);
  std::vector<StampedPose> key_frames;
  for (const auto& [stamp, pose] : pipeline.KeyFramePoses()) {
    key_frames.push_back(StampedPoseFromPlanar(stamp, pose));
  }
  bag::WriteTumTrajectory(files.key_frames(), key_frames);
  pipeline.map().WritePgmYaml(files.map_pgm(), files.map_yaml());
  pipeline.map().WritePng(files.map_png());
  WriteRoutines(files.routines(), pipeline.scans());
  WriteLoops(files.loops(), pipeline.loops());
  if (rgbd != nullptr) WriteCameraPoses(run_dir, pipeline, *rgbd);
  WriteQualityFile(files.quality(), SlamRunQuality(pipeline.quality(), result, rgbd));
}

void WriteVisualRun(const std::filesystem::path& run_dir, const std::vector<VisualFrame>& frames,
                    const VisualOdometryStats& stats, const ReconstructionResult& result) {
  CreateRunDirectory(run_dir);
  const RunFiles files(run_dir);
  std::vector<StampedPose> trajectory, key_frames;
  std::string routines = "time,routine,matching_ratio\n";
  char confidence[32];
  for (const VisualFrame& frame : frames) {
    std::snprintf(confidence, sizeof confidence, "%.4f", frame.step.alignment.confidence);
    routines += bag::FormatTumStamp(frame.stamp_ns) + (frame.step.tracked ? ",rgbd," : ",lost,") +
                (frame.step.new_segment ? "1.0000" : confidence) + "\n";
    if (!frame.step.tracked) continue;
    if (frame.step.previous_became_key_frame) key_frames.push_back(trajectory.back());
    trajectory.push_back(StampedPoseFromIsometry(frame.stamp_ns, frame.step.T_world_camera));
    if (frame.step.new_key_frame) key_frames.push_back(trajectory.back());
  }
  bag::WriteTumTrajectory(files.trajectory(), trajectory);
  bag::WriteTumTrajectory(files.key_frames(), key_frames);
  WriteFileAtomically(files.routines(), routines);
  ReconstructionQuality quality;
  quality.visual_odometry = true;
  quality.frames = stats.frames;
  quality.frames_tracked = stats.tracked;
  quality.key_frames = stats.key_frames;
  quality.segments = stats.segments;
  quality.run_time_s = result.run_time_s;
  quality.scans_per_s = result.scans_per_s;
  quality.warnings = result.warnings;
  WriteQualityFile(files.quality(), quality);
}

}  // namespace littermap::run
