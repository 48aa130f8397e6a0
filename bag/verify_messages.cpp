#include "bag/verify_messages.hpp"

#include <map>
#include <string>
#include <string_view>
#include <utility>

#include "bag/camera_image.hpp"
#include "bag/jpeg_decoder.hpp"
#include "bag/message_stream.hpp"
#include "core/error.hpp"

namespace littermap::bag {
namespace {

constexpr std::uint64_t kProgressEvery = 256;  // messages between progress reports

// Depth when the image's own format or encoding says 16-bit or floating point, as depth cameras
// publish it; colour otherwise. (The pipeline's roles go by topic name, which verification of a
// bag without roles resolved cannot; the payload says how it decodes.)
bool IsDepth(const CameraImage& image) {
  if (const auto* compressed = std::get_if<msg::CompressedImage>(&image)) {
    const std::string& f = compressed->format;
    return f.find("16UC1") != std::string::npos || f.find("mono16") != std::string::npos ||
           f.find("compressedDepth") != std::string::npos;
  }
  const std::string& e = std::get<msg::Image>(image).encoding;
  return e == "16UC1" || e == "mono16" || e == "32FC1";
}

// The camera namespace of an image or camera info topic, as image_transport pairs them: the
// camera info of "/cam/color/image_raw/compressed" is "/cam/color/camera_info".
std::string CameraNamespace(std::string topic) {
  for (const std::string_view transport : {"/compressedDepth", "/compressed"}) {
    if (topic.ends_with(transport)) topic.resize(topic.size() - transport.size());
  }
  return topic.substr(0, topic.rfind('/'));
}

// Decodes the image's pixels and checks their size against its camera's camera info.
void VerifyImage(const BagReader& reader, const DecodedMessage& message, const CameraImage& image,
                 const std::map<std::string, std::pair<int, int>>& camera_sizes) {
  cv::Mat pixels;
  try {
    const auto* compressed = std::get_if<msg::CompressedImage>(&image);
    if (compressed != nullptr && !IsDepth(image) && IsJpeg(compressed->data)) {
      // A damaged JPEG may still decode (to wrong pixels): verification says so.
      JpegImage jpeg = DecodeJpeg(compressed->data);
      if (!jpeg.damage.empty())
        ThrowUndecodable(reader, message, "JPEG is damaged: " + jpeg.damage);
      pixels = std::move(jpeg.bgr);
    } else {
      pixels = IsDepth(image) ? DecodeDepthMm(image) : DecodeColor(image);
    }
  } catch (const BadInputError& e) {
    ThrowUndecodable(reader, message, e.what());
  }
  const auto size = camera_sizes.find(CameraNamespace(message.topic->name));
  if (size == camera_sizes.end() || size->second.first == 0) return;
  if (pixels.cols != size->second.first || pixels.rows != size->second.second) {
    ThrowUndecodable(reader, message,
                     "image of " + std::to_string(pixels.cols) + "x" + std::to_string(pixels.rows) +
                         " pixels, but " + size->first + "/camera_info says " +
                         std::to_string(size->second.first) + "x" +
                         std::to_string(size->second.second));
  }
}

}  // namespace

VerifyResult VerifyMessages(BagReader& reader, const ProgressCallback& progress) {
  reader.SetVerifyChecksums(true);
  MessageStream stream(reader);
  const std::uint64_t total = reader.info().message_count;
  VerifyResult result;
  std::map<std::string, std::pair<int, int>> camera_sizes;  // camera namespace: width, height
  while (auto decoded = stream.Next()) {
    ++result.decoded_messages;
    if (const auto* info = std::get_if<msg::CameraInfo>(&decoded->message)) {
      camera_sizes[CameraNamespace(decoded->topic->name)] = {static_cast<int>(info->width),
                                                             static_cast<int>(info->height)};
    } else if (const std::optional<CameraImage> image = TakeCameraImage(decoded->message)) {
      VerifyImage(reader, *decoded, *image, camera_sizes);
      ++result.decoded_images;
    }
    if (result.decoded_messages % kProgressEvery == 0) {
      ReportProgress(progress, {"verifying", result.decoded_messages, total});
    }
  }
  result.warnings = stream.warnings();
  result.damage = reader.damage();
  return result;
}

}  // namespace littermap::bag
