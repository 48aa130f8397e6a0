#pragma once
// Aligns an RGB-D frame to an RGB-D key frame (thesis 2.4): 2D features matched between the
// colour images (ORB by default; SIFT or AKAZE) with a ratio test, matches without valid depth
// dropped, the rest back-projected through the camera model (distortion undone) to 3D pairs
// (p in the key frame, q in the frame); bad pairs rejected by the thesis's circular angle
// histogram (Alg. 2.3.2: a = atan2(q_y − p_y, c − p_x + q_x) in the body frame — x forward,
// y left, z up, which makes it blind to pitch and height — voted into M bins, the fullest bin
// kept; bin 0 is centred on a = 0) or by RANSAC, or not at all; a rigid estimate from the kept
// pairs by SVD (Umeyama, no scale); then ICP over all matched pairs with a shrinking distance
// threshold, which takes back the good pairs the strict rejection dropped and leaves out the bad
// ones.
//
// Frames: optical (z forward, x right, y down), metres. The result's T_keyframe_frame maps
// points of the frame into the key frame: p ≈ T_keyframe_frame · q.

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "bag/ros_messages.hpp"

namespace littermap::reconstruct {

enum class RgbdFeatures { kOrb, kSift, kAkaze };
enum class PairRejection { kCircularHistogram, kRansac, kNone };

// The colour camera of a registered RGB-D sensor.
struct RgbdCameraModel {
  double fx = 525, fy = 525, cx = 319.5, cy = 239.5;
  std::vector<double> distortion;  // OpenCV order (k1 k2 p1 p2 [k3 ...]); empty: none
};
// From a CameraInfo's K and D ("plumb_bob" or "rational_polynomial"). Throws BadInputError for
// a zero focal length.
RgbdCameraModel CameraModelFromInfo(const msg::CameraInfo& info);

struct RgbdImage {
  cv::Mat colour_bgr;           // CV_8UC3
  cv::Mat depth;                // CV_16UC1 registered to colour; 0 = no reading
  double depth_unit_m = 0.001;  // metres per depth unit (1 mm in a run bag; TUM: 1/5000)
};

struct RgbdAlignerOptions {
  RgbdFeatures features = RgbdFeatures::kOrb;
  int max_features = 1000;  // matching is quadratic in it: 1000 keeps an alignment near 20 ms
  // FAST corner contrast: OpenCV's 20 finds little on grass, and a camera pitched down by a root
  // sees grass alone; 4 keeps enough corners there for routine 3 to carry the pose.
  int orb_fast_threshold = 4;
  double ratio_test = 0.8;  // best match distance below this × the second best
  double min_depth_m = 0.2;
  double max_depth_m = 8.0;
  PairRejection rejection = PairRejection::kCircularHistogram;
  double histogram_offset_m = 3.0;  // the thesis's c
  int histogram_bins = 15;          // the thesis's M
  double ransac_threshold_m = 0.05;
  int ransac_iterations = 300;
  std::uint64_t ransac_seed = 1;
  double icp_initial_distance_m = 0.4;  // first ICP threshold, halved each iteration down to
  double icp_max_distance_m = 0.05;     // this: a pair farther apart after alignment is an outlier
  int icp_max_iterations = 30;
  int min_pairs = 6;  // fewer kept pairs or ICP inliers: no alignment
  // The ICP inliers must spread at least this far (standard deviation along their second
  // principal axis) in the key frame: points along one trunk or edge leave a rotation free.
  double min_spread_m = 0.05;

  void Validate() const;
};

struct RgbdAlignment {
  bool ok = false;
  Eigen::Isometry3d T_keyframe_frame = Eigen::Isometry3d::Identity();
  int matches = 0;              // after the ratio test
  int pairs = 0;                // of which with valid depth in both images
  int pairs_kept = 0;           // of which kept by the rejection
  int icp_inliers = 0;          // pairs within icp_max_distance_m after ICP
  double icp_inlier_ratio = 0;  // icp_inliers / pairs
  double rms_m = 0;             // over the ICP inliers
  int icp_iterations = 0;
  double spread_m = 0;  // of the ICP inliers, see RgbdAlignerOptions::min_spread_m
  // icp_inlier_ratio · min(1, icp_inliers / 30): high only with many consistent pairs.
  double confidence = 0;
};

// The features of one RGB-D image, extracted once: a key frame is matched against many frames.
struct RgbdKeyPoints {
  cv::Mat descriptors;                  // one row per key point
  std::vector<Eigen::Vector3d> points;  // back-projected, optical frame; z = 0: no valid depth
};

// 3D feature pairs of two RGB-D images: p[i] in the key frame matches q[i] in the frame.
struct RgbdPairs {
  std::vector<Eigen::Vector3d> p, q;
  int matches = 0;  // after the ratio test, with or without depth
};

class RgbdAligner {
 public:
  explicit RgbdAligner(const RgbdAlignerOptions& options = {});

  // Extract from both, Match, then AlignPairs. Throws UsageError for images of the wrong type
  // or size.
  RgbdAlignment Align(const RgbdImage& keyframe, const RgbdImage& frame,
                      const RgbdCameraModel& camera) const;
  RgbdAlignment Align(const RgbdKeyPoints& keyframe, const RgbdKeyPoints& frame) const;

  // Feature detection, depth lookup and back-projection (distortion undone). Throws UsageError
  // for an image of the wrong type or size.
  RgbdKeyPoints Extract(const RgbdImage& image, const RgbdCameraModel& camera) const;
  // Ratio-test matching; pairs whose key points both have depth.
  RgbdPairs Match(const RgbdKeyPoints& keyframe, const RgbdKeyPoints& frame) const;

  // The rejection and estimation steps on given 3D pairs (p in the key frame, q in the frame),
  // for tests and ablations; the alignment's feature counts are left 0.
  RgbdAlignment AlignPairs(const std::vector<Eigen::Vector3d>& p,
                           const std::vector<Eigen::Vector3d>& q) const;

  // Indices of the pairs the configured rejection keeps.
  std::vector<int> RejectPairs(const std::vector<Eigen::Vector3d>& p,
                               const std::vector<Eigen::Vector3d>& q) const;

 private:
  RgbdAlignerOptions options_;
};

}  // namespace littermap::reconstruct
