#include "detect/object_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

// The parts of `blob` (roi-sized) connected in space: 4-neighbours with points closer than the
// gap at their depth, on the image's pixels sampled every `step` (the blob's resolution when it
// came from geometry at that step). Samples without a point, or with one within
// split_min_height_m of the ground, belong to no part.
struct Part {
  int samples = 0;
  int j0 = 0, i0 = 0, j1 = 0, i1 = 0;  // the samples' box (columns j, rows i)
  float lowest_m = 0, highest_m = 0;   // heights above the ground of its points
};

struct Parts {
  int step = 1;
  cv::Point first;  // the roi's pixel of sample (0, 0), on the image's grid of samples
  cv::Mat labels;   // CV_32S per sample: 0 none, else 1 + the part's index
  std::vector<Part> parts;

  // The part's pixels as a mask of `box` (roi pixels): each blob pixel takes its sample's part.
  cv::Mat Mask(std::size_t part, const cv::Mat& blob, cv::Rect* box) const {
    const Part& p = parts[part];
    *box = cv::Rect(first.x + p.j0 * step, first.y + p.i0 * step, (p.j1 - p.j0 + 1) * step,
                    (p.i1 - p.i0 + 1) * step) &
           cv::Rect(cv::Point(0, 0), blob.size());
    cv::Mat mask(box->size(), CV_8U, cv::Scalar(0));
    const int label = static_cast<int>(part) + 1;
    for (int v = 0; v < box->height; ++v) {
      const int i = (v + box->y - first.y) / step;
      for (int u = 0; u < box->width; ++u) {
        const int j = (u + box->x - first.x) / step;
        if (labels.at<int>(i, j) == label && blob.at<std::uint8_t>(v + box->y, u + box->x)) {
          mask.at<std::uint8_t>(v, u) = 255;
        }
      }
    }
    return mask;
  }
};

Parts LabelPartsInSpace(const OrganizedCloud& cloud, const GroundSurface& surface,
                        const cv::Mat& blob, const cv::Rect& roi, int step,
                        const ObjectClusterOptions& options) {
  Parts out;
  out.step = step;
  out.first = {(step - roi.x % step) % step, (step - roi.y % step) % step};
  const int cols = (roi.width - out.first.x + step - 1) / step;
  const int rows = (roi.height - out.first.y + step - 1) / step;
  const auto index = [&](int j, int i) {
    return static_cast<std::size_t>(
        cloud.Index(roi.x + out.first.x + j * step, roi.y + out.first.y + i * step));
  };
  // Height above the ground of every sample that may join a part, NaN for the others: points
  // this close to the ground would chain everything standing on it into one part.
  cv::Mat heights(rows, cols, CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  for (int i = 0; i < rows; ++i) {
    const auto* in = blob.ptr<std::uint8_t>(out.first.y + i * step) + out.first.x;
    auto* h = heights.ptr<float>(i);
    for (int j = 0; j < cols; ++j) {
      if (!in[j * step] || cloud.depth_m[index(j, i)] <= 0) continue;
      const auto above = static_cast<float>(surface.HeightAbove(cloud.points_m[index(j, i)]));
      if (above >= options.split_min_height_m) h[j] = above;
    }
  }
  const double gap_per_m = options.split_max_gap_per_m * step;  // the samples' footprint
  out.labels = cv::Mat(rows, cols, CV_32S, cv::Scalar(0));
  std::vector<cv::Point> stack;
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) {
      if (out.labels.at<int>(i, j) || std::isnan(heights.at<float>(i, j))) continue;
      const int label = static_cast<int>(out.parts.size()) + 1;
      Part part{0, j, i, j, i, heights.at<float>(i, j), heights.at<float>(i, j)};
      out.labels.at<int>(i, j) = label;
      stack.assign(1, {j, i});
      while (!stack.empty()) {
        const cv::Point p = stack.back();
        stack.pop_back();
        const float h = heights.at<float>(p.y, p.x);
        ++part.samples;
        part.j0 = std::min(part.j0, p.x), part.j1 = std::max(part.j1, p.x);
        part.i0 = std::min(part.i0, p.y), part.i1 = std::max(part.i1, p.y);
        part.lowest_m = std::min(part.lowest_m, h), part.highest_m = std::max(part.highest_m, h);
        const Eigen::Vector3f& here = cloud.points_m[index(p.x, p.y)];
        const auto gap = static_cast<float>(options.split_max_gap_m +
                                            gap_per_m * cloud.depth_m[index(p.x, p.y)]);
        const cv::Point neighbours[] = {
            {p.x + 1, p.y}, {p.x - 1, p.y}, {p.x, p.y + 1}, {p.x, p.y - 1}};
        for (const cv::Point& q : neighbours) {
          if (q.x < 0 || q.y < 0 || q.x >= cols || q.y >= rows) continue;
          if (out.labels.at<int>(q.y, q.x) || std::isnan(heights.at<float>(q.y, q.x))) continue;
          if ((cloud.points_m[index(q.x, q.y)] - here).squaredNorm() >= gap * gap) continue;
          out.labels.at<int>(q.y, q.x) = label;
          stack.push_back(q);
        }
      }
      out.parts.push_back(part);
    }
  }
  return out;
}

