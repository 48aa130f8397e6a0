#include "reconstruct/rgbd_aligner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

using Points = std::vector<Eigen::Vector3d>;

// Umeyama's least-squares rigid transform taking q[i] onto p[i] over `indices`.
Eigen::Isometry3d FitRigid(const Points& p, const Points& q, const std::vector<int>& indices) {
  Eigen::Matrix3Xd from(3, static_cast<Eigen::Index>(indices.size()));
  Eigen::Matrix3Xd to(3, static_cast<Eigen::Index>(indices.size()));
  for (std::size_t k = 0; k < indices.size(); ++k) {
    from.col(static_cast<Eigen::Index>(k)) = q[static_cast<std::size_t>(indices[k])];
    to.col(static_cast<Eigen::Index>(k)) = p[static_cast<std::size_t>(indices[k])];
  }
  Eigen::Isometry3d T;
  T.matrix() = Eigen::umeyama(from, to, false);
  return T;
}

std::vector<int> Within(const Points& p, const Points& q, const Eigen::Isometry3d& T,
                        double max_distance_m) {
  std::vector<int> inliers;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if ((p[i] - T * q[i]).norm() < max_distance_m) inliers.push_back(static_cast<int>(i));
  }
  return inliers;
}

// Standard deviation of p[indices] along its second principal axis.
double SecondSpread(const Points& p, const std::vector<int>& indices) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const int i : indices) mean += p[static_cast<std::size_t>(i)];
  mean /= static_cast<double>(indices.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const int i : indices) {
    const Eigen::Vector3d d = p[static_cast<std::size_t>(i)] - mean;
    covariance += d * d.transpose();
  }
  covariance /= static_cast<double>(indices.size());
  const Eigen::Vector3d eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvalues();  // increasing
  return std::sqrt(std::max(0.0, eigenvalues(1)));
}

cv::Ptr<cv::Feature2D> MakeDetector(const RgbdAlignerOptions& options) {
  switch (options.features) {
    case RgbdFeatures::kOrb:
      return cv::ORB::create(options.max_features, 1.2f, 8, 31, 0, 2, cv::ORB::HARRIS_SCORE, 31,
                             options.orb_fast_threshold);
    case RgbdFeatures::kSift:
      return cv::SIFT::create(options.max_features);
    case RgbdFeatures::kAkaze:
      return cv::AKAZE::create();
  }
  return cv::ORB::create(options.max_features);
}

// Metres at the keypoint's pixel, or 0.
double DepthAt(const RgbdImage& image, const cv::Point2f& pixel,
               const RgbdAlignerOptions& options) {
  const int u = static_cast<int>(std::lround(pixel.x)), v = static_cast<int>(std::lround(pixel.y));
  if (u < 0 || v < 0 || u >= image.depth.cols || v >= image.depth.rows) return 0;
  const double z = image.depth.at<std::uint16_t>(v, u) * image.depth_unit_m;
  return z >= options.min_depth_m && z <= options.max_depth_m ? z : 0;
}

void CheckImage(const RgbdImage& image) {
  if (image.colour_bgr.type() != CV_8UC3 || image.depth.type() != CV_16UC1 ||
      image.colour_bgr.size() != image.depth.size()) {
    throw UsageError("RGB-D alignment needs 8-bit BGR colour and 16-bit depth of the same size");
  }
  if (!(image.depth_unit_m > 0)) throw UsageError("RGB-D alignment: depth unit must be positive");
}

}  // namespace

RgbdCameraModel CameraModelFromInfo(const msg::CameraInfo& info) {
  RgbdCameraModel camera;
  camera.fx = info.k[0];
  camera.fy = info.k[4];
  camera.cx = info.k[2];
  camera.cy = info.k[5];
  if (!(camera.fx > 0) || !(camera.fy > 0)) {
    throw BadInputError("camera info " + info.header.frame_id + ": zero focal length in K");
  }
  if (std::any_of(info.d.begin(), info.d.end(), [](double d) { return d != 0; })) {
    camera.distortion = info.d;
  }
  return camera;
}

