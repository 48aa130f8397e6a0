#include "detect/segmentation_score.hpp"

#include <algorithm>
#include <unordered_map>

#include "core/error.hpp"

namespace littermap::detect {

std::vector<ObjectIou> ScoreSegmentation(const FrameSegmentation& segmentation,
                                         const cv::Mat& truth_mask, const cv::Mat& depth_mm,
                                         const std::vector<int>& object_ids, int min_depth_pixels) {
  if (truth_mask.type() != CV_16UC1 || depth_mm.type() != CV_16UC1 ||
      truth_mask.size() != depth_mm.size()) {
    throw BadInputError("instance mask and depth must be 16-bit images of one size");
  }
  std::unordered_map<int, int> pixels, with_depth;  // object id -> truth pixel counts
  for (int v = 0; v < truth_mask.rows; ++v) {
    const auto* row = truth_mask.ptr<std::uint16_t>(v);
    const auto* depth = depth_mm.ptr<std::uint16_t>(v);
    for (int u = 0; u < truth_mask.cols; ++u) {
      if (row[u] == 0 || row[u] == 65535) continue;
      ++pixels[row[u] - 1];
      with_depth[row[u] - 1] += depth[u] > 0 ? 1 : 0;
    }
  }
  std::vector<ObjectIou> scores;
  for (const int id : object_ids) {
    const auto found = pixels.find(id);
    if (found == pixels.end() || with_depth[id] < min_depth_pixels) continue;
    ObjectIou score{id, found->second, 0.0};
    const auto value = static_cast<std::uint16_t>(id + 1);
    for (const SegmentedObject& object : segmentation.objects) {
      int intersection = 0;
      for (int v = 0; v < object.box.height; ++v) {
        const auto* truth = truth_mask.ptr<std::uint16_t>(object.box.y + v) + object.box.x;
        const auto* mine = object.mask.ptr<std::uint8_t>(v);
        for (int u = 0; u < object.box.width; ++u) intersection += (mine[u] && truth[u] == value);
      }
      if (intersection == 0) continue;
      const double iou =
          double(intersection) / double(found->second + object.pixels - intersection);
      score.iou = std::max(score.iou, iou);
    }
    scores.push_back(score);
  }
  return scores;
}

}  // namespace littermap::detect
