#pragma once
// The files of a reconstructed run (run/run_files.hpp): trajectory.tum (a pose for every scan,
// optimised), odometry.tum, keyframes.tum, map.pgm + map.yaml (ROS map_server), map.png
// (preview), routines.csv (per scan: time, routine, matching ratio, thesis fig. 2.5.2.1; and the
// landmark sightings holding its key frame in the graph) and quality.json (run/quality_file.hpp);
// with the RGB-D routine also camera.tum (the camera's optical frame in 3D at every frame tracked,
// from the optimised poses) and camera_sources.csv (laser / rgbd / odometry per frame).

#include <filesystem>
#include <string>
#include <vector>

#include "reconstruct/reconstruction.hpp"
#include "reconstruct/rgbd_tracker.hpp"
#include "reconstruct/slam_pipeline.hpp"

namespace littermap::run {

// Creates run_dir if needed. Throws UsageError if a file cannot be created. rgbd: the tracker
// the pipeline ran with, or null.
void WriteRun(const std::filesystem::path& run_dir, const reconstruct::SlamPipeline& pipeline,
              const reconstruct::ReconstructionResult& result,
              const reconstruct::RgbdTracker* rgbd = nullptr);

// A visual-odometry run (a bag without laser): trajectory.tum (the camera's optical frame at
// every frame tracked), keyframes.tum, routines.csv (per frame: time, "rgbd" or "lost", the
// alignment's confidence) and quality.json (frames, tracked, key frames, segments, run time).
void WriteVisualRun(const std::filesystem::path& run_dir,
                    const std::vector<reconstruct::VisualFrame>& frames,
                    const reconstruct::VisualOdometryStats& stats,
                    const reconstruct::ReconstructionResult& result);

}  // namespace littermap::run
