#pragma once
// A colour log-likelihood tabulated on a 32x32x32 BGR grid: evaluating two Gaussian mixtures on
// every pixel of a VGA frame costs more than the rest of the segmentation, while the table
// costs 32768 evaluations per model and a lookup per pixel. Quantising to 8 levels of 256 is
// below the JPEG noise of the colour images.

#include <array>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace littermap::detect {

class ColourTable {
 public:
  static constexpr int kBits = 5;
  static constexpr int kLevels = 1 << kBits;

  ColourTable() : table_(kLevels * kLevels * kLevels, 0.0f) {}
  // The table of a constant log-likelihood.
  explicit ColourTable(float log_likelihood)
      : table_(kLevels * kLevels * kLevels, log_likelihood) {}
  // The cells' centre colours, kLevels^3 x 3 CV_32F in table order, to evaluate a model on.
  static cv::Mat CellCentres();
  // Takes one log-likelihood per cell (CV_32F, kLevels^3 values in CellCentres' order).
  explicit ColourTable(const cv::Mat& log_likelihoods);

  float operator()(const cv::Vec3b& bgr) const {
    constexpr int kShift = 8 - kBits;
    return table_[static_cast<std::size_t>(((bgr[0] >> kShift) << (2 * kBits)) |
                                           ((bgr[1] >> kShift) << kBits) | (bgr[2] >> kShift))];
  }

 private:
  std::vector<float> table_;
};

}  // namespace littermap::detect
