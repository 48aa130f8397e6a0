#include "run/detect_run.hpp"

#include <algorithm>
#include <cstdio>

#include "bag/tum_trajectory.hpp"
#include "core/output_folder.hpp"
#include "detect/item_visibility.hpp"
#include "detect/litter_classifier.hpp"
#include "run/detections_file.hpp"
#include "run/items_file.hpp"
#include "run/run_files.hpp"
#include "run/sensor_roles_file.hpp"

namespace littermap::run {

DetectRunResult DetectRun(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                          const DetectRunOptions& options, const ProgressCallback& progress,
                          const detect::FrameCallback& on_frame) {
  DetectRunResult result;
  result.output_dir = options.output_dir.empty() ? run_dir : options.output_dir;
  PrepareOutputFolder(result.output_dir, {"-o", RunFiles::Names(), options.force_output});
  const std::vector<StampedPose> trajectory = bag::ReadTumTrajectory(
      options.trajectory.empty() ? RunFiles(run_dir).trajectory() : options.trajectory);
  const auto classifier = detect::LitterClassifier::Load(options.model);
  const std::size_t clutter = classifier.ClassIndex("clutter");
  const RunFiles output(result.output_dir);
  DetectionsCsvWriter detections(output.detections());
  detect::ItemFusion fusion(options.fusion, classifier.classes().size());
  detect::ItemVisibilityOptions visibility;
  visibility.min_depth_m = options.objects.segmentation.cloud.min_depth_m;
  visibility.max_depth_m = options.objects.segmentation.cloud.max_depth_m;
  detect::RunObjectsOptions objects = options.objects;
  const bag::SensorRoles roles = ResolveBagRoles(bag, options.topic_roles, objects.frames.topics);
  objects.frames.topics = roles.topics;
  WriteSensorRoles(output.sensor_roles(), roles);
  result.objects = detect::ForEachRunObject(
      bag, trajectory, objects, progress,
      [&](const detect::PlacedObject& placed) {
        const detect::Classification c = classifier.Classify(placed.sample);
        int candidate = -1;
        if (c.best != clutter) {
          detect::Sighting sighting{placed.frame->index,     placed.frame->stamp_ns,
                                    placed.position_world_m, placed.object->size_m,
                                    placed.object->range_m,  placed.object->pixels,
                                    c.probabilities};
          candidate = fusion.Add(sighting);
        }
        detections.Write(placed, classifier.classes()[c.best], c, candidate);
      },
      [&](const detect::ProcessedFrame& processed) {
        const detect::FrameVisibility view(processed, visibility);
        fusion.Observe(processed.frame.index, [&](const Eigen::Vector3d& place, double size_m) {
          return view.CouldSee(place, size_m);
        });
        if (on_frame) on_frame(processed);
      });
  detect::FusedItems fused = fusion.Fuse();
  detections.Close(fused.item_of_candidate);
  for (detect::LitterItem& item : fused.items) {
    item.best_class =
        classifier.Decide(item.class_probabilities, options.fusion.min_litter_probability);
    item.confidence = item.class_probabilities[item.best_class];
  }
  const ItemsWritten items = WriteItemsCsv(output.items(), fused.items, classifier);
  result.litter_items = items.litter;
  result.natural_objects = items.natural;
  result.seldom_seen = fused.seldom_seen;
  result.merged = fused.merged;
  if (result.objects.frames_without_pose > 0) {
    result.warnings.push_back(std::to_string(result.objects.frames_without_pose) +
                              " frames lay outside the trajectory and were skipped");
  }
  return result;
}

std::string DetectSummary(const DetectRunResult& result, const detect::FusionOptions& fusion) {
  char figures[400];
  std::snprintf(figures, sizeof figures,
                "%zu frames, %zu objects, %zu litter items and %zu natural objects seen in >= %d "
                "views and >= %.0f%% of the frames that could see them; %zu seen in fewer were "
                "dropped, %zu merged with a neighbour within %.2f m",
                result.objects.frames, result.objects.objects, result.litter_items,
                result.natural_objects, fusion.min_views, 100 * fusion.min_seen_share,
                result.seldom_seen, result.merged, fusion.association_radius_m);
  return "wrote " + result.output_dir.string() + ": " + figures + "\n" +
         SegmentationTimeLine(result.objects);
}

std::string SegmentationTimeLine(const detect::RunObjectsResult& result) {
  const double n = static_cast<double>(std::max<std::size_t>(1, result.frames));
  const auto& t = result.time;
  char line[256];
  std::snprintf(line, sizeof line,
                "segmentation %.1f ms/frame (cloud+normals %.1f, components %.1f, ground %.1f, "
                "texture+graph cut %.1f, objects %.1f)",
                t.total_ms() / n, t.cloud_ms / n, t.components_ms / n, t.ground_ms / n,
                t.texture_ms / n, t.objects_ms / n);
  return line;
}

}  // namespace littermap::run
