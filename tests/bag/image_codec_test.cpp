// Colour and depth images in a run bag: lossless depth, faithful colour, clear errors.

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "bag/image_codec.hpp"
#include "core/error.hpp"

namespace littermap::bag {
namespace {

const std::string kTumPair = std::string(LITTERMAP_DATASETS_DIR) + "/tum_pair/";

cv::Mat RealDepthMm() {
  const cv::Mat raw = cv::imread(kTumPair + "1_depth.png", cv::IMREAD_UNCHANGED);
  EXPECT_EQ(raw.type(), CV_16UC1) << "missing " << kTumPair << "1_depth.png";
  cv::Mat depth_mm;
  raw.convertTo(depth_mm, CV_16UC1, 1.0 / 5.0);  // TUM: 5000 units per metre
  return depth_mm;
}

TEST(ImageCodec, DepthPngIsLosslessOnRealDepth) {
  const cv::Mat depth = RealDepthMm();
  ASSERT_FALSE(depth.empty());
  const auto encoded = EncodeDepthPng(depth, {{1, 2}, "camera"});
  EXPECT_EQ(encoded.format, "16UC1; png compressed");
  EXPECT_EQ(encoded.header.frame_id, "camera");
  EXPECT_LT(encoded.data.size(), depth.total() * 2 / 3) << "depth should compress";
  const cv::Mat decoded = DecodeDepthMm(encoded);
  ASSERT_EQ(decoded.type(), CV_16UC1);
  EXPECT_EQ(cv::norm(decoded, depth, cv::NORM_INF), 0.0);
  // Other PNG readers agree (byte order, filters): OpenCV's own decoder gives the same pixels.
  const cv::Mat by_opencv = cv::imdecode(encoded.data, cv::IMREAD_UNCHANGED);
  EXPECT_EQ(cv::norm(by_opencv, depth, cv::NORM_INF), 0.0);
}

TEST(ImageCodec, CompressedDepthTransportPayloadDecodes) {
  const cv::Mat depth = RealDepthMm();
  auto image = EncodeDepthPng(depth, {});
  image.format = "16UC1; compressedDepth png";
  image.data.insert(image.data.begin(), 12, 0);  // compressed_depth_image_transport's header
  EXPECT_EQ(cv::norm(DecodeDepthMm(image), depth, cv::NORM_INF), 0.0);
}

TEST(ImageCodec, ColourJpegKeepsTheImage) {
  const cv::Mat colour = cv::imread(kTumPair + "1.png", cv::IMREAD_COLOR);
  ASSERT_FALSE(colour.empty()) << "missing " << kTumPair << "1.png";
  const auto encoded = EncodeColorJpeg(colour, {});
  EXPECT_EQ(encoded.format, "bgr8; jpeg compressed bgr8");
  const cv::Mat decoded = DecodeColor(encoded);
  ASSERT_EQ(decoded.size(), colour.size());
  // Quality 90 JPEG of a real photo: PSNR well above 30 dB.
  EXPECT_GT(cv::PSNR(decoded, colour), 30.0);
}

TEST(ImageCodec, DamagedPayloadsAreBadInput) {
  msg::CompressedImage image;
  image.format = "bgr8; jpeg compressed bgr8";
  EXPECT_THROW(DecodeColor(image), BadInputError);
  image.data = {0xff, 0xd8, 0x00, 0x01, 0x02};
  EXPECT_THROW(DecodeColor(image), BadInputError);
  const cv::Mat colour(4, 4, CV_8UC3, cv::Scalar(1, 2, 3));
  EXPECT_THROW(DecodeDepthMm(EncodeColorJpeg(colour, {})), BadInputError)
      << "an 8-bit colour image is not depth";
  image.format = "16UC1; compressedDepth png";
  image.data.assign(12, 0);
  EXPECT_THROW(DecodeDepthMm(image), BadInputError);
}

}  // namespace
}  // namespace littermap::bag
