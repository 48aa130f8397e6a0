#include "detect/frame_segmenter.hpp"

#include <chrono>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

double MsSince(std::chrono::steady_clock::time_point* start) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - *start).count();
  *start = now;
  return ms;
}

}  // namespace

void SegmentationOptions::Validate() const {
  cloud.Validate();
  components.Validate();
  ground.Validate();
  texture.Validate();
  objects.Validate();
}

FrameSegmenter::FrameSegmenter(const SegmentationOptions& options)
    : options_((options.Validate(), options)), cloud_builder_(options.cloud) {}

FrameSegmentation FrameSegmenter::Segment(const cv::Mat& colour_bgr, const cv::Mat& depth_mm,
                                          const CameraIntrinsics& intrinsics,
                                          const Eigen::Isometry3f& T_level_camera) {
  const SegmentationOptions& options = options_;
  const OrganizedCloud& cloud = cloud_;
  if (colour_bgr.type() != CV_8UC3 || colour_bgr.size() != depth_mm.size()) {
    throw UsageError("segmentation: colour must be CV_8UC3 of the depth image's size");
  }
  FrameSegmentation out;
  auto clock = std::chrono::steady_clock::now();
  cloud_builder_.Build(depth_mm, intrinsics, T_level_camera, &cloud_);
  out.timings.cloud_ms = MsSince(&clock);
  const Components components = LabelComponents(cloud, colour_bgr, options.components);
  out.components = components.sizes.size();
  out.timings.components_ms = MsSince(&clock);
  const GroundResult ground = FindGround(cloud, components, options.ground);
  out.ground_found = ground.found;
  out.ground_points = ground.points;
  out.ground_rms_m = ground.rms_residual_m;
  out.ground = ground.surface;
  out.timings.ground_ms = MsSince(&clock);
  out.refinement = RefineGroundByTexture(colour_bgr, cloud, ground, options.texture);
  out.timings.texture_ms = MsSince(&clock);
  ObjectClusterResult objects =
      ExtractObjects(colour_bgr, cloud, ground, out.refinement, options.objects);
  out.objects = std::move(objects.objects);
  out.blobs = objects.blobs;
  out.refined = objects.refined;
  out.timings.objects_ms = MsSince(&clock);
  return out;
}

cv::Mat DrawSegmentation(const cv::Mat& colour_bgr, const FrameSegmentation& segmentation) {
  cv::Mat out = colour_bgr.clone();
  const cv::Mat& labels = segmentation.refinement.labels;
  if (labels.empty()) return out;
  for (int v = 0; v < out.rows; ++v) {
    for (int u = 0; u < out.cols; ++u) {
      cv::Vec3b& c = out.at<cv::Vec3b>(v, u);
      cv::Vec3b tint = c;
      if (segmentation.refinement.non_ground.at<std::uint8_t>(v, u)) {
        tint = {0, 0, 255};
      } else if (labels.at<std::uint8_t>(v, u) == kGround) {
        tint = {255, 0, 0};
      } else if (labels.at<std::uint8_t>(v, u) == kUncertain) {
        tint = {0, 255, 255};
      }
      for (int k = 0; k < 3; ++k) c[k] = static_cast<std::uint8_t>((3 * c[k] + tint[k]) / 4);
    }
  }
  for (const auto& object : segmentation.objects) {
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(object.mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE,
                     object.box.tl());
    cv::drawContours(out, contours, -1, cv::Scalar(0, 255, 0), 1);
  }
  return out;
}

}  // namespace littermap::detect
