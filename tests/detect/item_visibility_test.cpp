// Whether a frame could have seen a place: in the image, within the depth range, large enough,
// not hidden behind a nearer reading, and with ground found in the frame.

#include "detect/item_visibility.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

// A frame whose camera is the world's origin (optical frame: z ahead) measuring a wall 3 m away.
struct WallFrame {
  RgbdFrame frame;
  FrameSegmentation segmentation;
  CameraIntrinsics intrinsics;
  WallFrame() {
    frame.depth_mm = cv::Mat(480, 640, CV_16U, cv::Scalar(3000));
    segmentation.ground_found = true;
  }
  ProcessedFrame Processed() const {
    return {frame, segmentation, Eigen::Isometry3d::Identity(), intrinsics};
  }
};

TEST(ItemVisibility, APlaceInViewBeforeTheMeasuredSurfaceCouldBeSeen) {
  const WallFrame wall;
  const ItemVisibilityOptions options;
  EXPECT_TRUE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, 2.0}, 0.1));
  EXPECT_TRUE(
      FrameVisibility(wall.Processed(), options).CouldSee({0.5, 0.2, 2.9}, 0.1));  // on the wall
  // Behind the wall (3.5 m against a 3 m reading): hidden.
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, 3.5}, 0.1));
}

TEST(ItemVisibility, OutOfTheImageOrTheDepthRangeCannotBeSeen) {
  const WallFrame wall;
  const ItemVisibilityOptions options;
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, -2.0}, 0.1));  // behind
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, 0.3}, 0.1));   // too near
  EXPECT_FALSE(
      FrameVisibility(wall.Processed(), options).CouldSee({3, 0, 2.0}, 0.1));  // right of view
  // At 1 m, 0.6 m right is u = 525 * 0.6 + 319.5 = 634.5: in the image, within its 10 px border;
  // 0.58 m right is u = 624, clear of it.
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0.6, 0, 1.0}, 0.1));
  EXPECT_TRUE(FrameVisibility(wall.Processed(), options).CouldSee({0.58, 0, 1.0}, 0.1));
  // 1 cm at 2 m is 2.6 px: too small to segment.
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, 2.0}, 0.01));
  // The last half metre of the depth range does not count: objects there are cut off in part.
  ItemVisibilityOptions far = options;
  far.max_depth_m = 3.2f;
  EXPECT_FALSE(FrameVisibility(wall.Processed(), far).CouldSee({0, 0, 2.9}, 0.1));
  far.far_margin_m = 0;
  EXPECT_TRUE(FrameVisibility(wall.Processed(), far).CouldSee({0, 0, 2.9}, 0.1));
  far.max_depth_m = 1.5f;
  EXPECT_FALSE(FrameVisibility(wall.Processed(), far).CouldSee({0, 0, 2.0}, 0.1));
}

TEST(ItemVisibility, APlaceWhereSegmentationCutOutSomethingWasNotMissed) {
  // The frame's segmentation found a non-ground region over the image centre (an object too large
  // with its neighbour, say, or called clutter this time): the frame saw something there.
  WallFrame wall;
  const ItemVisibilityOptions options;
  wall.segmentation.refinement.non_ground = cv::Mat::zeros(480, 640, CV_8U);
  EXPECT_TRUE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, 2.0}, 0.1));
  wall.segmentation.refinement.non_ground(cv::Rect(300, 220, 40, 40)).setTo(255);
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, 2.0}, 0.1));
  // Beside the region (u = 525 * 0.3 / 2 + 319.5 = 398): ground there, a miss.
  EXPECT_TRUE(FrameVisibility(wall.Processed(), options).CouldSee({0.3, 0, 2.0}, 0.1));
}

TEST(ItemVisibility, RejectsADepthRangeTheMarginLeavesEmpty) {
  const WallFrame wall;
  ItemVisibilityOptions options;
  options.far_margin_m = 4.2f;  // 4.5 - 4.2 < 0.4
  EXPECT_THROW(FrameVisibility(wall.Processed(), options), UsageError);
}

TEST(ItemVisibility, NoDepthOrNoGroundSeesNothing) {
  WallFrame wall;
  const ItemVisibilityOptions options;
  wall.frame.depth_mm(cv::Rect(310, 230, 20, 20)).setTo(0);  // no reading around the centre
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0, 0, 2.0}, 0.1));
  EXPECT_TRUE(FrameVisibility(wall.Processed(), options).CouldSee({0.3, 0, 2.0}, 0.1));
  wall.segmentation.ground_found = false;
  EXPECT_FALSE(FrameVisibility(wall.Processed(), options).CouldSee({0.3, 0, 2.0}, 0.1));
}

}  // namespace
}  // namespace littermap::detect