// Whether a measured object is litter-sized.
bool LitterSized(const SegmentedObject& object, const ObjectClusterOptions& options) {
  return object.size_m >= options.min_size_m && object.size_m <= options.max_size_m &&
         object.height_m <= options.max_height_m;
}

// The litter-sized parts of a blob too large for litter, measured as they are; none when there
// are more than split_max_parts of them (clutter, not litter beside a trunk). A part must lie on
// the ground (lowest point at most split_max_base_m above it).
void AddLitterSizedParts(const OrganizedCloud& cloud, const GroundSurface& surface,
                         const cv::Mat& blob, const cv::Rect& roi, int step,
                         const ObjectClusterOptions& options, ObjectClusterResult* result) {
  const Parts parts = LabelPartsInSpace(cloud, surface, blob, roi, step, options);
  std::vector<SegmentedObject> litter;
  for (std::size_t k = 0; k < parts.parts.size(); ++k) {
    const Part& part = parts.parts[k];
    if (part.samples * step * step < std::max(options.min_pixels, options.min_depth_points) ||
        part.highest_m > options.max_height_m || part.lowest_m > options.split_max_base_m) {
      continue;
    }
    cv::Rect box;
    const cv::Mat mask = parts.Mask(k, blob, &box);
    SegmentedObject object;
    if (Measure(cloud, surface, mask, box + roi.tl(), options, &object) &&
        LitterSized(object, options)) {
      if (static_cast<int>(litter.size()) == options.split_max_parts) return;
      litter.push_back(std::move(object));
    }
  }
  for (auto& object : litter) result->objects.push_back(std::move(object));
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
  RequireOption(split_max_gap_m > 0, kStage, "split_max_gap_m", "> 0");
  RequireOption(split_max_gap_per_m >= 0, kStage, "split_max_gap_per_m", ">= 0");
  RequireOption(split_min_height_m >= 0, kStage, "split_min_height_m", ">= 0");
  RequireOption(split_max_base_m > split_min_height_m, kStage, "split_max_base_m",
                "> split_min_height_m");
  RequireOption(split_max_parts >= 1, kStage, "split_max_parts", ">= 1");
}

ObjectClusterResult ExtractObjects(const cv::Mat& colour_bgr, const OrganizedCloud& cloud,
                                   const GroundResult& ground,
                                   const TextureRefinementResult& refinement,
                                   const ObjectClusterOptions& options, int blob_step_px) {
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
    // Too large for litter: its parts that are apart in space may not be.
    const auto cut_into_parts = [&] {
      if (options.split) {
        ++result.split;
        AddLitterSizedParts(cloud, ground.surface, blob, roi, blob_step_px, options, &result);
      } else {
        ++result.rejected_size;
      }
    };
    cv::Mat mask = blob;
    if (options.refine) {
      cv::Mat core;
      cv::erode(blob, core, cv::Mat());
      if (CoreTooLarge(cloud, ground.surface, core, roi, options)) {
        cut_into_parts();
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
        object.size_m < options.min_size_m) {
      ++result.rejected_size;
      continue;
    }
    if (!LitterSized(object, options)) {
      cut_into_parts();
      continue;
    }
    result.objects.push_back(std::move(object));
  }
  return result;
}

}  // namespace littermap::detect
