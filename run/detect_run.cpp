#include "run/detect_run.hpp"

#include "bag/tum_trajectory.hpp"
#include "detect/litter_classifier.hpp"
#include "run/detections_file.hpp"
#include "run/items_file.hpp"
#include "run/run_files.hpp"

namespace littermap::run {

DetectRunResult DetectRun(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                          const DetectRunOptions& options, const ProgressCallback& progress,
                          const std::function<void(const detect::RgbdFrame&,
                                                   const detect::FrameSegmentation&)>& on_frame) {
  DetectRunResult result;
  result.output_dir = options.output_dir.empty() ? run_dir : options.output_dir;
  const std::vector<StampedPose> trajectory = bag::ReadTumTrajectory(
      options.trajectory.empty() ? RunFiles(run_dir).trajectory() : options.trajectory);
  const auto classifier = detect::LitterClassifier::Load(options.model);
  const std::size_t clutter = classifier.ClassIndex("clutter");
  std::filesystem::create_directories(result.output_dir);
  const RunFiles output(result.output_dir);
  DetectionsCsvWriter detections(output.detections());
  detect::ItemFusion fusion(options.fusion, classifier.classes().size());
  result.objects = detect::ForEachRunObject(
      bag, trajectory, options.objects, progress,
      [&](const detect::PlacedObject& placed) {
        const detect::Classification c = classifier.Classify(placed.sample);
        long item = -1;
        if (c.best != clutter) {
          detect::Sighting sighting{placed.frame->index,     placed.frame->stamp_ns,
                                    placed.position_world_m, placed.object->size_m,
                                    placed.object->range_m,  c.probabilities};
          item = static_cast<long>(fusion.Add(sighting));
        }
        detections.Write(placed, classifier.classes()[c.best], c, item);
      },
      on_frame);
  detections.Close();
  const ItemsWritten items = WriteItemsCsv(output.items(), fusion.Items(), classifier);
  result.litter_items = items.litter;
  result.natural_objects = items.natural;
  return result;
}

}  // namespace littermap::run
