// RGB-D alignment (thesis 2.4): the rejection and estimation steps on synthetic pairs with a known
// motion, and the whole aligner on a real TUM freiburg2 desk pair checked against OpenCV's own
// RGB-D odometry on the same images.

#include "reconstruct/rgbd_aligner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/rgbd.hpp>

#include "core/error.hpp"
#include "tum_pair.hpp"

namespace littermap::reconstruct {
namespace {

double AngleDeg(const Eigen::Isometry3d& T) {
  return Eigen::AngleAxisd(T.linear()).angle() * 180 / M_PI;
}

Eigen::Isometry3d Motion(double x, double y, double z, double yaw, double pitch, double roll) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  // Optical frame: yaw turns about y (down), pitch about x (right), roll about z (forward).
  T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()) *
                Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

struct SyntheticPairs {
  std::vector<Eigen::Vector3d> p, q;
  std::vector<bool> good;
};

// Points 1–5 m in front of the key frame; q = T⁻¹ p + noise; `outliers` of them matched to
// random other points.
SyntheticPairs MakePairs(const Eigen::Isometry3d& T_keyframe_frame, int count, double outliers,
                         std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> lateral(-2, 2), depth(1, 5), unit(0, 1);
  std::normal_distribution<double> noise(0, 0.005);
  SyntheticPairs pairs;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d p(lateral(random), 0.5 * lateral(random), depth(random));
    Eigen::Vector3d q = T_keyframe_frame.inverse() * p;
    const bool good = unit(random) >= outliers;
    if (!good) q = Eigen::Vector3d(lateral(random), 0.5 * lateral(random), depth(random));
    pairs.p.push_back(p);
    pairs.q.push_back(q + Eigen::Vector3d(noise(random), noise(random), noise(random)));
    pairs.good.push_back(good);
  }
  return pairs;
}

TEST(RgbdAligner, EveryRejectionRecoversAKnownMotionDespiteOutliers) {
  const Eigen::Isometry3d truth = Motion(0.12, 0.02, 0.3, 0.15, 0.1, 0.02);
  const SyntheticPairs pairs = MakePairs(truth, 300, 0.3, 7);
  for (const PairRejection rejection :
       {PairRejection::kCircularHistogram, PairRejection::kRansac, PairRejection::kNone}) {
    RgbdAlignerOptions options;
    options.rejection = rejection;
    const RgbdAlignment result = RgbdAligner(options).AlignPairs(pairs.p, pairs.q);
    ASSERT_TRUE(result.ok) << static_cast<int>(rejection);
    const Eigen::Isometry3d error = truth.inverse() * result.T_keyframe_frame;
    EXPECT_LT(error.translation().norm(), 0.01) << static_cast<int>(rejection);
    EXPECT_LT(AngleDeg(error), 0.3) << static_cast<int>(rejection);
    EXPECT_NEAR(result.icp_inlier_ratio, 0.7, 0.06) << static_cast<int>(rejection);
    EXPECT_LT(result.rms_m, 0.015);
  }
}

TEST(RgbdAligner, TheCircularHistogramKeepsTheGoodPairsUnderPitchAndForwardMotion) {
  // The thesis: invariant to pitch and to translation along z, so the good pairs share one bin;
  // the outliers spread over the others (those near a = 0 stay: it is a cheap first filter).
  const SyntheticPairs pairs = MakePairs(Motion(0.05, 0, 0.4, 0.0, 0.3, 0.0), 300, 0.4, 11);
  const std::vector<int> kept = RgbdAligner().RejectPairs(pairs.p, pairs.q);
  int good_kept = 0, good_all = 0;
  for (const int i : kept) good_kept += pairs.good[static_cast<std::size_t>(i)] ? 1 : 0;
  for (const bool good : pairs.good) good_all += good ? 1 : 0;
  const double precision_before = static_cast<double>(good_all) / 300.0;
  const double precision_after = static_cast<double>(good_kept) / static_cast<double>(kept.size());
  EXPECT_GE(static_cast<double>(good_kept) / good_all, 0.95);  // recall
  EXPECT_GE(precision_after, precision_before + 0.1) << precision_before;
}

TEST(RgbdAligner, RefusesWhenTooFewPairsAgree) {
  const SyntheticPairs pairs = MakePairs(Motion(0.1, 0, 0, 0.1, 0, 0), 40, 1.0, 3);  // all wrong
  const RgbdAlignment result = RgbdAligner().AlignPairs(pairs.p, pairs.q);
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.confidence, 0);
}

