#pragma once
// Uncompressed sensor_msgs/Image, as cameras' ROS 2 drivers publish them and many bags hold
// them: colour in bgr8, rgb8, bgra8, rgba8 or mono8; depth in 16UC1 / mono16 (millimetres) or
// 32FC1 (metres). Rows may be padded (step) and 16-bit data big-endian.

#include <opencv2/core.hpp>

#include "bag/ros_messages.hpp"

namespace littermap::bag {

// Returns CV_8UC3 BGR. Throws BadInputError naming the encoding when it is not a colour one,
// or when the data is shorter than height x step or step shorter than a row.
cv::Mat DecodeRawColor(const msg::Image& image);
// Returns CV_16UC1 depth in millimetres, 0 = no reading (32FC1: NaN, infinite, not positive or
// beyond 65.535 m). Throws BadInputError as DecodeRawColor.
cv::Mat DecodeRawDepthMm(const msg::Image& image);

}  // namespace littermap::bag
