#include "detect/texture_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc/detail/gcgraph.hpp>

#include "core/error.hpp"
#include "detect/colour_gmm.hpp"
#include "detect/colour_table.hpp"
#include "detect/every_nth.hpp"

namespace littermap::detect {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
const double kLogUniform = -3.0 * std::log(256.0);  // uniform density over the BGR cube

// The |height| a point at depth z may have and still be ground: two sigma of the depth noise.
double GroundBand(const TextureRefinementOptions& options, float z) {
  return std::max(options.min_ground_band_m, 2.0 * options.depth_noise_per_m2 * z * z);
}

cv::Rect GroundRegion(const GroundResult& ground, int width, int height) {
  int u0 = width, v0 = height, u1 = -1, v1 = -1;
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      if (!ground.is_ground[static_cast<std::size_t>(v * width + u)]) continue;
      u0 = std::min(u0, u);
      u1 = std::max(u1, u);
      v0 = std::min(v0, v);
      v1 = std::max(v1, v);
    }
  }
  return u1 < 0 ? cv::Rect() : cv::Rect(u0, v0, u1 - u0 + 1, v1 - v0 + 1);
}

// Geometry's verdict per pixel (thesis: certain object, certain background, uncertain).
cv::Mat GeometricLabels(const OrganizedCloud& cloud, const GroundResult& ground,
                        const cv::Rect& region, int ground_top,
                        const TextureRefinementOptions& options, std::vector<float>* heights) {
  cv::Mat labels(cloud.height, cloud.width, CV_8U, cv::Scalar(kOutside));
  heights->assign(cloud.points_m.size(), kNaN);
  for (int v = region.y; v < region.br().y; ++v) {
    auto* row = labels.ptr<std::uint8_t>(v);
    for (int u = region.x; u < region.br().x; ++u) {
      const int i = cloud.Index(u, v);
      const auto index = static_cast<std::size_t>(i);
      if (!cloud.HasPoint(i)) {
        // Above the ground's box (the margin) only points are examined: the rest is far away.
        row[u] = v >= ground_top ? kUncertain : kOutside;
        continue;
      }
      const float z = cloud.depth_m[index];
      const double band = GroundBand(options, z);
      const double h = ground.surface.HeightAbove(cloud.points_m[index]);
      (*heights)[index] = static_cast<float>(h);
      if (ground.is_ground[index] && std::abs(h) <= band) {
        row[u] = kGround;
      } else if (h < -(band + options.max_depth_below_ground_m)) {
        row[u] = kOutside;
      } else if (!ground.is_ground[index] && h > band + options.min_object_height_m) {
        row[u] = kNonGround;
      } else {
        row[u] = kUncertain;
      }
    }
  }
  return labels;
}

// The colour model of the pixels labelled `label`. With `uniform_share` > 0 the model is mixed
// with a uniform density: the non-ground model must also accept litter colours that no certain
// non-ground pixel of this frame showed.
ColourTable LearnTable(const cv::Mat& colour_bgr, const cv::Mat& labels, std::uint8_t label,
                       const TextureRefinementOptions& options, double uniform_share,
                       bool* learnt) {
  const int count = cv::countNonZero(labels == label);
  *learnt = count >= options.min_nonground_training_pixels;
  if (!*learnt) return ColourTable(static_cast<float>(kLogUniform));
  const int step = std::max(1, count / options.max_training_pixels);
  std::vector<float> colours;
  colours.reserve(static_cast<std::size_t>(3 * (count / step + 1)));
  EveryNth thinned(static_cast<std::size_t>(step));
  for (int v = 0; v < labels.rows; ++v) {
    const auto* row = labels.ptr<std::uint8_t>(v);
    const auto* pixels = colour_bgr.ptr<cv::Vec3b>(v);
    for (int u = 0; u < labels.cols; ++u) {
      if (row[u] != label || !thinned.Take()) continue;
      colours.insert(colours.end(),
                     {float(pixels[u][0]), float(pixels[u][1]), float(pixels[u][2])});
    }
  }
  const cv::Mat samples(static_cast<int>(colours.size() / 3), 3, CV_32F, colours.data());
  ColourGmmOptions gmm_options;
  gmm_options.components = std::min(options.gmm_components, samples.rows / 10);
  gmm_options.max_samples = options.max_training_pixels;
  // Thesis 3.1 step 4: K-means initialises the mixture, which is trained and retrained once.
  gmm_options.max_em_iterations = 2;
  ColourGmm gmm(gmm_options);
  gmm.Train(samples);
  cv::Mat table = gmm.LogLikelihoods(ColourTable::CellCentres());
  if (uniform_share > 0) {
    for (float& value : cv::Mat_<float>(table)) {
      value = static_cast<float>(std::log((1 - uniform_share) * std::exp(double(value)) +
                                          uniform_share * std::exp(kLogUniform)));
    }
  }
  return ColourTable(table);
}

