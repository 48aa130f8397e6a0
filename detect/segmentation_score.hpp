#pragma once
// How well a frame's segmentation cuts out the objects the simulator knows are there: for every
// truth object in a frame, the intersection over union of its instance-mask pixels and the
// pixels of the detected object that overlaps it most (0 when none does).

#include <map>
#include <vector>

#include <opencv2/core.hpp>

#include "detect/frame_segmenter.hpp"

namespace littermap::detect {

struct ObjectIou {
  int object_id = 0;  // world object id (mask value - 1)
  int truth_pixels = 0;
  double iou = 0;
};

// truth_mask: the simulator's CV_16UC1 instance mask of the frame (sim/instance_masks.hpp);
// depth_mm: the frame's depth. Scores the objects in `object_ids` that cover at least
// min_depth_pixels pixels with a depth reading (what an RGB-D segmentation can see).
std::vector<ObjectIou> ScoreSegmentation(const FrameSegmentation& segmentation,
                                         const cv::Mat& truth_mask, const cv::Mat& depth_mm,
                                         const std::vector<int>& object_ids, int min_depth_pixels);

}  // namespace littermap::detect
