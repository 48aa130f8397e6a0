// Earth Mover's Distance between colour histograms (thesis 3.2): a metric over the nine bins
// with known values for single-bin histograms. cv::EMD works in float: tolerance 1e-6.

#include "detect/colour_emd.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

constexpr double kTolerance = 1e-6;  // cv::EMD computes in float

ColourHistogram Only(ColourBin bin, double count = 1) {
  ColourHistogram h;
  h[bin] = count;
  return h;
}

ColourHistogram Mixed() {
  ColourHistogram h;
  h[ColourBin::kRed] = 30;
  h[ColourBin::kGreen] = 50;
  h[ColourBin::kWhite] = 15;
  h[ColourBin::kBlue] = 5;
  return h;
}

TEST(ColourEmd, IdentityIsZeroAndScaleDoesNotMatter) {
  EXPECT_NEAR(ColourEmd(Mixed(), Mixed()), 0.0, kTolerance);
  EXPECT_NEAR(ColourEmd(Mixed(), Mixed().Normalised()), 0.0, kTolerance) << "counts vs shares";
  EXPECT_NEAR(ColourEmd(Only(ColourBin::kCyan, 3), Only(ColourBin::kCyan, 700)), 0, kTolerance);
}

TEST(ColourEmd, IsSymmetric) {
  ColourHistogram other = Only(ColourBin::kOrange, 10);
  other[ColourBin::kBlack] = 4;
  other[ColourBin::kMagenta] = 1;
  EXPECT_NEAR(ColourEmd(Mixed(), other), ColourEmd(other, Mixed()), kTolerance);
  EXPECT_GT(ColourEmd(Mixed(), other), 0.1);
}

TEST(ColourEmd, SingleBinHistogramsAreTheirGroundDistance) {
  // Centres: red 353, orange 30 degrees: 37 degrees apart.
  EXPECT_NEAR(ColourEmd(Only(ColourBin::kRed), Only(ColourBin::kOrange)), 37.0 / 180, kTolerance);
  // Green 109.5, magenta 297.5: 188 degrees, the short way 172.
  EXPECT_NEAR(ColourEmd(Only(ColourBin::kGreen), Only(ColourBin::kMagenta)), 172.0 / 180,
              kTolerance);
  EXPECT_NEAR(ColourEmd(Only(ColourBin::kBlack), Only(ColourBin::kWhite)), 1.0, kTolerance);
  EXPECT_NEAR(ColourEmd(Only(ColourBin::kRed), Only(ColourBin::kBlack)), 0.5, kTolerance);
  EXPECT_NEAR(ColourEmd(Only(ColourBin::kBlue), Only(ColourBin::kWhite)), 0.5, kTolerance);
}

TEST(ColourEmd, MovesOnlyTheMassThatDiffers) {
  ColourHistogram half = Only(ColourBin::kRed, 1);
  half[ColourBin::kGreen] = 1;
  // Half the mass moves from green (109.5) to red (353): 116.5 degrees.
  EXPECT_NEAR(ColourEmd(half, Only(ColourBin::kRed)), 0.5 * 116.5 / 180, kTolerance);
}

TEST(ColourEmd, AdjacentHuesAreCloserThanOppositeOnes) {
  const double adjacent = ColourEmd(Only(ColourBin::kRed), Only(ColourBin::kOrange));
  const double opposite = ColourEmd(Only(ColourBin::kRed), Only(ColourBin::kCyan));
  EXPECT_LT(adjacent, opposite);
  EXPECT_LT(ColourEmd(Only(ColourBin::kGreen), Only(ColourBin::kYellow)),
            ColourEmd(Only(ColourBin::kGreen), Only(ColourBin::kMagenta)));
  EXPECT_LT(ColourEmd(Only(ColourBin::kBlue), Only(ColourBin::kCyan)),
            ColourEmd(Only(ColourBin::kBlue), Only(ColourBin::kYellow)));
}

TEST(ColourEmd, GroundDistanceIsAMetric) {
  const cv::Mat d = ColourBinGroundDistances();
  ASSERT_EQ(d.size(), cv::Size(kColourBinCount, kColourBinCount));
  ASSERT_EQ(d.type(), CV_32F);
  for (int a = 0; a < kColourBinCount; ++a) {
    EXPECT_EQ(d.at<float>(a, a), 0.0f);
    for (int b = 0; b < kColourBinCount; ++b) {
      EXPECT_EQ(d.at<float>(a, b), d.at<float>(b, a));
      EXPECT_GE(d.at<float>(a, b), 0.0f);
      EXPECT_LE(d.at<float>(a, b), 1.0f);
      if (a != b) {
        EXPECT_GT(d.at<float>(a, b), 0.0f);
      }
      for (int c = 0; c < kColourBinCount; ++c) {
        EXPECT_LE(d.at<float>(a, c), d.at<float>(a, b) + d.at<float>(b, c) + 1e-6f)
            << a << " " << b << " " << c;
      }
    }
  }
}

TEST(ColourEmd, EmptyOrInvalidHistogramIsAUsageError) {
  EXPECT_THROW(ColourEmd(ColourHistogram(), Mixed()), UsageError);
  EXPECT_THROW(ColourEmd(Mixed(), ColourHistogram()), UsageError);
  EXPECT_THROW(ColourEmd(Mixed(), Only(ColourBin::kRed, -2)), UsageError);
}

}  // namespace
}  // namespace littermap::detect
