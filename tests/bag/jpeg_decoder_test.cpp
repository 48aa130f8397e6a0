// JPEG decoding through libjpeg: the pixels OpenCV's imdecode gives, and damage that libjpeg
// reads past reported, with nothing printed.

#include "bag/jpeg_decoder.hpp"

#include <gtest/gtest.h>

#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::bag {
namespace {

// A smooth picture with some edges (JPEG of pure noise says little about real frames).
cv::Mat Picture(int type) {
  cv::Mat image(121, 163, CV_8UC3);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      image.at<cv::Vec3b>(v, u) = {static_cast<std::uint8_t>(u + v),
                                   static_cast<std::uint8_t>(2 * u),
                                   static_cast<std::uint8_t>(255 - v)};
    }
  }
  cv::circle(image, {80, 60}, 30, {20, 200, 40}, cv::FILLED);
  if (type == CV_8UC1) cv::cvtColor(image, image, cv::COLOR_BGR2GRAY);
  return image;
}

std::vector<std::uint8_t> Jpeg(const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, 85}));
  return bytes;
}

TEST(JpegDecoder, PixelsAreWhatOpenCvGivesForColourAndGrey) {
  for (const int type : {CV_8UC3, CV_8UC1}) {
    SCOPED_TRACE(type);
    const std::vector<std::uint8_t> jpeg = Jpeg(Picture(type));
    const JpegImage decoded = DecodeJpeg(jpeg);
    const cv::Mat reference = cv::imdecode(jpeg, cv::IMREAD_COLOR);
    ASSERT_EQ(decoded.bgr.type(), reference.type());
    ASSERT_EQ(decoded.bgr.size(), reference.size());
    EXPECT_EQ(cv::norm(decoded.bgr, reference, cv::NORM_INF), 0);
    EXPECT_EQ(decoded.damage, "");
  }
}

TEST(JpegDecoder, DamageIsReportedOrRefusedAndNothingIsPrinted) {
  const std::vector<std::uint8_t> good = Jpeg(Picture(CV_8UC3));
  std::vector<std::uint8_t> truncated(good.begin(), good.begin() + good.size() / 2);
  std::vector<std::uint8_t> flipped = good;
  for (std::size_t i = flipped.size() / 2; i < flipped.size() - 2; i += 41) flipped[i] ^= 0xff;
  std::vector<std::uint8_t> header_only(good.begin(), good.begin() + 20);
  // Cut short: libjpeg fills in the rest and warns.
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(DecodeJpeg(truncated).damage.rfind("Premature end of JPEG file", 0), 0u);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  // Bit flips in the entropy-coded data: warned about, or refused where they make a marker.
  ::testing::internal::CaptureStderr();
  try {
    EXPECT_NE(DecodeJpeg(flipped).damage, "");
  } catch (const BadInputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("JPEG does not decode: ", 0), 0u) << error.what();
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  ::testing::internal::CaptureStderr();
  EXPECT_THROW(DecodeJpeg(header_only), BadInputError);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_FALSE(IsJpeg(std::vector<std::uint8_t>{0x89, 'P', 'N', 'G'}));
}

}  // namespace
}  // namespace littermap::bag
