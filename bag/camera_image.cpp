#include "bag/camera_image.hpp"

#include "bag/image_codec.hpp"
#include "bag/message_header.hpp"
#include "bag/raw_image.hpp"

namespace littermap::bag {

CameraImage DecodeCameraImage(const BagReader& reader, const BagMessage& message) {
  if (message.topic->type == MessageTraits<msg::Image>::kTypeName) {
    return DecodeBagMessage<msg::Image>(reader, message);
  }
  return DecodeBagMessage<msg::CompressedImage>(reader, message);
}

std::optional<CameraImage> TakeCameraImage(AnyMessage& message) {
  if (auto* compressed = std::get_if<msg::CompressedImage>(&message)) return std::move(*compressed);
  if (auto* raw = std::get_if<msg::Image>(&message)) return std::move(*raw);
  return std::nullopt;
}

TimestampNs StampOf(const CameraImage& image) {
  return std::visit([](const auto& m) { return StampOf(m.header); }, image);
}

cv::Mat DecodeColor(const CameraImage& image) {
  if (const auto* raw = std::get_if<msg::Image>(&image)) return DecodeRawColor(*raw);
  return DecodeColor(std::get<msg::CompressedImage>(image));
}

cv::Mat DecodeDepthMm(const CameraImage& image) {
  if (const auto* raw = std::get_if<msg::Image>(&image)) return DecodeRawDepthMm(*raw);
  return DecodeDepthMm(std::get<msg::CompressedImage>(image));
}

}  // namespace littermap::bag
