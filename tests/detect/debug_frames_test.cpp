// Segmentation pictures of processed frames: one PNG per frame named by its index, nothing without
// a directory, and a file that cannot be written named.

#include "detect/debug_frames.hpp"

#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::detect {
namespace {

const CameraIntrinsics kIntrinsics;
const FrameSegmentation kNothingSegmented;

ProcessedFrame Processed(const RgbdFrame& frame) {
  return {frame, kNothingSegmented, Eigen::Isometry3d::Identity(), kIntrinsics};
}

TEST(DebugFrames, WritesAPictureOfEveryFrame) {
  test::TempDir dir;
  const FrameCallback write = DebugFrameWriter(dir / "frames" / "run");
  ASSERT_TRUE(write);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "frames" / "run"));  // created at once
  RgbdFrame frame;
  frame.index = 7;
  frame.colour_bgr = cv::Mat(12, 16, CV_8UC3, cv::Scalar(10, 20, 30));
  write(Processed(frame));
  const cv::Mat picture = cv::imread((dir / "frames" / "run" / "frame_000007.png").string());
  ASSERT_FALSE(picture.empty());
  EXPECT_EQ(picture.size(), frame.colour_bgr.size());
  EXPECT_EQ(picture.at<cv::Vec3b>(3, 4), cv::Vec3b(10, 20, 30));  // nothing segmented: as taken
}

TEST(DebugFrames, NothingWithoutADirectory) { EXPECT_FALSE(DebugFrameWriter({})); }

TEST(DebugFrames, AFileThatCannotBeWrittenIsNamed) {
  test::TempDir dir;
  const FrameCallback write = DebugFrameWriter(dir / "frames");
  std::filesystem::create_directories(dir / "frames" / "frame_000001.png");  // in the way
  RgbdFrame frame;
  frame.index = 1;
  frame.colour_bgr = cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(0));
  try {
    write(Processed(frame));
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {  // a folder where the file belongs: the path is at fault
    EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
    EXPECT_EQ(std::string(error.what()), (dir / "frames" / "frame_000001.png").string() +
                                             ": cannot write a file: Is a directory");
  }
}

}  // namespace
}  // namespace littermap::detect
