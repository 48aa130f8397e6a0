// Colour GMM (thesis 3.2 "GMM energy"): a single Gaussian against its closed form, two
// well-separated colour clusters, the energy ordering, the batch and single evaluations agreeing,
// determinism, degenerate data and model files.

#include "detect/colour_gmm.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

const cv::Vec3f kRed(40, 30, 200);    // BGR
const cv::Vec3f kGreen(50, 170, 60);  // BGR

// n colours around `centre`, independent Gaussian noise of sigma grey levels per channel.
cv::Mat Cluster(const cv::Vec3f& centre, int n, double sigma, std::uint64_t seed) {
  cv::Mat samples(n, 3, CV_32F);
  cv::RNG rng(seed);
  rng.fill(samples, cv::RNG::NORMAL, 0, sigma);
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) samples.at<float>(i, c) += centre[c];
  }
  return samples;
}

cv::Mat RedAndGreen() {
  cv::Mat samples = Cluster(kRed, 1500, 6, 1);
  samples.push_back(Cluster(kGreen, 1500, 6, 2));
  return samples;
}

cv::Mat Patch(const cv::Vec3f& bgr, int size = 20) {
  return cv::Mat(size, size, CV_8UC3, cv::Scalar(bgr[0], bgr[1], bgr[2]));
}

TEST(ColourGmm, SingleComponentIsTheSampleGaussian) {
  ColourGmmOptions options;
  options.components = 1;
  ColourGmm gmm(options);
  const ColourGmmTrainResult result = gmm.Train(Cluster(kGreen, 1000, 5, 3));
  EXPECT_EQ(result.samples_used, 1000u);
  EXPECT_EQ(result.floored_eigenvalues, 0);
  const cv::Vec3d mean = gmm.mean(0);
  const cv::Matx33d cov = gmm.covariance(0);
  EXPECT_NEAR(cv::norm(mean - cv::Vec3d(kGreen)), 0, 1.0) << "5 / sqrt(1000) sigma: 0.16";
  EXPECT_NEAR(cov(1, 1), 25, 5) << "sample variance of 1000 draws: 25 +- 1.1";
  // log N(x) = -1.5 log 2 pi - 0.5 log det C - 0.5 d^T C^-1 d, evaluated in double here; the
  // model evaluates in float: 1e-4.
  const cv::Vec3f x(60, 160, 70);
  const cv::Vec3d d = cv::Vec3d(x) - mean;
  const double expected = -1.5 * std::log(2 * std::numbers::pi) -
                          0.5 * std::log(cv::determinant(cov)) - 0.5 * d.dot(cov.inv() * d);
  EXPECT_NEAR(gmm.LogLikelihood(x), expected, 1e-4);
  EXPECT_NEAR(gmm.weight(0), 1.0, 1e-12);
}

TEST(ColourGmm, TwoClustersAreLikelyNearTheirCentresOnly) {
  for (GmmCovariance covariance : {GmmCovariance::kFull, GmmCovariance::kDiagonal}) {
    ColourGmmOptions options;
    options.covariance = covariance;
    ColourGmm gmm(options);
    gmm.Train(RedAndGreen());
    const double red = gmm.LogLikelihood(kRed), green = gmm.LogLikelihood(kGreen);
    const double between = gmm.LogLikelihood(0.5f * (kRed + kGreen));
    const double blue = gmm.LogLikelihood(cv::Vec3f(200, 60, 40));
    // Each cluster holds half the weight: log(0.5) - 1.5 log(2 pi 36) = -9.2 at its centre.
    EXPECT_GT(red, -10.5);
    EXPECT_GT(green, -10.5);
    EXPECT_GT(red, between + 20);
    EXPECT_GT(green, blue + 20);
  }
}

TEST(ColourGmm, EnergyIsLowForColoursOfTheModel) {
  ColourGmm gmm;
  gmm.Train(RedAndGreen());
  const double red = gmm.Energy(Patch(kRed));
  const double orange = gmm.Energy(Patch(cv::Vec3f(40, 120, 220)));
  const double blue = gmm.Energy(Patch(cv::Vec3f(200, 60, 40)));
  EXPECT_LT(red, orange);
  EXPECT_LT(orange, blue);
  // Mean, not sum: a larger patch of the same colour has the same energy.
  EXPECT_NEAR(gmm.Energy(Patch(kRed, 40)), red, 1e-9);
  // Half red, half blue under a mask over the red half only.
  cv::Mat image = Patch(kRed);
  image(cv::Rect(10, 0, 10, 20)).setTo(cv::Scalar(200, 60, 40));
  cv::Mat mask = cv::Mat::zeros(20, 20, CV_8U);
  mask(cv::Rect(0, 0, 10, 20)).setTo(255);
  EXPECT_NEAR(gmm.Energy(image, mask), red, 1e-9);
  EXPECT_THROW(gmm.Energy(image, cv::Mat::zeros(20, 20, CV_8U)), UsageError);
}

