#include "detect/object_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Eigenvalues>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "detect/seeded_the_rng.hpp"

namespace littermap::detect {
namespace {

// The seed of GrabCut's k-means++ draws for every object (SeededTheRng).
constexpr std::uint64_t kGrabCutSeed = 1;

cv::Rect Grown(const cv::Rect& box, const ObjectClusterOptions& options, const cv::Size& image) {
  const int dx =
      std::max(options.min_box_margin_px, int(std::lround(options.box_margin * box.width)));
  const int dy =
      std::max(options.min_box_margin_px, int(std::lround(options.box_margin * box.height)));
  return cv::Rect(box.x - dx, box.y - dy, box.width + 2 * dx, box.height + 2 * dy) &
         cv::Rect(cv::Point(0, 0), image);
}

// Extent along the principal horizontal axes of the points: 4 sigma covers a uniform segment's
// full length (sqrt(12) sigma) with margin for the depth noise of a few points.
Eigen::Vector2f HorizontalExtent(const std::vector<Eigen::Vector3f>& points) {
  Eigen::Vector2f mean = Eigen::Vector2f::Zero();
  for (const auto& p : points) mean += p.head<2>();
  mean /= static_cast<float>(points.size());
  Eigen::Matrix2f covariance = Eigen::Matrix2f::Zero();
  for (const auto& p : points) {
    const Eigen::Vector2f d = p.head<2>() - mean;
    covariance += d * d.transpose();
  }
  covariance /= static_cast<float>(points.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2f> eigen(covariance);
  return {std::sqrt(12.0f * std::max(0.0f, eigen.eigenvalues()[1])),
          std::sqrt(12.0f * std::max(0.0f, eigen.eigenvalues()[0]))};
}

// Whether a blob's core alone is too tall or too wide for litter. The refined object holds the
// core (GrabCut keeps it), so it is at least as tall and, in practice, as wide: such a core (a
// trunk, a bush, a bench, a keyboard on a desk) is rejected before GrabCut is spent on it. The
// height needs one depth point of the core, the width as many as Measure needs.
bool CoreTooLarge(const OrganizedCloud& cloud, const GroundSurface& surface, const cv::Mat& core,
                  const cv::Rect& roi, const ObjectClusterOptions& options) {
  std::vector<Eigen::Vector3f> points;
  for (int v = 0; v < roi.height; ++v) {
    const auto* row = core.ptr<std::uint8_t>(v);
    for (int u = 0; u < roi.width; ++u) {
      const int i = cloud.Index(u + roi.x, v + roi.y);
      if (!row[u] || !cloud.HasPoint(i)) continue;
      const Eigen::Vector3f& p = cloud.points_m[static_cast<std::size_t>(i)];
      if (surface.HeightAbove(p) > options.max_height_m) return true;
      points.push_back(p);
    }
  }
  return static_cast<int>(points.size()) >= options.min_depth_points &&
         HorizontalExtent(points)[0] > options.max_size_m;
}

// GrabCut in the grown box; returns the refined object mask of `roi` size.
// blob, core and others: roi-sized masks of this blob, of its core (GrabCut keeps it) and of
// every other non-ground pixel.
cv::Mat RefineWithGrabCut(const cv::Mat& colour_bgr, const cv::Mat& blob, const cv::Mat& core,
                          const cv::Mat& others, const cv::Mat& labels, const cv::Rect& roi,
                          int max_pixels, int fringe_px) {
  cv::Mat mask(roi.size(), CV_8U, cv::Scalar(cv::GC_PR_BGD));
  cv::Mat fringe;
  if (fringe_px > 0) {
    cv::dilate(blob, fringe, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}), {-1, -1},
               fringe_px);
  }
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      const std::uint8_t label = labels.at<std::uint8_t>(v + roi.y, u + roi.x);
      auto& m = mask.at<std::uint8_t>(v, u);
      if (blob.at<std::uint8_t>(v, u)) {
        m = core.at<std::uint8_t>(v, u) ? cv::GC_FGD : cv::GC_PR_FGD;
      } else if (others.at<std::uint8_t>(v, u) ||
                 (label == kGround && (fringe.empty() || !fringe.at<std::uint8_t>(v, u)))) {
        m = cv::GC_BGD;  // another object's pixel, or ground beyond the blob's fringe
      }
    }
  }
  const double scale = std::min(1.0, std::sqrt(double(max_pixels) / double(roi.area())));
  cv::Mat small_colour = colour_bgr(roi), small_mask = mask;
  if (scale < 1) {
    cv::resize(colour_bgr(roi), small_colour, cv::Size(), scale, scale, cv::INTER_AREA);
    cv::resize(mask, small_mask, small_colour.size(), 0, 0, cv::INTER_NEAREST);
  }
  cv::Mat background_model, foreground_model;
  try {
    const SeededTheRng seeded(kGrabCutSeed);  // the same cut whatever was refined before
    cv::grabCut(small_colour, small_mask, cv::Rect(), background_model, foreground_model, 1,
                cv::GC_INIT_WITH_MASK);
  } catch (const cv::Exception&) {
    return blob.clone();  // too few samples of one side for its GMM: keep the blob
  }
  cv::Mat refined = (small_mask == cv::GC_FGD) | (small_mask == cv::GC_PR_FGD);
  if (scale < 1) {
    cv::resize(refined, refined, roi.size(), 0, 0, cv::INTER_NEAREST);
    refined.setTo(0, mask == cv::GC_BGD);
    refined.setTo(255, mask == cv::GC_FGD);
  }
  // Keep what is connected to the blob: GrabCut may switch on look-alike pixels elsewhere.
  cv::Mat components;
  cv::connectedComponents(refined, components, 8, CV_32S);
  std::vector<unsigned char> keep(static_cast<std::size_t>(roi.area()) + 1, 0);
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      if (blob.at<std::uint8_t>(v, u)) keep[static_cast<std::size_t>(components.at<int>(v, u))] = 1;
    }
  }
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      const int c = components.at<int>(v, u);
      refined.at<std::uint8_t>(v, u) = (c > 0 && keep[static_cast<std::size_t>(c)]) ? 255 : 0;
    }
  }
  return refined;
}

