#include "detect/organized_cloud.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <pcl/features/integral_image_normal.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/rgbd.hpp>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Back-projects every pixel into camera-frame points and depths (NaN and 0 where there is none).
void FillCameraPoints(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                      const OrganizedCloudOptions& options, std::vector<Eigen::Vector3f>* points,
                      std::vector<float>* depth_m) {
  depth_m->resize(depth_mm.total());
  points->resize(depth_mm.total());
  // The rays' slopes, one per column and per row, as BackProject computes them.
  std::vector<float> x_slope(static_cast<std::size_t>(depth_mm.cols));
  for (int u = 0; u < depth_mm.cols; ++u) {
    x_slope[static_cast<std::size_t>(u)] = intrinsics.BackProject(u, 0, 1.0f).x();
  }
  for (int v = 0; v < depth_mm.rows; ++v) {
    const auto* row = depth_mm.ptr<std::uint16_t>(v);
    const float y_slope = intrinsics.BackProject(0, v, 1.0f).y();
    const std::size_t first = static_cast<std::size_t>(v) * static_cast<std::size_t>(depth_mm.cols);
    for (int u = 0; u < depth_mm.cols; ++u) {
      const std::size_t i = first + static_cast<std::size_t>(u);
      const float z = 0.001f * row[u];
      const bool valid = z >= options.min_depth_m && z <= options.max_depth_m;
      (*points)[i] = valid
                         ? Eigen::Vector3f(x_slope[static_cast<std::size_t>(u)] * z, y_slope * z, z)
                         : Eigen::Vector3f::Constant(kNaN);
      (*depth_m)[i] = valid ? z : 0.0f;
    }
  }
}

// Every step-th point of every step-th row: the cloud the normals are estimated on.
void FillCoarseCloud(const std::vector<Eigen::Vector3f>& points, int width, int height, int step,
                     pcl::PointCloud<pcl::PointXYZ>* coarse) {
  const auto coarse_width = static_cast<std::uint32_t>(width / step);
  const auto coarse_height = static_cast<std::uint32_t>(height / step);
  if (coarse->width != coarse_width || coarse->height != coarse_height) {
    coarse->resize(coarse_width, coarse_height);
  }
  coarse->is_dense = false;
  for (std::uint32_t cv = 0; cv < coarse_height; ++cv) {
    const std::size_t first = static_cast<std::size_t>(cv) * static_cast<std::size_t>(step) *
                              static_cast<std::size_t>(width);
    for (std::uint32_t cu = 0; cu < coarse_width; ++cu) {
      (*coarse)(cu, cv).getVector3fMap() = points[first + cu * static_cast<std::size_t>(step)];
    }
  }
}

// Checks the depth image against the intrinsics and fills the cloud's size, camera-frame points
// and depths. Throws UsageError for an image that is not CV_16UC1 of the intrinsics' size.
void FillCameraCloud(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                     const OrganizedCloudOptions& options, OrganizedCloud* out) {
  if (depth_mm.type() != CV_16UC1 || depth_mm.cols != intrinsics.width ||
      depth_mm.rows != intrinsics.height) {
    throw UsageError("segmentation: depth image is not CV_16UC1 of " +
                     std::to_string(intrinsics.width) + "x" + std::to_string(intrinsics.height) +
                     " as the camera info says");
  }
  out->width = depth_mm.cols;
  out->height = depth_mm.rows;
  FillCameraPoints(depth_mm, intrinsics, options, &out->points_m, &out->depth_m);
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
  RequireOption(fals_window_px >= 1 && fals_window_px <= 7 && fals_window_px % 2 == 1,
                "segmentation", "fals_window_px", "1, 3, 5 or 7");
}

struct OrganizedCloudBuilder::Pcl {
  pcl::PointCloud<pcl::PointXYZ>::Ptr coarse = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::PointCloud<pcl::Normal> normals;
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> estimator;
  // FALS: the camera-frame points as an image, its normals, and where a window crosses an edge.
  std::unique_ptr<cv::rgbd::RgbdNormals> fals;
  cv::Mat points, fals_normals, edges;
};

