#pragma once
// How each object class is shown to people: a plural label, its nouns, and a colour from the
// Okabe-Ito palette, which colour-blind readers tell apart too. Unknown classes get their own name,
// grey.

#include <string>
#include <string_view>

#include <opencv2/core.hpp>

namespace littermap::reports {

struct ClassStyle {
  std::string label;  // "Food containers": a heading, a legend
  std::string one;    // "food container": mid-sentence, one of them
  std::string many;   // "food containers"
  cv::Scalar bgr;
  std::string hex;  // "#E69F00"
};

ClassStyle StyleOf(std::string_view class_name);

}  // namespace littermap::reports
