#pragma once
// Training samples cut from a simulated run (`littermap samples`): every object the segmentation
// finds (run_objects.hpp) is labelled from the simulator's truth by what lies where it was
// placed, and the labelled crops are written as a sample directory (object_sample.hpp).

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/progress.hpp"
#include "detect/run_objects.hpp"
#include "eval/detection_metrics.hpp"

namespace littermap::detect {

struct SampleCollectionOptions {
  RunObjectsOptions objects;
  double label_radius_m = 0.2;         // see LabelAt
  std::filesystem::path debug_frames;  // when set, a picture of every processed frame goes here
};

struct SampleCollection {
  std::size_t samples = 0;                          // written
  std::map<std::string, std::size_t> label_counts;  // samples per label
  RunObjectsResult objects;                         // frames, objects, timings
};

// The label of an object at xy (world frame): the class of the nearest truth object ("natural"
// for a natural one) if it lies within radius_m, "clutter" if none lies within 2 radius_m, and
// empty in between: ambiguous, not a sample.
std::string LabelAt(const std::vector<eval::TruthObject>& truth, const Eigen::Vector2d& xy,
                    double radius_m);

// Places the bag's objects with truth_dir/trajectory.tum, labels them from truth_dir's
// litter.csv and natural.csv and writes the samples to output_dir, each with its source
// "BAG_NAME:FRAME". Throws BadInputError for a bag or truth file at fault.
SampleCollection CollectSamples(const std::filesystem::path& bag,
                                const std::filesystem::path& truth_dir,
                                const std::filesystem::path& output_dir,
                                const SampleCollectionOptions& options,
                                const ProgressCallback& progress = {});

// What the collection came to: "wrote DIR: N samples (LABEL COUNT, ...)".
std::string CollectionSummary(const SampleCollection& collection,
                              const std::filesystem::path& output_dir);

}  // namespace littermap::detect
