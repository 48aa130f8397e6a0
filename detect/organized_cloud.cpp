#include "detect/organized_cloud.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <pcl/features/integral_image_normal.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

void FillCameraCloud(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                     const OrganizedCloudOptions& options, pcl::PointCloud<pcl::PointXYZ>* cloud,
                     std::vector<float>* depth_m) {
  if (cloud->width != static_cast<std::uint32_t>(depth_mm.cols) ||
      cloud->height != static_cast<std::uint32_t>(depth_mm.rows)) {
    cloud->resize(static_cast<std::uint32_t>(depth_mm.cols),
                  static_cast<std::uint32_t>(depth_mm.rows));
  }
  cloud->is_dense = false;
  depth_m->resize(depth_mm.total());
  for (int v = 0; v < depth_mm.rows; ++v) {
    const auto* row = depth_mm.ptr<std::uint16_t>(v);
    for (int u = 0; u < depth_mm.cols; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * depth_mm.cols + u;
      const float z = 0.001f * row[u];
      pcl::PointXYZ& p = (*cloud)[i];
      if (z < options.min_depth_m || z > options.max_depth_m) {
        p.x = p.y = p.z = kNaN;
        (*depth_m)[i] = 0.0f;
        continue;
      }
      const Eigen::Vector3f xyz = intrinsics.BackProject(u, v, z);
      p.x = xyz.x();
      p.y = xyz.y();
      p.z = xyz.z();
      (*depth_m)[i] = z;
    }
  }
}

}  // namespace

void OrganizedCloudOptions::Validate() const {
  if (!(min_depth_m > 0) || !(max_depth_m > min_depth_m)) {
    throw UsageError("segmentation: need 0 < min_depth_m < max_depth_m");
  }
  if (!(normal_smoothing_px >= 1) || !(max_depth_change_factor > 0)) {
    throw UsageError("segmentation: normal_smoothing_px must be >= 1, max_depth_change_factor > 0");
  }
}

struct OrganizedCloudBuilder::Pcl {
  pcl::PointCloud<pcl::PointXYZ>::Ptr camera = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::PointCloud<pcl::Normal> normals;
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> estimator;
};

OrganizedCloudBuilder::OrganizedCloudBuilder(const OrganizedCloudOptions& options)
    : options_(options), pcl_(std::make_unique<Pcl>()) {
  options_.Validate();
  // Covariance-based normals over integral images (thesis 3.1, step 1).
  pcl_->estimator.setNormalEstimationMethod(pcl_->estimator.COVARIANCE_MATRIX);
  pcl_->estimator.setMaxDepthChangeFactor(options_.max_depth_change_factor);
  pcl_->estimator.setNormalSmoothingSize(options_.normal_smoothing_px);
  pcl_->estimator.setDepthDependentSmoothing(false);
}

OrganizedCloudBuilder::~OrganizedCloudBuilder() = default;

void OrganizedCloudBuilder::Build(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                                  const Eigen::Isometry3f& T_level_camera, OrganizedCloud* out) {
  if (depth_mm.type() != CV_16UC1 || depth_mm.cols != intrinsics.width ||
      depth_mm.rows != intrinsics.height) {
    throw UsageError("segmentation: depth image is not CV_16UC1 of " +
                     std::to_string(intrinsics.width) + "x" + std::to_string(intrinsics.height) +
                     " as the camera info says");
  }
  out->width = depth_mm.cols;
  out->height = depth_mm.rows;
  FillCameraCloud(depth_mm, intrinsics, options_, pcl_->camera.get(), &out->depth_m);
  pcl_->estimator.setInputCloud(pcl_->camera);
  pcl_->estimator.compute(pcl_->normals);

  const Eigen::Matrix3f R = T_level_camera.linear();
  const auto& camera = *pcl_->camera;
  out->points_m.resize(camera.size());
  out->normals.resize(camera.size());
  for (std::size_t i = 0; i < camera.size(); ++i) {
    const bool valid = out->depth_m[i] > 0;
    out->points_m[i] = valid ? Eigen::Vector3f(T_level_camera * camera[i].getVector3fMap())
                             : Eigen::Vector3f::Constant(kNaN);
    const pcl::Normal& n = pcl_->normals[i];
    out->normals[i] = valid && std::isfinite(n.normal_x)
                          ? Eigen::Vector3f(R * Eigen::Vector3f(n.normal_x, n.normal_y, n.normal_z))
                          : Eigen::Vector3f::Constant(kNaN);
  }
}

}  // namespace littermap::detect
