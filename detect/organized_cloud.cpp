#include "detect/organized_cloud.hpp"

#include <algorithm>
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

// Back-projects every pixel (points, depths) and every step-th pixel of every step-th row into
// the cloud the normals are estimated on.
void FillCameraCloud(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                     const OrganizedCloudOptions& options, std::vector<Eigen::Vector3f>* points,
                     std::vector<float>* depth_m, pcl::PointCloud<pcl::PointXYZ>* coarse) {
  const int step = options.normal_step_px;
  const auto coarse_width = static_cast<std::uint32_t>(depth_mm.cols / step);
  const auto coarse_height = static_cast<std::uint32_t>(depth_mm.rows / step);
  if (coarse->width != coarse_width || coarse->height != coarse_height) {
    coarse->resize(coarse_width, coarse_height);
  }
  coarse->is_dense = false;
  depth_m->resize(depth_mm.total());
  points->resize(depth_mm.total());
  for (int v = 0; v < depth_mm.rows; ++v) {
    const auto* row = depth_mm.ptr<std::uint16_t>(v);
    for (int u = 0; u < depth_mm.cols; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * depth_mm.cols + u;
      const float z = 0.001f * row[u];
      const bool valid = z >= options.min_depth_m && z <= options.max_depth_m;
      (*points)[i] = valid ? intrinsics.BackProject(u, v, z) : Eigen::Vector3f::Constant(kNaN);
      (*depth_m)[i] = valid ? z : 0.0f;
      if (u % step != 0 || v % step != 0 || u / step >= int(coarse_width) ||
          v / step >= int(coarse_height)) {
        continue;
      }
      (*coarse)(static_cast<std::uint32_t>(u / step), static_cast<std::uint32_t>(v / step))
          .getVector3fMap() = (*points)[i];
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
  if (normal_step_px < 1 || normal_step_px > 8 ||
      static_cast<float>(normal_step_px) > normal_smoothing_px) {
    throw UsageError(
        "segmentation: normal_step_px must be from 1 to 8 and at most "
        "normal_smoothing_px");
  }
}

struct OrganizedCloudBuilder::Pcl {
  pcl::PointCloud<pcl::PointXYZ>::Ptr coarse = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::PointCloud<pcl::Normal> normals;
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> estimator;
};

OrganizedCloudBuilder::OrganizedCloudBuilder(const OrganizedCloudOptions& options)
    : options_(options), pcl_(std::make_unique<Pcl>()) {
  options_.Validate();
  // Covariance-based normals over integral images (thesis 3.1, step 1).
  using Estimator = pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal>;
  switch (options_.normal_method) {
    case NormalMethod::kCovariance:
      pcl_->estimator.setNormalEstimationMethod(Estimator::COVARIANCE_MATRIX);
      break;
    case NormalMethod::kAverage3dGradient:
      pcl_->estimator.setNormalEstimationMethod(Estimator::AVERAGE_3D_GRADIENT);
      break;
    case NormalMethod::kSimple3dGradient:
      pcl_->estimator.setNormalEstimationMethod(Estimator::SIMPLE_3D_GRADIENT);
      break;
    case NormalMethod::kAverageDepthChange:
      pcl_->estimator.setNormalEstimationMethod(Estimator::AVERAGE_DEPTH_CHANGE);
      break;
  }
  pcl_->estimator.setMaxDepthChangeFactor(options_.max_depth_change_factor);
  pcl_->estimator.setNormalSmoothingSize(options_.normal_smoothing_px /
                                         static_cast<float>(options_.normal_step_px));
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
  FillCameraCloud(depth_mm, intrinsics, options_, &out->points_m, &out->depth_m,
                  pcl_->coarse.get());
  pcl_->estimator.setInputCloud(pcl_->coarse);
  pcl_->estimator.compute(pcl_->normals);

  const Eigen::Matrix3f R = T_level_camera.linear();
  const int step = options_.normal_step_px;
  const int coarse_width = static_cast<int>(pcl_->normals.width);
  const int coarse_height = static_cast<int>(pcl_->normals.height);
  out->normals.resize(out->points_m.size());
  for (int v = 0; v < out->height; ++v) {
    const int cv = std::min(v / step, coarse_height - 1);
    for (int u = 0; u < out->width; ++u) {
      const auto i = static_cast<std::size_t>(out->Index(u, v));
      Eigen::Vector3f& point = out->points_m[i];
      Eigen::Vector3f& normal = out->normals[i];
      normal = Eigen::Vector3f::Constant(kNaN);
      if (!(out->depth_m[i] > 0)) continue;
      point = T_level_camera * point;
      const pcl::Normal& n =
          pcl_->normals(static_cast<std::uint32_t>(std::min(u / step, coarse_width - 1)),
                        static_cast<std::uint32_t>(cv));
      if (std::isfinite(n.normal_x))
        normal = R * Eigen::Vector3f(n.normal_x, n.normal_y, n.normal_z);
    }
  }
}

}  // namespace littermap::detect