// Measures the object of `mask` (roi-sized) in 3D; false if it has too few depth points.
bool Measure(const OrganizedCloud& cloud, const GroundSurface& surface, const cv::Mat& mask,
             const cv::Rect& roi, const ObjectClusterOptions& options, SegmentedObject* object) {
  std::vector<Eigen::Vector3f> points;
  int pixels = 0;
  int u0 = roi.width, v0 = roi.height, u1 = -1, v1 = -1;
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      if (!mask.at<std::uint8_t>(v, u)) continue;
      ++pixels;
      u0 = std::min(u0, u), v0 = std::min(v0, v), u1 = std::max(u1, u), v1 = std::max(v1, v);
      const int i = cloud.Index(u + roi.x, v + roi.y);
      if (cloud.HasPoint(i)) points.push_back(cloud.points_m[static_cast<std::size_t>(i)]);
    }
  }
  if (static_cast<int>(points.size()) < options.min_depth_points) return false;
  object->box = cv::Rect(roi.x + u0, roi.y + v0, u1 - u0 + 1, v1 - v0 + 1);
  object->mask = mask(cv::Rect(u0, v0, u1 - u0 + 1, v1 - v0 + 1)).clone();
  object->pixels = pixels;
  object->depth_points = static_cast<int>(points.size());
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();
  float top = -1e9f, range = 0;
  for (const auto& p : points) {
    mean += p;
    top = std::max(top, static_cast<float>(surface.HeightAbove(p)));
    range += p.norm();
  }
  mean /= static_cast<float>(points.size());
  const Eigen::Vector2f extent = HorizontalExtent(points);
  object->size_m = extent[0];
  object->width_m = extent[1];
  object->height_m = top;
  object->centroid_level_m = mean;
  object->ground_level_m = {mean.x(), mean.y(),
                            static_cast<float>(surface.HeightAt(mean.x(), mean.y()))};
  object->range_m = range / static_cast<float>(points.size());
  return true;
}

}  // namespace

void ObjectClusterOptions::Validate() const {
  constexpr const char* kStage = "segmentation";
  RequireOption(min_pixels >= 1, kStage, "min_pixels", ">= 1");
  RequireOption(min_depth_points >= 3, kStage, "min_depth_points", ">= 3");
  RequireOption(min_size_m >= 0, kStage, "min_size_m", ">= 0");
  RequireOption(max_size_m > min_size_m, kStage, "max_size_m", "> min_size_m");
  RequireOption(max_height_m > 0, kStage, "max_height_m", "> 0");
  RequireOption(box_margin >= 0, kStage, "box_margin", ">= 0");
  RequireOption(min_box_margin_px >= 1, kStage, "min_box_margin_px", ">= 1");
  RequireOption(max_refine_pixels >= 100, kStage, "max_refine_pixels", ">= 100");
  RequireOption(uncertain_fringe_px >= 0 && uncertain_fringe_px <= 20, kStage,
                "uncertain_fringe_px", "from 0 to 20");
}

ObjectClusterResult ExtractObjects(const cv::Mat& colour_bgr, const OrganizedCloud& cloud,
                                   const GroundResult& ground,
                                   const TextureRefinementResult& refinement,
                                   const ObjectClusterOptions& options) {
  ObjectClusterResult result;
  if (!ground.found) return result;
  cv::Mat blobs, stats, centroids;
  const int count =
      cv::connectedComponentsWithStats(refinement.non_ground, blobs, stats, centroids, 8, CV_32S);
  const cv::Size image(cloud.width, cloud.height);
  for (int b = 1; b < count; ++b) {
    const cv::Rect box(stats.at<int>(b, cv::CC_STAT_LEFT), stats.at<int>(b, cv::CC_STAT_TOP),
                       stats.at<int>(b, cv::CC_STAT_WIDTH), stats.at<int>(b, cv::CC_STAT_HEIGHT));
    if (stats.at<int>(b, cv::CC_STAT_AREA) < options.min_pixels) continue;
    ++result.blobs;
    const cv::Rect roi = Grown(box, options, image);
    const cv::Mat blob = blobs(roi) == b;
    cv::Mat mask = blob;
    if (options.refine) {
      cv::Mat core;
      cv::erode(blob, core, cv::Mat());
      if (CoreTooLarge(cloud, ground.surface, core, roi, options)) {
        ++result.rejected_size;
        continue;
      }
      ++result.refined;
      mask = RefineWithGrabCut(colour_bgr, blob, core, refinement.non_ground(roi) & ~blob,
                               refinement.labels, roi, options.max_refine_pixels,
                               options.uncertain_fringe_px);
    }
    SegmentedObject object;
    if (cv::countNonZero(mask) < options.min_pixels ||
        !Measure(cloud, ground.surface, mask, roi, options, &object) ||
        object.size_m < options.min_size_m || object.size_m > options.max_size_m ||
        object.height_m > options.max_height_m) {
      ++result.rejected_size;
      continue;
    }
    result.objects.push_back(std::move(object));
  }
  return result;
}

}  // namespace littermap::detect
