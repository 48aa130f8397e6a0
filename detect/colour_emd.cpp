#include "detect/colour_emd.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

bool IsChromatic(int bin) {
  return bin != static_cast<int>(ColourBin::kBlack) && bin != static_cast<int>(ColourBin::kWhite);
}

double HueCentreDeg(int bin) {
  const HueInterval hue = ColourBinHueInterval(static_cast<ColourBin>(bin));
  return std::fmod(0.5 * (hue.begin_deg + hue.end_deg), 360.0);
}

double GroundDistance(int a, int b) {
  if (a == b) return 0.0;
  if (IsChromatic(a) && IsChromatic(b)) {
    const double d = std::abs(HueCentreDeg(a) - HueCentreDeg(b));
    return std::min(d, 360.0 - d) / 180.0;
  }
  if (IsChromatic(a) || IsChromatic(b)) return kAchromaticToChromaticDistance;
  return kBlackToWhiteDistance;
}

// Shares as the one-column weight signature cv::EMD takes with a user cost matrix.
cv::Mat Signature(const ColourHistogram& histogram, const char* which) {
  histogram.Validate(std::string("colour EMD: histogram ") + which);
  if (!(histogram.Total() > 0)) {
    throw UsageError(std::string("colour EMD: histogram ") + which + " is empty");
  }
  const ColourHistogram shares = histogram.Normalised();
  cv::Mat signature(kColourBinCount, 1, CV_32F);
  for (int i = 0; i < kColourBinCount; ++i) {
    signature.at<float>(i) = static_cast<float>(shares.counts[static_cast<std::size_t>(i)]);
  }
  return signature;
}

}  // namespace

cv::Mat ColourBinGroundDistances() {
  cv::Mat cost(kColourBinCount, kColourBinCount, CV_32F);
  for (int a = 0; a < kColourBinCount; ++a) {
    for (int b = 0; b < kColourBinCount; ++b) {
      cost.at<float>(a, b) = static_cast<float>(GroundDistance(a, b));
    }
  }
  return cost;
}

double ColourEmd(const ColourHistogram& a, const ColourHistogram& b) {
  static const cv::Mat kCost = ColourBinGroundDistances();
  const cv::Mat signature_a = Signature(a, "a");
  const cv::Mat signature_b = Signature(b, "b");
  try {
    return cv::EMD(signature_a, signature_b, cv::DIST_USER, kCost);
  } catch (const cv::Exception& e) {
    throw InternalError(std::string("colour EMD: cv::EMD failed: ") + e.what());
  }
}

}  // namespace littermap::detect