double Beta(const cv::Mat& colour_bgr, const cv::Mat& labels) {
  double sum = 0;
  std::size_t pairs = 0;
  for (int v = 0; v + 1 < labels.rows; ++v) {
    for (int u = 0; u + 1 < labels.cols; ++u) {
      if (labels.at<std::uint8_t>(v, u) != kUncertain) continue;
      const cv::Vec3d c = colour_bgr.at<cv::Vec3b>(v, u);
      const cv::Vec3d right = colour_bgr.at<cv::Vec3b>(v, u + 1);
      const cv::Vec3d down = colour_bgr.at<cv::Vec3b>(v + 1, u);
      sum += (c - right).dot(c - right) + (c - down).dot(c - down);
      pairs += 2;
    }
  }
  return sum > 0 ? static_cast<double>(pairs) / (2.0 * sum) : 0.0;
}

struct CutModels {
  const ColourTable& ground;
  const ColourTable& non_ground;
  double beta;
};

std::size_t GraphCut(const cv::Mat& colour_bgr, const cv::Mat& labels,
                     const std::vector<float>& heights, const OrganizedCloud& cloud,
                     const CutModels& models, const TextureRefinementOptions& options,
                     cv::Mat* non_ground) {
  // The graph holds the uncertain pixels only: a few per cent of the frame.
  std::vector<int> pixel_of_node;
  std::vector<int> node(labels.total(), -1);
  const std::size_t pixels = labels.total();
  for (std::size_t i = 0; i < pixels; ++i) {
    if (labels.data[i] != kUncertain) continue;
    node[i] = static_cast<int>(pixel_of_node.size());
    pixel_of_node.push_back(static_cast<int>(i));
  }
  const int nodes = static_cast<int>(pixel_of_node.size());
  if (nodes == 0) return 0;
  // Single precision: the weights are log-likelihoods and smoothness terms of at most a few tens,
  // and the max-flow moves half the memory. Up to two edges (a pair of arcs each) per node.
  cv::detail::GCGraph<float> graph(static_cast<unsigned>(nodes), static_cast<unsigned>(4 * nodes));
  const auto* colour = colour_bgr.ptr<cv::Vec3b>(0);
  const int width = labels.cols, height = labels.rows;
  auto smoothness = [&](int a, int b) {
    const cv::Vec3d d = cv::Vec3d(colour[a]) - cv::Vec3d(colour[b]);
    return options.smoothness_weight * std::exp(-models.beta * d.dot(d));
  };
  for (int n = 0; n < nodes; ++n) graph.addVtx();
  for (int n = 0; n < nodes; ++n) {
    const int i = pixel_of_node[static_cast<std::size_t>(n)];
    const auto index = static_cast<std::size_t>(i);
    double to_ground = -models.ground(colour[i]);  // cost of calling the pixel ground
    double to_object = -models.non_ground(colour[i]);
    if (!std::isnan(heights[index])) {
      const double band = GroundBand(options, cloud.depth_m[index]);
      to_ground += options.height_weight * std::clamp(heights[index] / band - 1.0, 0.0, 3.0);
    }
    // 4-neighbours: an edge to an uncertain one (added once, from its left or upper end), a
    // terminal weight for a decided one.
    const int u = i % width, v = i / width;
    const int neighbours[4] = {u + 1 < width ? i + 1 : -1, v + 1 < height ? i + width : -1,
                               u > 0 ? i - 1 : -1, v > 0 ? i - width : -1};
    for (int k = 0; k < 4; ++k) {
      const int j = neighbours[k];
      if (j < 0) continue;
      const int m = node[static_cast<std::size_t>(j)];
      if (m >= 0) {
        if (k < 2) {
          const auto w = static_cast<float>(smoothness(i, j));
          graph.addEdges(n, m, w, w);
        }
        continue;
      }
      const std::uint8_t other = labels.data[j];
      if (other == kGround) to_object += smoothness(i, j);
      if (other == kNonGround) to_ground += smoothness(i, j);
    }
    graph.addTermWeights(n, static_cast<float>(to_ground), static_cast<float>(to_object));
  }
  graph.maxFlow();
  std::size_t cut = 0;
  for (int n = 0; n < nodes; ++n) {
    if (!graph.inSourceSegment(n)) continue;
    non_ground->data[pixel_of_node[static_cast<std::size_t>(n)]] = 255;
    ++cut;
  }
  return cut;
}

}  // namespace