// OpenCV's photometric+geometric RGB-D odometry (Steinbruecker/Audras) from frame to key frame.
template <typename OdometryKind>
Eigen::Isometry3d OpenCvOdometry(const TumPair& pair, const char* kind) {
  const cv::Matx33f K(520.909f, 0, 325.141f, 0, 521.007f, 249.702f, 0, 0, 1);
  cv::Ptr<OdometryKind> odometry = OdometryKind::create();
  odometry->setCameraMatrix(cv::Mat(K));
  // The pair is 14 cm apart; OpenCV's default sanity limit (15 cm) sits right at it.
  odometry->setMaxTranslation(0.5);
  const auto prepare = [](const RgbdImage& image, cv::Mat& grey, cv::Mat& depth_m) {
    cv::cvtColor(image.colour_bgr, grey, cv::COLOR_BGR2GRAY);
    image.depth.convertTo(depth_m, CV_32F, image.depth_unit_m);
    depth_m.setTo(std::numeric_limits<float>::quiet_NaN(), image.depth == 0);
  };
  cv::Mat grey_kf, depth_kf, grey_f, depth_f, Rt;
  prepare(pair.first, grey_kf, depth_kf);
  prepare(pair.second, grey_f, depth_f);
  // Source: the frame; destination: the key frame; Rt maps source points into the destination.
  if (!odometry->compute(grey_f, depth_f, cv::Mat(), grey_kf, depth_kf, cv::Mat(), Rt)) {
    ADD_FAILURE() << "OpenCV " << kind << " did not converge";
  }
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) T.linear()(r, c) = Rt.at<double>(r, c);
    T.translation()(r) = Rt.at<double>(r, 3);
  }
  return T;
}

TEST(RgbdAligner, TumDeskPairAgreesWithOpenCvRgbdOdometry) {
  const TumPair pair = LoadTumPair();
  ASSERT_FALSE(pair.first.colour_bgr.empty()) << "tum_pair data set missing";
  const RgbdAlignment ours = RgbdAligner().Align(pair.first, pair.second, pair.camera);
  ASSERT_TRUE(ours.ok);
  const Eigen::Isometry3d reference = OpenCvOdometry<cv::rgbd::RgbdOdometry>(pair, "RgbdOdometry");
  const Eigen::Isometry3d difference = reference.inverse() * ours.T_keyframe_frame;
  EXPECT_LT(difference.translation().norm(), 0.02)
      << "ours " << ours.T_keyframe_frame.translation().transpose() << " OpenCV "
      << reference.translation().transpose();
  EXPECT_LT(AngleDeg(difference), 1.0);
  EXPECT_GE(ours.pairs_kept, 20);
  EXPECT_GE(ours.icp_inlier_ratio, 0.5);
  std::printf(
      "TUM desk pair: %d matches, %d with depth, %d kept, ICP inliers %d (%.2f), rms "
      "%.4f m; t = [%.4f %.4f %.4f] m, %.2f deg; OpenCV t = [%.4f %.4f %.4f] m, %.2f "
      "deg; difference %.4f m, %.2f deg\n",
      ours.matches, ours.pairs, ours.pairs_kept, ours.icp_inliers, ours.icp_inlier_ratio,
      ours.rms_m, ours.T_keyframe_frame.translation().x(), ours.T_keyframe_frame.translation().y(),
      ours.T_keyframe_frame.translation().z(), AngleDeg(ours.T_keyframe_frame),
      reference.translation().x(), reference.translation().y(), reference.translation().z(),
      AngleDeg(reference), difference.translation().norm(), AngleDeg(difference));
}

TEST(RgbdAligner, SiftAndAkazeAgreeWithOrbOnTheTumPair) {
  const TumPair pair = LoadTumPair();
  ASSERT_FALSE(pair.first.colour_bgr.empty()) << "tum_pair data set missing";
  const RgbdAlignment orb = RgbdAligner().Align(pair.first, pair.second, pair.camera);
  ASSERT_TRUE(orb.ok);
  for (const RgbdFeatures features : {RgbdFeatures::kSift, RgbdFeatures::kAkaze}) {
    RgbdAlignerOptions options;
    options.features = features;
    const RgbdAlignment other = RgbdAligner(options).Align(pair.first, pair.second, pair.camera);
    ASSERT_TRUE(other.ok) << static_cast<int>(features);
    const Eigen::Isometry3d difference = orb.T_keyframe_frame.inverse() * other.T_keyframe_frame;
    EXPECT_LT(difference.translation().norm(), 0.02) << static_cast<int>(features);
    EXPECT_LT(AngleDeg(difference), 1.0) << static_cast<int>(features);
  }
}

TEST(RgbdAligner, RefusesImagesOfTheWrongKind) {
  RgbdImage bad;
  bad.colour_bgr = cv::Mat(4, 4, CV_8UC1);
  bad.depth = cv::Mat(4, 4, CV_16UC1);
  EXPECT_THROW(RgbdAligner().Align(bad, bad, {}), UsageError);
  RgbdAlignerOptions options;
  options.histogram_bins = 1;
  EXPECT_THROW(RgbdAligner{options}, UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct
