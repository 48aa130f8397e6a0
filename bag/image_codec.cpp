#include "bag/image_codec.hpp"

#include <span>

#include <opencv2/imgcodecs.hpp>

#include "bag/jpeg_decoder.hpp"
#include "bag/png16.hpp"
#include "bag/png_decoder.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"

namespace littermap::bag {
namespace {

// compressed_depth_image_transport prefixes its PNG with a 12-byte ConfigHeader
// (int32 format, float32 depthQuantA, float32 depthQuantB).
constexpr std::size_t kCompressedDepthHeaderBytes = 12;

std::vector<std::uint8_t> EncodeOrThrow(const char* extension, const cv::Mat& image,
                                        const std::vector<int>& parameters) {
  std::vector<std::uint8_t> bytes;
  if (!cv::imencode(extension, image, bytes, parameters)) {
    throw InternalError(std::string("cannot encode image as ") + extension);
  }
  return bytes;
}

// PNG and JPEG go through bag/png_decoder and bag/jpeg_decoder (the libraries' messages caught,
// not printed); other formats through OpenCV.
cv::Mat DecodeOrThrow(std::span<const std::uint8_t> bytes, int flags, const std::string& format) {
  if (bytes.empty()) throw BadInputError("image (" + format + ") has no data");
  const bool colour = flags == cv::IMREAD_COLOR;
  try {
    if (IsPng(bytes)) return colour ? DecodePngColor(bytes) : DecodePng16(bytes);
    if (IsJpeg(bytes)) {
      if (!colour) throw BadInputError("a JPEG is not a 16-bit single-channel image");
      return DecodeJpeg(bytes).bgr;
    }
  } catch (const BadInputError& error) {
    throw BadInputError("image (" + format + "): " + error.what());
  }
  const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8UC1,
                       const_cast<std::uint8_t*>(bytes.data()));
  cv::Mat image = cv::imdecode(buffer, flags);
  if (image.empty()) throw BadInputError("image (" + format + ") does not decode");
  return image;
}

}  // namespace

void WriteImageFile(const std::filesystem::path& file, const cv::Mat& image,
                    const std::vector<int>& parameters) {
  const std::vector<std::uint8_t> bytes =
      EncodeOrThrow(file.extension().string().c_str(), image, parameters);
  WriteFileAtomically(file, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

msg::CompressedImage EncodeColorJpeg(const cv::Mat& colour_bgr, const msg::Header& header,
                                     const ImageCodecOptions& options) {
  if (colour_bgr.type() != CV_8UC3) throw InternalError("EncodeColorJpeg: image is not 8UC3");
  msg::CompressedImage image;
  image.header = header;
  image.format = "bgr8; jpeg compressed bgr8";
  image.data = EncodeOrThrow(".jpg", colour_bgr, {cv::IMWRITE_JPEG_QUALITY, options.jpeg_quality});
  return image;
}

msg::CompressedImage EncodeDepthPng(const cv::Mat& depth_mm, const msg::Header& header,
                                    const ImageCodecOptions& options) {
  if (depth_mm.type() != CV_16UC1) throw InternalError("EncodeDepthPng: image is not 16UC1");
  msg::CompressedImage image;
  image.header = header;
  image.format = "16UC1; png compressed";
  image.data = EncodePng16(depth_mm, {.zlib_level = options.png_compression});
  return image;
}

cv::Mat DecodeColor(const msg::CompressedImage& image) {
  cv::Mat colour = DecodeOrThrow(image.data, cv::IMREAD_COLOR, image.format);
  if (colour.depth() != CV_8U) colour.convertTo(colour, CV_8U, 1.0 / 256.0);
  return colour;
}

cv::Mat DecodeDepthMm(const msg::CompressedImage& image) {
  std::span<const std::uint8_t> bytes(image.data);
  const bool compressed_depth = image.format.find("compressedDepth") != std::string::npos;
  if (compressed_depth) {
    if (bytes.size() <= kCompressedDepthHeaderBytes) {
      throw BadInputError("depth image (" + image.format + ") is shorter than its header");
    }
    bytes = bytes.subspan(kCompressedDepthHeaderBytes);
  }
  cv::Mat depth = DecodeOrThrow(bytes, cv::IMREAD_UNCHANGED, image.format);
  if (depth.type() != CV_16UC1) {
    throw BadInputError("depth image (" + image.format + ") is not 16-bit single-channel");
  }
  return depth;
}

}  // namespace littermap::bag
