#pragma once
// Object clusters above the ground (thesis 3.1, cluster refinement): connected blobs of the
// refined non-ground mask, each refined in an enlarged box by GrabCut (colour GMMs of the blob
// and of its surroundings, graph cut) seeded with what geometry is sure of: the blob's core is
// object, certain ground and other objects are background, so boundary pixels and pixels
// without depth are decided by colour but geometry's background stays background. Blobs are
// then measured in 3D and kept when litter-sized (3-40 cm by default). A blob whose core alone is
// taller or wider than litter is not refined: on a cluttered frame (a desk) most of GrabCut's
// time went to such blobs. Such a blob, or one refined too large, is cut into its parts connected
// in space (a can lying against a trunk, a cup beside a plastic bag are one blob in the image but
// apart in depth), and each litter-sized part is kept as measured, without GrabCut.

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
  // Blobs too large for litter are cut into parts whose 4-neighbouring points are closer than
  // split_max_gap_m + split_max_gap_per_m * depth (the components step's gap).
  bool split = true;
  double split_max_gap_m = 0.02;
  double split_max_gap_per_m = 0.02;
  // Points lower than this above the ground are left out of the parts: the ground between a can
  // and a trunk, when the cut took it for non-ground, would join them.
  double split_min_height_m = 0.015;
  // A part is litter only if it lies on the ground: its lowest point at most this high above
  // it. Pieces of a bush or a bench, or of the clutter on a desk, float above it.
  double split_max_base_m = 0.05;
  // A blob of more litter-sized parts than this is clutter (the leaves of a bush, a desk's
  // things): none of its parts is kept.
  int split_max_parts = 3;
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
  std::size_t split = 0;          // blobs too large for litter cut into parts
  std::size_t rejected_size = 0;  // too small, too large or too tall
};

// blob_step_px: the refinement's masks were made on every blob_step_px-th pixel of every
// blob_step_px-th row (FrameSegmenter's geometry step) and brought to full size; blobs are then
// cut into parts on that grid too.
ObjectClusterResult ExtractObjects(const cv::Mat& colour_bgr, const OrganizedCloud& cloud,
                                   const GroundResult& ground,
                                   const TextureRefinementResult& refinement,
                                   const ObjectClusterOptions& options, int blob_step_px = 1);

}  // namespace littermap::detect
