#pragma once
// Whether a processed frame could have seen an object at a place in the world: the place projects
// into the image clear of its border, lies within the depth range segmentation uses, is large
// enough in the image for an object of its size to be segmented, the depth measured there is not
// nearer (something in front hides it), and segmentation labelled no pixel there non-ground (a
// frame that cut something out at the place saw an object, if not as this item).
// ItemFusion::Observe counts the frames that could see an item and did not.

#include <Eigen/Core>

#include "detect/run_objects.hpp"

namespace littermap::detect {

struct ItemVisibilityOptions {
  float min_depth_m = 0.4f;  // segmentation's depth range (OrganizedCloudOptions)
  float max_depth_m = 4.5f;
  // Within this of max_depth_m a place does not count: an object there straddles the range limit
  // and its far points are cut off, so small ones come and go from frame to frame.
  float far_margin_m = 0.5f;
  int border_px = 10;               // nearer the image border: an object may be cut off
  double min_object_px = 12;        // the object's size as seen from there, at least
  double occlusion_margin_m = 0.2;  // depth measured this much nearer than the place: hidden
  int depth_window_px = 2;          // the depth there: median of the (2w+1)^2 window's readings
  void Validate() const;
};

// One frame's view, asked about every item the frame did not see.
class FrameVisibility {
 public:
  FrameVisibility(const ProcessedFrame& frame, const ItemVisibilityOptions& options);
  bool CouldSee(const Eigen::Vector3d& position_world_m, double size_m) const;

 private:
  ProcessedFrame frame_;  // a copy: the caller's may be a temporary
  ItemVisibilityOptions options_;
  Eigen::Isometry3d T_camera_world_;
};

}  // namespace littermap::detect
