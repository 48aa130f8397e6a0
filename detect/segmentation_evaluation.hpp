#pragma once
// Segmentation IoU over a simulated run (`littermap eval segmentation`): every masked frame of
// the run is segmented as `detect` does, and every litter and natural object it shows is scored
// by ScoreSegmentation (segmentation_score.hpp) against the simulator's instance mask.

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

#include "core/progress.hpp"
#include "detect/frame_segmenter.hpp"

namespace littermap::detect {

struct SegmentationEvaluationOptions {
  int min_depth_pixels = 100;        // an object showing fewer pixels with depth is not scored
  SegmentationOptions segmentation;  // the segmentation scored
};

struct ClassIou {
  std::size_t objects = 0;  // object-frame pairs scored
  double mean_iou = 0;
  double found_share = 0;  // pairs with IoU >= 0.5
};

struct SegmentationEvaluation {
  std::map<std::string, ClassIou> classes;  // litter classes, "natural", and "all"
};

// truth_dir: the simulator's TRUTH_DIR (litter.csv, natural.csv, masks/index.csv and the masks).
// Throws BadInputError naming the bag or truth file at fault.
SegmentationEvaluation EvaluateSegmentation(const std::filesystem::path& bag,
                                            const std::filesystem::path& truth_dir,
                                            const SegmentationEvaluationOptions& options,
                                            const ProgressCallback& progress = {});

// As a JSON object (2-space indent): {CLASS: {objects, mean_iou, found_share}}.
std::string ToJson(const SegmentationEvaluation& evaluation);
// As a table with a line per class.
std::string ToText(const SegmentationEvaluation& evaluation);

}  // namespace littermap::detect