void RgbdAlignerOptions::Validate() const {
  if (max_features < 10) throw UsageError("RGB-D aligner max_features must be at least 10");
  if (orb_fast_threshold < 1) throw UsageError("RGB-D orb_fast_threshold must be at least 1");
  if (!(min_spread_m >= 0)) throw UsageError("RGB-D min_spread_m must be >= 0");
  if (!(ratio_test > 0 && ratio_test <= 1)) throw UsageError("RGB-D ratio_test must be in (0, 1]");
  if (!(min_depth_m >= 0 && max_depth_m > min_depth_m)) {
    throw UsageError("RGB-D depth range must satisfy 0 <= min_depth_m < max_depth_m");
  }
  if (histogram_bins < 2 || !(histogram_offset_m > 0)) {
    throw UsageError("RGB-D histogram needs at least 2 bins and a positive offset");
  }
  if (!(ransac_threshold_m > 0) || ransac_iterations < 1 || !(icp_max_distance_m > 0) ||
      !(icp_initial_distance_m > 0) || icp_max_iterations < 1 || min_pairs < 3) {
    throw UsageError("RGB-D RANSAC/ICP thresholds and counts must be positive (min_pairs >= 3)");
  }
}

RgbdAligner::RgbdAligner(const RgbdAlignerOptions& options) : options_(options) {
  options_.Validate();
}

std::vector<int> RgbdAligner::RejectPairs(const Points& p, const Points& q) const {
  std::vector<int> all(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) all[i] = static_cast<int>(i);
  switch (options_.rejection) {
    case PairRejection::kNone:
      return all;
    case PairRejection::kCircularHistogram: {
      const int bins = options_.histogram_bins;
      std::vector<std::vector<int>> votes(static_cast<std::size_t>(bins));
      for (std::size_t i = 0; i < p.size(); ++i) {
        // The thesis's a = atan2(q_y − p_y, c − p_x + q_x) is in the body frame (x forward,
        // y left, z up): body x = optical z, body y = −optical x.
        const double a =
            std::atan2(p[i].x() - q[i].x(), options_.histogram_offset_m - p[i].z() + q[i].z());
        // Bins centred on multiples of the bin width, bin 0 on a = 0 where the pairs of a small
        // motion fall (edges there would split them by the sign of a tiny q_y − p_y).
        int bin = static_cast<int>(std::floor(a / (2 * std::numbers::pi / bins) + 0.5)) % bins;
        if (bin < 0) bin += bins;
        votes[static_cast<std::size_t>(bin)].push_back(static_cast<int>(i));
      }
      return *std::max_element(votes.begin(), votes.end(),
                               [](const auto& a, const auto& b) { return a.size() < b.size(); });
    }
    case PairRejection::kRansac: {
      if (p.size() < 3) return {};
      std::mt19937_64 random(options_.ransac_seed);
      std::uniform_int_distribution<int> pick(0, static_cast<int>(p.size()) - 1);
      std::vector<int> best;
      for (int iteration = 0; iteration < options_.ransac_iterations; ++iteration) {
        std::vector<int> sample = {pick(random), pick(random), pick(random)};
        if (sample[0] == sample[1] || sample[1] == sample[2] || sample[0] == sample[2]) continue;
        const auto inliers = Within(p, q, FitRigid(p, q, sample), options_.ransac_threshold_m);
        if (inliers.size() > best.size()) best = inliers;
      }
      return best;
    }
  }
  return all;
}

