// Pairing colour and depth images into RGB-D frames by stamp, as a run bag interleaves them.

#include "bag/rgbd_pairing.hpp"

#include <gtest/gtest.h>

#include "bag/message_header.hpp"

namespace littermap::bag {
namespace {

msg::CompressedImage Image(TimestampNs stamp_ns, const char* format) {
  msg::CompressedImage image;
  image.header = MakeHeader(stamp_ns, "camera");
  image.format = format;
  return image;
}

constexpr TimestampNs kMs = 1'000'000;

TEST(RgbdPairing, PairsColourAndDepthWithinTheGapInEitherOrder) {
  RgbdPairing pairing(0.02);
  EXPECT_FALSE(pairing.AddColour(Image(100 * kMs, "jpeg")));
  const auto first = pairing.AddDepth(Image(115 * kMs, "png"));
  ASSERT_TRUE(first);
  EXPECT_EQ(first->stamp_ns, 100 * kMs);  // the colour image's stamp
  EXPECT_EQ(std::get<msg::CompressedImage>(first->colour).format, "jpeg");
  EXPECT_EQ(std::get<msg::CompressedImage>(first->depth).format, "png");
  EXPECT_FALSE(pairing.AddDepth(Image(200 * kMs, "png")));
  const auto second = pairing.AddColour(Image(190 * kMs, "jpeg"));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->stamp_ns, 190 * kMs);
}

TEST(RgbdPairing, AnImageWithoutPartnerWaitsUntilANewerOneReplacesIt) {
  RgbdPairing pairing(0.02);
  EXPECT_FALSE(pairing.AddDepth(Image(100 * kMs, "png")));    // its colour image was lost
  EXPECT_FALSE(pairing.AddColour(Image(200 * kMs, "jpeg")));  // 100 ms apart: no pair
  const auto frame = pairing.AddDepth(Image(201 * kMs, "png"));
  ASSERT_TRUE(frame);
  EXPECT_EQ(StampOf(frame->depth), 201 * kMs);
}

TEST(RgbdPairing, ResetForgetsTheWaitingImages) {
  RgbdPairing pairing(0.02);
  EXPECT_FALSE(pairing.AddColour(Image(100 * kMs, "jpeg")));
  pairing.Reset();
  EXPECT_FALSE(pairing.AddDepth(Image(100 * kMs, "png")));
}

}  // namespace
}  // namespace littermap::bag