TEST(ColourGmm, BatchEvaluationEqualsSingleColours) {
  ColourGmm gmm;
  gmm.Train(RedAndGreen());
  cv::Mat image(8, 8, CV_8UC3);
  cv::randu(image, 0, 256);
  cv::Mat mask = cv::Mat::zeros(8, 8, CV_8U);
  mask.at<std::uint8_t>(1, 1) = 1;
  mask.at<std::uint8_t>(5, 2) = 255;
  const cv::Mat all = gmm.LogLikelihoodImage(image);
  const cv::Mat masked = gmm.LogLikelihoodImage(image, mask);
  ASSERT_EQ(all.type(), CV_32F);
  for (int r = 0; r < 8; ++r) {
    for (int c = 0; c < 8; ++c) {
      const double single = gmm.LogLikelihood(image.at<cv::Vec3b>(r, c));
      EXPECT_EQ(all.at<float>(r, c), static_cast<float>(single));
      EXPECT_EQ(masked.at<float>(r, c), mask.at<std::uint8_t>(r, c) ? all.at<float>(r, c) : 0.0f);
    }
  }
  const cv::Mat rows = gmm.LogLikelihoods(image);
  ASSERT_EQ(rows.rows, 64);
  EXPECT_EQ(rows.at<float>(13), all.at<float>(1, 5));
}

TEST(ColourGmm, TrainingIsDeterministicAndSubsamples) {
  cv::Mat samples = RedAndGreen();
  samples.push_back(Cluster(cv::Vec3f(200, 200, 200), 7000, 10, 4));
  ColourGmm a, b;
  const ColourGmmTrainResult result = a.Train(samples);
  b.Train(samples);
  EXPECT_EQ(result.samples_given, 10000u);
  EXPECT_EQ(result.samples_used, 2000u);
  for (int j = 0; j < a.components(); ++j) {
    EXPECT_EQ(a.weight(j), b.weight(j));
    EXPECT_EQ(a.mean(j), b.mean(j));
  }
  EXPECT_EQ(a.LogLikelihood(kRed), b.LogLikelihood(kRed));
  EXPECT_GT(a.LogLikelihood(cv::Vec3f(200, 200, 200)), a.LogLikelihood(cv::Vec3f(0, 0, 255)));
}

TEST(ColourGmm, FlatColourStaysFiniteThanksToTheVarianceFloor) {
  ColourGmm gmm;  // 5 components on 2 distinct colours
  cv::Mat samples(100, 1, CV_8UC3, cv::Scalar(10, 200, 30));
  samples(cv::Rect(0, 0, 1, 30)).setTo(cv::Scalar(90, 90, 90));
  const ColourGmmTrainResult result = gmm.Train(samples);
  EXPECT_GT(result.floored_eigenvalues, 0);
  EXPECT_TRUE(std::isfinite(result.mean_log_likelihood));
  // At most the peak of a unit-variance Gaussian: -1.5 log(2 pi) = -2.76.
  EXPECT_LE(gmm.LogLikelihood(cv::Vec3b(10, 200, 30)), -2.75);
  EXPECT_TRUE(std::isfinite(gmm.LogLikelihood(cv::Vec3b(255, 0, 255))));
}

TEST(ColourGmm, RejectsMisuse) {
  ColourGmm gmm;
  EXPECT_THROW(gmm.LogLikelihood(kRed), UsageError) << "untrained";
  EXPECT_THROW(gmm.Train(Cluster(kRed, 4, 5, 1)), UsageError) << "fewer samples than components";
  EXPECT_THROW(gmm.Train(cv::Mat(10, 2, CV_32F)), UsageError) << "not N x 3";
  ColourGmmOptions options;
  options.components = 0;
  EXPECT_THROW(ColourGmm{options}, UsageError);
  gmm.Train(RedAndGreen());
  EXPECT_THROW(gmm.LogLikelihoodImage(cv::Mat(4, 4, CV_8UC1)), UsageError);
  EXPECT_THROW(gmm.LogLikelihoodImage(Patch(kRed), cv::Mat::zeros(3, 3, CV_8U)), UsageError);
}

class ColourGmmFile : public testing::TestWithParam<const char*> {};

TEST_P(ColourGmmFile, RoundTripsExactly) {
  ColourGmmOptions options;
  options.covariance = GmmCovariance::kFull;  // the default is diagonal: cover both
  ColourGmm gmm(options);
  gmm.Train(RedAndGreen());
  cv::FileStorage out(GetParam(), cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  gmm.Write(out, "ground_colour");
  cv::FileStorage in(out.releaseAndGetString(), cv::FileStorage::READ | cv::FileStorage::MEMORY);
  const ColourGmm read = ColourGmm::Read(in["ground_colour"]);
  ASSERT_EQ(read.components(), gmm.components());
  EXPECT_EQ(read.options().covariance, GmmCovariance::kFull);
  for (int j = 0; j < gmm.components(); ++j) {
    EXPECT_EQ(read.weight(j), gmm.weight(j));
    EXPECT_EQ(read.mean(j), gmm.mean(j));
    EXPECT_EQ(read.covariance(j), gmm.covariance(j));
  }
  for (const cv::Vec3f& c : {kRed, kGreen, cv::Vec3f(0, 0, 0), cv::Vec3f(255, 128, 7)}) {
    EXPECT_EQ(read.LogLikelihood(c), gmm.LogLikelihood(c));
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, ColourGmmFile, testing::Values(".yml", ".json", ".xml"));

TEST(ColourGmmFile, MalformedModelNamesTheField) {
  const std::string yaml =
      "%YAML:1.0\n---\ng:\n  colour_space: bgr\n  covariance: full\n"
      "  weights: !!opencv-matrix\n    rows: 2\n    cols: 1\n    dt: d\n    data: [0.5, 0.5]\n"
      "  means: !!opencv-matrix\n    rows: 2\n    cols: 2\n    dt: d\n    data: [1, 2, 3, 4]\n";
  cv::FileStorage in(yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  try {
    ColourGmm::Read(in["g"]);
    FAIL() << "expected BadInputError";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("means"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ColourGmm::Read(in["missing"]), BadInputError);
}

}  // namespace
}  // namespace littermap::detect
