#pragma once
// A run's detections scored from files, as `littermap eval detections` does it: the simulator's
// truth files read together, the run's items carried into the truth's frame, and the metrics
// (detection_metrics.hpp) as a text report.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "eval/detection_metrics.hpp"

namespace littermap::eval {

struct DetectionTruth {
  std::vector<TruthObject> objects;             // litter, then natural look-alikes
  std::optional<VisiblePixels> visible_pixels;  // when a visibility file was given
};

// litter.csv, then natural.csv and masks/visible.csv when their paths are not empty. Throws
// BadInputError as the readers do.
DetectionTruth ReadDetectionTruth(const std::filesystem::path& litter,
                                  const std::filesystem::path& natural,
                                  const std::filesystem::path& visible);

// Items placed in a run's own map frame, carried into the truth's frame by the rigid alignment
// of the run's trajectory onto the reference (TUM files; the alignment ATE uses,
// trajectory_metrics.hpp). Throws BadInputError for a file at fault and for trajectories that do
// not associate.
std::vector<DetectedItem> AlignItems(std::vector<DetectedItem> items,
                                     const std::filesystem::path& estimate,
                                     const std::filesystem::path& reference);

// EvaluateDetections (detection_metrics.hpp) against the truth of the files.
DetectionMetrics EvaluateDetections(const std::vector<DetectedItem>& detected,
                                    const DetectionTruth& truth,
                                    const DetectionMetricsOptions& options);

// The metrics as text: the counts and rates (hidden objects when the truth was filtered by
// visibility, ignored detections when there are any), the per-class table and the confusion
// table.
std::string ToText(const DetectionMetrics& metrics, const DetectionMetricsOptions& options);

}  // namespace littermap::eval
