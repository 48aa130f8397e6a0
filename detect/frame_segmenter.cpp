#include "detect/frame_segmenter.hpp"

#include <algorithm>
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

// The options as they apply to images sampled every `step` pixels: pixel counts shrink by step^2,
// pixel lengths and the metric gap between neighbours (the pixel footprint) by step.
SegmentationOptions AtStep(SegmentationOptions options, int step) {
  if (step == 1) return options;
  const auto count = [step](int n) { return std::max(1, n / (step * step)); };
  options.cloud.normal_smoothing_px =
      std::max(1.0f, options.cloud.normal_smoothing_px / static_cast<float>(step));
  options.cloud.normal_step_px = std::max(1, options.cloud.normal_step_px / step);
  options.cloud.fals_window_px = (options.cloud.fals_window_px / step) | 1;
  options.components.max_gap_per_m *= step;
  options.ground.min_component_points = count(options.ground.min_component_points);
  options.ground.min_joined_points = count(options.ground.min_joined_points);
  options.texture.region_margin_px /= step;
  options.texture.min_nonground_training_pixels =
      count(options.texture.min_nonground_training_pixels);
  return options;
}

CameraIntrinsics AtStep(const CameraIntrinsics& K, int step) {
  // Sample (u, v) is the full image's pixel (step u, step v).
  CameraIntrinsics out = K;
  out.fx /= step, out.fy /= step, out.cx /= step, out.cy /= step;
  out.width = K.width / step, out.height = K.height / step;
  return out;
}

// A label image of the geometry's resolution brought to the full image's size: each full pixel
// takes its sample's label.
cv::Mat ToFullSize(const cv::Mat& labels, const cv::Size& full, int step) {
  cv::Mat out(full, labels.type(), cv::Scalar(0));
  cv::Mat covered;
  cv::resize(labels, covered, labels.size() * step, 0, 0, cv::INTER_NEAREST);
  covered.copyTo(out(cv::Rect(cv::Point(0, 0), covered.size())));
  return out;
}

}  // namespace

void SegmentationOptions::Validate() const {
  RequireOption(geometry_step_px >= 1 && geometry_step_px <= 4, "segmentation", "geometry_step_px",
                "from 1 to 4");
  cloud.Validate();
  components.Validate();
  ground.Validate();
  texture.Validate();
  objects.Validate();
}

FrameSegmenter::FrameSegmenter(const SegmentationOptions& options)
    : options_((options.Validate(), options)),
      geometry_(AtStep(options, options.geometry_step_px)),
      cloud_builder_(geometry_.cloud) {}

FrameSegmentation FrameSegmenter::Segment(const cv::Mat& colour_bgr, const cv::Mat& depth_mm,
                                          const CameraIntrinsics& intrinsics,
                                          const Eigen::Isometry3f& T_level_camera) {
  const SegmentationOptions& options = geometry_;
  const int step = options_.geometry_step_px;
  if (colour_bgr.type() != CV_8UC3 || colour_bgr.size() != depth_mm.size()) {
    throw UsageError("segmentation: colour must be CV_8UC3 of the depth image's size");
  }
  FrameSegmentation out;
  auto clock = std::chrono::steady_clock::now();
  const CameraIntrinsics K = AtStep(intrinsics, step);
  if (step > 1) {
    BuildPoints(depth_mm, intrinsics, T_level_camera, options_.cloud, &full_points_);  // checks
    const cv::Size size(K.width, K.height);
    cv::resize(depth_mm(cv::Rect(cv::Point(0, 0), size * step)), depth_mm_, size, 0, 0,
               cv::INTER_NEAREST);
    cv::resize(colour_bgr(cv::Rect(cv::Point(0, 0), size * step)), colour_, size, 0, 0,
               cv::INTER_AREA);
  }
  // The images the geometry works on: the full ones at step 1.
  const cv::Mat& depth = step > 1 ? depth_mm_ : depth_mm;
  const cv::Mat& colour = step > 1 ? colour_ : colour_bgr;
  cloud_builder_.Build(depth, K, T_level_camera, &cloud_);
  const OrganizedCloud& cloud = cloud_;
  out.timings.cloud_ms = MsSince(&clock);
  const Components components = LabelComponents(cloud, colour, options.components);
  out.components = components.sizes.size();
  out.timings.components_ms = MsSince(&clock);
  const GroundResult ground = FindGround(cloud, components, options.ground);
  out.ground_found = ground.found;
  out.ground_points = ground.points * static_cast<std::size_t>(step * step);
  out.ground_rms_m = ground.rms_residual_m;
  out.ground = ground.surface;
  out.timings.ground_ms = MsSince(&clock);
  out.refinement = RefineGroundByTexture(colour, cloud, ground, options.texture);
  if (step > 1) {
    out.refinement.labels = ToFullSize(out.refinement.labels, colour_bgr.size(), step);
    out.refinement.non_ground = ToFullSize(out.refinement.non_ground, colour_bgr.size(), step);
    const cv::Rect& r = out.refinement.region;
    out.refinement.region = cv::Rect(r.x * step, r.y * step, r.width * step, r.height * step);
  }
  out.timings.texture_ms = MsSince(&clock);
  ObjectClusterResult objects = ExtractObjects(colour_bgr, step > 1 ? full_points_ : cloud, ground,
                                               out.refinement, options_.objects, step);
  out.objects = std::move(objects.objects);
  out.blobs = objects.blobs;
  out.refined = objects.refined;
  out.split = objects.split;
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
