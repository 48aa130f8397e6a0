// PNG decoding through libpng: the pixels OpenCV's imdecode gives, for every kind of PNG a
// camera or a data set writes, and a damaged PNG refused with libpng's reason and nothing printed.

#include "bag/png_decoder.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"

namespace littermap::bag {
namespace {

cv::Mat Noise(int type, unsigned seed) {
  cv::Mat image(37, 53, type);  // odd sizes: no row padding hides a stride error
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
  return image;
}

std::vector<std::uint8_t> Png(const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes));
  return bytes;
}

void ExpectSamePixels(const cv::Mat& a, const cv::Mat& b) {
  ASSERT_EQ(a.type(), b.type());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0);
}

TEST(PngDecoder, ColourIsWhatOpenCvGivesForGreyColourAlphaAnd16Bit) {
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4}) {
    SCOPED_TRACE(type);
    const std::vector<std::uint8_t> png = Png(Noise(type, 7));
    ExpectSamePixels(DecodePngColor(png), cv::imdecode(png, cv::IMREAD_COLOR));
  }
}

TEST(PngDecoder, SixteenBitGreyIsExact) {
  const cv::Mat depth = Noise(CV_16UC1, 3);
  ExpectSamePixels(DecodePng16(Png(depth)), depth);
}

TEST(PngDecoder, DepthMustBeSixteenBitGrey) {
  EXPECT_THROW(DecodePng16(Png(Noise(CV_8UC1, 1))), BadInputError);
  EXPECT_THROW(DecodePng16(Png(Noise(CV_16UC3, 1))), BadInputError);
}

TEST(PngDecoder, DamagedPngIsRefusedWithLibpngsReasonAndNothingPrinted) {
  const std::vector<std::uint8_t> good = Png(Noise(CV_16UC1, 5));
  std::vector<std::uint8_t> truncated(good.begin(), good.begin() + good.size() / 2);
  std::vector<std::uint8_t> flipped = good;
  for (std::size_t i = 60; i < flipped.size() - 20; i += 97) flipped[i] ^= 0x5a;
  std::vector<std::uint8_t> signature_only(good.begin(), good.begin() + 8);
  for (const auto* bytes : {&truncated, &flipped, &signature_only}) {
    ::testing::internal::CaptureStderr();
    try {
      DecodePng16(*bytes);
      ADD_FAILURE() << "a damaged PNG decoded";
    } catch (const BadInputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind("PNG does not decode: ", 0), 0u) << error.what();
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  }
  EXPECT_FALSE(IsPng(std::vector<std::uint8_t>{0xff, 0xd8, 0xff, 0xe0, 0, 0, 0, 0}));
}

}  // namespace
}  // namespace littermap::bag
