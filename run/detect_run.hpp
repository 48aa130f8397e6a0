#pragma once
// The detect stage of a run: segments every n-th RGB-D frame of the bag, classifies the objects,
// places them with the run's trajectory and fuses the sightings into items, writing
// detections.csv and items.csv (run/detections_file.hpp, run/items_file.hpp).
// `littermap detect` and `littermap survey` both call it.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "detect/item_fusion.hpp"
#include "detect/run_objects.hpp"

namespace littermap::run {

struct DetectRunOptions {
  std::filesystem::path model;       // the classifier of `littermap train`
  std::filesystem::path trajectory;  // placing the objects; empty: RUN_DIR/trajectory.tum
  std::filesystem::path output_dir;  // where to write; empty: the run directory
  bool force_output = false;         // write among other files too (core/output_folder.hpp)
  detect::RunObjectsOptions objects;
  detect::FusionOptions fusion;
  // Sensor role -> topic (--topic ROLE=NAME); the other roles are found in the bag by
  // bag/sensor_roles.hpp, starting from objects.frames.topics.
  std::map<std::string, std::string> topic_roles;
};

struct DetectRunResult {
  std::filesystem::path output_dir;
  detect::RunObjectsResult objects;  // frames, objects, frames without a pose, timings
  std::size_t litter_items = 0;      // in items.csv
  std::size_t natural_objects = 0;
  std::size_t seldom_seen = 0;        // candidates dropped for their seen share (min_seen_share)
  std::size_t merged = 0;             // candidates merged into a neighbour within the radius
  std::vector<std::string> warnings;  // for the user's attention
};

// `on_frame` (optional) sees each processed frame: its segmentation and camera pose. Throws
// BadInputError for a bag, trajectory or model at fault, UsageError for an output that cannot be
// written.
DetectRunResult DetectRun(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                          const DetectRunOptions& options, const ProgressCallback& progress = {},
                          const detect::FrameCallback& on_frame = {});

// What the run came to: "wrote DIR: N frames, ... seen in >= min_views views and ..." and the
// segmentation's time line.
std::string DetectSummary(const DetectRunResult& result, const detect::FusionOptions& fusion);

// Milliseconds per frame of the segmentation, in total and by step.
std::string SegmentationTimeLine(const detect::RunObjectsResult& result);

}  // namespace littermap::run
