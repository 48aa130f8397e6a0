#pragma once
// The organized point cloud of one depth image with surface normals (thesis 3.1, step 1):
// points and normals in a gravity-levelled frame (origin at base_link, z up, x forward) so that
// "ground-like" and "height above the ground" mean the same on every frame, even while the robot
// is tilted by a root.

#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "detect/camera_intrinsics.hpp"

namespace littermap::detect {

// OpenCV's FALS (cv::rgbd::RgbdNormals: a least-squares plane in a window, by box
// filters), or PCL's integral-image normal estimators (pcl::IntegralImageNormalEstimation). FALS
// is the default: 8 ms a full-resolution park frame on one core against 45 ms for PCL's covariance
// normals, and segmentation IoU 0.680 against 0.647 (mean of the demo's week 1 and world seeds 11
// and 12; window 3: 0.664, 7: 0.657).
enum class NormalMethod {
  kCovariance,
  kAverage3dGradient,
  kSimple3dGradient,
  kAverageDepthChange,
  kFals,
};

struct OrganizedCloudOptions {
  float min_depth_m = 0.4f;  // nearer readings are sensor artefacts on a Kinect-class camera
  float max_depth_m = 4.5f;  // litter of a few cm is a handful of pixels beyond
  NormalMethod normal_method = NormalMethod::kFals;
  // PCL's methods: the neighbourhood size in pixels of the full image.
  float normal_smoothing_px = 10.0f;
  // FALS: the side of the window in pixels of the cloud (odd; OpenCV allows 1 to 7).
  int fals_window_px = 5;
  // The depth change (relative to depth) between neighbouring pixels that is an edge: PCL stops
  // smoothing there; FALS leaves every pixel whose window holds one without a normal.
  float max_depth_change_factor = 0.02f;
  // Normals may be estimated on every normal_step_px-th pixel of every normal_step_px-th row
  // and shared by the block: with PCL's covariance normals a step of 2 costs a quarter of the
  // time (41 -> 11 ms a frame) and changes a normal by 1.4 deg (median), but blurs small objects
  // into the ground (segmentation IoU 0.61 -> 0.57 on a park seed). The points themselves stay
  // at full resolution.
  int normal_step_px = 1;
  void Validate() const;
};

struct OrganizedCloud {
  int width = 0;
  int height = 0;
  std::vector<Eigen::Vector3f> points_m;  // level frame; NaN where there is no depth
  // Level frame, unit, towards the camera; NaN if unknown. Empty in a cloud of points only.
  std::vector<Eigen::Vector3f> normals;
  std::vector<float> depth_m;  // optical-axis depth, 0 where there is none

  int Index(int u, int v) const { return v * width + u; }
  bool HasPoint(int i) const { return depth_m[static_cast<std::size_t>(i)] > 0; }
  bool HasNormal(int i) const { return !std::isnan(normals[static_cast<std::size_t>(i)].x()); }
};

// Builds the clouds of a sequence of frames. It keeps PCL's integral images and clouds between
// frames: allocating them anew (tens of MB) cost more than computing the normals.
class OrganizedCloudBuilder {
 public:
  explicit OrganizedCloudBuilder(const OrganizedCloudOptions& options);
  ~OrganizedCloudBuilder();
  OrganizedCloudBuilder(const OrganizedCloudBuilder&) = delete;
  OrganizedCloudBuilder& operator=(const OrganizedCloudBuilder&) = delete;

  // depth_mm: CV_16UC1 registered to colour, 0 = no reading. T_level_camera: the optical frame
  // in the levelled base frame. Fills *cloud (its buffers are reused). Throws UsageError if the
  // image size differs from the intrinsics.
  void Build(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
             const Eigen::Isometry3f& T_level_camera, OrganizedCloud* cloud);

 private:
  struct Pcl;
  OrganizedCloudOptions options_;
  std::unique_ptr<Pcl> pcl_;
};

// The points alone (no normals) of a depth image, in the level frame: what objects are measured
// on when the normals were estimated at a coarser level. Throws as Build does.
void BuildPoints(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                 const Eigen::Isometry3f& T_level_camera, const OrganizedCloudOptions& options,
                 OrganizedCloud* cloud);

}  // namespace littermap::detect