void TextureRefinementOptions::Validate() const {
  constexpr const char* kStage = "segmentation";
  RequireOption(gmm_components >= 1 && gmm_components <= 20, kStage, "gmm_components",
                "from 1 to 20");
  RequireOption(max_training_pixels >= 50, kStage, "max_training_pixels", ">= 50");
  RequireOption(depth_noise_per_m2 >= 0, kStage, "depth_noise_per_m2", ">= 0");
  RequireOption(region_margin_px >= 0, kStage, "region_margin_px", ">= 0");
  RequireOption(min_ground_band_m > 0, kStage, "min_ground_band_m", "> 0");
  RequireOption(min_object_height_m >= 0, kStage, "min_object_height_m", ">= 0");
  RequireOption(max_depth_below_ground_m >= 0, kStage, "max_depth_below_ground_m", ">= 0");
  RequireOption(smoothness_weight >= 0, kStage, "smoothness_weight", ">= 0");
  RequireOption(height_weight >= 0, kStage, "height_weight", ">= 0");
  RequireOption(min_nonground_training_pixels >= 1, kStage, "min_nonground_training_pixels",
                ">= 1");
}

TextureRefinementResult RefineGroundByTexture(const cv::Mat& colour_bgr,
                                              const OrganizedCloud& cloud,
                                              const GroundResult& ground,
                                              const TextureRefinementOptions& options) {
  TextureRefinementResult result;
  result.non_ground = cv::Mat::zeros(cloud.height, cloud.width, CV_8U);
  const cv::Rect ground_box = GroundRegion(ground, cloud.width, cloud.height);
  const int ground_top = ground_box.y;
  const int region_top = std::max(0, ground_box.y - options.region_margin_px);
  result.region = ground_box.empty() ? ground_box
                                     : cv::Rect(ground_box.x, region_top, ground_box.width,
                                                ground_box.br().y - region_top);
  std::vector<float> heights;
  result.labels = GeometricLabels(cloud, ground, result.region, ground_top, options, &heights);
  if (result.region.empty()) return result;

  bool ground_learnt = false;
  const ColourTable ground_model =
      LearnTable(colour_bgr, result.labels, kGround, options, 0.0, &ground_learnt);
  if (!ground_learnt) return result;
  const ColourTable non_ground_model = LearnTable(colour_bgr, result.labels, kNonGround, options,
                                                  0.5, &result.non_ground_model_learnt);
  // Ground-component pixels coloured like the non-ground become uncertain.
  const auto* colour = colour_bgr.ptr<cv::Vec3b>(0);
  const std::size_t pixels = result.labels.total();
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t& label = result.labels.data[i];
    if (label == kNonGround) result.non_ground.data[i] = 255;
    if (label == kGround &&
        non_ground_model(colour[i]) - ground_model(colour[i]) > options.colour_anomaly_log_ratio) {
      label = kUncertain;
    }
    if (label == kUncertain) ++result.uncertain;
  }
  const CutModels models{ground_model, non_ground_model, Beta(colour_bgr, result.labels)};
  result.cut_to_non_ground =
      GraphCut(colour_bgr, result.labels, heights, cloud, models, options, &result.non_ground);
  return result;
}

}  // namespace littermap::detect