namespace {

// OpenCV's FALS normals of the coarse cloud into `normals` (as PCL's estimator would fill it). A
// window that holds a point without depth has no normal; one that crosses a depth step of more
// than max_depth_change_factor of the depth, between neighbouring pixels, gets none either, as
// PCL leaves the pixels next to an edge without one (FALS would average across the step).
void FalsNormals(const pcl::PointCloud<pcl::PointXYZ>& cloud, float max_depth_change_factor,
                 int window_px, cv::rgbd::RgbdNormals& fals, cv::Mat& points, cv::Mat& normals,
                 cv::Mat& edges, pcl::PointCloud<pcl::Normal>* out) {
  const int width = static_cast<int>(cloud.width), height = static_cast<int>(cloud.height);
  points.create(height, width, CV_32FC3);
  edges.create(height, width, CV_8UC1);
  edges.setTo(0);
  for (int v = 0; v < height; ++v) {
    auto* row = points.ptr<cv::Vec3f>(v);
    auto* edge = edges.ptr<std::uint8_t>(v);
    for (int u = 0; u < width; ++u) {
      const pcl::PointXYZ& p = cloud(static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v));
      row[u] = {p.x, p.y, p.z};
      const float step = 2.0f * max_depth_change_factor * (std::abs(p.z) + 1.0f);
      if (u > 0 && !(std::abs(p.z - row[u - 1][2]) <= step)) edge[u] = edge[u - 1] = 1;
      if (v > 0) {
        const float above = points.ptr<cv::Vec3f>(v - 1)[u][2];
        if (!(std::abs(p.z - above) <= step)) edge[u] = edges.ptr<std::uint8_t>(v - 1)[u] = 1;
      }
    }
  }
  fals(points, normals);
  cv::dilate(edges, edges, cv::getStructuringElement(cv::MORPH_RECT, {window_px, window_px}));
  for (int v = 0; v < height; ++v) {
    const auto* n = normals.ptr<cv::Vec3f>(v);
    const auto* edge = edges.ptr<std::uint8_t>(v);
    for (int u = 0; u < width; ++u) {
      pcl::Normal& o = (*out)(static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v));
      if (edge[u] || !std::isfinite(n[u][0])) {
        o.normal_x = o.normal_y = o.normal_z = kNaN;
        continue;
      }
      const cv::Vec3f& p = points.ptr<cv::Vec3f>(v)[u];
      const float sign = n[u].dot(p) > 0 ? -1.0f : 1.0f;  // towards the camera, as PCL's are
      o.normal_x = sign * n[u][0];
      o.normal_y = sign * n[u][1];
      o.normal_z = sign * n[u][2];
    }
  }
}

}  // namespace

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
    case NormalMethod::kFals:
      break;  // made at the first frame, when the image size is known
  }
  pcl_->estimator.setMaxDepthChangeFactor(options_.max_depth_change_factor);
  pcl_->estimator.setNormalSmoothingSize(options_.normal_smoothing_px /
                                         static_cast<float>(options_.normal_step_px));
  pcl_->estimator.setDepthDependentSmoothing(false);
}

OrganizedCloudBuilder::~OrganizedCloudBuilder() = default;

void OrganizedCloudBuilder::Build(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                                  const Eigen::Isometry3f& T_level_camera, OrganizedCloud* out) {
  FillCameraCloud(depth_mm, intrinsics, options_, out);
  FillCoarseCloud(out->points_m, out->width, out->height, options_.normal_step_px,
                  pcl_->coarse.get());
  if (options_.normal_method == NormalMethod::kFals) {
    const int width = static_cast<int>(pcl_->coarse->width);
    const int height = static_cast<int>(pcl_->coarse->height);
    const int step = options_.normal_step_px;
    if (!pcl_->fals || pcl_->points.cols != width || pcl_->points.rows != height) {
      const cv::Matx33f K(static_cast<float>(intrinsics.fx / step), 0,
                          static_cast<float>(intrinsics.cx / step), 0,
                          static_cast<float>(intrinsics.fy / step),
                          static_cast<float>(intrinsics.cy / step), 0, 0, 1);
      pcl_->fals = std::make_unique<cv::rgbd::RgbdNormals>(
          height, width, CV_32F, cv::Mat(K), options_.fals_window_px,
          cv::rgbd::RgbdNormals::RGBD_NORMALS_METHOD_FALS);
    }
    pcl_->normals.resize(pcl_->coarse->width, pcl_->coarse->height);
    FalsNormals(*pcl_->coarse, options_.max_depth_change_factor, options_.fals_window_px,
                *pcl_->fals, pcl_->points, pcl_->fals_normals, pcl_->edges, &pcl_->normals);
  } else {
    pcl_->estimator.setInputCloud(pcl_->coarse);
    pcl_->estimator.compute(pcl_->normals);
  }

  const Eigen::Matrix3f R = T_level_camera.linear();
  const int step = options_.normal_step_px;
  const int coarse_width = static_cast<int>(pcl_->normals.width);
  const int coarse_height = static_cast<int>(pcl_->normals.height);
  out->normals.resize(out->points_m.size());
  std::vector<std::uint32_t> coarse_column(static_cast<std::size_t>(out->width));
  for (int u = 0; u < out->width; ++u) {
    coarse_column[static_cast<std::size_t>(u)] =
        static_cast<std::uint32_t>(std::min(u / step, coarse_width - 1));
  }
  for (int v = 0; v < out->height; ++v) {
    const auto cv = static_cast<std::uint32_t>(std::min(v / step, coarse_height - 1));
    for (int u = 0; u < out->width; ++u) {
      const auto i = static_cast<std::size_t>(out->Index(u, v));
      Eigen::Vector3f& point = out->points_m[i];
      Eigen::Vector3f& normal = out->normals[i];
      normal = Eigen::Vector3f::Constant(kNaN);
      if (!(out->depth_m[i] > 0)) continue;
      point = T_level_camera * point;
      const pcl::Normal& n = pcl_->normals(coarse_column[static_cast<std::size_t>(u)], cv);
      if (std::isfinite(n.normal_x))
        normal = R * Eigen::Vector3f(n.normal_x, n.normal_y, n.normal_z);
    }
  }
}

void BuildPoints(const cv::Mat& depth_mm, const CameraIntrinsics& intrinsics,
                 const Eigen::Isometry3f& T_level_camera, const OrganizedCloudOptions& options,
                 OrganizedCloud* out) {
  FillCameraCloud(depth_mm, intrinsics, options, out);
  out->normals.clear();
  for (std::size_t i = 0; i < out->points_m.size(); ++i) {
    if (out->depth_m[i] > 0) out->points_m[i] = T_level_camera * out->points_m[i];
  }
}

}  // namespace littermap::detect
