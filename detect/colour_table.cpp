#include "detect/colour_table.hpp"

#include "core/error.hpp"

namespace littermap::detect {

cv::Mat ColourTable::CellCentres() {
  constexpr float kStep = 256.0f / kLevels;
  cv::Mat centres(kLevels * kLevels * kLevels, 3, CV_32F);
  int i = 0;
  for (int b = 0; b < kLevels; ++b) {
    for (int g = 0; g < kLevels; ++g) {
      for (int r = 0; r < kLevels; ++r, ++i) {
        centres.at<float>(i, 0) = (float(b) + 0.5f) * kStep;
        centres.at<float>(i, 1) = (float(g) + 0.5f) * kStep;
        centres.at<float>(i, 2) = (float(r) + 0.5f) * kStep;
      }
    }
  }
  return centres;
}

ColourTable::ColourTable(const cv::Mat& log_likelihoods) {
  if (log_likelihoods.type() != CV_32F || log_likelihoods.total() != kLevels * kLevels * kLevels) {
    throw InternalError("ColourTable: expected one CV_32F value per cell");
  }
  table_.assign(log_likelihoods.begin<float>(), log_likelihoods.end<float>());
}

}  // namespace littermap::detect
