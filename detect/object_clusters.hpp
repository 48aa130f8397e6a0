#pragma once
// Object clusters above the ground (thesis 3.1, cluster refinement): connected blobs of the
// refined non-ground mask, each refined in an enlarged box by GrabCut (colour GMMs of the blob
// and of its surroundings, graph cut) seeded with what geometry is sure of: the blob's core is
// object, certain ground and other objects are background, so boundary pixels and pixels
// without depth are decided by colour but geometry's background stays background. Blobs are
// then measured in 3D and kept when litter-sized (3-40 cm by default). A blob whose core alone is
// taller or wider than litter is rejected before GrabCut: on a cluttered frame (a desk) most of
// GrabCut's time went to such blobs.

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "detect/ground_surface.hpp"
#include "detect/organized_cloud.hpp"
#include "detect/texture_refinement.hpp"

namespace littermap::detect {

struct ObjectClusterOptions {
  int min_pixels = 12;
  int min_depth_points = 6;
  double min_size_m = 0.03;  // largest horizontal extent
  double max_size_m = 0.40;
  double max_height_m = 0.35;  // highest point above the ground surface
  double box_margin = 0.3;     // GrabCut box: the blob's box grown by this share on each side
  int min_box_margin_px = 6;
  bool refine = true;  // GrabCut per cluster
  // GrabCut's cost grows with the pixels of its box: a larger box is refined at a reduced scale
  // that brings it to this many pixels (its colour models need no more), and the mask brought
  // back to full resolution keeps geometry's certain pixels as they were.
  int max_refine_pixels = 3000;
  // Ground within this many pixels of a blob is left to GrabCut rather than fixed as
  // background: normals shared by a block of normal_step_px pixels blur the boundary.
  int uncertain_fringe_px = 2;
  void Validate() const;
};

struct SegmentedObject {
  cv::Rect box;  // image box of the object
  cv::Mat mask;  // CV_8U of box size, 255 = object pixel
  int pixels = 0;
  int depth_points = 0;
  Eigen::Vector3f centroid_level_m = Eigen::Vector3f::Zero();  // mean object point, level frame
  Eigen::Vector3f ground_level_m = Eigen::Vector3f::Zero();    // ground surface below it
  float size_m = 0;                                            // largest horizontal extent
  float width_m = 0;                                           // horizontal extent across it
  float height_m = 0;  // highest point above the ground surface
  float range_m = 0;   // mean depth
};

struct ObjectClusterResult {
  std::vector<SegmentedObject> objects;
  std::size_t blobs = 0;          // blobs examined
  std::size_t refined = 0;        // blobs GrabCut ran on (the others' cores were too large)
  std::size_t rejected_size = 0;  // too small, too large or too tall
};

ObjectClusterResult ExtractObjects(const cv::Mat& colour_bgr, const OrganizedCloud& cloud,
                                   const GroundResult& ground,
                                   const TextureRefinementResult& refinement,
                                   const ObjectClusterOptions& options);

}  // namespace littermap::detect
