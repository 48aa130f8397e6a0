#include "detect/sample_collection.hpp"

#include <utility>

#include "bag/tum_trajectory.hpp"
#include "detect/debug_frames.hpp"
#include "detect/object_sample.hpp"

namespace littermap::detect {

std::string LabelAt(const std::vector<eval::TruthObject>& truth, const Eigen::Vector2d& xy,
                    double radius_m) {
  double best = 1e9;
  const eval::TruthObject* nearest = nullptr;
  for (const auto& object : truth) {
    const double d = (object.position_m - xy).norm();
    if (d < best) best = d, nearest = &object;
  }
  if (nearest != nullptr && best <= radius_m) {
    return nearest->litter ? nearest->class_name : std::string("natural");
  }
  return best > 2 * radius_m ? "clutter" : "";
}

SampleCollection CollectSamples(const std::filesystem::path& bag,
                                const std::filesystem::path& truth_dir,
                                const std::filesystem::path& output_dir,
                                const SampleCollectionOptions& options,
                                const ProgressCallback& progress) {
  const auto truth = eval::ReadTruthDirectory(truth_dir);
  const auto trajectory = bag::ReadTumTrajectory(truth_dir / "trajectory.tum");
  std::vector<ObjectSample> samples;
  SampleCollection collection;
  const std::string source = bag.filename().string();
  collection.objects = ForEachRunObject(
      bag, trajectory, options.objects, progress,
      [&](const PlacedObject& placed) {
        std::string label =
            LabelAt(truth, placed.position_world_m.head<2>(), options.label_radius_m);
        if (label.empty()) return;
        ObjectSample sample = placed.sample;
        sample.label = label;
        sample.source = source + ":" + std::to_string(placed.frame->index);
        ++collection.label_counts[label];
        samples.push_back(std::move(sample));
      },
      DebugFrameWriter(options.debug_frames));
  WriteSamples(output_dir, samples);
  collection.samples = samples.size();
  return collection;
}

std::string CollectionSummary(const SampleCollection& collection,
                              const std::filesystem::path& output_dir) {
  std::string text =
      "wrote " + output_dir.string() + ": " + std::to_string(collection.samples) + " samples (";
  const char* separator = "";
  for (const auto& [label, count] : collection.label_counts) {
    text += separator + label + " " + std::to_string(count);
    separator = ", ";
  }
  return text + ")";
}

}  // namespace littermap::detect
