#pragma once
// A camera image as a bag may hold it: sensor_msgs/CompressedImage (JPEG or PNG, as littermap
// records) or uncompressed sensor_msgs/Image (bag/raw_image.hpp). Readers keep images as stored
// and decode only the frames they use.

#include <optional>
#include <variant>

#include <opencv2/core.hpp>

#include "bag/bag_reader.hpp"
#include "bag/message_stream.hpp"
#include "bag/ros_messages.hpp"
#include "core/time.hpp"

namespace littermap::bag {

using CameraImage = std::variant<msg::CompressedImage, msg::Image>;

// Decodes a message of either image type; another type is a BadInputError naming the topic.
CameraImage DecodeCameraImage(const BagReader& reader, const BagMessage& message);
// Moves the image out of a decoded message of either image type; nullopt for other types.
std::optional<CameraImage> TakeCameraImage(AnyMessage& message);
TimestampNs StampOf(const CameraImage& image);
// CV_8UC3 BGR, CV_16UC1 millimetres; BadInputError when the image does not decode.
cv::Mat DecodeColor(const CameraImage& image);
cv::Mat DecodeDepthMm(const CameraImage& image);

}  // namespace littermap::bag
