#pragma once
// Ground segmentation of one RGB-D frame, the whole of thesis 3.1 (Alg. 3.1.4.1): organized
// cloud and normals → connected components → strict ground → texture learning and graph cut →
// object clusters refined one by one.

#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "detect/camera_intrinsics.hpp"
#include "detect/connected_components.hpp"
#include "detect/ground_surface.hpp"
#include "detect/object_clusters.hpp"
#include "detect/organized_cloud.hpp"
#include "detect/texture_refinement.hpp"

namespace littermap::detect {

struct SegmentationOptions {
  OrganizedCloudOptions cloud;
  ComponentOptions components;
  GroundOptions ground;
  TextureRefinementOptions texture;
  ObjectClusterOptions objects;
  // The frame's geometry (normals, components, the ground and its texture cut) is computed on
  // every geometry_step_px-th pixel of every geometry_step_px-th row; objects are then refined
  // by GrabCut and measured at full resolution, so their outlines keep the image's detail.
  // Pixel counts and sizes of the options are of the full image at every step. Step 2 (with
  // GrabCut boxes of box_margin 0.3, max_refine_pixels 3000) is the camera's rate on one core and
  // finds as many items as step 1 (README's `detect` section has the figures);
  // samples/detect_full.yaml is step 1, on which the shipped model was trained.
  int geometry_step_px = 2;
  void Validate() const;
};

struct SegmentationTimings {
  double cloud_ms = 0, components_ms = 0, ground_ms = 0, texture_ms = 0, objects_ms = 0;
  double total_ms() const { return cloud_ms + components_ms + ground_ms + texture_ms + objects_ms; }
  SegmentationTimings& operator+=(const SegmentationTimings& other) {
    cloud_ms += other.cloud_ms;
    components_ms += other.components_ms;
    ground_ms += other.ground_ms;
    texture_ms += other.texture_ms;
    objects_ms += other.objects_ms;
    return *this;
  }
};

struct FrameSegmentation {
  bool ground_found = false;
  std::size_t ground_points = 0;  // pixels of the full image (geometry_step_px^2 per sample)
  double ground_rms_m = 0;
  GroundSurface ground;
  TextureRefinementResult refinement;  // labels before the cut, non-ground after it; full size
  std::vector<SegmentedObject> objects;
  std::size_t components = 0;
  std::size_t blobs = 0;
  std::size_t refined = 0;  // blobs refined by GrabCut
  std::size_t split = 0;    // blobs too large for litter cut into parts
  SegmentationTimings timings;
};

// Segments the frames of one camera; keeps its buffers from frame to frame.
class FrameSegmenter {
 public:
  explicit FrameSegmenter(const SegmentationOptions& options);

  // colour_bgr CV_8UC3 and depth_mm CV_16UC1 (registered, millimetres) of the intrinsics' size.
  FrameSegmentation Segment(const cv::Mat& colour_bgr, const cv::Mat& depth_mm,
                            const CameraIntrinsics& intrinsics,
                            const Eigen::Isometry3f& T_level_camera);

 private:
  SegmentationOptions options_;   // as given
  SegmentationOptions geometry_;  // the same at the geometry's resolution
  OrganizedCloudBuilder cloud_builder_;
  OrganizedCloud cloud_;        // at the geometry's resolution, with normals
  OrganizedCloud full_points_;  // every pixel's point, when the geometry's step is over 1
  cv::Mat colour_, depth_mm_;   // the images at the geometry's resolution, when over 1
};

// A picture of the result for people: ground tinted blue, uncertain pixels yellow, non-ground
// after the cut red, object outlines green.
cv::Mat DrawSegmentation(const cv::Mat& colour_bgr, const FrameSegmentation& segmentation);

}  // namespace littermap::detect
