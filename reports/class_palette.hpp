#pragma once
// How each object class is shown to people: a plural label and a colour from the Okabe-Ito
// palette, which colour-blind readers tell apart too. Unknown classes get their own name, grey.

#include <string>
#include <string_view>

#include <opencv2/core.hpp>

namespace littermap::reports {

struct ClassStyle {
  std::string label;  // "Food containers"
  cv::Scalar bgr;
  std::string hex;  // "#E69F00"
};

ClassStyle StyleOf(std::string_view class_name);

}  // namespace littermap::reports
