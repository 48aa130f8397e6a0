// Uncompressed camera images as real drivers publish them: channel orders, padded rows,
// big-endian depth, float depth in metres, and errors that name the encoding.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "bag/camera_image.hpp"
#include "bag/raw_image.hpp"
#include "bag/rgbd_pairing.hpp"
#include "support/expect_bad_input.hpp"

namespace littermap::bag {
namespace {

msg::Image Raw(std::string encoding, std::uint32_t width, std::uint32_t height,
               std::uint32_t step) {
  msg::Image image;
  image.encoding = std::move(encoding);
  image.width = width;
  image.height = height;
  image.step = step;
  image.data.assign(std::size_t{step} * height, 0);
  return image;
}

TEST(RawImage, ColourOrdersAndPaddedRows) {
  // 2x2 rgb8 with 2 bytes of padding per row: pixel (1, 1) is pure red.
  msg::Image rgb = Raw("rgb8", 2, 2, 8);
  rgb.data[8 + 3] = 255;
  const cv::Mat bgr = DecodeRawColor(rgb);
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(1, 1), cv::Vec3b(0, 0, 255));
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(0, 0, 0));

  msg::Image bgra = Raw("bgra8", 1, 1, 4);
  bgra.data = {10, 20, 30, 40};
  EXPECT_EQ(DecodeRawColor(bgra).at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  msg::Image mono = Raw("mono8", 1, 1, 1);
  mono.data = {77};
  EXPECT_EQ(DecodeRawColor(mono).at<cv::Vec3b>(0, 0), cv::Vec3b(77, 77, 77));
}

TEST(RawImage, DepthInMillimetresAndMetres) {
  msg::Image big = Raw("16UC1", 1, 1, 2);
  big.is_bigendian = 1;
  big.data = {0x04, 0xD2};  // 1234 mm
  EXPECT_EQ(DecodeRawDepthMm(big).at<std::uint16_t>(0, 0), 1234);

  msg::Image metres = Raw("32FC1", 5, 1, 20);
  const float values[] = {1.2345f, std::numeric_limits<float>::quiet_NaN(), -1.0f, 70.0f,
                          std::numeric_limits<float>::infinity()};
  std::memcpy(metres.data.data(), values, sizeof(values));
  const cv::Mat depth = DecodeRawDepthMm(metres);
  ASSERT_EQ(depth.type(), CV_16UC1);
  EXPECT_EQ(depth.at<std::uint16_t>(0, 0), 1235);  // rounded to the millimetre
  for (int u = 1; u < 5; ++u) EXPECT_EQ(depth.at<std::uint16_t>(0, u), 0) << u;
}

TEST(RawImage, ErrorsNameTheEncoding) {
  msg::Image short_data = Raw("rgb8", 4, 4, 12);
  short_data.data.resize(20);
  test::ExpectBadInput([&] { DecodeRawColor(short_data); }, "rgb8, 4x4, step 12");
  test::ExpectBadInput([&] { DecodeRawColor(Raw("bayer_rggb8", 2, 2, 2)); }, "'bayer_rggb8'");
  test::ExpectBadInput([&] { DecodeRawDepthMm(Raw("rgb8", 2, 2, 6)); }, "'rgb8'");
  test::ExpectBadInput([&] { DecodeRawColor(Raw("rgb8", 4, 1, 2)); }, "too few");
}

TEST(RawImage, PairsWithCompressedImages) {
  RgbdPairing pairing(0.02);
  msg::Image colour = Raw("rgb8", 1, 1, 3);
  colour.header.stamp = {100, 0};
  msg::Image depth = Raw("32FC1", 1, 1, 4);
  depth.header.stamp = {100, 5'000'000};
  const float one_metre = 1.0f;
  std::memcpy(depth.data.data(), &one_metre, sizeof(one_metre));
  EXPECT_FALSE(pairing.AddColour(colour));
  const auto frame = pairing.AddDepth(depth);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->stamp_ns, 100'000'000'000);
  EXPECT_EQ(DecodeDepthMm(frame->depth).at<std::uint16_t>(0, 0), 1000);
  EXPECT_EQ(DecodeColor(frame->colour).type(), CV_8UC3);
}

}  // namespace
}  // namespace littermap::bag