RgbdAlignment RgbdAligner::AlignPairs(const Points& p, const Points& q) const {
  RgbdAlignment result;
  result.pairs = static_cast<int>(p.size());
  const std::vector<int> kept = RejectPairs(p, q);
  result.pairs_kept = static_cast<int>(kept.size());
  if (result.pairs_kept < options_.min_pairs) return result;

  // ICP over every matched pair from the estimate of the kept ones: the pairs within a distance
  // threshold refit the transform; the threshold halves from icp_initial_distance_m (the kept
  // pairs may still hold outliers that bias the first estimate) down to icp_max_distance_m,
  // where it stays until the inliers no longer change.
  Eigen::Isometry3d T = FitRigid(p, q, kept);
  std::vector<int> inliers;
  double threshold_m = std::max(options_.icp_initial_distance_m, options_.icp_max_distance_m);
  for (int iteration = 1; iteration <= options_.icp_max_iterations; ++iteration) {
    result.icp_iterations = iteration;
    std::vector<int> now = Within(p, q, T, threshold_m);
    if (static_cast<int>(now.size()) < options_.min_pairs) break;
    T = FitRigid(p, q, now);
    const bool final_threshold = threshold_m <= options_.icp_max_distance_m;
    const bool settled = final_threshold && now == inliers;
    inliers = std::move(now);
    if (settled) break;
    threshold_m = std::max(options_.icp_max_distance_m, threshold_m / 2);
  }
  inliers = Within(p, q, T, options_.icp_max_distance_m);
  result.icp_inliers = static_cast<int>(inliers.size());
  if (result.icp_inliers < options_.min_pairs) return result;
  double sum_sq = 0;
  for (const int i : inliers) {
    sum_sq += (p[static_cast<std::size_t>(i)] - T * q[static_cast<std::size_t>(i)]).squaredNorm();
  }
  result.rms_m = std::sqrt(sum_sq / result.icp_inliers);
  result.spread_m = SecondSpread(p, inliers);
  if (result.spread_m < options_.min_spread_m) return result;
  result.icp_inlier_ratio = static_cast<double>(result.icp_inliers) / result.pairs;
  result.confidence = result.icp_inlier_ratio * std::min(1.0, result.icp_inliers / 30.0);
  result.T_keyframe_frame = T;
  result.ok = true;
  return result;
}

RgbdAlignment RgbdAligner::Align(const RgbdImage& keyframe, const RgbdImage& frame,
                                 const RgbdCameraModel& camera) const {
  return Align(Extract(keyframe, camera), Extract(frame, camera));
}

RgbdAlignment RgbdAligner::Align(const RgbdKeyPoints& keyframe, const RgbdKeyPoints& frame) const {
  const RgbdPairs pairs = Match(keyframe, frame);
  RgbdAlignment result = AlignPairs(pairs.p, pairs.q);
  result.matches = pairs.matches;
  return result;
}

RgbdKeyPoints RgbdAligner::Extract(const RgbdImage& image, const RgbdCameraModel& camera) const {
  CheckImage(image);
  const cv::Ptr<cv::Feature2D> detector = MakeDetector(options_);
  std::vector<cv::KeyPoint> keys;
  RgbdKeyPoints features;
  cv::Mat grey;
  cv::cvtColor(image.colour_bgr, grey, cv::COLOR_BGR2GRAY);
  detector->detectAndCompute(grey, cv::noArray(), keys, features.descriptors);
  if (keys.empty()) return features;
  std::vector<cv::Point2f> pixels;
  pixels.reserve(keys.size());
  for (const cv::KeyPoint& key : keys) pixels.push_back(key.pt);
  const cv::Matx33d K(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  std::vector<cv::Point2f> rays;
  cv::undistortPoints(pixels, rays, K, camera.distortion);
  features.points.reserve(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const double z = DepthAt(image, pixels[i], options_);
    features.points.emplace_back(rays[i].x * z, rays[i].y * z, z);
  }
  return features;
}

RgbdPairs RgbdAligner::Match(const RgbdKeyPoints& keyframe, const RgbdKeyPoints& frame) const {
  RgbdPairs pairs;
  if (keyframe.descriptors.empty() || frame.descriptors.empty()) return pairs;
  const int norm = options_.features == RgbdFeatures::kSift ? cv::NORM_L2 : cv::NORM_HAMMING;
  cv::BFMatcher matcher(norm);
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(frame.descriptors, keyframe.descriptors, knn, 2);
  for (const auto& candidates : knn) {
    if (candidates.size() < 2 ||
        candidates[0].distance >= options_.ratio_test * candidates[1].distance) {
      continue;
    }
    ++pairs.matches;
    const Eigen::Vector3d& p = keyframe.points[static_cast<std::size_t>(candidates[0].trainIdx)];
    const Eigen::Vector3d& q = frame.points[static_cast<std::size_t>(candidates[0].queryIdx)];
    if (p.z() == 0 || q.z() == 0) continue;
    pairs.p.push_back(p);
    pairs.q.push_back(q);
  }
  return pairs;
}

}  // namespace littermap::reconstruct
